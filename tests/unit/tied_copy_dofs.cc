// The tied-copy DoF layer: with every face tied it has exactly the unknowns
// of the continuous FE_Q space; releasing faces duplicates exactly the nodes
// that the released faces separate (a crack-front node stays one unknown).
#include "../check.h"

#include <amfrac/dofs/tied_copy_dofs.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>

using namespace amfrac;

namespace
{
  /** Release the faces whose centres are in @p centres. */
  template <int dim>
  typename TiedCopyDoFs<dim>::FaceFilter
  release_at(const std::vector<Point<dim>> &centres)
  {
    return [centres](const auto &cell, const unsigned int f) {
      for (const auto &c : centres)
        if (cell->face(f)->center().distance(c) < 1e-10)
          return true;
      return false;
    };
  }

  /** Give every cell the rigid translation of its fragment (@p isolated
   * cells one, all others another) on the reduced numbering: the number of
   * reduced entries two cells would set differently. Zero if and only if
   * the released faces separate the fragments, so that each one moves
   * rigidly, stress free. */
  unsigned int
  translation_conflicts(const TiedCopyDoFs<3>       &dofs,
                        const std::vector<Point<3>> &isolated)
  {
    const Tensor<1, 3>                   a({1., 2., 3.}), b({-1., 0., 5.});
    std::vector<double>                  value(dofs.n_dofs(), std::nan(""));
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    unsigned int conflicts = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        bool moved_alone = false;
        for (const auto &c : isolated)
          moved_alone = moved_alone || cell->center().distance(c) < 1e-10;
        const Tensor<1, 3> &shift = moved_alone ? a : b;
        dofs.get_dof_indices(cell, indices);
        for (const auto i : indices)
          {
            const double v = shift[dofs.component(i)];
            if (!std::isnan(value[i]) && value[i] != v)
              ++conflicts;
            value[i] = v;
          }
      }
    return conflicts;
  }

  /** Crack insertion's node-splitting cases in 3D (Q1). */
  void
  check_splitting_3d()
  {
    // A face inside the mesh, its edges all interior: every node of it is
    // a crack-front node and none splits.
    Triangulation<3> cube;
    GridGenerator::subdivided_hyper_cube(cube, 3, 0, 3);
    TiedCopyDoFs<3> inside(cube, 1);
    inside.distribute(release_at<3>({Point<3>(1.5, 1.5, 1)}));
    CHECK(inside.n_dofs() == 3 * 64);

    // 2 x 2 x 1 cells, two faces meeting at the edge x = y = 1 (an L):
    // the two nodes on that edge and the four at the L's outer ends split
    // in two, 18 + 6 nodes, and cell A (the corner x, y < 1) becomes a
    // fragment that can translate on its own.
    Triangulation<3> slab;
    GridGenerator::subdivided_hyper_rectangle(slab,
                                              {2, 2, 1},
                                              Point<3>(0, 0, 0),
                                              Point<3>(2, 2, 1));
    const Point<3>  A(0.5, 0.5, 0.5);
    TiedCopyDoFs<3> l_crack(slab, 1);
    l_crack.distribute(
      release_at<3>({Point<3>(1, 0.5, 0.5), Point<3>(0.5, 1, 0.5)}));
    CHECK(l_crack.n_dofs() == 3 * 24);
    CHECK(translation_conflicts(l_crack, {A}) == 0);
    // One leg of the L only: A is still bonded to its other neighbour, and
    // the translations conflict on the nodes of the intact face.
    TiedCopyDoFs<3> one_leg(slab, 1);
    one_leg.distribute(release_at<3>({Point<3>(1, 0.5, 0.5)}));
    CHECK(one_leg.n_dofs() == 3 * (18 + 2));
    CHECK(translation_conflicts(one_leg, {A}) > 0);
  }

  template <int dim>
  void
  check_continuous_count(const unsigned int degree)
  {
    Triangulation<dim> tria;
    GridGenerator::subdivided_hyper_cube(tria, 3);
    TiedCopyDoFs<dim> dofs(tria, degree);
    dofs.distribute();
    DoFHandler<dim> q(tria);
    q.distribute_dofs(FESystem<dim>(FE_Q<dim>(degree), dim));
    CHECK(dofs.n_dofs() == q.n_dofs());
    CHECK(dofs.n_copies()
          == tria.n_active_cells() * std::pow(degree + 1, dim) * dim);
  }

  /** With hanging nodes: free unknowns (reduced minus constrained) equal
   * those of FE_Q with deal.II's hanging-node constraints. */
  template <int dim>
  void
  check_hanging_count(const unsigned int degree)
  {
    Triangulation<dim> tria;
    GridGenerator::subdivided_hyper_cube(tria, 3);
    for (unsigned int step = 0; step < 2; ++step)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->center()[0] < 1. / 3 + 1e-12 * step
              && cell->center()[1] < 0.5)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    TiedCopyDoFs<dim> dofs(tria, degree);
    dofs.distribute();
    DoFHandler<dim> q(tria);
    q.distribute_dofs(FESystem<dim>(FE_Q<dim>(degree), dim));
    AffineConstraints<double> hanging;
    DoFTools::make_hanging_node_constraints(q, hanging);
    hanging.close();
    const auto free_copies
      = dofs.n_dofs() - dofs.hanging_node_constraints().n_constraints();
    const auto free_q = q.n_dofs() - hanging.n_constraints();
    CHECK(dofs.hanging_node_constraints().n_constraints() > 0);
    CHECK(free_copies == free_q);
    if (free_copies != free_q)
      std::cerr << "  " << dim << "D Q" << degree << ": " << free_copies
                << " free unknowns, FE_Q has " << free_q << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {1u, 2u})
    {
      check_continuous_count<2>(degree);
      check_continuous_count<3>(degree);
      check_hanging_count<2>(degree);
      check_hanging_count<3>(degree);
    }

  check_splitting_3d();

  // 2 x 2 squares, Q1: 9 nodes. Releasing the lower half of the vertical
  // mid-line splits its boundary node (1,0) only: the centre node (1,1) is
  // still connected around the released face (a crack front).
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {2, 2},
                                            Point<2>(0, 0),
                                            Point<2>(2, 2));
  TiedCopyDoFs<2> dofs(tria, 1);
  dofs.distribute(release_at<2>({Point<2>(1, 0.5)}));
  CHECK(dofs.n_dofs() == 2 * 10);
  // The whole mid-line: (1,0), (1,1), (1,2) all split.
  dofs.distribute(release_at<2>({Point<2>(1, 0.5), Point<2>(1, 1.5)}));
  CHECK(dofs.n_dofs() == 2 * 12);
  // Both mid-lines: the centre node becomes four, each mid-edge node two.
  dofs.distribute(release_at<2>(
    {Point<2>(1, 0.5), Point<2>(1, 1.5), Point<2>(0.5, 1), Point<2>(1.5, 1)}));
  CHECK(dofs.n_dofs() == 2 * (9 + 4 + 3));

  // Q2: the released lower half-line carries 3 nodes on it; the crack
  // tip (1,1) does not split: 25 + 2 = 27 nodes.
  TiedCopyDoFs<2> quadratic(tria, 2);
  quadratic.distribute(release_at<2>({Point<2>(1, 0.5)}));
  CHECK(quadratic.n_dofs() == 2 * 27);

  // Reduced indices of a cell are distinct, components are consecutive
  // per node, and the copies of a tied node share their reduced index.
  dofs.distribute();
  std::vector<types::global_dof_index> a(8), b(8);
  auto cell = dofs.copy_handler().begin_active();
  dofs.get_dof_indices(cell, a);
  std::vector<types::global_dof_index> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  CHECK(std::unique(sorted.begin(), sorted.end()) == sorted.end());
  for (unsigned int i = 0; i < dofs.n_dofs(); i += 2)
    CHECK(dofs.component(i) == 0 && dofs.component(i + 1) == 1
          && dofs.support_point(i).distance(dofs.support_point(i + 1)) == 0);
  return amfrac_test::summary();
}

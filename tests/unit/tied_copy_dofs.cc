// The tied-copy DoF layer: with every face tied it has exactly the unknowns
// of the continuous FE_Q space; releasing faces duplicates exactly the nodes
// that the released faces separate (a crack-front node stays one unknown).
#include "../check.h"

#include <amfrac/dofs/tied_copy_dofs.h>
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

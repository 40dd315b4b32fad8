// The tied-copy DoF layer: with every face tied it has exactly the unknowns
// of the continuous FE_Q space; releasing faces duplicates exactly the nodes
// that the released faces separate (a crack-front node stays one unknown).
#include "../check.h"

#include <amfrac/dofs/tied_copy_dofs.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <set>

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

  bool
  near(const double a, const double b)
  {
    return std::abs(a - b) < 1e-12;
  }

  /** Crack insertion's release() gives the numbering a fresh
   * distribute() gives: rounds of faces released one after the other on a
   * mesh with hanging nodes (released faces next to the refined cells),
   * on the ranks the test runs on. */
  template <int dim>
  void
  check_release_equals_distribute(const unsigned int degree)
  {
    parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    std::vector<unsigned int>            cells(dim, 4);
    cells[0] = 6;
    Point<dim> far;
    for (unsigned int d = 0; d < dim; ++d)
      far[d] = cells[d];
    GridGenerator::subdivided_hyper_rectangle(tria, cells, Point<dim>(), far);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] > 4 && cell->center()[1] > 2)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();

    using Key = std::pair<CellId, unsigned int>;
    std::set<Key> released;
    const auto    filter = [&](const auto &cell, const unsigned int f) {
      return released.count({cell->id(), f}) > 0;
    };
    TiedCopyDoFs<dim> incremental(tria, degree);
    incremental.distribute(filter);
    // Round 1: the plane x = 3 below y = 2 (a crack from the boundary);
    // round 2: its continuation and a branch along y = 2 (a T, nodes
    // split three ways); round 3: the faces x = 4 next to the refined
    // cells (hanging nodes around them).
    const std::vector<std::function<bool(const Point<dim> &)>> rounds{
      [](const Point<dim> &c) { return near(c[0], 3) && c[1] < 2; },
      [](const Point<dim> &c) {
        return (near(c[0], 3) && c[1] < 3) || (near(c[1], 2) && c[0] < 3);
      },
      [](const Point<dim> &c) { return near(c[0], 4) && c[1] < 2; }};
    for (const auto &in_round : rounds)
      {
        std::vector<typename TiedCopyDoFs<dim>::Face> faces;
        for (const auto &cell :
             incremental.copy_handler().active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f) && cell->neighbor(f)->is_active()
                && !cell->neighbor_is_coarser(f)
                && in_round(cell->face(f)->center())
                && released.count({cell->id(), f}) == 0)
              {
                released.insert({cell->id(), f});
                released.insert(
                  {cell->neighbor(f)->id(), cell->neighbor_of_neighbor(f)});
                faces.emplace_back(cell, f);
              }
        CHECK(!faces.empty());
        const auto before = incremental.n_dofs();
        incremental.release(faces, filter);
        CHECK(incremental.n_dofs() > before);
        TiedCopyDoFs<dim> fresh(tria, degree);
        fresh.distribute(filter);
        CHECK(incremental.n_dofs() == fresh.n_dofs());
        CHECK(incremental.locally_owned_dofs() == fresh.locally_owned_dofs());
        CHECK(incremental.locally_relevant_dofs()
              == fresh.locally_relevant_dofs());
        unsigned int                         differ = 0;
        std::vector<types::global_dof_index> a(
          fresh.get_fe().n_dofs_per_cell()),
          b(a.size());
        for (const auto &cell : fresh.copy_handler().active_cell_iterators())
          {
            fresh.get_dof_indices(cell, a);
            incremental.get_dof_indices(cell, b);
            differ += a != b;
          }
        for (types::global_dof_index i = 0; i < fresh.n_dofs(); ++i)
          differ += fresh.support_point(i) != incremental.support_point(i)
                    || fresh.component(i) != incremental.component(i);
        const auto &lines = fresh.hanging_node_constraints().get_lines();
        const auto &other = incremental.hanging_node_constraints().get_lines();
        CHECK(lines.size() > 0);
        differ += lines.size() != other.size();
        for (std::size_t l = 0; l < std::min(lines.size(), other.size()); ++l)
          differ += lines[l].index != other[l].index
                    || lines[l].entries != other[l].entries;
        CHECK(differ == 0);
        if (differ != 0)
          std::cerr << "  " << dim << "D Q" << degree << ": " << differ
                    << " differences after " << faces.size() << " faces"
                    << std::endl;
      }
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
  for (const unsigned int degree : {1u, 2u})
    {
      check_release_equals_distribute<2>(degree);
      check_release_equals_distribute<3>(degree);
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

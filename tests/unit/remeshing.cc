// The size field of the seed's global remeshing (issue 8) on a structured
// prism laminate [0, 4] x [0, 2] of two plies, cells of in-plane step
// 0.5:
// - in_plane_size() of a wedge is the mean of its triangle's edges,
//   (2 + sqrt 2) h / 3;
// - RemeshingRule: h (eta_target / eta_K)^(1/p) for p = 1 and 2, bounded
//   by h / 4 and 2 h and by the minimum size; an error-free cell doubles;
// - InPlaneSizeField: a constant size is that constant everywhere (also
//   outside the mesh); a size that jumps between two halves is the
//   smaller one on the columns they share and the linear interpolation
//   between columns; predicted_triangles() is the area over that of the
//   equilateral triangle, and scale(2) divides it by 4;
// - Gmsh meshes the rectangle with the field: its number of triangles is
//   within 20 % of the prediction, and every edge of a field that halves
//   the size on one half is within a factor 1.6 of the field there;
// - a .geo remeshed with a size (tests/app/meshes/disk.geo, argv[1]): its
//   own sizes (0.7) give way, the disk of radius 2 gets the number of
//   triangles the size predicts (within 20 %) and keeps its named
//   boundary (every boundary edge an id of x-, x+, y-, y+).
#include "../check.h"

#include <amfrac/adaptivity/remeshing.h>
#include <amfrac/geometry/laminate.h>
#include <amfrac/geometry/plane_mesh.h>
#include <amfrac/parameters/parameters.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

using namespace amfrac;

namespace
{
  const double h = 0.5;

  struct Box
  {
    parameters::Parameters prm;
    Laminate               laminate;
    Triangulation<3>       mesh;

    Box()
      : prm(parameters::Parameters::from_string(
        "set Dimension = 3\nsubsection Geometry\n"
        "  set Stacking sequence = [0/90]\n  set Ply thickness = 0.25\n"
        "  set Length = 4\n  set Width = 2\n"
        "  set Elements along length = 8\n  set Elements along width = 4\n"
        "  set Elements per ply = 2\n  set Element shape = prism\nend\n"))
      , laminate(prm.geometry, prm.materials)
    {
      make_laminate_mesh(prm.geometry, laminate, mesh);
    }
  };

  void
  check_rule(const Box &box)
  {
    const double wedge = (2 + std::sqrt(2.)) * h / 3;
    for (const auto &cell : box.mesh.active_cell_iterators())
      CHECK_CLOSE(in_plane_size(cell), wedge, 1e-12);

    dealii::Vector<float> errors(box.mesh.n_active_cells());
    // Cells 0..4: the target, 4 and 1000 times it, none, 1/1000 of it.
    const std::vector<double> ratio = {1, 4, 1000, 0, 1e-3};
    for (unsigned int k = 0; k < ratio.size(); ++k)
      errors[k] = ratio[k] * 0.01;
    RemeshingRule rule;
    for (const unsigned int p : {1u, 2u})
      {
        rule.degree      = p;
        const auto sizes = rule.new_sizes(box.mesh, errors, 0.01);
        CHECK_CLOSE(sizes[0], wedge, 1e-6); // float errors
        CHECK_CLOSE(sizes[1],
                    wedge * std::max(0.25, std::pow(0.25, 1. / p)),
                    1e-6);
        CHECK_CLOSE(sizes[2], 0.25 * wedge, 1e-12);
        CHECK_CLOSE(sizes[3], 2 * wedge, 1e-12);
        CHECK_CLOSE(sizes[4], 2 * wedge, 1e-12);
      }
    rule.min_size    = 0.3;
    const auto sizes = rule.new_sizes(box.mesh, errors, 0.01);
    CHECK_CLOSE(sizes[2], 0.3, 1e-12);
  }

  void
  check_field(const Box &box)
  {
    const unsigned int n = box.mesh.n_active_cells();
    InPlaneSizeField   constant(box.mesh, std::vector<double>(n, 0.2));
    CHECK(constant.n_triangles() == 64);
    for (const Point<2> &p : {Point<2>(0, 0),
                              Point<2>(1.3, 0.7),
                              Point<2>(4, 2),
                              Point<2>(-1, 0.5),
                              Point<2>(2, 2.3)})
      CHECK_CLOSE(constant(p), 0.2, 1e-12);
    const double area = 8;
    CHECK_CLOSE(constant.predicted_triangles(),
                area / (std::sqrt(3.) / 4 * 0.04),
                1e-9);
    constant.scale(2);
    CHECK_CLOSE(constant.predicted_triangles(),
                area / (std::sqrt(3.) / 4 * 0.16),
                1e-9);
    CHECK_CLOSE(constant.range().first, 0.4, 1e-12);

    // 0.1 left of x = 2, 0.3 right of it.
    std::vector<double> sizes(n);
    for (const auto &cell : box.mesh.active_cell_iterators())
      sizes[cell->active_cell_index()] = cell->center()[0] < 2 ? 0.1 : 0.3;
    const InPlaneSizeField halves(box.mesh, sizes);
    CHECK_CLOSE(halves(Point<2>(1, 1)), 0.1, 1e-12);
    CHECK_CLOSE(halves(Point<2>(2, 0.5)), 0.1, 1e-12);
    CHECK_CLOSE(halves(Point<2>(3, 1)), 0.3, 1e-12);
    // Halfway between the column x = 2 (0.1) and x = 2.5 (0.3), on a
    // vertical edge of the structured grid.
    CHECK_CLOSE(halves(Point<2>(2.25, 1)), 0.2, 1e-12);
    CHECK_CLOSE(halves.range().first, 0.1, 1e-12);
    CHECK_CLOSE(halves.range().second, 0.3, 1e-12);
  }

  void
  check_gmsh(const Box &box)
  {
    const unsigned int n = box.mesh.n_active_cells();
    for (const bool graded : {false, true})
      {
        std::vector<double> sizes(n, 0.1);
        if (graded)
          for (const auto &cell : box.mesh.active_cell_iterators())
            if (cell->center()[0] > 2.5)
              sizes[cell->active_cell_index()] = 0.05;
        const InPlaneSizeField field(box.mesh, sizes);
        const PlaneMesh plane = mesh_open_hole_plane(4, 2, 0, field.function());
        const double    predicted = field.predicted_triangles();
        std::cout << (graded ? "graded" : "uniform")
                  << " field: " << plane.triangles.size()
                  << " triangles, predicted " << predicted << std::endl;
        CHECK(std::abs(plane.triangles.size() / predicted - 1) < 0.2);
        double worst = 1;
        for (const auto &t : plane.triangles)
          for (unsigned int i = 0; i < 3; ++i)
            {
              const Point<2> &a      = plane.points[t[i]];
              const Point<2> &b      = plane.points[t[(i + 1) % 3]];
              const double    wanted = field(0.5 * (a + b));
              const double    ratio  = a.distance(b) / wanted;
              worst                  = std::max({worst, ratio, 1 / ratio});
            }
        std::cout << "  largest edge-to-field ratio " << worst << std::endl;
        CHECK(worst < 1.6);
      }
  }

  void
  check_geo(const std::string &meshes)
  {
    const double    size = 0.15;
    const PlaneMesh plane
      = read_plane_mesh(meshes + "/disk.geo",
                        [&](const Point<2> &) { return size; });
    const double predicted = M_PI * 4 / (std::sqrt(3.) / 4 * size * size);
    std::cout << "disk.geo remeshed with h = " << size << ": "
              << plane.triangles.size() << " triangles, predicted " << predicted
              << std::endl;
    CHECK(std::abs(plane.triangles.size() / predicted - 1) < 0.2);
    CHECK(!plane.edges.empty());
    for (const auto id : plane.edge_ids)
      CHECK(id <= 3);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
    {
      std::cerr << "usage: unit_remeshing MESHES_FOLDER\n";
      return 2;
    }
  const Box box;
  check_rule(box);
  check_field(box);
  check_gmsh(box);
  check_geo(argv[1]);
  return amfrac_test::summary();
}

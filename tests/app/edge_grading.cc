// Geometry/Edge grading on the CalculiX peer's [0/90]s plate
// (prm/benchmarks/calculix_plate.prm: simply supported, u_z = 0 on the
// lateral faces, uniform pressure). The stress next to a supported lateral
// face under the loaded top face is singular, so the centre deflection
// converges slowly on uniform meshes; elements shrinking towards the edges
// buy accuracy for the same number of unknowns. Checks:
// - the mesh: element lengths along x and y shrink geometrically from the
//   middle, the longest Edge grading times the shortest, symmetric, summing
//   to the side, and the cell count unchanged;
// - on 14 x 14 Q2 elements, the graded mesh's centre deflection is within
//   0.1 % of the converged 3D value and at least twice as accurate as the
//   uniform mesh's;
// - Clapeyron (load work = 2 x strain energy) on the graded mesh.
// Reference 0.143677 mm: graded Q2 meshes (Edge grading 8) of 24 to 56
// elements per side fitted to W - C n^-q (q = 3.8, W = 0.1436755), plus
// 1e-6 from two elements per ply (doc/benchmarks/README.md section 2).
//
// usage: app_edge_grading calculix_plate.prm
#include "../check.h"

#include <algorithm>
#include <amfrac/geometry/laminate.h>
#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <set>
#include <sstream>

using namespace amfrac;

namespace
{
  const double       converged_deflection = 0.143677;
  const unsigned int elements             = 14;
  const double       grading              = 6;

  std::string
  with_mesh(const std::string &scene, const double edge_grading)
  {
    std::ostringstream text;
    text << scene
         << "\nsubsection Geometry\n  set Elements along length = " << elements
         << "\n  set Elements along width = " << elements
         << "\n  set Edge grading = " << edge_grading << "\nend\n";
    return text.str();
  }

  /** The element lengths along axis @p d (cells in the bottom row). */
  std::vector<double>
  element_lengths(const Triangulation<3> &mesh, const unsigned int d)
  {
    std::set<std::pair<double, double>> spans;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        double lo = 1e300, hi = -1e300;
        for (const unsigned int v : cell->vertex_indices())
          {
            lo = std::min(lo, cell->vertex(v)[d]);
            hi = std::max(hi, cell->vertex(v)[d]);
          }
        spans.emplace(lo, hi);
      }
    std::vector<double> lengths;
    for (const auto &span : spans)
      lengths.push_back(span.second - span.first);
    return lengths;
  }

  void
  check_mesh(const parameters::Parameters &prm)
  {
    Triangulation<3> mesh;
    make_laminate_mesh(prm.geometry,
                       Laminate(prm.geometry, prm.materials),
                       mesh);
    CHECK(mesh.n_active_cells() == elements * elements * 4);
    for (const unsigned int d : {0u, 1u})
      {
        const auto lengths = element_lengths(mesh, d);
        CHECK(lengths.size() == elements);
        double sum = 0;
        for (unsigned int i = 0; i < lengths.size(); ++i)
          {
            sum += lengths[i];
            CHECK_CLOSE(lengths[i], lengths[elements - 1 - i], 1e-10);
            if (i > 0 && i < elements / 2)
              CHECK_CLOSE(lengths[i] / lengths[i - 1],
                          lengths[1] / lengths[0],
                          1e-10);
          }
        CHECK_CLOSE(sum, 100, 1e-10);
        const double longest
          = *std::max_element(lengths.begin(), lengths.end());
        CHECK_CLOSE(longest / lengths[0], grading, 1e-10);
      }
  }

  /** The centre deflection, after checking Clapeyron. */
  double
  centre_deflection(const parameters::Parameters &prm)
  {
    Simulator<3> simulator(prm, MPI_COMM_WORLD);
    simulator.run();
    const History &h = simulator.history();
    CHECK_CLOSE(h.value(0, "load_work") / (2 * h.value(0, "strain_energy")),
                1,
                1e-8);
    return -h.value(0, "p0_uz");
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ifstream                    file(argc == 2 ? argv[1] : "");
  if (!file)
    {
      std::cerr << "usage: app_edge_grading calculix_plate.prm\n";
      return 2;
    }
  std::stringstream text;
  text << file.rdbuf();
  const auto uniform
    = parameters::Parameters::from_string(with_mesh(text.str(), 1));
  const auto graded
    = parameters::Parameters::from_string(with_mesh(text.str(), grading));
  check_mesh(graded);

  const double error_uniform
    = 1 - centre_deflection(uniform) / converged_deflection;
  const double error_graded
    = 1 - centre_deflection(graded) / converged_deflection;
  std::cout << elements << " x " << elements
            << " Q2 elements: centre deflection error " << error_uniform
            << " (uniform), " << error_graded << " (Edge grading = " << grading
            << ")" << std::endl;
  CHECK(error_graded > 0 && error_graded < 1e-3);
  CHECK(error_graded < 0.5 * error_uniform);
  return amfrac_test::summary();
}

// Refinement during delamination growth in 3D (issue 4): the DCB strip of
// prm/dcb_adaptive_3d.prm (2 mm Q1 elements in the plane, one per arm
// through the thickness) to an opening of 2.6 mm, its mesh following the
// front by the process-zone rule along the plies (cut_xy). Checks:
// - the refinement stays in the plane: every cell still spans its whole
//   ply (1.5 mm) through the thickness;
// - the mesh follows the front: several changes during the growth, with
//   coarsening among them, and at most a fifth of the cells of the uniform
//   0.25 mm mesh (400 x 8 x 2 = 6400);
// - every transfer keeps the dissipated energy (1e-12), never shrinks the
//   damaged or debonded area and leaves the interface in balance;
// - the crack grows, the energy balance closes to 1e-8 of the external
//   work with the remeshing term, and that term stays within 2 % of the
//   external work (measured 0.75 %: coarsening behind the front changes
//   the bending stiffness of the Q1 arms, which the transfer cannot
//   keep).
//
// usage: app_dcb_adaptive_3d SCENE.prm WORKDIR
#include "../check.h"
#include "scene.h"

#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>

using namespace amfrac;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: app_dcb_adaptive_3d SCENE.prm WORKDIR\n";
      return 2;
    }
  const auto prm
    = amfrac_test::scene_with(argv[1],
                              std::string(
                                "subsection Time\n  set End time = 2.6\n"
                                "  set Number of steps = 87\nend\n"
                                "subsection Output\n  set Field format = none\n"
                                "  set Directory = ")
                                + argv[2] + "\nend");
  Simulator<3> simulator(prm, MPI_COMM_WORLD);
  simulator.run();

  const double ply      = prm.geometry.ply_thickness[0];
  bool         in_plane = true;
  unsigned int cells    = 0;
  for (const auto &cell : simulator.dofs()
                            .copy_handler()
                            .get_triangulation()
                            .active_cell_iterators())
    {
      in_plane
        = in_plane
          && std::abs(amfrac_test::thickness_extent(cell) - ply) < 1e-9 * ply;
      ++cells;
    }
  amfrac_test::check(in_plane,
                     "every cell spans its ply through the thickness",
                     __FILE__,
                     __LINE__);

  const auto [growth, balance, remeshing]
    = amfrac_test::dcb_totals(simulator.history(), prm.geometry.width);
  std::cout << "crack growth " << growth << " mm, balance error / external "
            << "work " << balance << ", remeshing energy / external work "
            << remeshing << ", " << cells << " cells at the end" << std::endl;
  CHECK(growth > 3);
  CHECK(std::abs(balance) < 1e-8);
  CHECK(std::abs(remeshing) < 0.02);

  const History *changes = simulator.adaptivity_history();
  CHECK(changes != nullptr);
  if (changes == nullptr)
    return amfrac_test::summary();
  unsigned int during_growth = 0, coarsened = 0;
  double       most_cells = 0;
  for (std::size_t r = 0; r < changes->n_rows(); ++r)
    {
      const auto value
        = [&](const std::string &column) { return changes->value(r, column); };
      most_cells = std::max(most_cells, value("cells"));
      during_growth += value("step") > 0;
      coarsened += value("aggregated_points") > 0;
      amfrac_test::check_transfer(*changes, r);
    }
  std::cout << changes->n_rows() << " mesh changes (" << during_growth
            << " during the run, " << coarsened << " with coarsening), at "
            << "most " << most_cells << " cells" << std::endl;
  CHECK(during_growth >= 4);
  CHECK(coarsened >= 1);
  CHECK(most_cells <= 6400 / 5);
  return amfrac_test::summary();
}

// Refinement during delamination growth (issue 4): the DCB of
// prm/dcb_adaptive_2d.prm (1 mm elements, refined to 0.25 mm around the
// crack front by the process-zone rule, coarsened behind it) against the
// uniformly fine mesh of prm/dcb_2d.prm (0.25 mm everywhere), both to an
// opening of 3 mm (past the peak, about 8 mm of crack growth). Checks:
// - the peak load within 1 % of the uniform mesh's (the bar), and
//   the load at two openings on the propagation branch within 0.5 % (the
//   refinement is along the plies only, so around the front the mesh is the
//   uniform one: measured 0.002 % and 0.005 %);
// - at most a third of the unknowns of the uniform mesh at any time;
// - the mesh follows the front: several changes during the growth, with
//   coarsening (aggregated interface points) among them;
// - every transfer keeps the dissipated energy (to round-off: each point
//   owns the part of its face that its weight covers, and a new point takes
//   the overlap-weighted densities of the old regions), never shrinks the
//   damaged or debonded area, and leaves the two faces of every interface
//   element in balance (round-off);
// - the energy balance of the run closes to 1e-8 of the external work
//   with the remeshing term (each transfer changes the stored energy of
//   the same displacement by the difference between the old and the new
//   mesh), and that term stays below 0.1 % of the external work.
//
// usage: app_dcb_adaptive_2d ADAPTIVE.prm UNIFORM.prm WORKDIR
#include "../check.h"
#include "scene.h"

#include <algorithm>
#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>

using namespace amfrac;

namespace
{
  constexpr double width = 20; // mm, out of plane

  std::unique_ptr<Simulator<2>>
  run(const std::string &file, const std::string &directory)
  {
    return amfrac_test::run_scene<2>(
      file,
      "subsection Time\n  set End time = 3\n  set Number of steps = 102\n"
      "end\nsubsection Output\n  set Field format = none\n"
      "  set Directory = "
        + directory + "\nend");
  }

  double
  peak_load(const History &h)
  {
    double peak = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      peak = std::max(peak, width * h.value(r, "force_x-"));
    return peak;
  }

  /** The load at the last row whose opening is at most @p delta. */
  double
  load_at(const History &h, const double delta)
  {
    double load = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      if (h.value(r, "time") <= delta)
        load = width * h.value(r, "force_x-");
    return load;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 4)
    {
      std::cerr << "usage: app_dcb_adaptive_2d ADAPTIVE.prm UNIFORM.prm "
                   "WORKDIR\n";
      return 2;
    }
  const std::string workdir  = argv[3];
  const auto        adaptive = run(argv[1], workdir + "/adaptive");
  const auto        uniform  = run(argv[2], workdir + "/uniform");

  const History &a = adaptive->history();
  const History &u = uniform->history();
  std::cout << "peak: adaptive " << peak_load(a) << " N, uniform "
            << peak_load(u) << " N" << std::endl;
  CHECK_CLOSE(peak_load(a) / peak_load(u), 1, 0.01);
  for (const double delta : {2.5, 2.9})
    {
      std::cout << "delta " << delta << ": adaptive " << load_at(a, delta)
                << " N, uniform " << load_at(u, delta) << " N" << std::endl;
      CHECK_CLOSE(load_at(a, delta) / load_at(u, delta), 1, 0.005);
    }
  const std::size_t last = a.n_rows() - 1;
  const double      work = a.value(last, "external_work");
  std::cout << "crack growth " << a.value(last, "debonded_i0") - 30
            << " mm; energy balance error " << a.value(last, "balance_error")
            << " and remeshing energy " << a.value(last, "remeshing_energy")
            << " of external work " << work << std::endl;
  CHECK(a.value(last, "debonded_i0") > 35);
  CHECK(std::abs(a.value(last, "balance_error")) < 1e-8 * work);
  CHECK(std::abs(a.value(last, "remeshing_energy")) < 1e-3 * work);

  const History *changes = adaptive->adaptivity_history();
  CHECK(changes != nullptr);
  if (changes == nullptr)
    return amfrac_test::summary();
  unsigned int during_growth = 0, coarsened = 0;
  double       most_unknowns = 0, worst_energy = 0, worst_imbalance = 0;
  for (std::size_t r = 0; r < changes->n_rows(); ++r)
    {
      const auto value
        = [&](const std::string &column) { return changes->value(r, column); };
      most_unknowns = std::max(most_unknowns, value("unknowns"));
      if (value("step") > 0)
        ++during_growth;
      if (value("aggregated_points") > 0)
        ++coarsened;
      if (value("dissipated_before") > 1e-3)
        worst_energy = std::max(
          worst_energy,
          std::abs(value("dissipated_after") / value("dissipated_before") - 1));
      worst_imbalance
        = std::max(worst_imbalance, value("interface_force_imbalance"));
      CHECK(value("debonded_after") >= value("debonded_before") - 1e-12);
      CHECK(value("damaged_after") >= value("damaged_before") - 1e-12);
    }
  const double uniform_unknowns = uniform->dofs().n_dofs();
  std::cout << changes->n_rows() << " mesh changes (" << during_growth
            << " during the run, " << coarsened
            << " with coarsening of the interface); at most " << most_unknowns
            << " unknowns against " << uniform_unknowns
            << " uniform; largest relative change of the dissipated energy "
               "in a transfer "
            << worst_energy << "; largest force imbalance " << worst_imbalance
            << std::endl;
  CHECK(during_growth >= 5);
  CHECK(coarsened >= 3);
  CHECK(most_unknowns <= uniform_unknowns / 3);
  CHECK(worst_energy < 1e-12);
  CHECK(worst_imbalance < 1e-10);
  return amfrac_test::summary();
}

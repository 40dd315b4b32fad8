// Explicit dynamics (Time integration = explicit) against known answers:
// - bar: prm/bar_wave.prm, a clamped bar under a suddenly applied end
//   traction, against one-dimensional wave theory: the end displacement on
//   the rising branch (t = L/2c, L/c) within 1 %, its extreme 2 p L / E1
//   within 2 % (sampled every microsecond; the 3D bar's lateral inertia
//   rounds the 1D kink) at 2 L / c within 3 %, back to rest at 4 L / c; energy
//   balance (work = kinetic + strain) within 1e-3 of the work at every output
//   time; a fixed time step above the estimated stable step is an input error;
// - dcb: a 2D DCB opened at 20 m/s (cohesive interfaces in an explicit
//   run): balance (work = kinetic + strain + interface work) within 1e-4
//   of the work, and the energy dissipated lies between G_Ic times the
//   newly debonded and G_Ic times the newly damaged length.
// usage: app_explicit_dynamics bar|dcb SCENE.prm WORKDIR
#include "../check.h"

#include <algorithm>
#include <amfrac/parameters/input_error.h>
#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>

using namespace amfrac;

namespace
{
  std::string
  read(const std::string &path, const std::string &overrides)
  {
    std::ifstream     file(path);
    std::stringstream text;
    text << file.rdbuf() << '\n' << overrides;
    return text.str();
  }

  /** Linear interpolation of column @p name at time @p t. */
  double
  at_time(const History &h, const std::string &name, const double t)
  {
    for (std::size_t r = 1; r < h.n_rows(); ++r)
      if (h.value(r, "time") >= t)
        {
          const double t0 = h.value(r - 1, "time"), t1 = h.value(r, "time");
          const double w = (t - t0) / (t1 - t0);
          return (1 - w) * h.value(r - 1, name) + w * h.value(r, name);
        }
    return h.value(h.n_rows() - 1, name);
  }

  double
  largest_balance_error(const History &h, double &work)
  {
    double error = 0;
    work         = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        error = std::max(error, std::abs(h.value(r, "balance_error")));
        work  = std::max(work, std::abs(h.value(r, "external_work")));
      }
    return error;
  }

  void
  bar(const std::string &prm, const std::string &workdir)
  {
    const double E = 135300, rho = 1.6e-9, L = 200, p = 10;
    const double c = std::sqrt(E / rho), u_max = 2 * p * L / E;
    const auto   parameters = parameters::Parameters::from_string(
      read(prm, "subsection Output\n  set Directory = " + workdir + "\nend\n"));
    Simulator<3> simulator(parameters, MPI_COMM_WORLD);
    simulator.run();
    const History &h = simulator.history();
    // Rising branch: the end moves at p c / E (pulled: negative).
    for (const double t : {0.5 * L / c, L / c})
      CHECK_CLOSE(-at_time(h, "p0_ux", t), p * c * t / E, 0.01 * p * c * t / E);
    std::size_t extreme = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      if (h.value(r, "p0_ux") < h.value(extreme, "p0_ux"))
        extreme = r;
    CHECK_CLOSE(-h.value(extreme, "p0_ux"), u_max, 0.02 * u_max);
    CHECK_CLOSE(h.value(extreme, "time"), 2 * L / c, 0.03 * 2 * L / c);
    CHECK(std::abs(at_time(h, "p0_ux", 4 * L / c)) < 0.05 * u_max);
    double       work;
    const double error = largest_balance_error(h, work);
    CHECK(error < 1e-3 * work);

    // A fixed step above the stable one is refused before any step.
    const auto too_large = parameters::Parameters::from_string(
      read(prm,
           "subsection Time\n  set Time step = 1e-6\nend\n"
           "subsection Output\n  set Directory = "
             + workdir + "-bad\nend\n"));
    bool refused = false;
    try
      {
        Simulator<3> unstable(too_large, MPI_COMM_WORLD);
        unstable.run();
      }
    catch (const InputError &e)
      {
        refused
          = std::string(e.what()).find("Time/Time step") != std::string::npos;
      }
    CHECK(refused);
  }

  void
  dcb(const std::string &prm, const std::string &workdir)
  {
    const double G_Ic       = 0.28;
    const auto   parameters = parameters::Parameters::from_string(
      read(prm,
           "subsection Geometry\n  set Elements along length = 100\nend\n"
             "subsection Boundary conditions\n  subsection x-\n"
             "    set Displacement = 0; y > h ? 1e4 * t : -1e4 * t\n  end\nend\n"
             "subsection Time\n  set Time integration = explicit\n"
             "  set End time = 2e-4\n  set Number of steps = 40\nend\n"
             "subsection Output\n  set Field format = none\n"
             "  set Directory = "
             + workdir + "\nend\n"));
    Simulator<2> simulator(parameters, MPI_COMM_WORLD);
    simulator.run();
    const History    &h    = simulator.history();
    const std::size_t last = h.n_rows() - 1;
    double            work;
    const double      error = largest_balance_error(h, work);
    CHECK(error < 1e-4 * work);
    const double dissipated = h.value(last, "dissipated_i0");
    const double debonded
      = h.value(last, "debonded_i0") - h.value(0, "debonded_i0");
    const double damaged
      = h.value(last, "damaged_i0") - h.value(0, "damaged_i0");
    CHECK(debonded > 1);
    CHECK(dissipated >= G_Ic * debonded * 0.999);
    CHECK(dissipated <= G_Ic * damaged * 1.001);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 4)
    {
      std::cerr << "usage: app_explicit_dynamics bar|dcb SCENE.prm WORKDIR\n";
      return 2;
    }
  const std::string mode = argv[1];
  if (mode == "bar")
    bar(argv[2], argv[3]);
  else
    dcb(argv[2], argv[3]);
  return amfrac_test::failures == 0 ? 0 : 1;
}

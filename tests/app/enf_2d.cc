// End-notched flexure, mode II, plane strain: the shipped scene
// prm/enf_2d.prm (AS4/PEEK, seed's law, Coulomb friction mu = 0.3 over the
// pre-crack) against beam theory (../shared/reference/README.md section 2):
// - the initial compliance within 3 % of C = (3 a^3 + 2 L^3)/(8 E b h^3) +
//   3 L/(10 b h G13) (with the shear term; a = a0 + 0.42 chi h, the
//   crack-tip rotation of Wang & Williams 1992);
// - the peak load within 5 % of the onset P_c of G_II = 9 P^2 a^2 /
//   (16 b^2 E h^3) (1 + 0.2 (E/G13) (h/a)^2) = G_IIc (the same corrected a,
//   Timoshenko shear term of Carlsson et al. 1986); the simple-beam value
//   sqrt(16 b^2 h^3 E G_IIc)/(3 a0) is printed too;
// - the crack grows stably past the peak, the load falls, friction
//   dissipates energy over the pre-crack and the energy balance closes;
// - no interpenetration of the arms: normal gap > -1e-3 h everywhere.
//
// usage: app_enf_2d enf_2d.prm WORKDIR
#include "../check.h"
#include "beam_theory.h"

#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>

using namespace amfrac;

namespace
{
  // The scene's data (prm/enf_2d.prm).
  const double b = 25.4, h = 1.56, L = 51, a0 = 35.7, E11 = 122700, E22 = 10100,
               G13 = 5500, G_IIc = 1.719;

  /** chi of the corrected beam theory (reference section 1). */
  double
  chi()
  {
    return amfrac_test::corrected_beam_chi(E11, E22, G13);
  }

  double
  compliance(const double a)
  {
    return (3 * a * a * a + 2 * L * L * L) / (8 * E11 * b * h * h * h)
           + 3 * L / (10 * b * h * G13);
  }

  double
  onset(const double a)
  {
    const double shear = 1 + 0.2 * (E11 / G13) * (h / a) * (h / a);
    return std::sqrt(16 * b * b * E11 * h * h * h * G_IIc
                     / (9 * a * a * shear));
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: app_enf_2d enf_2d.prm WORKDIR\n";
      return 2;
    }
  Simulator<2> simulator(parameters::Parameters::from_string(
                           amfrac_test::scene_until(argv[1], 4.0, 80, argv[2])),
                         MPI_COMM_WORLD);
  simulator.run();
  const History &hist = simulator.history();
  const auto     load
    = [&](const std::size_t r) { return b * hist.value(r, "force_y+"); };

  const double a_corrected = a0 + 0.42 * chi() * h;
  const double C_fe        = hist.value(0, "time") / load(0);
  std::cout << "compliance " << C_fe << " mm/N, beam theory (with shear) "
            << compliance(a_corrected) << " (simple " << compliance(a0) << ")"
            << std::endl;
  CHECK_CLOSE(C_fe / compliance(a_corrected), 1, 0.03);

  std::size_t peak = 0;
  for (std::size_t r = 0; r < hist.n_rows(); ++r)
    if (load(r) > load(peak))
      peak = r;
  const double P_c = onset(a_corrected);
  std::cout << "peak " << load(peak)
            << " N at delta = " << hist.value(peak, "time")
            << " mm; beam theory " << P_c << " N (corrected, with shear), "
            << onset(a0)
                 * std::sqrt(1 + 0.2 * (E11 / G13) * (h / a0) * (h / a0))
            << " N (simple)" << std::endl;
  CHECK_CLOSE(load(peak) / P_c, 1, 0.05);

  const std::size_t last   = hist.n_rows() - 1;
  const double      growth = hist.value(last, "debonded_i0") - a0;
  std::cout << "crack growth " << growth << " mm, load at the end "
            << load(last) << " N, friction " << hist.value(last, "friction_i0")
            << " N, dissipated " << hist.value(last, "dissipated_i0")
            << " N (per mm of width)" << std::endl;
  CHECK(growth > 5);
  CHECK(load(last) < 0.9 * load(peak));
  CHECK(hist.value(last, "friction_i0") > 0);
  CHECK(std::abs(hist.value(last, "balance_error"))
        < 1e-6 * hist.value(last, "external_work"));

  double min_gap = 0;
  for (std::size_t r = 0; r < hist.n_rows(); ++r)
    min_gap = std::min(min_gap, hist.value(r, "min_opening_i0"));
  std::cout << "most negative normal gap " << min_gap << " mm (limit "
            << -1e-3 * h << ")" << std::endl;
  CHECK(min_gap > -1e-3 * h);
  return amfrac_test::summary();
}

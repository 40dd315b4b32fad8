// Mixed-mode bending, G_II/G = 0.5, plane strain: the shipped scene
// prm/mmb_2d.prm (AS4/PEEK, Camanho-Davila law with Benzeggagh-Kenane,
// loading lever as a linear constraint) against the beam theory of Reeder
// & Crews (1990) with the ASTM D6671 corrections: the lever load P splits
// into a DCB part P_I = P (3c - L)/(4L) and an ENF part P_II = P (c + L)/L,
//   G_I  = 12 P_I^2 (a + chi h)^2 / (b^2 h^3 E11),
//   G_II =  9 P_II^2 (a + 0.42 chi h)^2 / (16 b^2 h^3 E11) (1 + 0.2 (E11/G13)
//          (h/a_II)^2),
//   C    = ((3c - L)/(4L))^2 C_DCB(a) + ((c + L)/L)^2 C_ENF(a),
// and the crack grows when G_I + G_II = G_Ic + (G_IIc - G_Ic) B^eta,
// B = G_II/(G_I + G_II). Checks:
// - the lever kinematics: w_saddle + (c/L)(w_saddle - w_hinge) = -t;
// - force_lever is conjugate to t: the ledger's external work equals the
//   trapezoidal integral of P dt, and the energy balance closes;
// - the initial compliance within 3 % of C(a0);
// - the peak load within 5 % of the onset P_c(a0);
// - the propagation branch within 2 % of the envelope (C(a) P_c(a),
//   P_c(a)) at a = 38, 42 and 46 mm;
// - the energy dissipated per unit of crack growth within 3 % of the BK
//   G_c at the beam-theory mode mix.
//
// usage: app_mmb_2d mmb_2d.prm WORKDIR
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
  // The scene's data (prm/mmb_2d.prm).
  const double b = 25.4, h = 1.56, L = 51, c = 43, a0 = 34, E11 = 122700,
               E22 = 10100, G13 = 5500, G_Ic = 0.969, G_IIc = 1.719,
               eta = 2.284;
  const double chi = amfrac_test::corrected_beam_chi(E11, E22, G13);

  struct Split
  {
    double G_I, G_II;
  };

  /** G_I and G_II at unit lever load and crack length @p a. */
  Split
  energy_release_rates(const double a)
  {
    const double P_I = (3 * c - L) / (4 * L), P_II = (c + L) / L;
    const double a_I = a + chi * h, a_II = a + 0.42 * chi * h;
    const double shear = 1 + 0.2 * (E11 / G13) * (h / a_II) * (h / a_II);
    return {12 * P_I * P_I * a_I * a_I / (b * b * h * h * h * E11),
            9 * P_II * P_II * a_II * a_II / (16 * b * b * h * h * h * E11)
              * shear};
  }

  double
  mode_mix(const double a)
  {
    const Split G = energy_release_rates(a);
    return G.G_II / (G.G_I + G.G_II);
  }

  double
  toughness(const double a)
  {
    return G_Ic + (G_IIc - G_Ic) * std::pow(mode_mix(a), eta);
  }

  double
  onset(const double a)
  {
    const Split G = energy_release_rates(a);
    return std::sqrt(toughness(a) / (G.G_I + G.G_II));
  }

  double
  compliance(const double a)
  {
    const double a_I = a + chi * h, a_II = a + 0.42 * chi * h;
    const double dcb = 8 * a_I * a_I * a_I / (E11 * b * h * h * h);
    const double enf
      = (3 * a_II * a_II * a_II + 2 * L * L * L) / (8 * E11 * b * h * h * h)
        + 3 * L / (10 * b * h * G13);
    const double f_I = (3 * c - L) / (4 * L), f_II = (c + L) / L;
    return f_I * f_I * dcb + f_II * f_II * enf;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: app_mmb_2d mmb_2d.prm WORKDIR\n";
      return 2;
    }
  Simulator<2> simulator(parameters::Parameters::from_string(
                           amfrac_test::scene_until(argv[1], 8.0, 80, argv[2])),
                         MPI_COMM_WORLD);
  simulator.run();
  const History    &hist = simulator.history();
  const std::size_t rows = hist.n_rows();
  const auto        load
    = [&](const std::size_t r) { return b * hist.value(r, "force_lever"); };
  const auto t = [&](const std::size_t r) { return hist.value(r, "time"); };

  double kinematics = 0, work = 0;
  for (std::size_t r = 0; r < rows; ++r)
    {
      const double w_A = hist.value(r, "lever_hinge");
      const double w_B = hist.value(r, "lever_saddle");
      kinematics       = std::max(kinematics,
                            std::abs(w_B + c / L * (w_B - w_A) + t(r)) / t(r));
      work += 0.5 * (load(r) + (r > 0 ? load(r - 1) : 0.))
              * (t(r) - (r > 0 ? t(r - 1) : 0.)) / b;
    }
  const double ledger_work = hist.value(rows - 1, "external_work");
  std::cout << "lever kinematics error " << kinematics << ", external work "
            << ledger_work << " (integral of P dt " << work << ") N mm/mm"
            << std::endl;
  CHECK(kinematics < 1e-9);
  CHECK_CLOSE(work / ledger_work, 1, 1e-4);
  CHECK(std::abs(hist.value(rows - 1, "balance_error")) < 1e-6 * ledger_work);

  const double C_fe = t(0) / load(0);
  std::cout << "compliance " << C_fe << " mm/N, beam theory " << compliance(a0)
            << ", mode mix G_II/G " << mode_mix(a0) << std::endl;
  CHECK_CLOSE(C_fe / compliance(a0), 1, 0.03);

  std::size_t peak = 0;
  for (std::size_t r = 0; r < rows; ++r)
    if (load(r) > load(peak))
      peak = r;
  std::cout << "peak " << load(peak) << " N at delta = " << t(peak)
            << " mm; beam theory " << onset(a0) << " N" << std::endl;
  CHECK_CLOSE(load(peak) / onset(a0), 1, 0.05);
  CHECK(hist.value(peak, "lever_hinge") > 0);

  for (const double a : {38., 42., 46.})
    {
      const double P = onset(a), delta = compliance(a) * P;
      double       fe = -1;
      for (std::size_t r = peak + 1; r < rows && fe < 0; ++r)
        if (t(r - 1) <= delta && delta < t(r))
          fe = load(r - 1)
               + (load(r) - load(r - 1)) * (delta - t(r - 1))
                   / (t(r) - t(r - 1));
      std::cout << "a = " << a << ": envelope " << P << " N at " << delta
                << " mm, amfrac " << fe << " N" << std::endl;
      CHECK_CLOSE(fe / P, 1, 0.02);
    }

  // Steady growth from 37 to 46 mm: dissipation per mm of crack.
  std::size_t from = 0, to = 0;
  for (std::size_t r = 0; r < rows; ++r)
    {
      const double tip = hist.value(r, "debonded_i0");
      if (from == 0 && tip >= 37)
        from = r;
      if (to == 0 && tip >= 46)
        to = r;
    }
  CHECK(to > from && from > 0);
  if (to > from && from > 0)
    {
      const double rate
        = (hist.value(to, "dissipated_i0") - hist.value(from, "dissipated_i0"))
          / (hist.value(to, "debonded_i0") - hist.value(from, "debonded_i0"));
      const double G_c = toughness(0.5 * (37 + 46));
      std::cout << "dissipated per crack growth " << rate
                << " N/mm, BK G_c at the beam-theory mode mix " << G_c
                << std::endl;
      CHECK_CLOSE(rate / G_c, 1, 0.03);
    }
  return amfrac_test::summary();
}

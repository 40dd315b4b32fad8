// Control = arc-length (Crisfield) through the snap-through of the clamped
// shallow arch of prm/shallow_arch_2d.prm (total Lagrangian):
//   cylindrical (psi = 0) and spherical (psi = 1): every converged point
//   lies on the one-mode shallow-arch curve q(c) (exact for this arch and
//   load) to 1.5 % of the limit load; the path passes the limit point
//   (within 1.5 % of the theory's), comes down to the valley (within 1.5 %)
//   and rises again until End time with the arch inverted; the work done
//   equals the strain energy.
#include "scene.h"

#include <algorithm>
#include <cmath>

using namespace amfrac;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  /** The shallow-arch theory of the scene's header. */
  struct Arch
  {
    double h = 0.5, e = 0.75, L = 100, Q11 = 135906, q_end = 0.016;

    double
    load(const double c) const
    {
      const double k = 2 * pi / L, EI = Q11 * h * h * h / 12, EA = Q11 * h;
      return k * k / 2
             * (EI * k * k * (e - c) + EA * k * k * c * (e * e - c * c) / 16);
    }

    /** The limit point and the valley: dq/dc = 0 at c = +-c*. */
    double
    turning_rise() const
    {
      return std::sqrt((e * e - 16 * h * h / 12) / 3);
    }
  };

  void
  follow(const std::string &file, const double psi)
  {
    std::ostringstream appended;
    appended << "subsection Nonlinear solver\n set Arc-length psi = " << psi
             << "\nend\nsubsection Output\n set Field format = none\nend\n";
    const auto     simulator = amfrac_test::run_scene<2>(file, appended.str());
    const History &history   = simulator->history();
    const Arch     arch;
    const double   q_max    = arch.load(arch.turning_rise());
    const double   valley   = arch.load(-arch.turning_rise());
    const std::size_t last  = history.n_rows() - 1;
    const double      scale = history.value(last, "strain_energy");
    // The limit point is the largest load while the arch is still up, the
    // valley the smallest once it is down (the end load is larger still).
    double      worst = 0, peak = 0, lowest_after_peak = 1e300;
    std::size_t peak_row = 0;
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        const double q = arch.q_end * history.value(r, "time");
        const double c = arch.e + history.value(r, "p0_uy");
        worst          = std::max(worst, std::abs(q - arch.load(c)) / q_max);
        if (c > 0 && q > peak)
          peak = q, peak_row = r;
        if (c < 0 && c > -arch.e)
          lowest_after_peak = std::min(lowest_after_peak, q);
        // The trapezoidal external work against the strain energy.
        CHECK(std::abs(history.value(r, "balance_error")) < 1e-3 * scale);
      }
    std::cout << "  psi = " << psi << ": " << history.n_rows()
              << " steps; limit load " << peak << " MPa (theory " << q_max
              << "), valley " << lowest_after_peak << " (theory " << valley
              << "); largest distance from q(c): " << worst
              << " of the limit load" << std::endl;
    CHECK(worst < 1.5e-2);
    CHECK_CLOSE(peak / q_max, 1., 1.5e-2);
    CHECK_CLOSE(lowest_after_peak / valley, 1., 1.5e-2);
    // Past the limit point the path came down and went up again to the
    // end, with the arch hanging below its supports.
    CHECK(peak_row > 5 && peak_row + 10 < last);
    CHECK(history.value(last, "time") >= 1.);
    CHECK(arch.e + history.value(last, "p0_uy") < -0.7);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
    {
      std::cerr << "usage: app_arc_length FILE.prm" << std::endl;
      return 1;
    }
  follow(argv[1], 0.);
  follow(argv[1], 1.);
  return amfrac_test::failures;
}

// Double cantilever beam, mode I, plane strain: the shipped scene
// prm/dcb_2d.prm (Mi et al. 1998 / Alfano & Crisfield 2001, Table I) against
// corrected beam theory (../shared/reference/README.md section 1):
// - peak load within 3 % of the onset P_c = 63.03 N;
// - the propagation branch within 3 % of P = sqrt(2 (G b)^1.5 (E I)^0.5 /
//   (3 delta)) at delta = 3.88 and 5.82 mm (44.57 and 36.39 N);
// - dissipated energy = G_Ic x newly debonded area within 2 %, and the
//   energy balance closed;
// - median Newton iterations per step <= 6, and an elastic step converges
//   in one iteration (the tangent is exact);
// - refining the mesh twice where the crack starts (28 < x < 32, where the
//   process zone sits at the peak) changes the peak by less than 2 %.
//
// usage: app_dcb_2d dcb_2d.prm WORKDIR
#include "../check.h"

#include <algorithm>
#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>

using namespace amfrac;

namespace
{
  const double width = 20, G_Ic = 0.28;

  /** The scene with overrides appended (later entries win). */
  parameters::Parameters
  scene(const std::string &text,
        const double       end_time,
        const std::string &directory,
        const unsigned int region_refinements = 0)
  {
    std::ostringstream overrides;
    overrides << text << "\nsubsection Geometry\n"
              << "  set Refinement region = x > 28 && x < 32\n"
              << "  set Region refinements = " << region_refinements
              << "\nend\nsubsection Time\n  set End time = " << end_time
              << "\n  set Number of steps = " << std::lround(30 * end_time)
              << "\nend\nsubsection Output\n  set Field format = none\n"
              << "  set Directory = " << directory << "\nend\n";
    return parameters::Parameters::from_string(overrides.str());
  }

  double
  load(const History &h, const std::size_t row)
  {
    return width * h.value(row, "force_x-");
  }

  std::size_t
  peak_row(const History &h)
  {
    std::size_t best = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      if (load(h, r) > load(h, best))
        best = r;
    return best;
  }

  double
  envelope(const double delta)
  {
    const double E = 135300, h = 1.5, I = width * h * h * h / 12;
    return std::sqrt(2 * std::pow(G_Ic * width, 1.5) * std::sqrt(E * I)
                     / (3 * delta));
  }

  /** The load at the row whose opening is nearest @p delta after the peak. */
  double
  load_at(const History &h, const double delta)
  {
    std::size_t best = peak_row(h);
    for (std::size_t r = best; r < h.n_rows(); ++r)
      if (std::abs(h.value(r, "time") - delta)
          < std::abs(h.value(best, "time") - delta))
        best = r;
    return load(h, best);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: app_dcb_2d dcb_2d.prm WORKDIR\n";
      return 2;
    }
  std::ifstream     file(argv[1]);
  std::stringstream text;
  text << file.rdbuf();
  const std::string workdir = argv[2];

  Simulator<2> simulator(scene(text.str(), 6, workdir + "/full"),
                         MPI_COMM_WORLD);
  simulator.run();
  const History &h    = simulator.history();
  const double   peak = load(h, peak_row(h));
  std::cout << "peak " << peak
            << " N at delta = " << h.value(peak_row(h), "time")
            << " mm (beam theory 63.03 N)" << std::endl;
  CHECK_CLOSE(peak / 63.03, 1, 0.03);
  for (const double delta : {3.88, 5.82})
    {
      const double P = load_at(h, delta);
      std::cout << "delta " << delta << ": " << P << " N (envelope "
                << envelope(delta) << " N)" << std::endl;
      CHECK_CLOSE(P / envelope(delta), 1, 0.03);
    }

  const std::size_t last = h.n_rows() - 1;
  const double      new_crack
    = h.value(last, "debonded_i0") - h.value(0, "debonded_i0");
  const double dissipated = h.value(last, "dissipated_i0");
  std::cout << "dissipated " << dissipated << " N, G_Ic x new crack "
            << G_Ic * new_crack << " N (per mm of width)" << std::endl;
  CHECK(new_crack > 10);
  CHECK_CLOSE(dissipated / (G_Ic * new_crack), 1, 0.02);
  CHECK(std::abs(h.value(last, "balance_error"))
        < 1e-6 * h.value(last, "external_work"));

  std::vector<double> iterations;
  for (std::size_t r = 0; r < h.n_rows(); ++r)
    iterations.push_back(h.value(r, "newton_iterations"));
  CHECK(h.value(0, "newton_iterations") == 1); // elastic: exact tangent
  std::nth_element(iterations.begin(),
                   iterations.begin() + iterations.size() / 2,
                   iterations.end());
  std::cout << "median Newton iterations " << iterations[iterations.size() / 2]
            << std::endl;
  CHECK(iterations[iterations.size() / 2] <= 6);

  // Mesh refinement: the peak with the crack-start region refined twice.
  Simulator<2> fine(scene(text.str(), 2.2, workdir + "/fine", 2),
                    MPI_COMM_WORLD);
  fine.run();
  const double fine_peak = load(fine.history(), peak_row(fine.history()));
  std::cout << "peak refined twice " << fine_peak << " N, scene mesh " << peak
            << " N" << std::endl;
  CHECK_CLOSE(fine_peak / peak, 1, 0.02);
  return amfrac_test::summary();
}

// A symmetric external ply drop in tension: the shipped scene
// prm/ply_drop.prm, a 3D Geometry/Mesh file (prm/ply_drop.geo) whose ply
// 2 stops inside the laminate, against strength of materials:
// - once the delamination has left the drop (crack area 0.5 .. 3.5 mm^2
//   of the 1 mm wide strip), the load stays within 1 % of the plateau
//   P = b sqrt(2 E1 G_c / (1/t_s - 1/t)) = 275.2 N;
// - over that growth the end displacement grows by P / (E1 b^2) (1/t_s -
//   1/t) per crack area, and the dissipated energy by G_c (least-squares
//   slopes within 3 %);
// - the energy balance closes (1e-6 of the external work).
//
// usage: app_ply_drop ply_drop.prm WORKDIR
#include "../check.h"

#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace amfrac;

namespace
{
  // The scene's data (prm/ply_drop.prm, prm/ply_drop.geo).
  const double E1 = 135300, G_c = 0.28, b = 1, t_s = 0.5, t = 1, L_thick = 10,
               L_thin = 6;

  /** The least-squares slope of @p column over the crack area in the
   * rows @p first .. @p last. */
  double
  slope(const History     &hist,
        const std::string &column,
        const std::size_t  first,
        const std::size_t  last)
  {
    double n = 0, sa = 0, sy = 0, saa = 0, say = 0;
    for (std::size_t r = first; r <= last; ++r)
      {
        const double a = hist.value(r, "debonded_i0"),
                     y = hist.value(r, column);
        n += 1;
        sa += a;
        sy += y;
        saa += a * a;
        say += a * y;
      }
    return (n * say - sa * sy) / (n * saa - sa * sa);
  }

  /** The scene with its mesh file found next to it and the history only
   * written to @p workdir. */
  std::string
  scene(const std::string &prm, const std::string &workdir)
  {
    std::ifstream     file(prm);
    std::stringstream text;
    const auto geo = std::filesystem::path(prm).parent_path() / "ply_drop.geo";
    text << file.rdbuf() << "\nsubsection Geometry\n  set Mesh file = "
         << std::filesystem::absolute(geo).string()
         << "\nend\nsubsection Output\n  set Field format = none\n"
         << "  set Directory = " << workdir << "\nend\n";
    return text.str();
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: app_ply_drop ply_drop.prm WORKDIR\n";
      return 2;
    }
  Simulator<3> simulator(parameters::Parameters::from_string(
                           scene(argv[1], argv[2])),
                         MPI_COMM_WORLD);
  simulator.run();
  const History &hist = simulator.history();
  const auto     load
    = [&](const std::size_t r) { return hist.value(r, "force_x+"); };
  const auto area
    = [&](const std::size_t r) { return hist.value(r, "debonded_i0"); };

  const double plateau = b * std::sqrt(2 * E1 * G_c / (1 / t_s - 1 / t));
  std::size_t  first = 0, last = 0;
  double       lowest = 1e300, highest = 0;
  for (std::size_t r = 0; r < hist.n_rows(); ++r)
    if (area(r) >= 0.5 && area(r) <= 3.5)
      {
        if (first == 0)
          first = r;
        last    = r;
        lowest  = std::min(lowest, load(r));
        highest = std::max(highest, load(r));
      }
  std::cout << "plateau " << lowest << " .. " << highest
            << " N over crack areas " << area(first) << " .. " << area(last)
            << " mm^2, strength of materials " << plateau << " N" << std::endl;
  CHECK(last > first + 10); // the crack grew through the window
  CHECK_CLOSE(lowest / plateau, 1, 0.01);
  CHECK_CLOSE(highest / plateau, 1, 0.01);

  // Each crack area turns thick section into thin under the same load.
  // The debonded area grows by whole quadrature points: least-squares
  // slopes over the window, not the ratio of its ends.
  const double stretch = slope(hist, "time", first, last);
  const double expected
    = 0.5 * (lowest + highest) / (E1 * b * b) * (1 / t_s - 1 / t);
  std::cout << "end displacement per crack area " << stretch
            << ", strength of materials " << expected << std::endl;
  CHECK_CLOSE(stretch / expected, 1, 0.03);

  const double toughness = slope(hist, "dissipated_i0", first, last);
  std::cout << "dissipated per crack area " << toughness << " N/mm, G_c " << G_c
            << std::endl;
  CHECK_CLOSE(toughness / G_c, 1, 0.03);

  const std::size_t end = hist.n_rows() - 1;
  std::cout << "balance error " << hist.value(end, "balance_error")
            << " of external work " << hist.value(end, "external_work")
            << std::endl;
  CHECK(std::abs(hist.value(end, "balance_error"))
        < 1e-6 * hist.value(end, "external_work"));
  return amfrac_test::summary();
}

#pragma once

// A scene file with text appended (later entries override earlier ones),
// and a run of it: how the application tests vary a shipped scene.

#include "../check.h"

#include <algorithm>
#include <amfrac/parameters/parameters.h>
#include <amfrac/postprocess/history.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

namespace amfrac_test
{
  /** The whole text of @p file (a .prm fragment to append). */
  inline std::string
  file_text(const std::string &file)
  {
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  inline amfrac::parameters::Parameters
  scene_with(const std::string &file, const std::string &appended)
  {
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf() << "\n" << appended << "\n";
    return amfrac::parameters::Parameters::from_string(text.str());
  }

  /** Output of @p workdir's history only (no field files). */
  inline std::string
  history_only(const std::string &workdir)
  {
    return "subsection Output\n  set Directory = " + workdir
           + "\n  set Field format = none\nend\n";
  }

  /** Appended to prm/hertz_indentation.prm: a 1 mm cube of one cell
   * (nu = 0) under a sphere of radius @p R and contact @p penalty whose
   * surface touches its four top corners together at t = 0 (they lie
   * sqrt(0.5) from the sphere's axis). */
  inline std::string
  one_cell_under_sphere(const double R, const double penalty)
  {
    std::ostringstream text;
    text << std::setprecision(17)
         << "subsection Geometry\n  set Ply thickness = 1\n  set Length = 1\n"
         << "  set Width = 1\n  set Elements along length = 1\n"
         << "  set Elements along width = 1\n  set Elements per ply = 1\n"
         << "  set Region refinements = 0\nend\n"
         << "subsection Materials\n  set nu12 = 0\n  set nu13 = 0\n"
         << "  set nu23 = 0\nend\n"
         << "subsection Impactor\n  set Radius = " << R
         << "\n  set Center = 0.5, 0.5, " << 1 + std::sqrt(R * R - 0.5)
         << "\n  set Penalty = " << penalty << "\nend\n";
    return text.str();
  }

  template <int dim>
  std::unique_ptr<amfrac::Simulator<dim>>
  run_scene(const std::string &file, const std::string &appended)
  {
    auto simulator
      = std::make_unique<amfrac::Simulator<dim>>(scene_with(file, appended),
                                                 MPI_COMM_WORLD);
    simulator->run();
    return simulator;
  }
  /** The 2D contact scene @p prm on its own graded mesh and on a mesh
   * that adapts during the run (ZZ after every step, the 5 % of the cells
   * with the largest error, from 6 region refinements up to 8 levels, as
   * tests/app/hertz_cylinder_adaptive.prm), history only, in
   * @p workdir/graded and @p workdir/adaptive. */
  inline std::pair<std::unique_ptr<amfrac::Simulator<2>>,
                   std::unique_ptr<amfrac::Simulator<2>>>
  graded_and_adapting(const std::string &prm, const std::string &workdir)
  {
    const std::string adaptive
      = "subsection Geometry\n  set Region refinements = 6\nend\n"
        "subsection Adaptivity\n  set Refine every = 1\n"
        "  set Refine fraction = 0.05\n"
        "  set Maximum refinement level = 8\nend\n";
    auto graded = run_scene<2>(prm, history_only(workdir + "/graded"));
    return {std::move(graded),
            run_scene<2>(prm, adaptive + history_only(workdir + "/adaptive"))};
  }
  /** The extent of @p cell through the thickness (z). */
  template <typename Cell>
  double
  thickness_extent(const Cell &cell)
  {
    double lowest = 1e300, highest = -1e300;
    for (const unsigned int v : cell->vertex_indices())
      {
        lowest  = std::min(lowest, cell->vertex(v)[2]);
        highest = std::max(highest, cell->vertex(v)[2]);
      }
    return highest - lowest;
  }

  /** A 3D DCB strip's totals at the last row of its history @p h: crack
   * growth beyond the 30 mm pre-crack of a strip @p width wide [mm], and
   * the balance error and the remeshing energy over the external work. */
  struct DcbTotals
  {
    double growth, balance, remeshing;
  };
  inline DcbTotals
  dcb_totals(const amfrac::History &h, const double width)
  {
    const std::size_t last = h.n_rows() - 1;
    const double      work = h.value(last, "external_work");
    return {h.value(last, "debonded_i0") / width - 30,
            h.value(last, "balance_error") / work,
            h.value(last, "remeshing_energy") / work};
  }

  /** What every mesh change during a load history must keep (row @p r of
   * adaptivity.csv): the dissipated energy (1e-12, once there is some),
   * the debonded and damaged areas (never smaller), and the balance of the
   * two faces of the interface elements (round-off). */
  inline void
  check_transfer(const amfrac::History &changes, const std::size_t r)
  {
    const auto value
      = [&](const std::string &column) { return changes.value(r, column); };
    if (value("dissipated_before") > 1e-3)
      CHECK_CLOSE(value("dissipated_after") / value("dissipated_before"),
                  1.,
                  1e-12);
    CHECK(value("debonded_after") >= value("debonded_before") - 1e-12);
    CHECK(value("damaged_after") >= value("damaged_before") - 1e-12);
    CHECK(value("interface_force_imbalance") < 1e-10);
  }

  /** The arms of prm/self_contact_hairpin_2d.prm pressed onto each other
   * (row @p r of its history, d = 0.6 mm): at x = 5 mm, far from the bend
   * and the free ends, the arms and the contact are three springs in
   * series, p = (d - g0) / (2 h / E + 1 / Penalty). The lower arm's inner
   * face moves by -p h / E (1e-3; measured 7.4e-5), its stress is -p
   * (5e-3; measured 1.3e-3: the squeezed bend and the free ends disturb
   * it), the faces penetrate there by p / Penalty (1e-2; measured 2.0e-3),
   * and at least 40 of the 52 nodes of the arms' inner faces touch
   * (measured 47: at the bend the arms part). */
  inline void
  check_hairpin_pressed(const amfrac::History &h, const std::size_t r)
  {
    const double       modulus = 70000, penalty = 5e5, thickness = 1, d = 0.6;
    const double       gap0 = 2 * (2.4 / M_PI - thickness / 2);
    const double       p = (d - gap0) / (2 * thickness / modulus + 1 / penalty);
    const double       lower = h.value(r, "p0_uy"), upper = h.value(r, "p1_uy");
    const double       penetration = -(gap0 + upper - lower);
    std::ostringstream line;
    line << std::setprecision(8) << "hairpin at t = " << h.value(r, "time")
         << ": lower arm " << lower << " of " << -p * thickness / modulus
         << ", stress " << h.value(r, "p0_stress_yy") << " of " << -p
         << ", penetration " << penetration << " of " << p / penalty
         << ", nodes " << h.value(r, "body_contact_nodes");
    std::cout << line.str() << std::endl;
    CHECK_CLOSE(lower,
                -p * thickness / modulus,
                1e-3 * p * thickness / modulus);
    CHECK_CLOSE(h.value(r, "p0_stress_yy"), -p, 5e-3 * p);
    CHECK_CLOSE(penetration, p / penalty, 1e-2 * p / penalty);
    CHECK(h.value(r, "body_contact_nodes") >= 40);
  }

  /** The larger of @p a and @p b, NaN if either is (std::max(a, NaN) is
   * a: a check "worse < tolerance" must fail on a NaN). */
  inline double
  worse(const double a, const double b)
  {
    if (std::isnan(a))
      return a;
    return b <= a ? a : b; // b if it is NaN
  }
  /** The largest magnitude of a column of a history; NaN if any value is
   * not a number (so that a check "largest < tolerance" fails). */
  inline double
  largest(const amfrac::History &h, const std::string &column)
  {
    double value = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double x = h.value(r, column);
        if (std::isnan(x))
          return x;
        value = std::max(value, std::abs(x));
      }
    return value;
  }
} // namespace amfrac_test

// A prescribed rigid sphere on the static Newton path (issue 10), on
// prm/hertz_indentation.prm:
// - flat: one cell, a 1 x 1 x 1 mm block (nu = 0: the corners stay where
//   they touch), free sideways, pressed by a sphere of radius 1e4 mm
//   centred over it, so that its four top corners are equally far from the
//   sphere's axis and touch it together at t = 0: uniaxial compression, the
//   block and the penalty springs in series, F = A d / (H / E + 1 /
//   Penalty), to 1e-6; the driver's work equals the strain plus the contact
//   energy to 1e-8 of it (F is linear in d, so the trapezoidal work is
//   exact); the deepest penetration F / Penalty to 1e-4; Newton takes at
//   most 2 iterations per step;
// - hertz: the scene. Force against indentation within 5 % of Hertz's law
//   F = 4/3 E* sqrt(R) d^(3/2) at every step (the figure) and 1 %
//   at the first; the peak pressure (Penalty times the deepest
//   penetration) within 3 % of Hertz's p0 = (6 F E*^2 / (pi^3 R^2))^(1/3)
//   once the contact radius spans 4 cells; a least-squares fit
//   d = alpha F^(2/3) + C F gives alpha within 1 % of Hertz's and a
//   negative C (the finite block with a held bottom is stiffer than the
//   half-space) within 0.5 to 4 times Boussinesq's far-field compliance
//   (1 + nu)(3 - 2 nu) / (2 pi E H); the balance error equals the
//   trapezoidal rule's error for the driver's work F ~ d^(3/2) within
//   25 %; Newton takes at most 4 iterations per step (the contact tangent
//   and the predictor are consistent).
// - cylinder: prm/hertz_cylinder_2d.prm, a cylinder pressed into a block in
//   plane strain: against the force per unit length F' the run measures,
//   Hertz's peak pressure p0 = sqrt(F' E* / (pi R)) within 1 % (measured
//   0.42 to 0.64 %) and his half-width a = sqrt(4 F' R / (pi E*)) within a
//   cell of the edge of the nodes in contact, once a spans 6 cells; Newton
//   takes at most 5 iterations per step (4, once 5).
// - cylinder_3d: the scene's block made 2 x 2 mm of 32 x 16 uniform cells
//   (on the scene's graded mesh the two differ by 0.15 %: the 3D mesh is
//   not the 2D one extruded there, which I did not trace further),
//   in 2D and in 3D with one cell across a 2 mm width held in y on both
//   sides (plane strain), pressed by a cylinder along y (Shape =
//   cylinder, Axis = 0, 3, 0: any length). The 3D solution is the 2D one
//   extruded, so the force per unit width, the penetration and the Newton
//   iterations equal the 2D run's at every step, to 1e-8, and twice as
//   many nodes touch.
// - cylinder_adaptive: prm/hertz_cylinder_2d.prm on a mesh that adapts
//   while the cylinder presses (ZZ every step, the largest 5 % of the
//   cells, from 6 region refinements up to the scene's 8 levels) against
//   the scene's graded mesh: the mesh changes at least 5 times and ends
//   with fewer cells (measured 244 against 505); the force per unit length
//   within 2 % of the graded mesh's at every step once it exceeds a tenth
//   of its last value (measured 1.3 %); Hertz's peak pressure within 1 %
//   over the last five steps, as on the graded mesh (measured 0.56 %,
//   graded 0.51 %); the energy balance, with the mesh changes' term,
//   within twice the graded run's (the trapezoidal rule's error).
// usage: app_hertz_indentation
//        flat|hertz|cylinder|cylinder_3d|cylinder_adaptive SCENE.prm
//        WORKDIR
#include "../check.h"
#include "scene.h"

#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <sstream>

using namespace amfrac;

namespace
{
  const double E = 70000, nu = 0.3, radius = 5, H = 20;

  void
  flat(const std::string &prm, const std::string &workdir)
  {
    const double       R = 1e4, penalty = 1e6, d = 0.01;
    std::ostringstream text;
    text << amfrac_test::one_cell_under_sphere(R, penalty)
         << "subsection Boundary conditions\n  subsection z-\n"
         << "    set Components = z\n  end\nend\n"
         << "subsection Time\n  set End time = " << d
         << "\n  set Number of steps = 4\nend\n"
         << amfrac_test::history_only(workdir);
    const auto     simulator = amfrac_test::run_scene<3>(prm, text.str());
    const History &h         = simulator->history();
    CHECK(h.n_rows() == 4);
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double t        = h.value(r, "time");
        const double expected = t / (1 / E + 1 / penalty);
        const double work     = h.value(r, "external_work");
        std::cout << "d = " << t << ": F " << h.value(r, "contact_force")
                  << " (" << expected << "), balance "
                  << h.value(r, "balance_error") / work << " of the work, "
                  << h.value(r, "newton_iterations") << " iterations"
                  << std::endl;
        CHECK_CLOSE(h.value(r, "contact_force"), expected, 1e-6 * expected);
        CHECK(h.value(r, "contact_nodes") == 4);
        // The deepest corner: the sphere's normal leans out by
        // r / R = 7e-5 there and shears the cell a little, so the four
        // penetrations differ by about that fraction.
        CHECK_CLOSE(h.value(r, "penetration"),
                    expected / penalty,
                    1e-4 * expected / penalty);
        CHECK_CLOSE(h.value(r, "contact_energy"),
                    0.5 * expected * expected / penalty,
                    1e-6 * work);
        CHECK(std::abs(h.value(r, "balance_error")) < 1e-8 * work);
        CHECK(h.value(r, "newton_iterations") <= 2);
      }
  }

  /** The relative error of the trapezoidal rule on n equal steps for a
   * force growing like d^(3/2) from 0. */
  double
  trapezoid_error(const unsigned int n)
  {
    double sum = 0.5 * std::pow(n, 1.5);
    for (unsigned int i = 1; i < n; ++i)
      sum += std::pow(i, 1.5);
    const double exact = 0.4 * std::pow(n, 2.5);
    return (sum - exact) / exact;
  }

  void
  hertz(const std::string &prm, const std::string &workdir)
  {
    const auto simulator
      = amfrac_test::run_scene<3>(prm, amfrac_test::history_only(workdir));
    const History &h       = simulator->history();
    const double   Es      = E / (1 - nu * nu);
    const double   penalty = 1e8;
    const double   cell    = 5. / 128; // 7 refinements of 5 mm cells
    CHECK(h.n_rows() == 12);
    // Least squares d = alpha F^(2/3) + C F: the normal equations.
    double aa = 0, ab = 0, bb = 0, ad = 0, bd = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double d  = h.value(r, "time");
        const double F  = 4 * h.value(r, "contact_force"); // quarter model
        const double Fh = 4. / 3 * Es * std::sqrt(radius) * std::pow(d, 1.5);
        const double a  = std::sqrt(radius * d);
        const double p0
          = std::cbrt(6 * F * Es * Es / (std::pow(M_PI, 3) * radius * radius));
        const double peak = penalty * h.value(r, "penetration");
        std::cout << "d = " << d << " mm: F " << F << " N, Hertz " << Fh << " ("
                  << F / Fh - 1 << "), peak pressure " << peak << " MPa, Hertz "
                  << p0 << " (" << peak / p0 - 1 << "), "
                  << h.value(r, "newton_iterations") << " iterations"
                  << std::endl;
        CHECK_CLOSE(F, Fh, (r == 0 ? 0.01 : 0.05) * Fh);
        if (a > 4 * cell)
          CHECK_CLOSE(peak, p0, 0.03 * p0);
        CHECK(h.value(r, "newton_iterations") <= 4);
        const double f = std::pow(F, 2. / 3);
        aa += f * f, ab += f * F, bb += F * F, ad += f * d, bd += F * d;
      }
    const double det   = aa * bb - ab * ab;
    const double alpha = (ad * bb - ab * bd) / det;
    const double C     = (aa * bd - ab * ad) / det;
    const double alpha_hertz
      = std::cbrt(9. / (16 * Es * Es * radius)); // d = alpha_H F^(2/3)
    const double boussinesq = (1 + nu) * (3 - 2 * nu) / (2 * M_PI * E * H);
    std::cout << "fit: alpha / alpha_Hertz " << alpha / alpha_hertz << ", C "
              << C << " mm/N (Boussinesq's far field " << -boussinesq << ")"
              << std::endl;
    CHECK_CLOSE(alpha / alpha_hertz, 1., 0.01);
    CHECK(C < -0.5 * boussinesq && C > -4 * boussinesq);

    const std::size_t last     = h.n_rows() - 1;
    const double      work     = h.value(last, "external_work");
    const double      expected = trapezoid_error(h.n_rows()) * work;
    std::cout << "balance " << h.value(last, "balance_error")
              << " N mm, the trapezoidal rule's error " << expected << " of "
              << work << " N mm" << std::endl;
    CHECK_CLOSE(h.value(last, "balance_error"), expected, 0.25 * expected);
  }

  /** Hertz's line contact in plane strain: a cylinder pressed into the
   * block of @p prm (prm/hertz_cylinder_2d.prm, a half model). */
  void
  cylinder(const std::string &prm, const std::string &workdir)
  {
    const auto simulator
      = amfrac_test::run_scene<2>(prm, amfrac_test::history_only(workdir));
    const History &h       = simulator->history();
    const double   Es      = E / (1 - nu * nu);
    const double   penalty = 1e8;
    const double   cell    = 5. / 256; // 8 refinements of 5 mm cells
    CHECK(h.n_rows() == 10);
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double F     = 2 * h.value(r, "contact_force"); // N/mm
        const double a     = std::sqrt(4 * F * radius / (M_PI * Es));
        const double p0    = std::sqrt(F * Es / (M_PI * radius));
        const double peak  = penalty * h.value(r, "penetration");
        const double nodes = h.value(r, "contact_nodes");
        // The nodes in contact lie at x = 0, h, ..., (n - 1) h: the edge
        // of the contact lies between the last of them and the next.
        const double edge = (nodes - 0.5) * cell;
        std::cout << "d = " << h.value(r, "time") << " mm: F' " << F
                  << " N/mm, peak pressure " << peak << " MPa, Hertz " << p0
                  << " (" << peak / p0 - 1 << "), half-width " << edge << " +- "
                  << 0.5 * cell << " mm, Hertz " << a << ", "
                  << h.value(r, "newton_iterations") << " iterations"
                  << std::endl;
        if (a > 6 * cell)
          {
            CHECK_CLOSE(peak, p0, 0.01 * p0);
            CHECK_CLOSE(edge, a, cell);
          }
        // The contact set grows by a node or two per step and settles in
        // two or three iterations; then Newton converges quadratically.
        CHECK(h.value(r, "newton_iterations") <= 5);
      }
    CHECK(2 * h.value(h.n_rows() - 1, "contact_force") > 500);
  }

  /** The 2D line contact of @p prm (a smaller uniform block) against a 3D
   * slice of it in plane strain, pressed by a cylinder. */
  void
  cylinder_3d(const std::string &prm, const std::string &workdir)
  {
    const std::string block
      = "subsection Geometry\n  set Ply thickness = 2\n  set Length = 2\n"
        "  set Elements along length = 32\n  set Elements per ply = 16\n"
        "  set Region refinements = 0\nend\n"
        "subsection Impactor\n  set Center = 0, 7, 0\nend\n";
    const auto plane = amfrac_test::run_scene<2>(
      prm, block + amfrac_test::history_only(workdir + "/2d"));
    const double      width = 2;
    const std::string slice
      = "set Dimension = 3\n"
        "subsection Geometry\n  set Width = 2\n"
        "  set Elements along width = 1\n  set Refinement region =\nend\n"
        "subsection Boundary conditions\n"
        "  subsection y-\n    set Components = y\n  end\n"
        "  subsection y+\n    set Type = displacement\n"
        "    set Components = y\n  end\n"
        "  subsection z-\n    set Type = displacement\n  end\nend\n"
        "subsection Impactor\n  set Face = z+\n  set Shape = cylinder\n"
        "  set Axis = 0, 3, 0\n  set Center = 0, 0.7, 7\n"
        "  set Velocity = 0, 0, -1\nend\n";
    const auto slab = amfrac_test::run_scene<3>(
      prm, block + slice + amfrac_test::history_only(workdir + "/3d"));
    const History &h2 = plane->history(), &h3 = slab->history();
    CHECK(h2.n_rows() == 10 && h3.n_rows() == 10);
    for (std::size_t r = 0; r < std::min(h2.n_rows(), h3.n_rows()); ++r)
      {
        const double F2 = h2.value(r, "contact_force");
        const double F3 = h3.value(r, "contact_force") / width;
        std::cout << "d = " << h2.value(r, "time") << " mm: F' 2D " << F2
                  << ", 3D " << F3 << " N/mm (" << F3 / F2 - 1 << "), "
                  << h3.value(r, "contact_nodes") << " nodes in 3D, "
                  << h2.value(r, "contact_nodes") << " in 2D" << std::endl;
        CHECK(F2 > 0);
        CHECK_CLOSE(F3, F2, 1e-8 * F2);
        CHECK_CLOSE(h3.value(r, "penetration"),
                    h2.value(r, "penetration"),
                    1e-8 * h2.value(r, "penetration"));
        CHECK(h3.value(r, "contact_nodes") == 2 * h2.value(r, "contact_nodes"));
        CHECK(h3.value(r, "newton_iterations")
              == h2.value(r, "newton_iterations"));
      }
    CHECK(h2.value(h2.n_rows() - 1, "contact_nodes") >= 3);
  }

  /** The cylinder of @p prm (prm/hertz_cylinder_2d.prm) on a mesh that
   * adapts during the indentation, against the scene's graded mesh. */
  void
  cylinder_adaptive(const std::string &prm, const std::string &workdir)
  {
    const auto [graded, adapted]
      = amfrac_test::graded_and_adapting(prm, workdir);
    const History &g = graded->history(), &a = adapted->history();
    const History *changes = adapted->adaptivity_history();
    CHECK(g.n_rows() == 10 && a.n_rows() == 10 && changes != nullptr);
    if (g.n_rows() != a.n_rows() || changes == nullptr)
      return;
    const auto cells = [](const Simulator<2> &s) {
      return s.dofs().copy_handler().get_triangulation().n_active_cells();
    };
    const std::size_t last      = a.n_rows() - 1;
    const double      last_F    = g.value(last, "contact_force");
    const double      Es        = E / (1 - nu * nu);
    double            deviation = 0, pressure = 0;
    for (std::size_t r = 0; r < a.n_rows(); ++r)
      {
        const double F = g.value(r, "contact_force");
        if (F > 0.1 * last_F)
          deviation
            = amfrac_test::worse(deviation,
                                 std::abs(a.value(r, "contact_force") / F - 1));
        // Hertz's peak pressure for the force per unit length of the
        // whole cylinder (the scene is a half model).
        const double p0
          = std::sqrt(2 * a.value(r, "contact_force") * Es / (M_PI * radius));
        if (r + 5 > last)
          pressure = amfrac_test::worse(
            pressure, std::abs(1e8 * a.value(r, "penetration") / p0 - 1));
      }
    const double work = a.value(last, "external_work");
    std::cout << "adaptive: " << changes->n_rows() << " mesh changes, "
              << cells(*adapted) << " cells at the end against "
              << cells(*graded) << " graded; force off by " << deviation
              << " at most; peak pressure off Hertz's by " << pressure
              << " at most; balance " << a.value(last, "balance_error") / work
              << " of the work (graded "
              << g.value(last, "balance_error") / g.value(last, "external_work")
              << "), remeshing energy "
              << a.value(last, "remeshing_energy") / work << " of it"
              << std::endl;
    CHECK(changes->n_rows() >= 5);
    CHECK(cells(*adapted) < cells(*graded));
    CHECK(deviation < 0.02);
    CHECK(pressure < 0.01);
    CHECK(std::abs(a.value(last, "balance_error"))
          < 2 * std::abs(g.value(last, "balance_error")));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      AssertThrow(argc == 4,
                  ExcMessage("usage: app_hertz_indentation "
                             "flat|hertz|cylinder|cylinder_3d|"
                             "cylinder_adaptive SCENE.prm WORKDIR"));
      const std::string which = argv[1];
      AssertThrow(which == "flat" || which == "hertz" || which == "cylinder"
                    || which == "cylinder_3d" || which == "cylinder_adaptive",
                  ExcMessage("unknown case '" + which + "'"));
      if (which == "flat")
        flat(argv[2], argv[3]);
      else if (which == "cylinder")
        cylinder(argv[2], argv[3]);
      else if (which == "cylinder_3d")
        cylinder_3d(argv[2], argv[3]);
      else if (which == "cylinder_adaptive")
        cylinder_adaptive(argv[2], argv[3]);
      else
        hertz(argv[2], argv[3]);
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  return amfrac_test::failures;
}

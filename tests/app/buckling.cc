// Linear buckling against the classical formulas.
//   strip <buckling_strip_2d.prm>: a clamped plate strip in plane strain,
//     orthotropic (the shipped [0_4] scene) and isotropic: the two lowest
//     critical forces within 1 % of the clamped-clamped Euler values with
//     Engesser's shear correction; mode 1 symmetric, mode 2 antisymmetric.
//   thin_film <buckling_thin_film_2d.prm>: a delaminated strip, the film's
//     local buckling within 5 % of the thin-film model (below it), the
//     bonded strip within 1 % of Euler-Engesser (states with cohesive
//     interfaces: the Newton tangent).
//   panel <delaminated_panel_2d.prm>: the seed's panel's local mode.
//   cycles <buckling_strip_2d.prm>: an analysis per refinement cycle, the
//     load factor converging.
//   softening <dcb_2d.prm>: a state with softening interface points is
//     refused with the reason.
//   prebuckled_strip <buckling_strip_2d.prm>: total Lagrangian states at
//     0.3 and 0.9 of the critical t predict the same t_c (1e-3), the small
//     strain one (2e-3) and Euler-Engesser's forces (1 %); the same two
//     analysed during one run that goes on (Buckling/Analysis times).
//   prebuckled_strip_remeshed <euler_strip_prism.prm>: the straight strip
//     on wedges with cohesive interfaces, total Lagrangian, remeshed at t =
//     0.2 and analysed at 0.3 on the new mesh: Euler-Engesser's force (1 %).
//   prebuckled_arch <shallow_arch_2d.prm>: the limit point predicted from
//     states at 0.5, 0.8, 0.95 of it, falling towards it.
//   prebuckled_panel <delaminated_panel.prm>: the panel's local buckling
//     from its pre-buckled state, equal to the small-strain analysis
//     without the imperfection.
//   prebuckled_plate <buckling_plate.prm>: 3D, a dead edge pressure: the
//     total Lagrangian state against the small-strain analysis (2e-3).
//   plate <buckling_plate.prm>: the specially orthotropic [0/90]s plate,
//     simply supported, under uniaxial compression: lambda_1 within 2 % of
//     classical plate theory for a thin plate (a/h = 100), clearly below it
//     for a thick one (a/h = 10); the mode is the (1, 1) half-wave.
//   plate_prism, prebuckled_plate_prism <buckling_plate.prm>: plate and
//     prebuckled_plate on wedges (every hexahedron split into two, the
//     diagonals alternating: the mesh keeps the quarter-turn symmetry
//     that the biaxial plate's double mode needs).
#include "scene.h"

#include <array>
#include <cmath>
#include <vector>

using namespace amfrac;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  /** Per unit width: the plane-strain bending stiffness Q11 h^3 / 12 of a
   * homogeneous strip and its shear stiffness 5/6 G13 h. */
  struct Strip
  {
    double E1, E2, nu12, G13, h, L;

    double
    euler(const double beta_L) const
    {
      const double nu21 = nu12 * E2 / E1;
      const double D    = E1 / (1 - nu12 * nu21) * h * h * h / 12;
      return beta_L * beta_L * D / (L * L);
    }

    /** Engesser: N = N_E / (1 + N_E / (kappa G h)). */
    double
    critical(const double beta_L) const
    {
      const double N_E = euler(beta_L);
      return N_E / (1 + N_E / (5. / 6. * G13 * h));
    }
  };

  // Clamped-clamped: beta L = 2 pi (symmetric), 8.9868 (antisymmetric).
  constexpr double beta_L_1 = 2 * pi;
  constexpr double beta_L_2 = 8.98681892;

  /** An isotropic material (E = 70 GPa, nu = 0.3) as .prm text. */
  const std::string isotropic
    = "subsection Materials\n set E1 = 70000\n set E2 = 70000\n"
      " set E3 = 70000\n set nu12 = 0.3\n set nu13 = 0.3\n"
      " set nu23 = 0.3\n set G12 = 26923.08\n set G13 = 26923.08\n"
      " set G23 = 26923.08\nend\n";

  /** The Geometry lines that turn a box scene's hexahedra into wedges
   * (every hexahedron split into two). */
  const std::string prisms = " set Element shape = prism\n";

  /** A square plate of side @p a on 10 x 10 elements as .prm text, with
   * the Geometry lines @p shape. */
  std::string
  square_plate(const double a, const std::string &shape = "")
  {
    std::ostringstream text;
    text << "subsection Geometry\n set Length = " << a << "\n set Width = " << a
         << "\n set Elements along length = 10\n"
            " set Elements along width = 10\n"
         << shape << "end\n";
    return text.str();
  }

  /** The strip of @p file with @p materials appended: the two lowest
   * critical forces (load factor times the reaction) against @p strip. */
  void
  check_strip(const std::string &file,
              const std::string &materials,
              const Strip       &strip)
  {
    const auto simulator = amfrac_test::run_scene<2>(
      file, materials + "\nsubsection Output\n set Field format = none\nend\n");
    const History &modes = *simulator->buckling_history();
    CHECK(modes.n_rows() == 3);
    const auto force = [&](const unsigned int mode) {
      return -modes.value(mode, "critical_reaction_x+_x");
    };
    std::cout << "  N_1 = " << force(0) << " (Engesser "
              << strip.critical(beta_L_1) << "), N_2 = " << force(1)
              << " (Engesser " << strip.critical(beta_L_2) << ")" << std::endl;
    CHECK_CLOSE(force(0) / strip.critical(beta_L_1), 1., 1e-2);
    CHECK_CLOSE(force(1) / strip.critical(beta_L_2), 1., 1e-2);
    CHECK(modes.value(2, "load_factor") > modes.value(1, "load_factor"));
    for (unsigned int k = 0; k < 3; ++k)
      CHECK(modes.value(k, "residual") < 1e-8);
    // Mode 1 has its largest deflection (scaled to 1) at mid-span; mode 2
    // is antisymmetric: none there, a large one at the quarter point.
    CHECK_CLOSE(modes.value(0, "p0_uy"), 1., 1e-3);
    CHECK(std::abs(modes.value(1, "p0_uy")) < 1e-6);
    CHECK(std::abs(modes.value(1, "p1_uy")) > 0.5);
  }

  void
  strip(const std::string &file)
  {
    std::cout << "orthotropic [0_4] strip, L/h = 100" << std::endl;
    check_strip(file, "", {135000, 10000, 0.3, 5000, 1, 100});
    std::cout << "isotropic strip, L/h = 100" << std::endl;
    check_strip(file, isotropic, {70000, 70000, 0.3, 26923.08, 1, 100});
  }

  /** lambda_1 of the [0/90]s plate by classical plate theory (m = n = 1,
   * square, specially orthotropic) under 1 MPa on the edge of a plate of
   * side @p a and thickness 2. */
  double
  classical_plate_factor(const double a)
  {
    const double E1 = 135000, E2 = 10000, nu12 = 0.3, G12 = 5000;
    const double d   = 1 - nu12 * nu12 * E2 / E1;
    const double Q11 = E1 / d, Q22 = E2 / d, Q12 = nu12 * E2 / d;
    // (z+^3 - z-^3) / 3 of the outer (0 deg) and inner (90 deg) ply pairs.
    const double outer = 2 * (1 - 0.125) / 3, inner = 2 * 0.125 / 3;
    const double D11 = Q11 * outer + Q22 * inner;
    const double D22 = Q22 * outer + Q11 * inner;
    const double D12 = Q12 * (outer + inner), D66 = G12 * (outer + inner);
    const double N = pi * pi / (a * a) * (D11 + 2 * (D12 + 2 * D66) + D22);
    return N / 2.; // per 1 MPa on a 2 mm edge
  }

  double
  plate_factor(const std::string &file,
               const double       a,
               const std::string &shape)
  {
    std::ostringstream appended;
    appended << square_plate(a, shape)
             << "subsection Buckling\n set Number of modes = 1\nend\n"
                "subsection Output\n set Field format = none\n"
                " set Point values = "
             << a / 2 << ", " << a / 2 << ", 1\nend\n";
    const auto     simulator = amfrac_test::run_scene<3>(file, appended.str());
    const History &modes     = *simulator->buckling_history();
    CHECK(modes.n_rows() == 1);
    // The (1, 1) mode: its largest deflection at the centre.
    CHECK_CLOSE(modes.value(0, "p0_uz"), 1., 1e-2);
    const double factor = modes.value(0, "load_factor");
    std::cout << "a/h = " << a / 2 << ": lambda_1 = " << factor
              << ", classical plate theory " << classical_plate_factor(a)
              << " (ratio " << factor / classical_plate_factor(a) << ")"
              << std::endl;
    return factor / classical_plate_factor(a);
  }

  /** An isotropic square plate (a/h = 100), simply supported, whose four
   * edges move inwards by 0.01 t mm at mid-plane: lambda_mn is
   * proportional to m^2 + n^2, and the plate is symmetric under a quarter
   * turn, so modes (1, 2) and (2, 1) share one load factor exactly, which
   * the block iteration must find twice. */
  void
  biaxial_plate(const std::string &file, const std::string &shape)
  {
    const double       a = 200, h = 2, E = 70000, nu = 0.3;
    std::ostringstream appended;
    appended << square_plate(a, shape) << isotropic
             << "subsection Boundary conditions\n";
    const char *faces[4] = {"x-", "x+", "y-", "y+"};
    const char *moves[4]
      = {"0.01*t; 0; 0", "-0.01*t; 0; 0", "0; 0.01*t; 0", "0; -0.01*t; 0"};
    for (unsigned int f = 0; f < 4; ++f)
      appended << " subsection " << faces[f]
               << "\n  set Type = displacement\n  set Components = "
               << (f < 2 ? "x" : "y")
               << ", z\n  set Displacement = " << moves[f]
               << "\n  set Pressure = 0\n  set Where = "
               << (f < 2 ? "abs(z-1)<1e-9; 1; 1" : "1; abs(z-1)<1e-9; 1")
               << "\n end\n";
    appended << "end\n"
                "subsection Buckling\n set Number of modes = 3\nend\n"
                "subsection Output\n set Field format = none\n"
                " set Point values = "
             << a / 2 << ", " << a / 2 << ", 1\nend\n";
    const auto     simulator = amfrac_test::run_scene<3>(file, appended.str());
    const History &modes     = *simulator->buckling_history();
    CHECK(modes.n_rows() == 3);
    const double D    = E * h * h * h / (12 * (1 - nu * nu));
    const double N_11 = 2 * pi * pi * D / (a * a);
    const auto   factor
      = [&](const unsigned int k) { return modes.value(k, "load_factor"); };
    const double N = modes.value(0, "critical_reaction_x-_x") / a;
    std::cout << "biaxial isotropic plate: N_11 = " << N << " (classical "
              << N_11 << "), lambda = " << factor(0) << ", " << factor(1)
              << ", " << factor(2) << std::endl;
    // Coarse (10 x 10): the edge layer of the supports converges from
    // below (-1.4 % on 40 x 40 with the same supports under edge pressure).
    CHECK_CLOSE(N / N_11, 1., 3e-2);
    CHECK_CLOSE(factor(1) / factor(0) / 2.5, 1., 3e-2);
    CHECK_CLOSE(factor(2) / factor(1), 1., 1e-6);
  }

  void
  plate(const std::string &file, const std::string &shape)
  {
    biaxial_plate(file, shape);
    const double thin = plate_factor(file, 200, shape);
    CHECK_CLOSE(thin, 1., 2e-2);
    // Transverse shear lowers a thick plate's load well below the thin
    // plate's formula.
    const double thick = plate_factor(file, 20, shape);
    CHECK(thick < 0.9);
    CHECK(thick < thin - 0.1);
  }
  /** The applied force at the first buckling load of the thin-film scene
   * with the delamination @p l long (0: none) and its log. */
  double
  thin_film_force(const std::string &file, const double l)
  {
    std::ostringstream appended;
    appended << "subsection Cohesive interfaces\n";
    if (l > 0)
      appended << " set Pre-crack region = abs(x - 50) < " << l / 2 << "\n";
    else
      appended << " set Pre-crack interfaces =\n";
    appended << "end\nsubsection Output\n set Field format = none\nend\n";
    const auto     simulator = amfrac_test::run_scene<2>(file, appended.str());
    const History &modes     = *simulator->buckling_history();
    CHECK(modes.n_rows() == 2);
    return -modes.value(0, "critical_reaction_x+_x");
  }

  /** The delaminated strip: the film's force at the first buckling load
   * against the thin-film model 4 pi^2 D_s / l^2, which clamps the film's
   * ends; the bonded strip against Euler-Engesser. */
  void
  thin_film(const std::string &file)
  {
    const double t_s = 0.2, t = 2;
    const Strip  film{135000, 10000, 0.3, 5000, t_s, 40};
    const double N_40 = thin_film_force(file, 40) * t_s / t;
    std::cout << "l = 40 mm: film force " << N_40 << ", thin-film model "
              << film.euler(beta_L_1) << " (ratio "
              << N_40 / film.euler(beta_L_1) << ")" << std::endl;
    CHECK_CLOSE(N_40 / film.euler(beta_L_1), 1., 5e-2);
    // The film's ends rotate with the bonded part, which lowers the load
    // below the clamped model, less so for a longer film.
    CHECK(N_40 < film.euler(beta_L_1));
    const Strip  short_film{135000, 10000, 0.3, 5000, t_s, 20};
    const double N_20 = thin_film_force(file, 20) * t_s / t;
    std::cout << "l = 20 mm: film force " << N_20 << ", thin-film model "
              << short_film.euler(beta_L_1) << " (ratio "
              << N_20 / short_film.euler(beta_L_1) << ")" << std::endl;
    CHECK(N_20 / short_film.euler(beta_L_1) < N_40 / film.euler(beta_L_1));
    // Bonded everywhere: the strip buckles as a whole, the interface's
    // penalty barely softening it.
    const Strip  strip{135000, 10000, 0.3, 5000, t, 100};
    const double N = thin_film_force(file, 0);
    std::cout << "bonded: " << N << ", Euler-Engesser "
              << strip.critical(beta_L_1) << std::endl;
    CHECK_CLOSE(N / strip.critical(beta_L_1), 1., 1e-2);
  }

  /** The seed's panel (prm/delaminated_panel_2d.prm): mode 1 is the
   * 4-ply sublaminate alone, at a load a little below the thin-film
   * model's (its ends rotate: 0.89 of it for t_s / l = 0.0135). */
  void
  panel(const std::string &file)
  {
    const auto simulator = amfrac_test::run_scene<2>(
      file, "subsection Output\n set Field format = none\nend\n");
    const History &modes = *simulator->buckling_history();
    CHECK(modes.n_rows() == 2);
    const double t_s = 4 * 0.127, t = 20 * 0.127;
    const Strip  film{135000, 10000, 0.3, 5000, t_s, 0.49 * 76.6};
    const double local = -modes.value(0, "critical_reaction_x+_x");
    const double model = film.euler(beta_L_1) * t / t_s;
    std::cout << "panel: local buckling " << local << " N/mm ("
              << local / 4.448222 * 25.4 << " lbf/in), thin-film model "
              << model << std::endl;
    CHECK(local < model && local > 0.85 * model);
    CHECK_CLOSE(modes.value(0, "p0_uy"), 1., 1e-2);
    CHECK(std::abs(modes.value(0, "p1_uy")) < 0.05);
  }

  /** The strip on a coarse mesh, refined uniformly twice: every cycle
   * analyses its mesh, and lambda_1 converges (by more than 4x per
   * halving of the elements) to the Euler-Engesser value. */
  void
  cycles(const std::string &file)
  {
    const auto simulator = amfrac_test::run_scene<2>(
      file,
      "subsection Geometry\n set Elements along length = 25\nend\n"
      "subsection Adaptivity\n set Refinement cycles = 2\n"
      " set Strategy = uniform\nend\n"
      "subsection Output\n set Field format = none\nend\n");
    const History &modes = *simulator->buckling_history();
    CHECK(modes.n_rows() == 9);
    std::vector<double> lambda;
    for (unsigned int r = 0; r < modes.n_rows(); ++r)
      if (modes.value(r, "mode") == 1)
        {
          CHECK(modes.value(r, "cycle") == lambda.size());
          lambda.push_back(modes.value(r, "load_factor"));
        }
    CHECK(lambda.size() == 3);
    std::cout << "lambda_1 by cycle: " << lambda[0] << ", " << lambda[1] << ", "
              << lambda[2] << std::endl;
    CHECK(std::abs(lambda[2] - lambda[1])
          < 0.25 * std::abs(lambda[1] - lambda[0]));
    const Strip strip{135000, 10000, 0.3, 5000, 1, 100};
    CHECK_CLOSE(-modes.value(6, "critical_reaction_x+_x")
                  / strip.critical(beta_L_1),
                1.,
                1e-2);
  }

  /** The strip of buckling_strip_2d.prm, total Lagrangian, analysed
   * after @p steps steps to t = @p end: the critical t of modes 1 and 2. */
  std::pair<double, double>
  prebuckled_strip_state(const std::string &file,
                         const double       end,
                         const unsigned int steps,
                         const Strip       &strip)
  {
    std::ostringstream appended;
    appended << "set Kinematics = total Lagrangian\n"
                "subsection Time\n set End time = "
             << end << "\n set Number of steps = " << steps
             << "\nend\nsubsection Output\n set Field format = none\nend\n";
    const auto     simulator = amfrac_test::run_scene<2>(file, appended.str());
    const History &modes     = *simulator->buckling_history();
    CHECK(modes.n_rows() == 3);
    const double N_1 = -modes.value(0, "critical_reaction_x+_x");
    const double N_2 = -modes.value(1, "critical_reaction_x+_x");
    std::cout << "  t = " << end
              << ": t_c = " << modes.value(0, "critical_time") << ", "
              << modes.value(1, "critical_time") << ", N = " << N_1 << ", "
              << N_2 << " (Engesser " << strip.critical(beta_L_1) << ", "
              << strip.critical(beta_L_2) << ")" << std::endl;
    CHECK_CLOSE(N_1 / strip.critical(beta_L_1), 1., 1e-2);
    CHECK_CLOSE(N_2 / strip.critical(beta_L_2), 1., 1e-2);
    CHECK(modes.value(0, "residual") < 1e-8);
    CHECK_CLOSE(modes.value(0, "p0_uy"), 1., 1e-3);
    CHECK(std::abs(modes.value(1, "p0_uy")) < 1e-6);
    CHECK_CLOSE(modes.value(0, "critical_time"),
                end * modes.value(0, "load_factor"),
                1e-12);
    return {modes.value(0, "critical_time"), modes.value(1, "critical_time")};
  }

  /** Linear buckling of a total Lagrangian state on a straight path: the
   * strip's critical t, predicted from about 0.3 and 0.9 of it, agree
   * with each other and with the small-strain analysis, and the critical
   * forces with Euler-Engesser. */
  void
  prebuckled_strip(const std::string &file)
  {
    const Strip strip{135000, 10000, 0.3, 5000, 1, 100};
    const auto  small = amfrac_test::run_scene<2>(
      file, "subsection Output\n set Field format = none\nend\n");
    const double t_small = small->buckling_history()->value(0, "critical_time");
    const auto   early   = prebuckled_strip_state(file, 1, 1, strip);
    const auto   late    = prebuckled_strip_state(file, 3, 6, strip);
    std::cout << "small strain: t_c = " << t_small << std::endl;
    CHECK_CLOSE(early.first / late.first, 1., 1e-3);
    CHECK_CLOSE(early.second / late.second, 1., 1e-3);
    CHECK_CLOSE(late.first / t_small, 1., 2e-3);

    // Both states analysed during one run (Analysis times), which goes on
    // past them: the same modes as the runs that end there.
    const auto simulator = amfrac_test::run_scene<2>(
      file,
      "set Kinematics = total Lagrangian\n"
      "subsection Time\n set End time = 3.2\n set Number of steps = 16\nend\n"
      "subsection Buckling\n set Analysis times = 0.9, 3\nend\n"
      "subsection Output\n set Field format = none\nend\n");
    const History &modes = *simulator->buckling_history();
    CHECK(modes.n_rows() == 6);
    CHECK_CLOSE(modes.value(0, "time"), 1., 1e-12);
    CHECK_CLOSE(modes.value(3, "time"), 3., 1e-12);
    CHECK_CLOSE(modes.value(0, "critical_time") / early.first, 1., 1e-6);
    CHECK_CLOSE(modes.value(4, "critical_time") / late.second, 1., 1e-6);
    // The analyses leave the load path as it was.
    const auto plain = amfrac_test::run_scene<2>(
      file,
      "set Kinematics = total Lagrangian\n"
      "subsection Time\n set End time = 3.2\n set Number of steps = 16\nend\n"
      "subsection Buckling\n set Number of modes = 0\nend\n"
      "subsection Output\n set Field format = none\nend\n");
    const History &with = simulator->history(), &without = plain->history();
    CHECK(with.n_rows() == 16 && without.n_rows() == 16);
    for (std::size_t r = 0; r < with.n_rows(); ++r)
      for (const std::string column : {"reaction_x+_x", "newton_iterations"})
        CHECK_CLOSE(with.value(r, column), without.value(r, column), 1e-12);
  }

  /** The strip of euler_strip_prism.prm (3D, wedges, plane strain,
   * straight: no imperfection) with total Lagrangian kinematics and
   * cohesive interfaces between its plies, remeshed after step 4 (t =
   * 0.2) and analysed at t = 0.3 on the new mesh: its pre-buckled state's
   * critical force is Euler-Engesser's (1 %), as on the first mesh. */
  void
  prebuckled_strip_remeshed(const std::string &file)
  {
    const Strip  strip{135000, 10000, 0.3, 5000, 1, 100};
    const double width     = 2;
    const auto   simulator = amfrac_test::run_scene<3>(
      file,
      "subsection Geometry\n set Imperfection mode = 0\nend\n"
        "subsection Cohesive interfaces\n set Interfaces = all\n"
        " set Quadrature = gauss\nend\n"
        "subsection Adaptivity\n set Refine every = 4\n"
        " set Strategy = error target\n set Target error = 0.05\nend\n"
        "subsection Buckling\n set Number of modes = 1\n"
        " set Analysis times = 0.3\nend\n"
        "subsection Time\n set End time = 0.3\n set Number of steps = 6\nend\n"
        "subsection Output\n set Field format = none\n"
        " set Directory = output-prebuckled-strip-remeshed\nend\n");
    const History *changes = simulator->adaptivity_history();
    CHECK(changes && changes->n_rows() >= 1
          && changes->value(0, "t") < 0.3 - 1e-12);
    const History &modes = *simulator->buckling_history();
    CHECK(modes.n_rows() == 1);
    CHECK_CLOSE(modes.value(0, "time"), 0.3, 1e-12);
    const double N_1 = -modes.value(0, "critical_reaction_x+_x") / width;
    std::cout << "  remeshed to " << changes->value(0, "cells")
              << " wedges at t = " << changes->value(0, "t")
              << "; at t = 0.3: N_1 = " << N_1 << " N/mm (Engesser "
              << strip.critical(beta_L_1) << ")" << std::endl;
    CHECK_CLOSE(N_1 / strip.critical(beta_L_1), 1., 1e-2);
    CHECK(modes.value(0, "residual") < 1e-8);
  }

  /** The shallow arch of shallow_arch_2d.prm in the one-mode (Marguerre)
   * theory of its header: t(c) with c the mid-span rise, and the
   * prediction of linearized pre-buckling from the state at c, t + mu
   * with K + mu dK/dt = 0 for the stiffness K = dt/ds, s = e - c. */
  struct ShallowArch
  {
    double k = 2 * pi / 100, e = 0.75, q = 0.016, h = 0.5;
    double Q11 = 135000 / (1 - 0.3 * 0.3 * 10000 / 135000);
    double EI = Q11 * h * h * h / 12, EA = Q11 * h;

    double
    t(const double c) const
    {
      return k * k / 2
             * (EI * k * k * (e - c) + EA * k * k * c * (e * e - c * c) / 16)
             / q;
    }
    double
    dt_dc(const double c) const
    {
      return k * k / 2 * (-EI * k * k + EA * k * k * (e * e - 3 * c * c) / 16)
             / q;
    }
    double
    d2t_dc2(const double c) const
    {
      return k * k / 2 * EA * k * k * (-6 * c) / 16 / q;
    }
    /** K = dt/ds = -dt/dc, dK/dt = (dK/ds) / K = (d2t/dc2) / K. */
    double
    predicted(const double c) const
    {
      const double K = -dt_dc(c), dK_dt = d2t_dc2(c) / K;
      return t(c) - K / dK_dt;
    }
    /** The rise at load parameter @p load on the rising branch. */
    double
    rise(const double load) const
    {
      double c = e;
      for (int it = 0; it < 100; ++it)
        c -= (t(c) - load) / dt_dc(c);
      return c;
    }
    /** The limit point: dt/dc = 0 at c^2 = (e^2 - 16 EI / EA) / 3. */
    double
    limit() const
    {
      return t(std::sqrt((e * e - 16 * EI / EA) / 3));
    }
  };

  /** Linear buckling of a total Lagrangian state on a curved path: the
   * shallow arch's limit point t_l predicted from states at 0.5, 0.8 and
   * 0.95 of it. The predictions fall towards it from above. Near a limit
   * point t(s) ~ t_l - a (s - s_l)^2 gives t + mu = 2 t_l - t (the
   * prediction overshoots by the distance to it), so (t + t_c) / 2 is t_l
   * to second order: from 0.95, within 2 % of the one-mode (Marguerre)
   * theory's t_l (the continuum differs from it by about 1 %, see the
   * scene). The one-mode theory's own prediction is a Rayleigh quotient of
   * the pencil (K_T, dK_T/dt) over the mode shape, an upper bound of the
   * continuum's lowest mu (up to that 1 %). */
  void
  prebuckled_arch(const std::string &file)
  {
    const ShallowArch   arch;
    const double        t_limit = arch.limit();
    std::vector<double> predictions;
    double              estimate = 0;
    for (const double fraction : {0.5, 0.8, 0.95})
      {
        const double       end = fraction * t_limit;
        std::ostringstream appended;
        appended << "subsection Nonlinear solver\n set Control = displacement"
                    "\nend\nsubsection Time\n set End time = "
                 << end
                 << "\n set Number of steps = 10\nend\n"
                    "subsection Buckling\n set Number of modes = 1\nend\n"
                    "subsection Output\n set Field format = none\nend\n";
        const auto simulator = amfrac_test::run_scene<2>(file, appended.str());
        const History &modes = *simulator->buckling_history();
        CHECK(modes.n_rows() == 1);
        const double t_c   = modes.value(0, "critical_time");
        const double bound = arch.predicted(arch.rise(end));
        estimate           = (end + t_c) / 2;
        std::cout << "arch at t = " << end << ": t_c = " << t_c
                  << ", one-mode bound " << bound
                  << ", (t + t_c) / 2 = " << estimate
                  << ", one-mode limit point " << t_limit << std::endl;
        CHECK(t_c < 1.01 * bound);
        CHECK(t_c > end);
        predictions.push_back(t_c);
      }
    CHECK(predictions[0] > predictions[1] && predictions[1] > predictions[2]);
    CHECK(predictions[2] > 0.98 * t_limit);
    CHECK_CLOSE(estimate / t_limit, 1., 2e-2);
  }

  /** The first buckling load of the nonlinear panel scene analysed at
   * t = @p end with @p kinematics (the imperfection mode or none), and
   * the mode's deflections of the sublaminate and the base. */
  std::array<double, 3>
  panel_buckling(const std::string &file,
                 const std::string &kinematics,
                 const double       end,
                 const bool         imperfect)
  {
    std::ostringstream appended;
    appended << "set Kinematics = " << kinematics
             << "\nsubsection Geometry\n set Imperfection mode = "
             << (imperfect ? 1 : 0)
             << "\nend\nsubsection Nonlinear solver\n set Control = "
                "displacement\nend\nsubsection Time\n set End time = "
             << end << "\n set Number of steps = " << 2 * end
             << "\nend\nsubsection Buckling\n set Number of modes = 1\n"
                " set Analysis times =\nend\n"
                "subsection Output\n set Field format = none\nend\n";
    const auto     simulator = amfrac_test::run_scene<2>(file, appended.str());
    const History &modes     = *simulator->buckling_history();
    CHECK(modes.n_rows() == 1);
    const double N = -modes.value(0, "critical_reaction_x+_x");
    std::cout << kinematics << (imperfect ? ", imperfect" : ", perfect")
              << ", t = " << end << ": N = " << N << " N/mm, mode p0_uy "
              << modes.value(0, "p0_uy") << ", p1_uy "
              << modes.value(0, "p1_uy") << std::endl;
    return {{N, modes.value(0, "p0_uy"), modes.value(0, "p1_uy")}};
  }

  /** The seed's panel (prm/delaminated_panel.prm), total Lagrangian with
   * the interfaces in the deformed frame: without the imperfection, the
   * pre-buckled state's local buckling load equals the small-strain
   * analysis's to O(strain) (5e-4 here); with it (1 % of the sublaminate's
   * thickness), the prediction from a quarter and from half the load
   * rises a little (the imperfect sublaminate's deflection), and the mode
   * is the sublaminate's alone. */
  void
  prebuckled_panel(const std::string &file)
  {
    const auto small   = panel_buckling(file, "small strain", 1, false);
    const auto perfect = panel_buckling(file, "total Lagrangian", 1, false);
    CHECK_CLOSE(perfect[0] / small[0], 1., 2e-3);
    const auto quarter = panel_buckling(file, "total Lagrangian", 1, true);
    const auto half    = panel_buckling(file, "total Lagrangian", 2, true);
    CHECK(quarter[0] > perfect[0] && half[0] > quarter[0]);
    CHECK_CLOSE(half[0] / perfect[0], 1., 2e-2);
    for (const auto &mode : {perfect, quarter, half})
      {
        CHECK_CLOSE(mode[1], 1., 1e-2);
        CHECK(std::abs(mode[2]) < 0.05);
      }
  }

  /** The plate of buckling_plate.prm (3D, 8 x 8) under the edge pressure
   * 20 t MPa: the first two critical t of the total Lagrangian state at
   * t = 1 (a dead load: the path tangent carries f(1)) against the
   * small-strain analysis, to the order of the critical strain (8e-4 for
   * mode 1); the mode is the (1, 1) half-wave. */
  void
  prebuckled_plate(const std::string &file, const std::string &shape)
  {
    std::array<std::array<double, 3>, 2> runs{};
    const char *kinematics[2] = {"small strain", "total Lagrangian"};
    for (unsigned int k = 0; k < 2; ++k)
      {
        std::ostringstream appended;
        appended << "set Kinematics = " << kinematics[k]
                 << "\nsubsection Geometry\n set Elements along length = 8\n"
                    " set Elements along width = 8\n"
                 << shape
                 << "end\n"
                    "subsection Boundary conditions\n subsection x+\n"
                    "  set Pressure = 20*t\n end\nend\n"
                    "subsection Buckling\n set Number of modes = 2\nend\n"
                    "subsection Time\n set End time = 1\n"
                    " set Number of steps = 2\nend\n"
                    "subsection Output\n set Field format = none\n"
                    " set Point values = 50, 50, 1\nend\n";
        const auto simulator = amfrac_test::run_scene<3>(file, appended.str());
        const History &modes = *simulator->buckling_history();
        CHECK(modes.n_rows() == 2);
        runs[k] = {{modes.value(0, "critical_time"),
                    modes.value(1, "critical_time"),
                    modes.value(0, "p0_uz")}};
        std::cout << kinematics[k] << ": t_c = " << runs[k][0] << ", "
                  << runs[k][1] << std::endl;
      }
    CHECK_CLOSE(runs[1][0] / runs[0][0], 1., 2e-3);
    CHECK_CLOSE(runs[1][1] / runs[0][1], 1., 5e-3);
    CHECK(runs[1][0] > runs[0][0]);
    CHECK_CLOSE(std::abs(runs[1][2]), 1., 1e-2);
  }

  /** A state with softening interface points has no symmetric positive
   * definite tangent: the analysis is refused with the reason. */
  void
  softening_state(const std::string &file)
  {
    bool refused = false;
    try
      {
        amfrac_test::run_scene<2>(
          file,
          "subsection Time\n set End time = 2.6\n set Number of steps = "
          "26\nend\nsubsection Buckling\n set Number of modes = 1\nend\n"
          "subsection Output\n set Field format = none\n"
          " set Directory = output-buckling-softening\nend\n");
      }
    catch (const std::exception &e)
      {
        std::cout << "refused: " << e.what() << std::endl;
        refused = std::string(e.what()).find("soften") != std::string::npos;
      }
    CHECK(refused);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                what = argc == 3 ? argv[1] : "";
  if (what == "strip")
    strip(argv[2]);
  else if (what == "plate")
    plate(argv[2], "");
  else if (what == "plate_prism")
    plate(argv[2], prisms);
  else if (what == "thin_film")
    thin_film(argv[2]);
  else if (what == "panel")
    panel(argv[2]);
  else if (what == "cycles")
    cycles(argv[2]);
  else if (what == "softening")
    softening_state(argv[2]);
  else if (what == "prebuckled_strip")
    prebuckled_strip(argv[2]);
  else if (what == "prebuckled_strip_remeshed")
    prebuckled_strip_remeshed(argv[2]);
  else if (what == "prebuckled_arch")
    prebuckled_arch(argv[2]);
  else if (what == "prebuckled_panel")
    prebuckled_panel(argv[2]);
  else if (what == "prebuckled_plate")
    prebuckled_plate(argv[2], "");
  else if (what == "prebuckled_plate_prism")
    prebuckled_plate(argv[2], prisms);
  else
    {
      std::cerr
        << "usage: app_buckling strip|plate|thin_film|panel|cycles|softening|"
           "prebuckled_strip|prebuckled_arch|prebuckled_panel|"
           "prebuckled_plate|plate_prism|prebuckled_plate_prism FILE\n";
      return 2;
    }
  return amfrac_test::summary();
}

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
//   plate <buckling_plate.prm>: the specially orthotropic [0/90]s plate,
//     simply supported, under uniaxial compression: lambda_1 within 2 % of
//     classical plate theory for a thin plate (a/h = 100), clearly below it
//     for a thick one (a/h = 10); the mode is the (1, 1) half-wave.
#include "scene.h"

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

  /** A square plate of side @p a on 10 x 10 elements as .prm text. */
  std::string
  square_plate(const double a)
  {
    std::ostringstream text;
    text << "subsection Geometry\n set Length = " << a << "\n set Width = " << a
         << "\n set Elements along length = 10\n"
            " set Elements along width = 10\nend\n";
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
  plate_factor(const std::string &file, const double a)
  {
    std::ostringstream appended;
    appended << square_plate(a)
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
  biaxial_plate(const std::string &file)
  {
    const double       a = 200, h = 2, E = 70000, nu = 0.3;
    std::ostringstream appended;
    appended << square_plate(a) << isotropic
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
  plate(const std::string &file)
  {
    biaxial_plate(file);
    const double thin = plate_factor(file, 200);
    CHECK_CLOSE(thin, 1., 2e-2);
    // Transverse shear lowers a thick plate's load well below the thin
    // plate's formula.
    const double thick = plate_factor(file, 20);
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
    plate(argv[2]);
  else if (what == "thin_film")
    thin_film(argv[2]);
  else if (what == "panel")
    panel(argv[2]);
  else if (what == "cycles")
    cycles(argv[2]);
  else if (what == "softening")
    softening_state(argv[2]);
  else
    {
      std::cerr
        << "usage: app_buckling strip|plate|thin_film|panel|cycles|softening "
           "FILE\n";
      return 2;
    }
  return amfrac_test::summary();
}

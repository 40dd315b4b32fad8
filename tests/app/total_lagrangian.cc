// Kinematics = total Lagrangian on the Newton path.
//   rotation <euler_strip_2d.prm>: one end of the strip turned by 90
//     degrees as a rigid body, the rest free: the whole strip turns rigidly
//     (every probe on R X - X), no strain energy, no reaction, no output
//     stress at the probe; in 2D and in 3D (a [0/90] plate with a cohesive
//     interface between the plies, on hexahedra and on wedges). With small
//     strains the same motion stores a large strain energy, which the test
//     also checks (it is what the test could catch).
//   rotation_sliding <euler_strip_2d.prm>: a cantilever of four plies with
//     soft, elastic cohesive interfaces (shear stiffer than normal: a frame
//     that mixes the modes changes their energy), its tip deflected after
//     the clamp and the tip were turned by 0 or 90 degrees: the interfaces
//     slide, and the two runs store the same energy in the plies and in
//     the interfaces and need the same force, to the Newton tolerance
//     (the interfaces' frame follows the deformed mid-surface; in the
//     undeformed frame the turned run's stored interface energy differs),
//     and the probe's output stress (second Piola-Kirchhoff) is the same
//     (a small-strain stress of the turned run is not).
//   euler <euler_strip_2d.prm>: the clamped strip with a first-mode
//     imperfection w0 bends over at the critical force N_1 of the linear
//     buckling analysis of the same mesh: past the bifurcation N follows the
//     imperfect Euler column N = N_1 (1 - w0 / w) (w the total mid-span
//     deflection) to 0.5 %, never exceeds N_1, and the work done equals the
//     strain energy.
//   euler_mode <euler_strip_2d.prm>: the same with the imperfection seeded
//     from the computed first buckling mode (Geometry/Imperfection mode).
//   euler_prism <euler_strip_prism.prm>: the same strip in 3D on wedges,
//     held in plane strain, its imperfection the first mode.
//   plastic_strip <plastic_strip_2d.prm>: the clamped [90_4] strip with
//     Hoffman plasticity compressed far past buckling, against the same
//     strip with elastic plies: the two runs agree bit for bit up to the
//     first yield, which comes after buckling; at the full shortening the
//     plastic strip carries less than 0.85 times the elastic force and
//     less than at its first yield, and its end force and plastic work lie
//     within 0.2 % of those of a mesh four times finer; kappa never
//     decreases, a fifth of the work or more is plastic, and the energy
//     balances.
//   panel_plastic <delaminated_panel.prm>: the panel with plastic plies to
//     t = 12 against the elastic one: bit for bit until the first yield,
//     which comes after the local buckling; the energy balances. The
//     elastic run goes on to t = 21 and is checked as in panel (ctest runs
//     the two as one test: the elastic run is shared).
//   plastic_strip_adaptive <plastic_strip_2d.prm>: the same on 50
//     elements adapted every 8 steps (ZZ of the second Piola-Kirchhoff
//     stress): kappa never lowered by a mesh change, the end force and
//     plastic work within 0.5 % and 1 % of the 400-element mesh with fewer
//     cells, the balance.
//   panel <delaminated_panel.prm>: the seed's panel with total Lagrangian
//     kinematics and contact, under displacement control to 0.21 mm: local
//     buckling of the sublaminate where the linear analysis' load and the
//     imperfection put it, then global bending, no delamination growth.
//   panel_growth <delaminated_panel.prm>: the scene's opening control
//     past the limit load for 64 steps: the switch to it comes when the
//     fronts dissipate (not when the buckled panel loses secant stiffness),
//     the delamination starts to grow at the limit load, the path is followed
//     back through the snap-back (t decreases), the fracture energy per new
//     debonded length lies between G_Ic and G_IIc, the sublaminates do not
//     interpenetrate, and the energy balances.
#include "scene.h"

#include <cmath>

using namespace amfrac;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  /** A rigid rotation by t pi/2 of face x- about the width axis, x+ free;
   * with @p remeshed, wedges remeshed (every size halved) after step 12,
   * before the end whatever step length Newton takes (16 steps, or 32
   * where it cuts back). */
  template <int dim>
  std::string
  rotation_scene(const std::string &kinematics,
                 const bool         wedges,
                 const bool         remeshed)
  {
    const std::string  z = dim == 2 ? "y" : "z";
    const std::string  a = "(t*pi/2)";
    std::ostringstream text;
    text << "set Dimension = " << dim << "\nset Kinematics = " << kinematics
         << "\nsubsection Geometry\n set Imperfection =\n"
         << " set Length = 20\n set Elements along length = 10\n"
         << (wedges ? " set Element shape = prism\n" : "");
    if (dim == 3)
      text << " set Stacking sequence = [0/90]\n set Width = 4\n"
              " set Elements along width = 2\nend\n"
              "subsection Cohesive interfaces\n set Interfaces = all\n"
           // Quadratic triangles have no nodal rule with positive weights.
           << (wedges ? " set Quadrature = gauss\n" : "") << "end\n";
    else
      text << "end\n";
    text << "subsection Boundary conditions\n subsection x-\n"
            "  set Type = displacement\n  set Components = "
         << (dim == 2 ? "x, y" : "x, y, z") << "\n  set Displacement = (cos"
         << a << "-1)*x + sin" << a << "*" << z << "; "
         << (dim == 3 ? "0; " : "") << "-sin" << a << "*x + (cos" << a << "-1)*"
         << z
         << "\n end\n subsection x+\n  set Type = free\n end\nend\n"
            "subsection Time\n set Number of steps = 16\nend\n"
            "subsection Output\n set Field format = none\n"
            " set Point values = 20, "
         << (dim == 3 ? "4, 0.5" : "0.5") << "\nend\n";
    if (remeshed)
      text << "subsection Adaptivity\n set Refine every = 12\n"
              " set Strategy = uniform\nend\n";
    return text.str();
  }

  template <int dim>
  double
  rigid_rotation(const std::string &file,
                 const std::string &kinematics,
                 const bool         wedges   = false,
                 const bool         remeshed = false)
  {
    const auto simulator = amfrac_test::run_scene<dim>(
      file, rotation_scene<dim>(kinematics, wedges, remeshed));
    if (remeshed)
      {
        // The turned state moves to unrelated meshes: a rigid motion is
        // linear in X, which the nodal transfer carries exactly.
        // The transferred state itself stores no energy: what the
        // transfer changed is round-off (a lost or distorted state, with
        // the turned face prescribed, would store a large one).
        const History *changes = simulator->adaptivity_history();
        CHECK(changes && changes->n_rows() >= 1);
        const double changed
          = changes ? changes->value(0, "remeshing_energy") : 1.;
        std::cout << "  remeshed " << (changes ? changes->n_rows() : 0)
                  << " times, the transfer changed the energy by " << changed
                  << " N mm" << std::endl;
        CHECK(std::abs(changed) < 1e-9);
      }
    const History    &history = simulator->history();
    const std::size_t last    = history.n_rows() - 1;
    const double      energy  = history.value(last, "strain_energy");
    std::cout << "  " << dim << "D, " << kinematics
              << ": strain energy after 90 degrees " << energy << " N mm"
              << std::endl;
    if (kinematics == "small strain")
      return energy;
    // The probe at (20, [4,] 0.5) goes to R X.
    const std::string z = dim == 2 ? "p0_uy" : "p0_uz";
    // To the Newton tolerance (relative to the first residual of a step:
    // a rigid motion has no force scale).
    CHECK_CLOSE(history.value(last, "p0_ux"), -20 + 0.5, 1e-5);
    CHECK_CLOSE(history.value(last, z), -20 - 0.5, 1e-5);
    CHECK(std::abs(energy) < 1e-9);
    // The probe's second Piola-Kirchhoff stress vanishes too.
    double stress = 0;
    for (const char *pair : {"xx", "yy", "zz", "yz", "xz", "xy"})
      stress
        = std::max(stress,
                   std::abs(
                     history.value(last, "p0_stress_" + std::string(pair))));
    std::cout << "  largest probe stress " << stress << " MPa" << std::endl;
    CHECK(stress < 1e-6);
    for (const std::string component : {"x", "y", "z"})
      if (component != "z" || dim == 3)
        CHECK(std::abs(history.value(last, "reaction_x-_" + component)) < 1e-6);
    return energy;
  }

  /** The cantilever of rotation_sliding turned by @p degrees. */
  std::string
  sliding_scene(const double degrees)
  {
    const std::string  a = "(" + std::to_string(degrees) + "*pi/180*min(t,1))";
    const std::string  s = "(0.5*max(t-1,0))";
    std::ostringstream text;
    // X -> R(a) X on the clamp; R(a) (X + s e_y) at the tip.
    text << "set Kinematics = total Lagrangian\nsubsection Geometry\n"
            " set Imperfection =\n set Length = 20\n"
            " set Elements along length = 20\nend\n"
            "subsection Cohesive interfaces\n set Interfaces = all\n"
            " set Normal stiffness = 1e4\n set Shear stiffness = 3e4\n"
            " set Normal strength = 1e3\n set Shear strength = 1e3\n"
            " set Mode I fracture energy = 1e3\n"
            " set Mode II fracture energy = 1e3\nend\n"
            "subsection Boundary conditions\n subsection x-\n"
            "  set Displacement = (cos"
         << a << "-1)*x - sin" << a << "*y; sin" << a << "*x + (cos" << a
         << "-1)*y\n end\n subsection x+\n  set Displacement = (cos" << a
         << "-1)*x - sin" << a << "*(y+" << s << "); sin" << a << "*x + cos"
         << a << "*(y+" << s << ") - y\n end\nend\n"
         << "subsection Time\n set End time = 2\n set Number of steps = 24\n"
            "end\nsubsection Output\n set Field format = none\n"
            " set Point values = 10, 0.3\nend\n";
    return text.str();
  }

  void
  rotation_sliding(const std::string &file)
  {
    std::vector<std::vector<double>> results;
    for (const double degrees : {0., 90.})
      {
        const auto simulator
          = amfrac_test::run_scene<2>(file, sliding_scene(degrees));
        const History    &h     = simulator->history();
        const std::size_t last  = h.n_rows() - 1;
        const double      force = std::hypot(h.value(last, "reaction_x+_x"),
                                        h.value(last, "reaction_x+_y"));
        results.push_back({h.value(last, "strain_energy"),
                           h.value(last, "interface_stored"),
                           force});
        // The probe's stress (second Piola-Kirchhoff: the same in both).
        for (const char *pair : {"xx", "yy", "zz", "yz", "xz", "xy"})
          results.back().push_back(
            h.value(last, "p0_stress_" + std::string(pair)));
        std::cout << "  turned by " << degrees << " degrees: strain energy "
                  << results.back()[0] << ", interfaces " << results.back()[1]
                  << " N mm/mm, tip force " << force << " N/mm" << std::endl;
      }
    // The interfaces hold a sizable part of the energy (the test would
    // not see a wrong frame otherwise).
    CHECK(results[0][1] > 0.02 * results[0][0]);
    for (unsigned int i = 0; i < 3; ++i)
      CHECK_CLOSE(results[1][i] / results[0][i], 1., 1e-6);
    double stress = 0, difference = 0;
    for (unsigned int i = 3; i < results[0].size(); ++i)
      {
        stress = std::max(stress, std::abs(results[0][i]));
        difference
          = std::max(difference, std::abs(results[1][i] - results[0][i]));
      }
    std::cout << "  probe stress: largest " << stress
              << " MPa, turned run differs by " << difference << std::endl;
    CHECK(stress > 1);
    CHECK(difference < 1e-6 * stress);
  }

  void
  rotation(const std::string &file)
  {
    rigid_rotation<2>(file, "total Lagrangian");
    rigid_rotation<3>(file, "total Lagrangian");
    // On wedges: the interface's frame on triangles.
    rigid_rotation<3>(file, "total Lagrangian", true);
    // Remeshed while turning: the transfer keeps the state strain free.
    rigid_rotation<3>(file, "total Lagrangian", true, true);
    // Small strains see the rotation as a strain of order one.
    CHECK(rigid_rotation<2>(file, "small strain") > 1e3);
  }

  /** The strip of @p file (in 2D, or in 3D @p width wide and held in
   * plane strain) with @p imperfection appended. */
  template <int dim>
  void
  euler(const std::string &file,
        const std::string &imperfection,
        const double       width = 1)
  {
    // N_1 of the perfect strip on the same mesh.
    const auto linear = amfrac_test::run_scene<dim>(
      file,
      "set Kinematics = small strain\nsubsection Geometry\n"
      " set Imperfection =\n set Imperfection mode = 0\nend\n"
      "subsection Time\n set Number of steps = 1\n"
      "end\nsubsection Buckling\n set Number of modes = 1\nend\n"
      "subsection Output\n set Field format = none\nend\n");
    const double N_1
      = -linear->buckling_history()->value(0, "critical_reaction_x+_x") / width;

    const auto simulator = amfrac_test::run_scene<dim>(
      file,
      imperfection + "subsection Output\n set Field format = none\nend\n");
    const History    &history    = simulator->history();
    const std::string deflection = dim == 2 ? "p0_uy" : "p0_uz";
    const double      w0         = 0.01; // the imperfection at mid-span
    double            largest    = 0;
    unsigned int      past       = 0;
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        const double N = -history.value(r, "reaction_x+_x") / width;
        const double w = w0 + history.value(r, deflection);
        largest        = std::max(largest, N);
        if (w > 10 * w0)
          {
            ++past;
            CHECK_CLOSE(N / (N_1 * (1 - w0 / w)), 1., 5e-3);
          }
        CHECK(std::abs(history.value(r, "balance_error"))
              < 1e-3 * history.value(r, "strain_energy"));
      }
    const std::size_t last = history.n_rows() - 1;
    std::cout << "  N_1 = " << N_1 << " N/mm; largest N = " << largest
              << ", at the end N = "
              << -history.value(last, "reaction_x+_x") / width
              << " with w = " << w0 + history.value(last, deflection) << " mm; "
              << past << " steps past w = 10 w0" << std::endl;
    CHECK(largest < N_1);
    CHECK(largest > 0.99 * N_1);
    CHECK(past >= 10);
    CHECK(history.value(last, deflection) > 1.);
  }
  /** The first @p steps displacement steps of 0.5 up to t = 21 on the
   * delaminated panel, without the buckling analyses (which leave the path
   * alone), with the appended @p materials. (The imperfection's mode is
   * computed under the load at the End time, so another End time changes
   * the path in the last digits.) */
  std::unique_ptr<Simulator<2>>
  panel_run(const std::string &file,
            const unsigned int steps,
            const std::string &materials = "")
  {
    return amfrac_test::run_scene<2>(
      file,
      "subsection Output\n set Field format = none\nend\n"
      "subsection Time\n set End time = 21\n set Number of steps = 42\n"
      "end\n"
      "subsection Nonlinear solver\n set Control = displacement\n"
      " set Maximum steps = "
        + std::to_string(steps)
        + "\nend\n"
          "subsection Buckling\n set Number of modes = 0\n"
          " set Analysis times =\nend\n"
        + materials);
  }

  /** The delaminated panel to t = 21 (@p history): the sublaminate's
   * deflection passes ten times the imperfection across 0.9 times the
   * linear analysis' 184.1 N/mm, then the base bends the other way, the
   * delamination not grown. */
  void
  check_panel(const History &history)
  {
    const double initial = history.value(0, "debonded_i15");
    double       before = 0, after = 1e300;
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        const double N = -history.value(r, "reaction_x+_x");
        const double w = history.value(r, "p0_uy");
        // Up to 10 times the imperfection: not yet buckled.
        if (w < 0.05)
          before = std::max(before, N);
        else
          after = std::min(after, N);
        CHECK_CLOSE(history.value(r, "debonded_i15"), initial, 1e-9);
      }
    const std::size_t last = history.n_rows() - 1;
    std::cout << "  local buckling between " << before << " and " << after
              << " N/mm; at the end N = "
              << -history.value(last, "reaction_x+_x") << " N/mm, deflections "
              << history.value(last, "p0_uy") << " and "
              << history.value(last, "p1_uy") << " mm" << std::endl;
    // With a mode-shaped imperfection w0, w / w0 = 1 / (1 - N / N_cr)
    // before buckling: ten times w0 at 0.9 N_cr (166 N/mm), N_cr of the
    // small-strain analysis of this mesh.
    CHECK(before < 0.9 * 184.1 && after > 0.9 * 184.1 && after < 184.1);
    CHECK(history.value(last, "p0_uy") > 1.);
    CHECK(history.value(last, "p1_uy") < -0.5);
  }

  /** The panel past its limit load under opening control (see the file
   * header). */
  void
  panel_growth(const std::string &file)
  {
    const auto simulator = amfrac_test::run_scene<2>(
      file,
      "subsection Output\n set Field format = none\nend\n"
      "subsection Nonlinear solver\n set Maximum steps = 64\nend\n");
    const History    &h    = simulator->history();
    const std::size_t rows = h.n_rows();
    const auto        N
      = [&](const std::size_t r) { return -h.value(r, "reaction_x+_x"); };
    const double initial = h.value(0, "debonded_i15");
    std::size_t  peak = 0, growth = rows, path = rows;
    for (std::size_t r = 0; r < rows; ++r)
      {
        if (path == rows && h.value(r, "path_control") != 0)
          path = r;
        if (N(r) > N(peak))
          peak = r;
        if (growth == rows && h.value(r, "debonded_i15") > initial + 0.2)
          growth = r;
        // Contact: at most a hundredth of a ply thickness of overlap.
        CHECK(h.value(r, "min_opening_i15") > -0.01 * 0.127);
      }
    CHECK(growth < rows && path > 0 && path < rows);
    // The switch to opening control follows the fronts' own dissipation
    // (more than the Dissipation increment, 0.002 N mm, in the step
    // before), not the secant estimate, which the buckled panel's loss of
    // secant stiffness passes from t = 12 on (at 0.0017 N mm per step at
    // the fronts).
    CHECK(h.value(path - 1, "dissipated_i15")
            - (path > 1 ? h.value(path - 2, "dissipated_i15") : 0.)
          > 0.002);
    const std::size_t last = rows - 1;
    double            back = h.value(peak, "time");
    for (std::size_t r = peak; r < rows; ++r)
      back = std::min(back, h.value(r, "time"));
    const double grown = h.value(last, "debonded_i15") - initial;
    const double fracture
      = (h.value(last, "dissipated_i15") - h.value(growth, "dissipated_i15"))
        / (h.value(last, "debonded_i15") - h.value(growth, "debonded_i15"));
    const double balance = std::abs(h.value(last, "balance_error"))
                           / h.value(last, "external_work");
    std::cout << "  limit load " << N(peak) << " N/mm at "
              << 0.01 * h.value(peak, "time") << " mm; growth from "
              << N(growth) << " N/mm; grown " << grown
              << " mm; opening control from step " << path << " at "
              << N(path - 1) << " N/mm; t back to " << back << " of "
              << h.value(peak, "time") << "; " << fracture
              << " N/mm dissipated per mm; balance " << balance << std::endl;
    // The delamination grows at the limit load, not before or long after.
    CHECK(N(growth) > 0.98 * N(peak));
    CHECK(grown > 3.);
    // Displacement control cannot return: the path went back in t (by
    // 1.8 % in these steps, 4.9 % in the whole run).
    CHECK(back < 0.99 * h.value(peak, "time"));
    // Mixed-mode growth: between the mode I and mode II energies.
    CHECK(fracture > 0.3 && fracture < 0.8);
    CHECK(balance < 5e-3);
  }

  /** The first row of the plastic run @p p with a yielding point; every
   * row before it must equal the elastic run @p e's bit for bit (elastic
   * plies pay nothing: points that never yielded are not visited). */
  std::size_t
  first_yield_of_identical(const History &p, const History &e)
  {
    std::size_t first = 0;
    while (first < p.n_rows() && p.value(first, "yielding_points") == 0)
      {
        for (const auto &column : e.column_names())
          CHECK(p.value(first, column) == e.value(first, column));
        ++first;
      }
    return first;
  }

  /** The plastic strip (prm/plastic_strip_2d.prm) against the same strip
   * with elastic plies. */
  void
  plastic_strip(const std::string &file)
  {
    const std::string output
      = "subsection Output\n set Directory = output-plastic-strip\nend\n";
    const auto plastic = amfrac_test::run_scene<2>(file, output);
    const auto elastic = amfrac_test::run_scene<2>(
      file, output + "subsection Materials\n set Plasticity = none\nend\n");
    const History &p = plastic->history(), &e = elastic->history();
    // Identical, bit for bit, up to the first yield (elastic plies pay
    // nothing: points that never yielded are not visited).
    const std::size_t first = first_yield_of_identical(p, e);
    const std::size_t last  = p.n_rows() - 1;
    const auto        N     = [](const History &h, const std::size_t r) {
      return -h.value(r, "reaction_x+_x");
    };
    // Both end at the full shortening: the plastic strip carries less.
    CHECK(p.value(last, "time") == 1 && e.value(e.n_rows() - 1, "time") == 1);
    const double ratio = N(p, last) / N(e, e.n_rows() - 1);
    std::cout << "  first yield at step " << first + 1
              << " (t = " << p.value(first, "time") << "), N = " << N(p, first)
              << " N/mm; at the end N = " << N(p, last) << " N/mm against "
              << N(e, e.n_rows() - 1) << " N/mm elastic (ratio " << ratio
              << "), plastic work " << p.value(last, "plastic_work") << " of "
              << p.value(last, "external_work") << " N mm/mm" << std::endl;
    // It yields after buckling (the membrane stress is far below the
    // strengths), at some 5 mm of deflection.
    CHECK(first > 10 && first < last - 10);
    CHECK(p.value(first, "p0_uy") > 3);
    CHECK(ratio < 0.85);
    // The end force and plastic work of 400 elements along the length
    // (the scene has 100; 2026-12-03: 2.5452 N/mm, 3.6720 N mm/mm).
    CHECK(std::abs(N(p, last) / 2.5452 - 1) < 2e-3);
    CHECK(std::abs(p.value(last, "plastic_work") / 3.6720 - 1) < 2e-3);
    CHECK(N(p, last) < N(p, first));
    for (std::size_t r = 1; r <= last; ++r)
      CHECK(p.value(r, "max_equivalent_plastic_strain")
            >= p.value(r - 1, "max_equivalent_plastic_strain"));
    // A fifth of the work or more goes into plastic flow, and the balance
    // closes (to the trapezoidal rule's error on the nonlinear path, as in
    // the elastic run).
    CHECK(p.value(last, "plastic_work") > 0.2 * p.value(last, "external_work"));
    CHECK(amfrac_test::largest(p, "balance_error")
          < 1e-4 * p.value(last, "external_work"));
  }

  /** The delaminated panel with plastic plies (default strengths,
   * hardening 1) under displacement steps to t = 12, against the elastic
   * panel: the imperfection is the elastic state's buckling mode (allowed
   * with plastic plies), both runs agree bit for bit until the first
   * yield, which comes after the local buckling, at the delamination's
   * fronts where peel and interlaminar shear meet the Hoffman surface;
   * the plastic run balances its energy as the elastic one does. */
  void
  panel_plastic(const std::string &file)
  {
    const auto plastic = panel_run(file,
                                   24,
                                   "subsection Materials\n"
                                   " set Plasticity = hoffman\n"
                                   " set Hardening = 1\nend\n");
    // The elastic panel goes on to t = 21 for its own checks (panel).
    const auto     elastic = panel_run(file, 42);
    const History &p = plastic->history(), &e = elastic->history();
    CHECK(p.n_rows() == 24 && e.n_rows() == 42);
    check_panel(e);
    const std::size_t first = first_yield_of_identical(p, e);
    const std::size_t last  = p.n_rows() - 1;
    std::cout << "  first yield at t = " << p.value(first, "time")
              << ", N = " << -p.value(first, "reaction_x+_x")
              << " N/mm; at t = 12: " << p.value(last, "yielding_points")
              << " yielding points, plastic work "
              << p.value(last, "plastic_work")
              << ", N = " << -p.value(last, "reaction_x+_x") << " against "
              << -e.value(last, "reaction_x+_x") << " N/mm elastic"
              << std::endl;
    // Both meshes carry the imperfection (the identity above), and the
    // plies yield only after the sublaminate buckled.
    CHECK(first < last && -p.value(first, "reaction_x+_x") > 184.1);
    CHECK(p.value(last, "plastic_work") > 0);
    CHECK(amfrac_test::largest(p, "balance_error")
          < 1e-3 * p.value(last, "external_work"));
  }

  /** The plastic strip on a coarse mesh adapted during the load history
   * (ZZ of S, every 8 steps): the plastic history moves to each new mesh
   * (tau_1), kappa is never lowered, and the end force and plastic work
   * approach those of the uniform 400-element mesh with fewer cells. */
  void
  plastic_strip_adaptive(const std::string &file)
  {
    const auto run = amfrac_test::run_scene<2>(
      file,
      "subsection Geometry\n set Elements along length = 50\nend\n"
      "subsection Adaptivity\n set Refine every = 8\n"
      " set Refine fraction = 0.3\n set Maximum refinement level = 2\nend\n"
      "subsection Output\n set Directory = output-plastic-strip-adaptive\n"
      "end\n");
    const History    &h       = run->history();
    const History    *changes = run->adaptivity_history();
    const std::size_t last    = h.n_rows() - 1;
    CHECK(changes && changes->n_rows() >= 5);
    for (std::size_t r = 0; changes && r < changes->n_rows(); ++r)
      CHECK(changes->value(r, "max_equivalent_plastic_strain_after")
            == changes->value(r, "max_equivalent_plastic_strain_before"));
    const double cells
      = changes ? changes->value(changes->n_rows() - 1, "cells") : 0;
    const double force = -h.value(last, "reaction_x+_x");
    const double work  = h.value(last, "plastic_work");
    std::cout << "  adaptive: " << cells << " cells at the end, N = " << force
              << " N/mm, plastic work " << work << " N mm/mm, balance "
              << amfrac_test::largest(h, "balance_error") << std::endl;
    // The uniform 400-element mesh has 1,600 cells (plastic_strip).
    CHECK(cells < 1600);
    CHECK(std::abs(force / 2.5452 - 1) < 5e-3);
    CHECK(std::abs(work / 3.6720 - 1) < 1e-2);
    CHECK(amfrac_test::largest(h, "balance_error")
          < 1e-4 * h.value(last, "external_work"));
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                what = argc > 2 ? argv[1] : "";
  if (what == "rotation")
    rotation(argv[2]);
  else if (what == "rotation_sliding")
    rotation_sliding(argv[2]);
  else if (what == "euler")
    euler<2>(argv[2], "");
  else if (what == "euler_prism")
    // The scene's strip is 2 mm wide; its imperfection is its first mode.
    euler<3>(argv[2], "", 2);
  else if (what == "panel")
    check_panel(panel_run(argv[2], 42)->history());
  else if (what == "panel_growth")
    panel_growth(argv[2]);
  else if (what == "panel_plastic")
    panel_plastic(argv[2]);
  else if (what == "plastic_strip")
    plastic_strip(argv[2]);
  else if (what == "plastic_strip_adaptive")
    plastic_strip_adaptive(argv[2]);
  else if (what == "euler_mode")
    // The first buckling mode instead of its formula, with the same
    // largest displacement.
    euler<2>(argv[2],
             "subsection Geometry\n set Imperfection =\n"
             " set Imperfection mode = 1\n"
             " set Imperfection amplitude = 0.01\nend\n");
  else
    {
      std::cerr << "usage: app_total_lagrangian "
                   "rotation|rotation_sliding|euler|euler_mode|euler_prism|"
                   "panel|"
                   "panel_growth|panel_plastic|plastic_strip|"
                   "plastic_strip_adaptive FILE.prm"
                << std::endl;
      return 1;
    }
  return amfrac_test::failures;
}

// Contact between the laminate's bodies (issue 10) against known answers:
// - pressed: prm/contact_blocks.prm without shear (tau = 0): the contact
//   force is the applied p A = 40 N (1e-4), the faces penetrate by
//   p / Penalty (1 %) and never by more than 1.02 p / Penalty while the
//   load is ramped (measured 1.008), every one of the 9 + 9 face nodes
//   touches, the
//   balance closes to 1e-5 of the work (measured 1.0e-6, at the onset);
//   pressed_2d: the same in plane strain (p L = 20 N/mm, 3 + 3 nodes);
// - slide: tau = 6 MPa > mu p: the friction force is mu times the normal
//   force (1e-4), the top block slides at the speed where the mass
//   damping takes the rest, v = (tau - mu p) A / (alpha m) (1 %), friction
//   dissipates mu N v (1 %), balance 1e-5 of the work;
// - stick: tau = 1.5 MPa < mu p: the friction force is tau A (1 %), no
//   dissipation (1e-9 of the work: round-off of the stick springs'
//   energy), the block stops, balance 1e-5;
// - collision: prm/bar_collision.prm: the momentum stays m v (1e-12), the
//   contact ends at 2 L / c (within 4 %), then the top bar moves at v and
//   the bottom one is at rest (2 % of v), the kinetic energy comes back
//   to within 3 % (the rest rings in the bars), balance 1e-3; and the
//   kinetic energy at every output time is that of the bars as the 1D
//   chain they are (nu = 0, one element across), with the contact's
//   spring Penalty A, integrated alongside (chain_kinetic_energy()), to
//   1e-10 of the initial energy (measured 3.9e-14): the penalty's and the
//   mesh's loss, 0.83 % of the energy left ringing in the bars (with the
//   run's penalty 10 % lower than the chain's: 1.1e-3, fails).
// - fragments: prm/fragment_collision.prm: the middle bar of three breaks
//   at its middle cross-section and nowhere else (one crack face, four
//   bodies), its halves fly into the outer bars: contact happens and ends
//   by 2 (L / 2) / c (10 %), penetration at most twice that of a single
//   node arriving at v on its contact spring, v sqrt(rho h / (2 Penalty))
//   (1e-4 of the cell), the momentum stays zero (1e-12 of a half's m v),
//   balance within 2 % of the initial energy.
// - hairpin: prm/self_contact_hairpin_2d.prm (one body touching itself)
//   pressed in an explicit run, see hairpin().
// - stick_adaptive, slide_adaptive: stick and slide with the mesh adapting
//   every 2 output steps (ADAPTIVE, the text of tests/app/contact_adaptive.prm
//   is the fourth argument): the contact surfaces are refined (more than
//   the 18 nodes of the fixed mesh touch) and their stick springs move to
//   the new nodes by place. Stick: the friction force is tau A (1 %), the
//   block stays where it stands on the fixed mesh (10 %; measured 4.8 %,
//   the refined surfaces' stiffness), friction dissipates at most 3e-4 of
//   the work and never less than zero (measured 1.1e-4: the few slips
//   after the changes); with the springs lost at each change the block
//   moves 18 % further and friction dissipates 5e-3 of the work, and with
//   each old node's force kept whole at a new node's smaller stiffness the
//   dissipation goes below zero and ends at 6.6e-4 (both measured, both
//   fail). Slide: the same checks as on the fixed mesh. The balance holds
//   to 5e-3 of the work (measured 1.9e-3 and 2.4e-4: at each change the
//   mismatched surfaces of a refined block on an unrefined one ring on
//   their penalty springs).
// usage: app_body_contact
//   pressed|pressed_2d|slide|stick|collision|fragments|hairpin SCENE.prm
//   WORKDIR
//   stick_adaptive|slide_adaptive SCENE.prm WORKDIR ADAPTIVE.prm
#include "../check.h"
#include "scene.h"

#include <algorithm>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <sstream>
#include <vector>

using namespace amfrac;

// CHECK_CLOSE with a tolerance relative to the expected value.
#define CHECK_RELATIVE(value, expected, tol) \
  CHECK_CLOSE((value), (expected), (tol)*std::abs(expected))

namespace
{
  using amfrac_test::largest;

  const double p = 10, area = 4, penalty = 5e5, mu = 0.3, alpha = 4e6;
  const double density = 2.7e-9, modulus = 70000;

  std::string
  output_to(const std::string &workdir)
  {
    return "subsection Output\n  set Directory = " + workdir + "\nend\n";
  }

  std::string
  with_shear(const double tau, const std::string &workdir)
  {
    std::ostringstream text;
    text << "subsection Boundary conditions\n  set Function constants = p=" << p
         << ", tau=" << tau << "\nend\n"
         << output_to(workdir);
    return text.str();
  }

  /** The balance relative to the external work, over all rows. */
  double
  relative_balance(const History &h)
  {
    const std::size_t last = h.n_rows() - 1;
    return largest(h, "balance_error") / h.value(last, "external_work");
  }

  /** The balance bound of a fixed mesh and of one that adapts. */
  double
  balance_bound(const bool adaptive)
  {
    return adaptive ? 5e-3 : 1e-5;
  }

  /** An adaptive run refined the contact surfaces. */
  void
  check_refined(const History &h)
  {
    std::cout << "  adaptive: " << largest(h, "body_contact_nodes")
              << " nodes in contact at most, remeshing energy "
              << h.value(h.n_rows() - 1, "remeshing_energy") << " N mm"
              << std::endl;
    CHECK(largest(h, "body_contact_nodes") > 18);
  }

  void
  pressed(const std::string &scene, const std::string &workdir)
  {
    const auto simulator = amfrac_test::run_scene<3>(
      scene,
      with_shear(0, workdir)
        + "subsection Contact\n  set Friction coefficient = 0\nend\n");
    const History    &h    = simulator->history();
    const std::size_t last = h.n_rows() - 1;
    std::cout << "pressed: normal force "
              << h.value(last, "body_contact_normal_force")
              << " N, penetration " << h.value(last, "body_contact_penetration")
              << " mm, deepest " << largest(h, "body_contact_penetration")
              << " mm, nodes " << h.value(last, "body_contact_nodes")
              << ", balance " << relative_balance(h) << std::endl;
    CHECK_RELATIVE(h.value(last, "body_contact_normal_force"), p * area, 1e-4);
    CHECK(largest(h, "body_contact_penetration") <= 1.02 * p / penalty);
    CHECK_RELATIVE(h.value(last, "body_contact_penetration"),
                   p / penalty,
                   1e-2);
    CHECK(h.value(last, "body_contact_nodes") == 18);
    CHECK(relative_balance(h) < 1e-5);
  }

  /** The same in plane strain: the blocks stacked along y, the force per
   * unit thickness p L = 20 N/mm. */
  void
  pressed_2d(const std::string &scene, const std::string &workdir)
  {
    const std::string text
      = "set Dimension = 2\n"
        "subsection Boundary conditions\n"
        "  subsection z-\n    set Type = free\n  end\n"
        "  subsection z+\n    set Type = free\n  end\n"
        "  subsection y-\n    set Type = displacement\n  end\n"
        "  subsection y+\n    set Type = traction\n"
        "    set Traction = 0; -p*min(t/5e-6, 1)\n  end\n"
        "end\n"
        "subsection Contact\n  set Friction coefficient = 0\nend\n"
        "subsection Output\n  set Point values = 1, 2\nend\n";
    const auto simulator
      = amfrac_test::run_scene<2>(scene, with_shear(0, workdir) + text);
    const History    &h    = simulator->history();
    const std::size_t last = h.n_rows() - 1;
    std::cout << "pressed 2D: normal force "
              << h.value(last, "body_contact_normal_force")
              << " N/mm, penetration "
              << h.value(last, "body_contact_penetration") << " mm, nodes "
              << h.value(last, "body_contact_nodes") << ", balance "
              << relative_balance(h) << std::endl;
    CHECK_RELATIVE(h.value(last, "body_contact_normal_force"), p * 2, 1e-4);
    CHECK_RELATIVE(h.value(last, "body_contact_penetration"),
                   p / penalty,
                   1e-2);
    CHECK(h.value(last, "body_contact_nodes") == 6);
    CHECK(relative_balance(h) < 1e-5);
  }

  void
  slide(const std::string &scene,
        const std::string &workdir,
        const std::string &adaptive = "")
  {
    const double tau = 6;
    const auto   simulator
      = amfrac_test::run_scene<3>(scene, with_shear(tau, workdir) + adaptive);
    const History    &h    = simulator->history();
    const std::size_t last = h.n_rows() - 1, before = last - 4;
    const double      dt = h.value(last, "time") - h.value(before, "time");
    const double      speed
      = (h.value(last, "p0_ux") - h.value(before, "p0_ux")) / dt;
    const double expected   = (tau - mu * p) * area / (alpha * density * area);
    const double normal     = h.value(last, "body_contact_normal_force");
    const double friction   = h.value(last, "body_contact_friction_force");
    const double dissipated = (h.value(last, "friction_dissipation")
                               - h.value(before, "friction_dissipation"))
                              / dt;
    std::cout << "slide: friction " << friction << " N of mu N " << mu * normal
              << " N, speed " << speed << " mm/s of " << expected
              << ", dissipation rate " << dissipated << " of "
              << friction * speed << ", balance " << relative_balance(h)
              << std::endl;
    CHECK_RELATIVE(normal, p * area, 1e-3);
    CHECK_RELATIVE(friction, mu * normal, 1e-4);
    CHECK_RELATIVE(speed, expected, 1e-2);
    CHECK_RELATIVE(dissipated, friction * speed, 1e-2);
    CHECK(relative_balance(h) < balance_bound(!adaptive.empty()));
    if (!adaptive.empty())
      check_refined(h);
  }

  void
  stick(const std::string &scene,
        const std::string &workdir,
        const std::string &adaptive = "")
  {
    const double tau = 1.5;
    const auto   simulator
      = amfrac_test::run_scene<3>(scene, with_shear(tau, workdir) + adaptive);
    const History    &h    = simulator->history();
    const std::size_t last = h.n_rows() - 1, before = last - 4;
    const double      friction = h.value(last, "body_contact_friction_force");
    const double      moved = h.value(last, "p0_ux") - h.value(before, "p0_ux");
    std::cout << "stick: friction " << friction << " N of tau A " << tau * area
              << " N, dissipated " << largest(h, "friction_dissipation")
              << " N mm, last moved " << moved << " mm" << std::endl;
    CHECK_RELATIVE(friction, tau * area, 1e-2);
    // The last mesh changes move the adaptive run's block a little (4.5e-7
    // mm in its last 4 rows: 1.7e-3 of where it stands).
    CHECK(std::abs(moved) < (adaptive.empty() ? 1e-3 : 1e-2)
                              * std::abs(h.value(last, "p0_ux")));
    CHECK(relative_balance(h) < balance_bound(!adaptive.empty()));
    const double work = h.value(last, "external_work");
    if (adaptive.empty())
      {
        CHECK(largest(h, "friction_dissipation") < 1e-9 * work);
        return;
      }
    // Where the block stands on the fixed mesh.
    const auto fixed_run
      = amfrac_test::run_scene<3>(scene, with_shear(tau, workdir));
    const History &f     = fixed_run->history();
    const double   fixed = f.value(f.n_rows() - 1, "p0_ux");
    double         least = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      least = std::min(least, h.value(r, "friction_dissipation"));
    std::cout << "  stands at " << h.value(last, "p0_ux") << " mm, " << fixed
              << " on the fixed mesh; dissipated "
              << h.value(last, "friction_dissipation") / work
              << " of the work, least " << least << " N mm" << std::endl;
    check_refined(h);
    CHECK_RELATIVE(h.value(last, "p0_ux"), fixed, 0.1);
    CHECK(h.value(last, "friction_dissipation") < 3e-4 * work);
    CHECK(least > -1e-12 * work);
  }

  /** The two bars of prm/bar_collision.prm as the one-dimensional chain
   * they are (nu = 0, one element across: each layer of four nodes moves
   * as one): layers of mass rho A h (half at the ends) joined by springs
   * E A / h, the two contact layers by the contact's one-sided spring
   * Penalty A (its two passes, half each), integrated by the same central
   * differences with the run's step @p dt. Returns the kinetic energy at
   * every output time (@p outputs of @p substeps steps each). */
  std::vector<double>
  chain_kinetic_energy(const double       dt,
                       const unsigned int substeps,
                       const unsigned int outputs)
  {
    const unsigned int  cells = 20, layers = cells + 1;
    const double        h = 0.5, v = 1000, k = modulus / h;
    std::vector<double> mass(2 * layers, density * h), u(2 * layers, 0),
      velocity(2 * layers, 0), force(2 * layers, 0);
    for (const unsigned int end : {0u, layers - 1, layers, 2 * layers - 1})
      mass[end] *= 0.5;
    for (unsigned int i = 0; i < layers - 1; ++i)
      velocity[i] = v;
    velocity[layers - 1] = velocity[layers] = v / 2;
    const auto forces                       = [&]() {
      std::fill(force.begin(), force.end(), 0.);
      for (unsigned int bar = 0; bar < 2; ++bar)
        for (unsigned int i = bar * layers; i < (bar + 1) * layers - 1; ++i)
          {
            const double f = k * (u[i + 1] - u[i]);
            force[i] += f;
            force[i + 1] -= f;
          }
      const double overlap = u[layers - 1] - u[layers];
      if (overlap > 0)
        {
          force[layers - 1] -= penalty * overlap;
          force[layers] += penalty * overlap;
        }
    };
    const auto kinetic = [&]() {
      double e = 0;
      for (unsigned int i = 0; i < 2 * layers; ++i)
        e += 0.5 * mass[i] * velocity[i] * velocity[i];
      return e;
    };
    std::vector<double> energies{kinetic()};
    forces();
    for (unsigned int out = 0; out < outputs; ++out)
      {
        for (unsigned int s = 0; s < substeps; ++s)
          {
            for (unsigned int i = 0; i < 2 * layers; ++i)
              {
                velocity[i] += 0.5 * dt * force[i] / mass[i];
                u[i] += dt * velocity[i];
              }
            forces();
            for (unsigned int i = 0; i < 2 * layers; ++i)
              velocity[i] += 0.5 * dt * force[i] / mass[i];
          }
        energies.push_back(kinetic());
      }
    return energies;
  }

  void
  collision(const std::string &scene, const std::string &workdir)
  {
    const auto simulator = amfrac_test::run_scene<3>(scene, output_to(workdir));
    const History &h     = simulator->history();
    const double   v = 1000, length = 10, c = std::sqrt(modulus / density);
    const double   momentum = density * 1 * 2 * length / 2 * v;
    double         drift = 0, ends = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        drift = std::max(drift, std::abs(h.value(r, "momentum_z") - momentum));
        if (h.value(r, "body_contact_nodes") > 0)
          ends = h.value(r, "time");
      }
    const std::size_t last = h.n_rows() - 1, before = last - 20;
    const double      dt    = h.value(last, "time") - h.value(before, "time");
    const auto        speed = [&](const std::string &column) {
      return (h.value(last, column) - h.value(before, column)) / dt;
    };
    const double kinetic
      = h.value(last, "kinetic_energy") / h.value(0, "kinetic_energy");
    std::cout << "collision: momentum drift " << drift / momentum
              << ", contact until " << ends
              << " s (2 L / c = " << 2 * length / c << " s), top bar "
              << speed("p1_uz") << " mm/s, bottom bar " << speed("p0_uz")
              << " mm/s, kinetic energy back " << kinetic << ", balance "
              << largest(h, "balance_error") / h.value(0, "kinetic_energy")
              << std::endl;
    CHECK(drift < 1e-12 * momentum);
    CHECK_RELATIVE(ends, 2 * length / c, 4e-2);
    CHECK_RELATIVE(speed("p1_uz"), v, 2e-2);
    CHECK(std::abs(speed("p0_uz")) < 2e-2 * v);
    CHECK(kinetic > 0.97 && kinetic <= 1);
    CHECK(largest(h, "balance_error") < 1e-3 * h.value(0, "kinetic_energy"));
    // The kinetic energy that comes back is the chain's, whose rest rings
    // in the bars (the penalty spring and the mesh spread the wave): the
    // same step as the run (Safety factor 0.8, whole steps per output).
    const double       interval = 8e-6 / 160;
    const double       chosen   = 0.8 * simulator->estimated_stable_time_step();
    const unsigned int substeps = std::ceil(interval / chosen * (1 - 1e-12));
    const auto         chain
      = chain_kinetic_energy(interval / substeps, substeps, h.n_rows() - 1);
    double worst = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double gap = std::abs(h.value(r, "kinetic_energy") - chain[r]);
        // A NaN would pass std::max unseen.
        CHECK(std::isfinite(gap));
        worst = std::max(worst, gap);
      }
    std::cout << "  the chain's kinetic energy back " << chain.back() / chain[0]
              << ", largest difference " << worst / chain[0]
              << " of the initial energy" << std::endl;
    CHECK(h.n_rows() == 161);
    CHECK(chain.back() > 0.97 * chain[0] && chain.back() < chain[0]);
    CHECK(worst < 1e-10 * chain[0]);
  }

  void
  fragments(const std::string &scene, const std::string &workdir)
  {
    const auto simulator = amfrac_test::run_scene<3>(scene, output_to(workdir));
    const History &h     = simulator->history();
    const double   v = 1000, half = 2.5, c = std::sqrt(modulus / density);
    const double   momentum = density * 1 * half * v;
    double         drift = 0, ends = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        drift = std::max(drift, std::abs(h.value(r, "momentum_z")));
        if (h.value(r, "body_contact_nodes") > 0)
          ends = h.value(r, "time");
      }
    const std::size_t last = h.n_rows() - 1;
    // A node of a fragment (half a 0.5 mm cell's mass) arriving at v on
    // its contact spring (Penalty x its area, both passes) penetrates by
    // v sqrt(rho h / (2 Penalty)) before the bar behind it loads it.
    const double cell  = 0.5,
                 limit = 2 * v * std::sqrt(density * cell / (2 * penalty));
    const double balance
      = largest(h, "balance_error") / h.value(0, "kinetic_energy");
    std::cout << "fragments: " << h.value(last, "fragments")
              << " bodies, crack faces " << h.value(last, "crack_faces")
              << ", contact until " << ends << " s (L / c = " << 2 * half / c
              << " s), deepest " << largest(h, "body_contact_penetration")
              << " mm (limit " << limit << "), momentum drift "
              << drift / momentum << ", balance " << balance << std::endl;
    CHECK(h.value(last, "fragments") == 4);
    CHECK(h.value(last, "crack_faces") == 1);
    CHECK(largest(h, "body_contact_nodes") > 0);
    CHECK_RELATIVE(ends, 2 * half / c, 0.1);
    CHECK(largest(h, "body_contact_penetration") < limit);
    CHECK(drift < 1e-12 * momentum);
    CHECK(balance < 2e-2);
  }

  /** prm/self_contact_hairpin_2d.prm pressed in an explicit run: the
   * upper arm moved down by d over 20 us and held (the arms touch from
   * 17.6 us), with mass damping (3e6 / s, about a fifth of critical for
   * the arms' through-thickness mode) that brings the folded strip to rest by
   * 30 us (kinetic energy below 1e-12 of the work; measured 3e-17). At
   * rest it is in the state of the static run to 1e-6 (the lower and the
   * upper arm's inner faces at x = 5 mm, the contact force and the deepest
   * penetration; measured 1.4e-8, 8.6e-10, 1.4e-9, 7.2e-9), which is the
   * known answer of check_hairpin_pressed(); balance 1e-4 of the work
   * (measured 3.6e-5). On the matching mesh (the upper arm not shifted)
   * the two runs come to rest in different states (the deepest
   * penetrations 3.3e-4 apart): fails. */
  void
  hairpin(const std::string &scene, const std::string &workdir)
  {
    const std::string explicit_run
      = "subsection Materials\n  set Density = 2.7e-9\nend\n"
        "subsection Boundary conditions\n  subsection y-\n"
        "    set Displacement = 0; y > 0 ? -d*min(t/2e-5, 1) : 0\n"
        "  end\nend\n"
        "subsection Time\n  set Time integration = explicit\n"
        "  set End time = 3e-5\n  set Number of steps = 30\n"
        "  set Rayleigh mass damping = 3e6\nend\n";
    const auto explicit_simulator = amfrac_test::run_scene<2>(
      scene, explicit_run + output_to(workdir + "/explicit"));
    const auto static_simulator
      = amfrac_test::run_scene<2>(scene, output_to(workdir + "/static"));
    const History    &h    = explicit_simulator->history();
    const History    &s    = static_simulator->history();
    const std::size_t last = h.n_rows() - 1, pressed = 4;
    CHECK(s.value(pressed, "time") == 1);
    amfrac_test::check_hairpin_pressed(h, last);
    double worst = 0;
    for (const char *column : {"p0_uy",
                               "p1_uy",
                               "body_contact_normal_force",
                               "body_contact_penetration"})
      {
        const double a = h.value(last, column), b = s.value(pressed, column);
        std::cout << "hairpin: " << column << " explicit " << a << ", static "
                  << b << std::endl;
        worst = amfrac_test::worse(worst, std::abs(a - b) / std::abs(b));
      }
    const double work = largest(h, "external_work");
    std::cout << "hairpin: largest difference " << worst << ", kinetic energy "
              << h.value(last, "kinetic_energy") / work << ", balance "
              << relative_balance(h) << std::endl;
    CHECK(worst < 1e-6);
    CHECK(h.value(last, "kinetic_energy") < 1e-12 * work);
    CHECK(relative_balance(h) < 1e-4);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                which = argc > 1 ? argv[1] : "";
  const bool adaptive = which == "stick_adaptive" || which == "slide_adaptive";
  if (argc != (adaptive ? 5 : 4))
    {
      std::cerr
        << "usage: app_body_contact "
           "pressed|pressed_2d|slide|stick|collision|fragments|hairpin "
           "SCENE.prm "
           "WORKDIR\n       app_body_contact stick_adaptive|slide_adaptive "
           "SCENE.prm WORKDIR ADAPTIVE.prm"
        << std::endl;
      return 2;
    }
  try
    {
      if (which == "stick_adaptive")
        stick(argv[2], argv[3], amfrac_test::file_text(argv[4]));
      else if (which == "slide_adaptive")
        slide(argv[2], argv[3], amfrac_test::file_text(argv[4]));
      else if (which == "pressed")
        pressed(argv[2], argv[3]);
      else if (which == "pressed_2d")
        pressed_2d(argv[2], argv[3]);
      else if (which == "slide")
        slide(argv[2], argv[3]);
      else if (which == "stick")
        stick(argv[2], argv[3]);
      else if (which == "collision")
        collision(argv[2], argv[3]);
      else if (which == "fragments")
        fragments(argv[2], argv[3]);
      else if (which == "hairpin")
        hairpin(argv[2], argv[3]);
      else
        {
          std::cerr << "unknown case " << which << std::endl;
          return 2;
        }
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  return amfrac_test::summary();
}

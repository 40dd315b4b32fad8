// Coulomb friction between the rigid impactor and the laminate (issue 10):
// - flat: one 1 mm cell (nu = 0), its bottom held, pressed 0.01 mm by a
//   sphere of radius 1e4 mm that touches its four top corners together at
//   t = 0, then dragged 0.05 mm along x in 10 steps.
//   - Pressing: springs in series (1e-6), nothing dissipated.
//   - The first dragging step sticks (the block shears by less than the
//     slide): F_x < mu N, nothing dissipated, at most 8 Newton iterations
//     from the slipping trial state. The second starts sliding.
//   - From the third on, all four corners slide: each corner's friction
//     force is mu times its normal force (the sums to 1e-12), F_x = mu N
//     (1e-4: the sphere's normals lean by 7e-5 at the corners), a step
//     dissipates mu N times the slide (1e-4: the corners' gaps change by
//     x dx / R as the sphere moves), at most 2 Newton iterations.
//   - Every step: the bottom's shear reaction balances F_x (1e-8), and the
//     driver's work equals strain, contact and stick energy and
//     dissipation (balance, 1e-8 of the work; measured 7e-10).
// - slide: prm/sliding_cylinder_2d.prm, a cylinder pressed 0.03 mm into a
//   block in plane strain and dragged 0.05 mm.
//   - Pressing: the surface slides inwards under the contact, the edge
//     nodes slip; F_x within 1e-3 of mu N of zero (the mesh is graded
//     around the path, not the first contact point), the dissipation
//     below 1e-3 of the work.
//   - Dragging, partial slip (Cattaneo-Mindlin): the sliding nodes spread
//     from the edges as F_x grows, within 4 nodes of the half-space's
//     2 (a - c) / h with c = a sqrt(1 - F_x / (mu N)) (measured 1.4 to
//     3.6 more: the edge nodes slip under pressing alone);
//   - full sliding (from the sixth dragging step on): friction = mu times
//     the normal sums (1e-10), F_x within 2 % of mu N (measured 0.989:
//     the normals lean, the pressure shifts forward), a step dissipates
//     F_x times the slide (1 %).
//   - Every step: the bottom's shear reaction balances F_x (1e-6 of N),
//     at most 8 Newton iterations. The drag changes the balance by less
//     than 1e-4 of what it dissipates (measured 2.4e-6; the balance error
//     is the trapezoidal rule's on the pressing, 4 % of the first step's
//     work, 0.2 % of the work at 0.03).
// - slide_adaptive: the same on a mesh that adapts during the run (ZZ
//   after every step, the 5 % of the cells with the largest error, from 6
//   region refinements up to the scene's 8 levels; the stick springs move
//   to the new nodes by position): the mesh changes at every step (16
//   changes); in full sliding friction = mu times the normal sums (1e-10)
//   and F_x within 2 % of mu N; at the end F_x and the dissipation within
//   3 % of the graded scene's (measured -1.75 % and -1.8 %, the normal
//   force -1.7 %: with half the graded mesh's nodes in contact; refining
//   more, 26 nodes, gives -2.1 %: not traced further); the balance, with
//   the mesh changes' term, within twice the graded run's (the
//   trapezoidal rule's error of the pressing; measured 0.92 of it).
// usage: app_impactor_friction flat|slide|slide_adaptive SCENE.prm WORKDIR
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
  const double mu = 0.3;

  void
  flat(const std::string &prm, const std::string &workdir)
  {
    const double       R = 1e4, penalty = 1e6, d = 0.01, E = 70000;
    std::ostringstream text;
    text << amfrac_test::one_cell_under_sphere(R, penalty)
         << "subsection Boundary conditions\n  subsection z-\n"
         << "    set Components = x, y, z\n  end\n"
         << "  subsection x-\n    set Type = free\n  end\n"
         << "  subsection y-\n    set Type = free\n  end\nend\n"
         << "subsection Impactor\n  set Path = max(t - " << d
         << ", 0); 0; -min(t, " << d << ")"
         << "\n  set Friction coefficient = " << mu << "\nend\n"
         << "subsection Time\n  set End time = " << d + 0.05
         << "\n  set Number of steps = 12\nend\n"
         << amfrac_test::history_only(workdir);
    const auto     simulator = amfrac_test::run_scene<3>(prm, text.str());
    const History &h         = simulator->history();
    CHECK(h.n_rows() == 12);
    const double slide = 0.005; // per dragging step
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double t    = h.value(r, "time");
        const double N    = h.value(r, "contact_force");
        const double Fx   = h.value(r, "contact_force_x");
        const double D    = h.value(r, "impactor_friction_dissipation");
        const double work = h.value(r, "external_work");
        std::cout << "t = " << t << ": N " << N << ", F_x " << Fx
                  << ", sliding " << h.value(r, "sliding_nodes")
                  << ", dissipation " << D << ", balance "
                  << h.value(r, "balance_error") / work << " of the work, "
                  << h.value(r, "newton_iterations") << " iterations"
                  << std::endl;
        CHECK(h.value(r, "contact_nodes") == 4);
        CHECK(std::abs(h.value(r, "balance_error")) < 1e-8 * work);
        if (t <= d + 1e-12)
          {
            // Pressing: springs in series, nothing tangential.
            CHECK_CLOSE(N, t / (1 / E + 1 / penalty), 1e-6 * N);
            CHECK(std::abs(D) < 1e-12 * work);
            CHECK(h.value(r, "newton_iterations") <= 2);
            continue;
          }
        // The reaction of the held bottom balances the drag.
        CHECK_CLOSE(h.value(r, "reaction_z-_x"), -Fx, 1e-8 * N);
        if (t < d + slide + 1e-12)
          {
            CHECK(h.value(r, "sliding_nodes") == 0);
            CHECK(Fx < mu * N);
            CHECK(std::abs(D) < 1e-12 * work);
            CHECK(h.value(r, "newton_iterations") <= 8);
            continue;
          }
        if (t < d + 2 * slide + 1e-12)
          continue;
        CHECK(h.value(r, "newton_iterations") <= 2);
        CHECK(h.value(r, "sliding_nodes") == 4);
        CHECK_CLOSE(h.value(r, "friction_force_sum"),
                    mu * h.value(r, "pressure_force_sum"),
                    1e-12 * N);
        CHECK_CLOSE(Fx, mu * N, 1e-4 * mu * N);
        const double step = D - h.value(r - 1, "impactor_friction_dissipation");
        CHECK_CLOSE(step, mu * N * slide, 1e-4 * mu * N * slide);
      }
  }

  void
  cylinder(const std::string &prm, const std::string &workdir)
  {
    const auto simulator
      = amfrac_test::run_scene<2>(prm, amfrac_test::history_only(workdir));
    const History &h    = simulator->history();
    const double   cell = 5. / 256, E = 70000, nu = 0.3, R = 5;
    // Steps may be cut where the drag starts.
    CHECK(h.n_rows() >= 16u);
    unsigned int full_slides = 0, partial = 0;
    double       pressed_balance = 0, last_sliding = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double t       = h.value(r, "time");
        const double N       = h.value(r, "contact_force");
        const double Fx      = h.value(r, "contact_force_x");
        const double D       = h.value(r, "impactor_friction_dissipation");
        const double work    = h.value(r, "external_work");
        const double nodes   = h.value(r, "contact_nodes");
        const double sliding = h.value(r, "sliding_nodes");
        const double balance = h.value(r, "balance_error");
        std::cout << "t = " << t << ": N " << N << " N/mm, F_x / (mu N) "
                  << Fx / (mu * N) << ", " << sliding << " of " << nodes
                  << " nodes slide, dissipation " << D << ", balance "
                  << balance << " of " << work << " N mm, "
                  << h.value(r, "newton_iterations") << " iterations"
                  << std::endl;
        CHECK(h.value(r, "newton_iterations") <= 8);
        CHECK_CLOSE(h.value(r, "reaction_y-_x"), -Fx, 1e-6 * N);
        if (t <= 0.03 + 1e-12)
          {
            CHECK(std::abs(Fx) < 1e-3 * mu * N);
            CHECK(D >= 0 && D < 1e-3 * work);
            CHECK(std::abs(balance) < 0.05 * work);
            pressed_balance = balance;
            continue;
          }
        if (sliding < nodes)
          {
            // Cattaneo-Mindlin for the half-space: the stick zone shrinks
            // to c = a sqrt(1 - Q / (mu P)).
            ++partial;
            const double Es       = E / (1 - nu * nu);
            const double a        = std::sqrt(4 * N * R / (M_PI * Es));
            const double c        = a * std::sqrt(1 - Fx / (mu * N));
            const double expected = 2 * (a - c) / cell;
            std::cout << "  partial slip: " << sliding << " nodes slide, "
                      << expected << " by Mindlin" << std::endl;
            CHECK(Fx > 0 && Fx < mu * N);
            CHECK(std::abs(sliding - expected) <= 4);
            CHECK(sliding >= last_sliding);
            last_sliding = sliding;
            continue;
          }
        ++full_slides;
        CHECK_CLOSE(h.value(r, "friction_force_sum"),
                    mu * h.value(r, "pressure_force_sum"),
                    1e-10 * N);
        CHECK_CLOSE(Fx, mu * N, 0.02 * mu * N);
        const double step = D - h.value(r - 1, "impactor_friction_dissipation");
        const double slide = t - h.value(r - 1, "time");
        CHECK_CLOSE(step, Fx * slide, 0.01 * Fx * slide);
      }
    const std::size_t last = h.n_rows() - 1;
    const double      drag_balance
      = h.value(last, "balance_error") - pressed_balance;
    const double dissipated = h.value(last, "impactor_friction_dissipation");
    std::cout << full_slides << " steps of full sliding after " << partial
              << " of partial slip; the drag changed the balance by "
              << drag_balance << " N mm of " << dissipated << " dissipated"
              << std::endl;
    CHECK(partial >= 3);
    CHECK(full_slides >= 7);
    CHECK(std::abs(drag_balance) < 1e-4 * dissipated);
  }

  /** The sliding cylinder of @p prm on a mesh that adapts during the run,
   * against the scene's graded mesh. */
  void
  cylinder_adaptive(const std::string &prm, const std::string &workdir)
  {
    const auto [graded, adapted]
      = amfrac_test::graded_and_adapting(prm, workdir);
    const History &g = graded->history(), &a = adapted->history();
    const History *changes = adapted->adaptivity_history();
    CHECK(changes != nullptr && changes->n_rows() >= 10);
    unsigned int full_slides = 0;
    for (std::size_t r = 0; r < a.n_rows(); ++r)
      {
        const double N = a.value(r, "contact_force");
        if (a.value(r, "sliding_nodes") < a.value(r, "contact_nodes")
            || a.value(r, "time") <= 0.03 + 1e-12)
          continue;
        ++full_slides;
        CHECK_CLOSE(a.value(r, "friction_force_sum"),
                    mu * a.value(r, "pressure_force_sum"),
                    1e-10 * N);
        CHECK_CLOSE(a.value(r, "contact_force_x"), mu * N, 0.02 * mu * N);
      }
    const std::size_t ga = g.n_rows() - 1, aa = a.n_rows() - 1;
    const double      Fx   = a.value(aa, "contact_force_x"),
                 Fx_graded = g.value(ga, "contact_force_x");
    const double D         = a.value(aa, "impactor_friction_dissipation"),
                 D_graded  = g.value(ga, "impactor_friction_dissipation");
    const double work      = a.value(aa, "external_work");
    std::cout << "adaptive: " << (changes ? changes->n_rows() : 0)
              << " mesh changes, " << full_slides
              << " steps of full sliding; at the end F_x " << Fx
              << " N/mm (graded " << Fx_graded << "), dissipated " << D
              << " N mm (graded " << D_graded << "), balance "
              << a.value(aa, "balance_error") / work
              << " of the work, mesh changes' term "
              << a.value(aa, "remeshing_energy") / work << " of it"
              << std::endl;
    CHECK(g.value(ga, "time") == a.value(aa, "time"));
    CHECK(full_slides >= 5);
    CHECK_CLOSE(Fx, Fx_graded, 0.03 * Fx_graded);
    CHECK_CLOSE(D, D_graded, 0.03 * D_graded);
    CHECK(std::abs(a.value(aa, "balance_error"))
          < 2 * std::abs(g.value(ga, "balance_error")));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  CHECK(argc == 4);
  const std::string which = argv[1];
  if (which == "flat")
    flat(argv[2], argv[3]);
  else if (which == "slide")
    cylinder(argv[2], argv[3]);
  else if (which == "slide_adaptive")
    cylinder_adaptive(argv[2], argv[3]);
  else
    CHECK(false);
  std::cout << "OK" << std::endl;
  return 0;
}

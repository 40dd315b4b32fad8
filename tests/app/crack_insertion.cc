// Crack insertion by node duplication (prm/cracked_bar_2d.prm): a bar
// pulled along its transverse direction with one cross-section weakened to
// 0.9 Yt breaks exactly there, at 0.9 Yt; the crack softens the force to
// zero after Gc times its area is dissipated (2 %), the two halves are two
// fragments, and the ledger balances. Argument: 2 (the scene) or 3 (the
// same bar in 3D, 2 x 2 elements across); or beam (prm/cracked_beam_2d.prm,
// transverse cracks that reach a cohesive interface), or indented_beam
// (prm/indented_beam_2d.prm, the same beam pressed by a loading nose), or
// indented_beam_3d (its start in 2D and extruded to 3D); or friction (the
// bar's crack closed and sheared, with and without Coulomb friction).
#include "scene.h"

#include <algorithm>
#include <amfrac/postprocess/interface_output.h>
#include <cmath>
#include <fstream>
#include <sstream>

using namespace amfrac;
using amfrac_test::file_text;

namespace
{
  /** The crack points of all ranks on the section x = 2 and elsewhere. */
  template <int dim>
  std::pair<unsigned long, unsigned long>
  crack_points_at_section(const Simulator<dim> &simulator)
  {
    unsigned long on_section = 0, elsewhere = 0;
    for (const auto &p : simulator.interface_points())
      if (p.interface == InterfacePointRecord<dim>::crack)
        (std::abs(p.position[0] - 2) < 1e-9 ? on_section : elsewhere) += 1;
    return {Utilities::MPI::sum(on_section, MPI_COMM_WORLD),
            Utilities::MPI::sum(elsewhere, MPI_COMM_WORLD)};
  }

  template <int dim>
  void
  check_bar(const std::string &file, const std::string &appended)
  {
    const auto simulator = amfrac_test::run_scene<dim>(
      file, appended + "\nsubsection Output\n set Field format = none\nend\n");
    const History &history = simulator->history();
    const double   area    = 1; // 1 mm thick, unit width (2D) or 1 mm wide
    const double   Gc = 1, onset = 0.9 * 50;

    // Every crack point lies on the weakened cross-section, which is cut
    // through (2 faces in 2D, 2 x 2 in 3D).
    const auto [on_section, elsewhere] = crack_points_at_section(*simulator);
    CHECK(elsewhere == 0);
    CHECK(on_section == (dim == 2 ? 2u * 2 : 4u * 4));

    const std::size_t last = history.n_rows() - 1;
    CHECK(history.value(last, "crack_faces") == (dim == 2 ? 2 : 4));
    CHECK(history.value(0, "fragments") == 1);
    CHECK(history.value(last, "fragments") == 2);
    double peak = 0;
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        peak = std::max(peak, history.value(r, "reaction_x+_x"));
        // The ledger: external work = strain energy + interface work.
        CHECK(std::abs(history.value(r, "balance_error"))
              < 1e-9 * std::max(1., history.value(r, "external_work")));
      }
    // Onset within the tolerance of the step cut (index 1.02: 1 % in
    // stress), plus the transverse stresses of plane strain.
    CHECK_CLOSE(peak / (onset * area), 1., 0.015);
    CHECK(std::abs(history.value(last, "reaction_x+_x")) < 1e-8 * peak);
    CHECK_CLOSE(history.value(last, "dissipated_cracks") / (Gc * area),
                1.,
                0.02);
    // What the bar took is what the crack dissipated, less the little its
    // faces held at insertion (the offset law's T0^2 / 2K).
    CHECK_CLOSE(history.value(last, "external_work")
                  + history.value(last, "inserted_energy_cracks"),
                history.value(last, "dissipated_cracks"),
                1e-6);
  }
  /** The 2D bar of prm/cracked_bar_2d.prm broken in tension (t <= 1),
   * pushed back into compression (t <= 2) and its right half then moved
   * across the crack (t <= 3), both ends held in x and y: with Crack
   * insertion/Friction coefficient = mu the crack's faces slide with a
   * shear force mu times the normal force and dissipate mu |N| per mm of
   * slip; without friction they slide freely. */
  void
  check_friction(const std::string &file)
  {
    // Both ends held in x and y; the bottom face free, so that the right
    // half can move across the crack.
    const std::string path
      = "subsection Boundary conditions\n"
        " subsection x-\n"
        "  set Components = x, y\n"
        "  set Displacement = 0; 0\n"
        " end\n"
        " subsection x+\n"
        "  set Components = x, y\n"
        "  set Displacement = if(t < 1, 0.07*t, if(t < 2, 0.07 - 0.08*(t - "
        "1), -0.01)); if(t < 2, 0, 0.2*(t - 2))\n"
        " end\n"
        " subsection y-\n"
        "  set Type = free\n"
        " end\n"
        "end\n"
        "subsection Time\n"
        " set End time = 3\n"
        " set Number of steps = 105\n"
        "end\n"
        "subsection Output\n"
        " set Field format = none\n"
        "end\n";
    for (const double mu : {0.3, 0.})
      {
        const auto simulator = amfrac_test::run_scene<2>(
          file,
          path + "subsection Crack insertion\n set Friction coefficient = "
            + std::to_string(mu) + "\nend\n");
        const History    &history = simulator->history();
        const std::size_t last    = history.n_rows() - 1;
        CHECK_CLOSE(history.value(last, "time"), 3, 1e-12);
        CHECK(history.value(last, "crack_faces") == 2);
        const double normal = history.value(last, "reaction_x+_x");
        const double shear  = history.value(last, "reaction_x+_y");
        std::cout << "mu = " << mu << ": normal force " << normal
                  << " N/mm, shear force " << shear << " N/mm, friction "
                  << history.value(last, "friction_cracks") << " N"
                  << std::endl;
        // Compressed by about E2 * 0.01 / 4 = 25 MPa over the 1 mm section.
        CHECK(normal < -20);
        CHECK_CLOSE(std::abs(shear), mu * std::abs(normal), 1e-6 * 25);
        // In the last step the halves keep their shape (the force is at
        // the Coulomb limit), so the faces slip by what the end moved and
        // friction dissipates mu |N| times that.
        const double moved
          = 0.2
            * (history.value(last, "time") - history.value(last - 1, "time"));
        const double dissipated = history.value(last, "friction_cracks")
                                  - history.value(last - 1, "friction_cracks");
        CHECK_CLOSE(dissipated, mu * std::abs(normal) * moved, 1e-6);
        for (std::size_t r = 0; r < history.n_rows(); ++r)
          CHECK(std::abs(history.value(r, "balance_error"))
                < 1e-6 * std::max(1., history.value(r, "external_work")));
      }
  }

  /** prm/cracked_beam_2d.prm: the run finishes; cracks only in the
   * bottom 90-degree plies (y < 0.25), through-thickness (vertical faces);
   * interface 1 above them damaged where they meet it; the ledger
   * balances to 1e-4 of the external work. With indented
   * (prm/indented_beam_2d.prm, the nose a prescribed impactor): the same,
   * the ledger (with the nose's work and contact energy) at every step,
   * and the nose pushing at every step with a penetration the penalty
   * keeps small. */
  void
  check_beam(const std::string &file, const bool indented)
  {
    const auto simulator = amfrac_test::run_scene<2>(
      file, "subsection Output\n set Field format = none\nend\n");
    const History    &history = simulator->history();
    const std::size_t last    = history.n_rows() - 1;
    CHECK_CLOSE(history.value(last, "time"), 1., 1e-12);
    CHECK(history.value(last, "crack_faces") >= 40);
    unsigned long wrong_place = 0, cracks = 0;
    for (const auto &p : simulator->interface_points())
      if (p.interface == InterfacePointRecord<2>::crack)
        {
          ++cracks;
          if (p.position[1] > 0.25 + 1e-9)
            ++wrong_place;
        }
    CHECK(Utilities::MPI::sum(wrong_place, MPI_COMM_WORLD) == 0);
    CHECK(Utilities::MPI::sum(cracks, MPI_COMM_WORLD) > 0);
    CHECK(history.value(last, "damaged_i1") > 0.5);
    CHECK(history.value(last, "dissipated_cracks") > 0);
    // The ledger, and the work of the insertions: the new tractions are
    // balanced to the split copies (Crack insertion/Balance inserted
    // tractions), so insertion_energy holds only the converged steps'
    // Newton residual on those rows. Measured: balance 1.4e-5 and
    // 1.7e-5, insertion_energy -1.7e-5 and -1.5e-5 of the external work
    // (plain and indented beam); unbalanced, -6.5e-4 of it.
    CHECK(std::abs(history.value(last, "balance_error"))
          < 1e-4 * history.value(last, "external_work"));
    CHECK(std::abs(history.value(last, "insertion_energy"))
          < 5e-5 * history.value(last, "external_work"));
    if (!indented)
      return;
    // As many cracks as under the prescribed deflection (163 both).
    CHECK(history.value(last, "crack_faces") >= 150);
    // Without the nose's last force and centre carried over a crack
    // insertion, its work jumps by F . c at every insertion.
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        CHECK(std::abs(history.value(r, "balance_error"))
              < 1e-4 * history.value(r, "external_work"));
        CHECK(history.value(r, "contact_force") > 0);
        CHECK(history.value(r, "penetration") < 1e-3);
      }
    // The nose travels 1.5 mm from touching the top face at y = 1.
    CHECK_CLOSE(history.value(last, "impactor_position"), 1 - 1.5 + 5, 1e-12);
  }
  /** prm/indented_beam_2d.prm's first part (@p short_prm appended) in
   * 2D and extruded to 3D (0.5 mm wide, one element across, held in y on
   * both sides: plane strain; the nose a cylinder along y): at every step
   * the 3D run's nose force, external work and dissipation are half the
   * 2D ones per mm (1e-8 of each one's largest value), with the same crack
   * faces and Newton iterations: the static crack insertion with a prescribed
   * impactor in 3D regroups the cylinder's nodes as in 2D. */
  void
  check_indented_beam_extruded(const std::string &file,
                               const std::string &short_prm)
  {
    const std::string shortened = file_text(short_prm);
    const auto        flat      = amfrac_test::run_scene<2>(
      file, shortened + "subsection Output\n set Directory = output_2d\nend\n");
    const auto extruded = amfrac_test::run_scene<3>(
      file,
      shortened
        + "set Dimension = 3\n"
          "subsection Geometry\n set Width = 0.5\n"
          " set Elements along width = 1\nend\n"
          "subsection Boundary conditions\n"
          " subsection z-\n  set Type = displacement\n"
          "  set Components = z\n"
          "  set Where = abs(x - 1) < 1e-9 || abs(x - 23) < 1e-9\n end\n"
          " subsection x-\n  set Where = z < 1e-9\n end\n"
          " subsection y-\n  set Where =\n end\n"
          " subsection y+\n  set Type = displacement\n"
          "  set Components = y\n end\nend\n"
          "subsection Impactor\n set Face = z+\n set Shape = cylinder\n"
          " set Axis = 0, 1, 0\n set Center = 12, 0, 6\n"
          " set Velocity = 0, 0, -1.5\nend\n"
          "subsection Output\n set Directory = output_3d\nend\n");
    const History &a = flat->history(), &b = extruded->history();
    CHECK(a.n_rows() == b.n_rows());
    if (a.n_rows() != b.n_rows())
      return;
    const double width = 0.5;
    for (const std::string column :
         {"contact_force", "external_work", "dissipated_cracks"})
      {
        const double scale = width * amfrac_test::largest(a, column);
        CHECK(scale > 0);
        for (std::size_t r = 0; r < a.n_rows(); ++r)
          CHECK(std::abs(b.value(r, column) - width * a.value(r, column))
                <= 1e-8 * scale);
      }
    for (std::size_t r = 0; r < a.n_rows(); ++r)
      {
        CHECK_CLOSE(b.value(r, "time"), a.value(r, "time"), 1e-12);
        CHECK(b.value(r, "crack_faces") == a.value(r, "crack_faces"));
        CHECK(b.value(r, "newton_iterations")
              == a.value(r, "newton_iterations"));
      }
    CHECK(a.value(a.n_rows() - 1, "crack_faces") >= 30);
  }
  /** The bar in explicit dynamics (tests/app/explicit_cracked_bar.prm
   * appended): it breaks at x = 2 only, into two fragments, after Gc
   * times the area is dissipated (2 %); the energy of every insertion
   * event is continuous (kinetic + strain + interface work before and
   * after, 1e-6 of the energy given to the bar) and the ledger balances
   * to 1e-4 of it over the whole run. */
  template <int dim>
  void
  check_explicit_bar(const std::string &file,
                     const std::string &appended,
                     const std::string &explicit_prm)
  {
    const auto simulator
      = amfrac_test::run_scene<dim>(file,
                                    appended + "\n" + file_text(explicit_prm));
    const History &history = simulator->history();
    const double   area = 1, Gc = 1;

    const auto [on_section, elsewhere] = crack_points_at_section(*simulator);
    CHECK(elsewhere == 0);
    CHECK(on_section == (dim == 2 ? 2u * 2 : 4u * 4));
    const std::size_t last = history.n_rows() - 1;
    CHECK(history.value(0, "fragments") == 1);
    CHECK(history.value(last, "fragments") == 2);
    CHECK_CLOSE(history.value(last, "dissipated_cracks") / (Gc * area),
                1.,
                0.02);
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      CHECK(std::abs(history.value(r, "balance_error"))
            < 1e-4 * std::max(0.1, history.value(r, "external_work")));

    const History *events = simulator->crack_history();
    CHECK(events != nullptr);
    if (events == nullptr)
      return;
    CHECK(events->n_rows() >= 1);
    double faces = 0;
    for (std::size_t r = 0; r < events->n_rows(); ++r)
      {
        faces += events->value(r, "faces");
        // Cracks start where the index first reaches 1 (the step is short
        // against the loading).
        CHECK(events->value(r, "hoffman") < 1.01);
        CHECK(std::abs(events->value(r, "energy_jump")) < 1e-6);
        CHECK(std::abs(events->value(r, "energy_after")
                       - events->value(r, "energy_before"))
              < 1e-6 * events->value(r, "energy_before"));
      }
    CHECK(faces == history.value(last, "crack_faces"));
  }
  /** Appended to a scene: Crack insertion/Balance inserted tractions. */
  std::string
  balance_switch(const bool balanced)
  {
    return std::string("\nsubsection Crack insertion\n set Balance inserted "
                       "tractions = ")
           + (balanced ? "true" : "false") + "\nend\n";
  }

  /** Insertion event @p r of @p events: the residual on the new points'
   * rows after the balance is below 1e-9 of what it was before. */
  void
  check_balanced_event(const History &events, const std::size_t r)
  {
    const double before = events.value(r, "residual_before");
    const double after  = events.value(r, "residual_after");
    std::cout << "  residual on the new points' rows " << before
              << " N, balanced " << after << " N" << std::endl;
    CHECK(after < 1e-9 * before);
  }

  /** The bar under a loading nose with friction
   * (tests/app/cracked_bar_nose.prm appended), statically: the section
   * x = 2 cracks (its two faces, nowhere else) and the node under the nose
   * splits into two copies that touch it with friction. The ledger
   * balances to 2e-6 of the external work at every step. A crack starts
   * from its points' stress, which does not balance the bulk's nodal
   * forces where the stress varies; with @p balanced (the default) the
   * new tractions are corrected until the split copies are in balance,
   * and the insertions do no work (insertion_energy below 1e-9 of the
   * work; measured 1e-12 N mm); without, the work of the out-of-balance
   * forces is booked as insertion_energy (measured -0.070 of 1.63 N mm).
   * Returns the time of the second insertion. */
  double
  check_bar_nose(const std::string &file,
                 const std::string &nose_prm,
                 const bool         balanced)
  {
    const auto simulator = amfrac_test::run_scene<2>(
      file, "\n" + file_text(nose_prm) + balance_switch(balanced));
    const History    &history          = simulator->history();
    const std::size_t last             = history.n_rows() - 1;
    const auto [on_section, elsewhere] = crack_points_at_section(*simulator);
    CHECK(elsewhere == 0);
    CHECK(on_section == 2u * 2);
    // The nose's friction holds the halves together at the end: the crack
    // has not dissipated all of Gc x area (1 N mm) yet.
    CHECK(history.value(last, "dissipated_cracks") > 0.5);
    double most_work = 0, touching = 0, rubbing = 0;
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        most_work = std::max(most_work, history.value(r, "external_work"));
        touching  = std::max(touching, history.value(r, "contact_nodes"));
        rubbing   = std::max(rubbing, history.value(r, "friction_force_sum"));
        CHECK(std::abs(history.value(r, "balance_error"))
              < 2e-6 * std::max(1., most_work));
      }
    const double booked = history.value(last, "insertion_energy");
    std::cout << (balanced ? "balanced" : "as the stress is")
              << ": insertion energy " << booked << " of " << most_work
              << " N mm; up to " << touching << " copies touch" << std::endl;
    CHECK(touching == 2);
    CHECK(rubbing > 0);
    if (balanced)
      CHECK(std::abs(booked) < 1e-9 * most_work);
    else
      CHECK(booked < -0.01 * most_work && -booked < 0.1 * most_work);
    // The nose rebuilt on the regrouped copies pushes the converged state
    // as before each insertion: the copies of the split node share its
    // friction (each taking the whole force: off by 4.1 N, checked).
    const History *events = simulator->crack_history();
    CHECK(events != nullptr && events->n_rows() == 2);
    for (std::size_t r = 0; events && r < events->n_rows(); ++r)
      {
        std::cout << "insertion at t = " << events->value(r, "time")
                  << ": the nose's force changes by "
                  << events->value(r, "impactor_force_jump") << " N"
                  << std::endl;
        CHECK(events->value(r, "impactor_force_jump") < 1e-10 * rubbing);
        if (balanced)
          {
            CHECK(events->value(r, "residual_before") > 1);
            check_balanced_event(*events, r);
          }
      }
    return events && events->n_rows() == 2 ? events->value(1, "time") : 0;
  }
  /** The nose scene of check_bar_nose() with Q2 elements (three points per
   * crack face, two least-squares iterations): balanced, the two events'
   * residuals on the new points' rows fall below 1e-9 of what they were
   * (measured 7.6 N to 1.1e-11 N, 1.1 N to 3e-14 N) and the insertions do
   * no work (measured -3.2e-13 of 1.36 N mm); as the stress is, they book
   * -4.1e-3 N mm. (Its ledger closes to 6.5e-4 N mm only, from the first
   * contact steps on, before any crack: a Q2 matter of the nose, not of
   * the insertion, so not checked here.) */
  void
  check_bar_nose_q2(const std::string &file, const std::string &nose_prm)
  {
    for (const bool balanced : {true, false})
      {
        const auto simulator = amfrac_test::run_scene<2>(
          file,
          "\n" + file_text(nose_prm)
            + "\nsubsection Discretization\n set Finite element degree = "
              "2\nend\n"
            + balance_switch(balanced));
        const History    &history = simulator->history();
        const std::size_t last    = history.n_rows() - 1;
        const double      booked  = history.value(last, "insertion_energy");
        const double      work    = history.value(last, "external_work");
        const History    *events  = simulator->crack_history();
        CHECK(events != nullptr && events->n_rows() == 2);
        std::cout << "Q2, " << (balanced ? "balanced" : "as the stress is")
                  << ": insertion energy " << booked << " of " << work
                  << " N mm" << std::endl;
        if (!balanced)
          {
            CHECK(booked < -1e-3 * work);
            continue;
          }
        CHECK(std::abs(booked) < 1e-9 * work);
        for (std::size_t r = 0; events && r < events->n_rows(); ++r)
          check_balanced_event(*events, r);
      }
  }
  /** The bar in explicit dynamics under a falling blunt striker with
   * friction (tests/app/explicit_cracked_bar_sphere.prm appended to
   * tests/app/explicit_cracked_bar.prm): cracks reach the top face under
   * the striker and split nodes it touches (more copies touch it than the
   * top face has nodes); the energy of every insertion event is
   * continuous (1e-6, with the contact energy and the stick springs'),
   * the striker rubs (friction forces and dissipation), and the ledger
   * balances to 1e-4 of the energy given (the striker's and the pull's). */
  void
  check_explicit_bar_sphere(const std::string &file,
                            const std::string &explicit_prm,
                            const std::string &sphere_prm)
  {
    const auto simulator = amfrac_test::run_scene<2>(
      file, file_text(explicit_prm) + "\n" + file_text(sphere_prm));
    const History    &history = simulator->history();
    const std::size_t last    = history.n_rows() - 1;
    CHECK(history.value(last, "fragments") == 2);
    // 0.5 m/s and 4e-6 t: 0.5 N mm.
    const double striker   = 0.5 * 4e-6 * 500 * 500;
    double       most_work = 0, rubbing = 0, touching = 0;
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        most_work = std::max(most_work, history.value(r, "external_work"));
        rubbing   = std::max(rubbing, history.value(r, "friction_force_sum"));
        touching  = std::max(touching, history.value(r, "contact_nodes"));
        CHECK(std::abs(history.value(r, "balance_error"))
              < 1e-4 * (striker + most_work));
      }
    std::cout << "up to " << touching << " copies touch, friction up to "
              << rubbing << " N, dissipation "
              << history.value(last, "impactor_friction_dissipation") << " N mm"
              << std::endl;
    // 9 nodes on the top face (8 elements along x).
    CHECK(touching > 9);
    CHECK(rubbing > 0);
    CHECK(history.value(last, "impactor_friction_dissipation") > 0);
    const History *events = simulator->crack_history();
    CHECK(events != nullptr && events->n_rows() >= 2);
    for (std::size_t r = 0; events && r < events->n_rows(); ++r)
      CHECK(std::abs(events->value(r, "energy_after")
                     - events->value(r, "energy_before"))
            < 1e-6 * events->value(r, "energy_before"));
  }
  /** prm/fragmenting_plate.prm, the stress test: more than 1000 faces
   * inserted, the fragments never fewer from one row to the next and at
   * least 5 at the end, energy continuous at every insertion event, the
   * ledger balanced to 1e-3 of the initial kinetic energy, and every fully
   * debonded crack area has dissipated Gc. */
  void
  check_fragmentation(const std::string &file)
  {
    const auto simulator = amfrac_test::run_scene<3>(
      file, "subsection Output\n set Field format = none\nend\n");
    const History    &history = simulator->history();
    const std::size_t last    = history.n_rows() - 1;
    const double      Gc = 0.3, initial = history.value(0, "kinetic_energy");
    CHECK(history.value(last, "crack_faces") > 1000);
    CHECK(history.value(last, "fragments") >= 5);
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      {
        if (r > 0)
          CHECK(history.value(r, "fragments")
                >= history.value(r - 1, "fragments"));
        CHECK(std::abs(history.value(r, "balance_error")) < 1e-3 * initial);
      }
    CHECK(history.value(last, "dissipated_cracks")
          >= Gc * history.value(last, "debonded_cracks") * (1 - 1e-6));
    const History *events = simulator->crack_history();
    CHECK(events != nullptr && events->n_rows() > 1);
    for (std::size_t r = 0; events && r < events->n_rows(); ++r)
      CHECK(std::abs(events->value(r, "energy_jump")) < 1e-6);
  }
  /** The largest jump of the displacement across the intact interior
   * faces of the locally owned cells, at the face centres (seen from the
   * finer side of a hanging face), over the largest displacement. */
  template <int dim>
  double
  intact_face_jump(const Simulator<dim> &simulator)
  {
    const auto &handler = simulator.dofs().copy_handler();
    const auto &fe      = simulator.dofs().get_fe();
    const auto &copies  = simulator.copy_solution();
    const auto  value   = [&](const auto &cell, const Point<dim> &x) {
      const Point<dim> unit
        = simulator.dofs().get_mapping().transform_real_to_unit_cell(cell, x);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      cell->get_dof_indices(dofs);
      Tensor<1, dim> u;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        u[fe.system_to_component_index(i).first]
          += copies(dofs[i]) * fe.shape_value(i, unit);
      return u;
    };
    const auto *interfaces = simulator.cohesive_interfaces();
    const auto  released   = interfaces->released_faces();
    double      jump = 0, largest = 0;
    for (const auto &cell : handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            const Point<dim> centre = cell->face(f)->center();
            largest = std::max(largest, value(cell, centre).norm());
            if (cell->at_boundary(f) || cell->neighbor(f)->has_children()
                || released(cell, f))
              continue;
            jump = std::max(
              jump,
              (value(cell, centre) - value(cell->neighbor(f), centre)).norm());
          }
    return jump / largest;
  }

  /** The bar with tests/app/crack_refinement.prm appended: the crack
   * inserted inside a refined region survives refinement and coarsening
   * around it (still exactly the section x = 2, 1 mm long, softening to
   * Gc times its area: the force through the bar never rises again after
   * the insertion), the mesh changes after the insertion (refined and
   * coarsened), and no intact face opens. In 3D without the Refinement
   * region (refused there with refinement during the history). */
  template <int dim>
  void
  check_refined_bar(const std::string &file,
                    const std::string &extra,
                    const std::string &appended)
  {
    const auto simulator
      = amfrac_test::run_scene<dim>(file, file_text(extra) + "\n" + appended);
    const History    &history = simulator->history();
    const std::size_t last    = history.n_rows() - 1;

    const auto [on_section, elsewhere] = crack_points_at_section(*simulator);
    CHECK(elsewhere == 0);
    CHECK(on_section >= 4);
    CHECK_CLOSE(history.value(last, "debonded_cracks"), 1., 1e-9);
    CHECK_CLOSE(history.value(last, "dissipated_cracks"), 1., 0.02);
    CHECK(history.value(last, "fragments") == 2);

    // After the peak the force only falls (a crack lost in a mesh change
    // would tie the bar again and the force would jump up), to zero.
    std::size_t first = last, at_peak = 0;
    for (std::size_t r = 0; r < history.n_rows() && first == last; ++r)
      if (history.value(r, "crack_faces") > 0)
        first = r;
    CHECK(first < last);
    for (std::size_t r = 0; r < history.n_rows(); ++r)
      if (history.value(r, "reaction_x+_x")
          > history.value(at_peak, "reaction_x+_x"))
        at_peak = r;
    const double peak = history.value(at_peak, "reaction_x+_x");
    CHECK_CLOSE(peak, 45, 0.03 * 45);
    for (std::size_t r = at_peak + 1; r < history.n_rows(); ++r)
      CHECK(history.value(r, "reaction_x+_x")
            <= history.value(r - 1, "reaction_x+_x") + 1e-6 * peak);
    CHECK(std::abs(history.value(last, "reaction_x+_x")) < 1e-8 * peak);

    // Mesh changes after the insertion, refining and coarsening (fewer
    // cells or fewer unknowns than before a change: refinement and
    // insertion only add).
    const History *changes = simulator->adaptivity_history();
    CHECK(changes != nullptr);
    const double crack_time = history.value(first, "time");
    bool         refined = false, coarsened = false;
    double       cells = -1, unknowns = -1;
    for (std::size_t r = 0; changes && r < changes->n_rows(); ++r)
      {
        const double now  = changes->value(r, "cells");
        const double dofs = changes->value(r, "unknowns");
        if (changes->value(r, "t") >= crack_time && cells >= 0)
          {
            refined   = refined || now > cells;
            coarsened = coarsened || now < cells || dofs < unknowns;
          }
        cells    = now;
        unknowns = dofs;
      }
    CHECK(refined);
    CHECK(coarsened);
    const double jump = intact_face_jump(*simulator);
    std::cout << "largest jump across an intact face: " << jump
              << " of the largest displacement" << std::endl;
    CHECK(jump < 1e-12);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                case_name = argv[1];
  const std::string                bar_3d    = "set Dimension = 3\n"
                                               "subsection Geometry\n set Width = 1\n"
                                               " set Elements along width = 2\nend\n"
                                               "subsection Boundary conditions\n subsection z-\n"
                                               "  set Type = displacement\n  set Components = z\n"
                                               "  set Displacement = 0\n end\nend\n";
  if (case_name == "2")
    check_bar<2>(argv[2], "");
  else if (case_name == "shared_support")
    check_bar<2>(argv[2], file_text(argv[3]));
  else if (case_name == "nose")
    {
      // The balance moves the second insertion (the first face's corrected
      // tractions load the second differently): measured t = 0.3714
      // against 0.3607 (the step is 0.0036).
      const double balanced  = check_bar_nose(argv[2], argv[3], true);
      const double as_stress = check_bar_nose(argv[2], argv[3], false);
      CHECK(std::abs(balanced - as_stress) < 0.05);
      check_bar_nose_q2(argv[2], argv[3]);
    }
  else if (case_name == "beam")
    check_beam(argv[2], false);
  else if (case_name == "indented_beam")
    check_beam(argv[2], true);
  else if (case_name == "indented_beam_3d")
    check_indented_beam_extruded(argv[2], argv[3]);
  else if (case_name == "friction")
    check_friction(argv[2]);
  else if (case_name == "refined_2")
    check_refined_bar<2>(argv[2], argv[3], "");
  else if (case_name == "refined_3")
    // In 3D the adaptivity refines along the plies only, and the
    // Refinement region (which cuts through the thickness) is refused.
    check_refined_bar<3>(argv[2],
                         argv[3],
                         bar_3d
                           + "subsection Geometry\n set Refinement region "
                             "=\nend\n");
  else if (case_name == "fragmentation")
    check_fragmentation(argv[2]);
  else if (case_name == "explicit_sphere")
    check_explicit_bar_sphere(argv[2], argv[3], argv[4]);
  else if (case_name == "explicit_2")
    check_explicit_bar<2>(argv[2], "", argv[3]);
  else if (case_name == "explicit_3")
    check_explicit_bar<3>(argv[2], bar_3d, argv[3]);
  else
    check_bar<3>(argv[2], bar_3d);
  return amfrac_test::summary();
}

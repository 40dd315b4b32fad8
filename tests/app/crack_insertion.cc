// Crack insertion by node duplication (prm/cracked_bar_2d.prm): a bar
// pulled along its transverse direction with one cross-section weakened to
// 0.9 Yt breaks exactly there, at 0.9 Yt; the crack softens the force to
// zero after Gc times its area is dissipated (2 %), the two halves are two
// fragments, and the ledger balances. Argument: 2 (the scene) or 3 (the
// same bar in 3D, 2 x 2 elements across); or beam (prm/cracked_beam_2d.prm,
// transverse cracks that reach a cohesive interface).
#include "scene.h"

#include <algorithm>
#include <amfrac/postprocess/interface_output.h>
#include <cmath>
#include <fstream>
#include <sstream>

using namespace amfrac;

namespace
{
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
    unsigned long on_section = 0, elsewhere = 0;
    for (const auto &p : simulator->interface_points())
      if (p.interface == InterfacePointRecord<dim>::crack)
        (std::abs(p.position[0] - 2) < 1e-9 ? on_section : elsewhere) += 1;
    on_section = Utilities::MPI::sum(on_section, MPI_COMM_WORLD);
    elsewhere  = Utilities::MPI::sum(elsewhere, MPI_COMM_WORLD);
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
  /** prm/cracked_beam_2d.prm: the run finishes; cracks only in the
   * bottom 90-degree plies (y < 0.25), through-thickness (vertical faces);
   * interface 1 above them damaged where they meet it; the ledger
   * balances to 1 % of the external work. */
  void
  check_beam(const std::string &file)
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
    CHECK(std::abs(history.value(last, "balance_error"))
          < 0.01 * history.value(last, "external_work"));
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
    std::ifstream     in(explicit_prm);
    std::stringstream text;
    text << in.rdbuf();
    const auto simulator
      = amfrac_test::run_scene<dim>(file, appended + "\n" + text.str());
    const History &history = simulator->history();
    const double   area = 1, Gc = 1;

    unsigned long on_section = 0, elsewhere = 0;
    for (const auto &p : simulator->interface_points())
      if (p.interface == InterfacePointRecord<dim>::crack)
        (std::abs(p.position[0] - 2) < 1e-9 ? on_section : elsewhere) += 1;
    CHECK(Utilities::MPI::sum(elsewhere, MPI_COMM_WORLD) == 0);
    CHECK(Utilities::MPI::sum(on_section, MPI_COMM_WORLD)
          == (dim == 2 ? 2u * 2 : 4u * 4));
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
  else if (case_name == "beam")
    check_beam(argv[2]);
  else if (case_name == "fragmentation")
    check_fragmentation(argv[2]);
  else if (case_name == "explicit_2")
    check_explicit_bar<2>(argv[2], "", argv[3]);
  else if (case_name == "explicit_3")
    check_explicit_bar<3>(argv[2], bar_3d, argv[3]);
  else
    check_bar<3>(argv[2], bar_3d);
  return amfrac_test::summary();
}

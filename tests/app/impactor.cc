// The rigid impactor (issue 10, first step) on prm/impact_plate_sphere.prm
// (a quarter model, a steel sphere of 5 mm radius at 10 m/s):
// - wall: every node of a 10 x 10 mm plate held, 1 mm cells: only the
//   corner node under the sphere's path touches it, a single spring of
//   k = Penalty * h^2 / 4, so the contact is a harmonic oscillator:
//   largest penetration v sqrt(m / k) and force v sqrt(m k) within 1 %,
//   contact for pi sqrt(m / k) within 2 %, rebound at the impact speed
//   within 1 % (elastic), energy balance within 1 % of the sphere's energy;
// - wall_cylinder: the same held plate struck by a cylinder along y
//   (Shape = cylinder) above the edge x = 0: the 11 nodes of that edge
//   touch together, two corners of h^2 / 4 and nine of h^2 / 2, a single
//   spring k = 5 Penalty h^2 with the same checks (and 11 nodes);
// - free: the same plate free to move along z (only the symmetry planes
//   held): the momentum of plate and sphere together stays that of t = 0
//   to 1e-9, the balance closes to 1 % of the initial energy, and the
//   sphere slows while the plate takes its momentum;
// - scene: tests/app/impactor_coarse.prm (20 x 20 cells, 20 us) on the
//   clamped plate with its two cohesive interfaces: the balance within 2 %
//   of the sphere's energy, contact, the sphere slowed.
// - scene_unbonded: the scene with its mid-plane released
//   (tests/app/impactor_unbonded.prm appended): the sphere strikes the top
//   half, which presses the bottom half through contact between the
//   bodies. The balance within 2 % of the sphere's energy (measured
//   1.4e-5), the halves touch (up to 104 nodes, 43 N), their penetration
//   below that of the sphere's whole force on one cell's area (measured
//   0.70 of it), the sphere's force below (150 N against 205 N) and the
//   plate's centre deeper (0.161 mm against 0.133 mm) than the bonded
//   plate's: the halves bend on their own.
// - wall_2d: the same in a 2D cross-section, where the sphere is a cylinder
//   (per unit width) and the corner node's spring k = Penalty * h / 2.
// - oblique_2d: a cylinder (free in every direction: Guided = false)
//   strikes a block of 10 x 2 mm held at its bottom at 45 degrees, with
//   friction mu = 0.3 and without: the balance with the friction's
//   dissipation closes within 1 % of the cylinder's energy; with friction
//   it dissipates and the tangential impulse is at most mu times the
//   normal one (its sliding nodes each at mu times their normal force; the
//   impulses from the cylinder's momentum), the cylinder leaves slower
//   along x than without friction, which changes its x velocity by less
//   than 5 % of the change with friction.
// - prescribed: prm/impact_plate_striker.prm (a tup of 8 mm radius driven
//   at 3 m/s: Motion = prescribed, its centre Center + Velocity t) with
//   tests/app/impactor_coarse.prm, against the same tup free with a mass
//   of 1 t (it keeps its speed to 1e-6), both at the same Time step:
//   contact force,
//   mean contact force, strain energy and the plate centre's deflection
//   agree to 1e-5 of their largest values row by row (measured 1.8e-7);
//   the striker's velocity is the prescribed one at every row; the
//   striker's work (its mean force times its move, external work)
//   balances the plate's energy within 1e-4 of that work (measured
//   1.9e-5, as the free heavy tup's balance against the energy it
//   lost). The same motion given as a Path that starts 1 mm off the
//   Center (Center + Path(t), Path(0) = 1 mm, Velocity 0) gives the same
//   history, the first row's velocity included (1e-9; measured 7.4e-11).
// - cracks_2d: prm/impact_beam_2d.prm's first 120 us (a cylinder at 4 m/s
//   on a cross-ply beam whose bottom 90-degree plies crack): at least 10
//   crack faces inserted; at every insertion event the energy (with the
//   impactor's contact energy) continuous to 1e-6 of the total; the
//   balance within 1e-5 of the cylinder's energy at every step; the
//   cylinder slowed.
// usage: app_impactor
//        wall|wall_cylinder|wall_2d|free|scene|oblique_2d|cracks_2d|
//        prescribed
//        SCENE.prm
//        COARSE.prm WORKDIR
//        app_impactor scene_unbonded SCENE.prm COARSE.prm UNBONDED.prm
//        WORKDIR
#include "../check.h"
#include "scene.h"

#include <amfrac/simulator/simulator.h>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>

using namespace amfrac;

namespace
{
  const double mass = 1.0275e-6, speed = 1e4, penalty = 5e5;

  using amfrac_test::largest;

  /** The largest signed value of a column (the contact force pushes the
   * plate in: positive). */
  double
  highest(const History &h, const std::string &column)
  {
    double value = -1e300;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      value = std::max(value, h.value(r, column));
    return value;
  }

  /** The smallest signed value of a column. */
  double
  lowest(const History &h, const std::string &column)
  {
    double value = 1e300;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      value = std::min(value, h.value(r, column));
    return value;
  }

  /** A 10 x 10 mm plate of 1 mm cells without interfaces, for @p end s in
   * @p rows output steps, history only, in @p workdir. */
  std::string
  small_plate(const double       end,
              const unsigned int rows,
              const std::string &workdir)
  {
    std::ostringstream text;
    text << "subsection Geometry\n  set Length = 10\n  set Width = 10\n"
         << "  set Elements along length = 10\n"
         << "  set Elements along width = 10\nend\n"
         << "subsection Cohesive interfaces\n  set Interfaces =\nend\n"
         << "subsection Time\n  set End time = " << end
         << "\n  set Number of steps = " << rows << "\nend\n"
         << "subsection Output\n  set Directory = " << workdir
         << "\n  set Field format = none\nend\n";
    return text.str();
  }

  /** A single contact spring of stiffness @p k against the harmonic
   * oscillator: the largest penetration v sqrt(m / k) and force
   * v sqrt(m k) within 1 %, contact for pi sqrt(m / k) within 2 %, the
   * rebound at the impact speed within 1 %, the balance within 1 % of the
   * sphere's energy. */
  void
  check_single_spring(const History     &h,
                      const double       k,
                      const unsigned int n_nodes = 1)
  {
    const double depth        = speed * std::sqrt(mass / k);
    const double force        = speed * std::sqrt(mass * k);
    const double lasts        = M_PI * std::sqrt(mass / k);
    const double start        = 0.001 / speed; // the initial gap
    double       last_contact = 0, energy = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        CHECK(h.value(r, "contact_nodes") == 0
              || h.value(r, "contact_nodes") == n_nodes);
        if (h.value(r, "contact_nodes") > 0)
          last_contact = h.value(r, "time");
        energy = std::max(energy, std::abs(h.value(r, "balance_error")));
        CHECK(std::isfinite(h.value(r, "balance_error")));
      }
    const std::size_t last = h.n_rows() - 1;
    std::cout << "penetration " << largest(h, "penetration") << " (" << depth
              << "), force " << largest(h, "contact_force") << " (" << force
              << "), contact until " << last_contact << " s (" << start + lasts
              << "), rebound " << h.value(last, "impactor_velocity")
              << " mm/s, balance " << energy / (0.5 * mass * speed * speed)
              << std::endl;
    CHECK_CLOSE(largest(h, "penetration"), depth, 0.01 * depth);
    CHECK_CLOSE(highest(h, "contact_force"), force, 0.01 * force);
    CHECK_CLOSE(last_contact, start + lasts, 0.02 * lasts);
    CHECK_CLOSE(h.value(last, "impactor_velocity"), speed, 0.01 * speed);
    CHECK(energy < 0.01 * 0.5 * mass * speed * speed);
  }

  void
  wall(const std::string &prm, const std::string &workdir, const bool cylinder)
  {
    std::string held;
    for (const char *face : {"x-", "x+", "y-", "y+", "z-", "z+"})
      held += std::string("subsection Boundary conditions\n  subsection ")
              + face
              + "\n    set Type = displacement\n    set Components = "
                "x, y, z\n  end\nend\n";
    const std::string roller = "subsection Impactor\n  set Shape = cylinder\n"
                               "  set Axis = 0, 1, 0\nend\n";
    const auto        simulator = amfrac_test::run_scene<3>(
      prm, small_plate(1.2e-5, 300, workdir) + held + (cylinder ? roller : ""));
    // The corner node's quarter cell, or the edge's nodes.
    if (cylinder)
      check_single_spring(simulator->history(), penalty * 5, 11);
    else
      check_single_spring(simulator->history(), penalty * 0.25);
  }

  /** The same in 2D: a cylinder (per unit width) on the held cross-section
   * of a 10 mm strip, 1 mm cells; the corner node's half cell edge. */
  void
  wall_2d(const std::string &workdir)
  {
    std::ostringstream text;
    text << "set Dimension = 2\nsubsection Geometry\n"
         << "  set Stacking sequence = [0]\n  set Ply thickness = 2\n"
         << "  set Length = 10\n  set Elements along length = 10\n"
         << "  set Elements per ply = 2\nend\n"
         << "subsection Materials\n  set E1 = 135300\n  set E2 = 9000\n"
         << "  set E3 = 9000\n  set G12 = 5200\n  set G13 = 5200\n"
         << "  set G23 = 3460\n  set nu12 = 0.24\n  set nu13 = 0.24\n"
         << "  set nu23 = 0.3\n  set Density = 1.6e-9\nend\n";
    for (const char *face : {"x-", "x+", "y-", "y+"})
      text << "subsection Boundary conditions\n  subsection " << face
           << "\n    set Type = displacement\n    set Components = x, y\n"
           << "  end\nend\n";
    text << "subsection Impactor\n  set Face = y+\n  set Radius = 5\n"
         << "  set Mass = " << mass << "\n  set Center = 0, 7.001, 0\n"
         << "  set Velocity = 0, " << -speed
         << ", 0\n  set Penalty = " << penalty << "\nend\n"
         << "subsection Time\n  set Time integration = explicit\n"
         << "  set Safety factor = 0.8\n  set End time = 1.2e-5\n"
         << "  set Number of steps = 300\nend\n"
         << "subsection Output\n  set Directory = " << workdir
         << "\n  set Field format = none\nend\n";
    Simulator<2> simulator(parameters::Parameters::from_string(text.str()),
                           MPI_COMM_WORLD);
    simulator.run();
    check_single_spring(simulator.history(), penalty * 0.5);
  }

  /** The cylinder's velocity change along x and y over the run of the
   * oblique impact with @p friction; its dissipation. */
  std::array<double, 3>
  oblique_impact(const double friction, const std::string &workdir)
  {
    std::ostringstream text;
    text << "set Dimension = 2\nsubsection Geometry\n"
         << "  set Stacking sequence = [0]\n  set Ply thickness = 2\n"
         << "  set Length = 10\n  set Elements along length = 40\n"
         << "  set Elements per ply = 8\nend\n"
         << "subsection Materials\n  set E1 = 70000\n  set E2 = 70000\n"
         << "  set E3 = 70000\n  set G12 = 26923\n  set G13 = 26923\n"
         << "  set G23 = 26923\n  set nu12 = 0.3\n  set nu13 = 0.3\n"
         << "  set nu23 = 0.3\n  set Density = 2.7e-9\nend\n"
         << "subsection Boundary conditions\n  subsection y-\n"
         << "    set Type = displacement\n  end\nend\n"
         << "subsection Impactor\n  set Face = y+\n  set Radius = 5\n"
         << "  set Guided = false\n  set Mass = " << mass
         << "\n  set Center = 4, 7.001, 0\n  set Velocity = " << 0.5 * speed
         << ", " << -0.5 * speed << ", 0\n  set Penalty = " << penalty
         << "\n  set Friction coefficient = " << friction << "\nend\n"
         << "subsection Time\n  set Time integration = explicit\n"
         << "  set End time = 2e-5\n  set Number of steps = 40\nend\n"
         << "subsection Output\n  set Directory = " << workdir
         << "\n  set Field format = none\nend\n";
    Simulator<2> simulator(parameters::Parameters::from_string(text.str()),
                           MPI_COMM_WORLD);
    simulator.run();
    const History    &h       = simulator.history();
    const double      energy0 = 0.5 * mass * 0.5 * speed * speed;
    const std::size_t last    = h.n_rows() - 1;
    double            balance = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      balance = std::max(balance, std::abs(h.value(r, "balance_error")));
    const double dvx = h.value(last, "impactor_velocity_x") - 0.5 * speed;
    const double dvy = h.value(last, "impactor_velocity") + 0.5 * speed;
    const double dissipated
      = friction > 0 ? h.value(last, "impactor_friction_dissipation") : 0.;
    std::cout << "mu = " << friction << ": balance " << balance / energy0
              << " of the cylinder's energy, velocity change " << dvx << ", "
              << dvy << " mm/s, dissipated " << dissipated / energy0
              << " of the energy, contact force " << largest(h, "contact_force")
              << " N/mm" << std::endl;
    CHECK(balance < 0.01 * energy0);
    CHECK(dvy > 0.5 * speed); // it bounced
    return {{dvx, dvy, dissipated}};
  }

  void
  oblique_2d(const std::string &workdir)
  {
    const auto with    = oblique_impact(0.3, workdir + "_friction");
    const auto without = oblique_impact(0, workdir);
    CHECK(with[2] > 0);
    CHECK(with[0] < 0 && with[0] > -0.3 * with[1] * 1.01);
    CHECK(std::abs(without[0]) < 0.05 * std::abs(with[0]));
  }

  void
  free_plate(const std::string &prm, const std::string &workdir)
  {
    std::string free;
    for (const char *face : {"x+", "y+"})
      free += std::string("subsection Boundary conditions\n  subsection ")
              + face + "\n    set Type = free\n  end\nend\n";
    const auto simulator
      = amfrac_test::run_scene<3>(prm, small_plate(1e-5, 50, workdir) + free);
    const History    &h       = simulator->history();
    const double      initial = -mass * speed;
    const double      energy0 = 0.5 * mass * speed * speed;
    double            drift = 0, balance = 0;
    const std::size_t last = h.n_rows() - 1;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        drift   = std::max(drift, std::abs(h.value(r, "momentum") - initial));
        balance = std::max(balance, std::abs(h.value(r, "balance_error")));
        CHECK(std::isfinite(h.value(r, "balance_error")));
      }
    std::cout << "momentum drift " << drift / std::abs(initial) << ", balance "
              << balance / energy0 << ", sphere at "
              << h.value(last, "impactor_velocity") << " mm/s, contact force "
              << largest(h, "contact_force") << " N" << std::endl;
    CHECK(drift < 1e-9 * std::abs(initial));
    CHECK(balance < 0.01 * energy0);
    CHECK(h.value(last, "impactor_velocity") > -0.99 * speed);
    CHECK(highest(h, "contact_force") > 0);
  }

  void
  scene(const std::string &prm,
        const std::string &coarse,
        const std::string &workdir)
  {
    std::ifstream     in(coarse);
    std::stringstream text;
    text << in.rdbuf() << "\nsubsection Output\n  set Directory = " << workdir
         << "\nend\n";
    const auto        simulator = amfrac_test::run_scene<3>(prm, text.str());
    const History    &h         = simulator->history();
    const double      energy0   = 0.5 * mass * speed * speed;
    const std::size_t last      = h.n_rows() - 1;
    std::cout << "balance " << largest(h, "balance_error") / energy0
              << " of the sphere's energy, contact force "
              << largest(h, "contact_force") << " N, sphere at "
              << h.value(last, "impactor_velocity") << " mm/s, plate strain "
              << h.value(last, "strain_energy") << " N mm" << std::endl;
    CHECK(largest(h, "balance_error") < 0.02 * energy0);
    CHECK(highest(h, "contact_force") > 0);
    CHECK(h.value(last, "impactor_velocity") > -0.99 * speed);
  }

  /** The largest difference of @p column between two histories of the
   * same rows, against the largest magnitude of the column in @p a. */
  double
  relative_difference(const History     &a,
                      const History     &b,
                      const std::string &column)
  {
    double difference = 0;
    for (std::size_t r = 0; r < a.n_rows(); ++r)
      {
        const double d = std::abs(a.value(r, column) - b.value(r, column));
        // A NaN must not pass.
        difference = std::isfinite(d) ? std::max(difference, d) : 1e300;
      }
    return difference / std::max(largest(a, column), 1e-300);
  }

  /** The coarse striker scene @p prm, against the same tup free and
   * heavy (see the file header). */
  void
  prescribed(const std::string &prm,
             const std::string &coarse,
             const std::string &workdir)
  {
    const double striker_speed = 3000, heavy_mass = 1;
    // Below the stable step of both runs (8.9e-9 s, the interfaces'
    // penalty); both take it.
    const std::string common
      = amfrac_test::file_text(coarse)
        + "subsection Time\n  set Time step = 8e-9\nend\n";
    const auto striker
      = amfrac_test::run_scene<3>(prm,
                                  common + amfrac_test::history_only(workdir));
    const auto heavy = amfrac_test::run_scene<3>(
      prm,
      common + "subsection Impactor\n  set Motion = free\n  set Mass = "
        + std::to_string(heavy_mass) + "\nend\n"
        + amfrac_test::history_only(workdir + "-heavy"));
    const History    &p = striker->history(), &f = heavy->history();
    const std::size_t last = p.n_rows() - 1;
    CHECK(p.n_rows() == f.n_rows() && p.n_rows() == 21);
    if (p.n_rows() != f.n_rows())
      return;
    double velocity_error = 0;
    for (std::size_t r = 1; r < p.n_rows(); ++r)
      velocity_error
        = amfrac_test::worse(velocity_error,
                             std::abs(p.value(r, "impactor_velocity")
                                      + striker_speed));
    const double work    = p.value(last, "external_work");
    const double balance = largest(p, "balance_error") / work;
    std::cout << "prescribed striker against a free one of 1 t: contact "
                 "force "
              << highest(p, "contact_force") << " N ("
              << highest(f, "contact_force") << " N), differences "
              << relative_difference(p, f, "contact_force") << ", "
              << relative_difference(p, f, "mean_contact_force") << ", "
              << relative_difference(p, f, "strain_energy") << ", "
              << relative_difference(p, f, "p0_uz") << "; the striker's work "
              << work << " N mm, balance " << balance << " of it (free: "
              << largest(f, "balance_error")
                   / (0.5 * heavy_mass * striker_speed * striker_speed
                      - f.value(last, "impactor_kinetic"))
              << " of the energy the sphere lost); velocity off by "
              << velocity_error << " mm/s" << std::endl;
    CHECK(highest(p, "contact_force") > 0);
    for (const char *column :
         {"contact_force", "mean_contact_force", "strain_energy", "p0_uz"})
      CHECK(relative_difference(p, f, column) < 1e-5);
    CHECK(velocity_error < 1e-9 * striker_speed);
    CHECK(work > 0);
    CHECK(balance < 1e-4);

    // The same motion as a Path that starts 1 mm off the Center (the
    // centre is Center + Path(t) from t = 0 on, Velocity is not used).
    const auto path = amfrac_test::run_scene<3>(
      prm,
      common
        + "subsection Impactor\n  set Center = 0, 0, 9.001\n"
          "  set Velocity = 0, 0, 0\n  set Path = 0; 0; 1 - 3000*t\nend\n"
        + amfrac_test::history_only(workdir + "-path"));
    const History &q    = path->history();
    double         same = 0;
    for (const char *column : {"contact_force",
                               "mean_contact_force",
                               "strain_energy",
                               "p0_uz",
                               "impactor_velocity",
                               "external_work"})
      same = amfrac_test::worse(same, relative_difference(q, p, column));
    std::cout << "the same motion as a Path: largest difference " << same
              << ", first row's velocity " << q.value(0, "impactor_velocity")
              << " mm/s" << std::endl;
    CHECK(q.n_rows() == p.n_rows());
    CHECK(same < 1e-9);
  }

  /** The scene with its mid-plane released (@p unbonded appended): the
   * sphere and the contact between the plate's halves together. */
  void
  scene_unbonded(const std::string &prm,
                 const std::string &coarse,
                 const std::string &unbonded,
                 const std::string &workdir)
  {
    const std::string text = amfrac_test::file_text(coarse)
                             + amfrac_test::file_text(unbonded)
                             + amfrac_test::history_only(workdir);
    const auto     simulator = amfrac_test::run_scene<3>(prm, text);
    const History &h         = simulator->history();
    const auto     bonded    = amfrac_test::run_scene<3>(prm,
                                                  amfrac_test::file_text(coarse)
                                                    + amfrac_test::history_only(
                                                      workdir + "-bonded"));
    const History &b         = bonded->history();
    const double   energy0   = 0.5 * mass * speed * speed;
    std::cout << "unbonded mid-plane: balance "
              << largest(h, "balance_error") / energy0
              << " of the sphere's energy, sphere force "
              << highest(h, "contact_force") << " N (bonded "
              << highest(b, "contact_force") << "), between the halves "
              << highest(h, "body_contact_normal_force") << " N at most, "
              << largest(h, "body_contact_nodes") << " nodes, deepest "
              << largest(h, "body_contact_penetration") << " mm, centre "
              << lowest(h, "p0_uz") << " mm (bonded " << lowest(b, "p0_uz")
              << ")" << std::endl;
    CHECK(largest(h, "balance_error") < 0.02 * energy0);
    CHECK(highest(h, "body_contact_normal_force") > 0);
    // No deeper than if the sphere's whole force pressed one cell's area
    // (1.5 mm square) between the halves (measured: 0.70 of that).
    CHECK(largest(h, "body_contact_penetration")
          < highest(h, "contact_force") / (1.5 * 1.5 * penalty));
    CHECK(highest(h, "contact_force") < highest(b, "contact_force"));
    CHECK(lowest(h, "p0_uz") < lowest(b, "p0_uz"));
  }

  /** A free cylinder cracks the bottom plies of a beam (@p prm,
   * prm/impact_beam_2d.prm, shortened by @p short_prm). */
  void
  cracks_2d(const std::string &prm,
            const std::string &short_prm,
            const std::string &workdir)
  {
    const auto simulator
      = amfrac_test::run_scene<2>(prm,
                                  amfrac_test::file_text(short_prm)
                                    + amfrac_test::history_only(workdir));
    const History    &h      = simulator->history();
    const std::size_t last   = h.n_rows() - 1;
    const double      energy = h.value(0, "impactor_kinetic");
    std::cout << h.value(last, "crack_faces") << " crack faces, balance "
              << largest(h, "balance_error") / energy
              << " of the cylinder's energy, its velocity "
              << h.value(last, "impactor_velocity") << " mm/s" << std::endl;
    CHECK(h.n_rows() == 61);
    CHECK(h.value(last, "crack_faces") >= 10);
    CHECK(largest(h, "balance_error") < 1e-5 * energy);
    CHECK(h.value(last, "impactor_velocity") > -0.9 * 4000);
    const History *events = simulator->crack_history();
    CHECK(events != nullptr);
    if (events == nullptr)
      return;
    double faces = 0;
    for (std::size_t r = 0; r < events->n_rows(); ++r)
      {
        faces += events->value(r, "faces");
        CHECK(std::abs(events->value(r, "energy_jump")) < 1e-6);
      }
    CHECK(faces == h.value(last, "crack_faces"));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      AssertThrow(argc == 5
                    || (argc == 6 && std::string(argv[1]) == "scene_unbonded"),
                  ExcMessage("usage: app_impactor wall|wall_cylinder|"
                             "wall_2d|free|scene|oblique_2d|cracks_2d|"
                             "prescribed SCENE.prm COARSE.prm WORKDIR"));
      const std::string which = argv[1];
      if (which == "wall" || which == "wall_cylinder")
        wall(argv[2], argv[4], which == "wall_cylinder");
      else if (which == "wall_2d")
        wall_2d(argv[4]);
      else if (which == "free")
        free_plate(argv[2], argv[4]);
      else if (which == "oblique_2d")
        oblique_2d(argv[4]);
      else if (which == "cracks_2d")
        cracks_2d(argv[2], argv[3], argv[4]);
      else if (which == "prescribed")
        prescribed(argv[2], argv[3], argv[4]);
      else if (which == "scene_unbonded")
        scene_unbonded(argv[2], argv[3], argv[4], argv[5]);
      else
        scene(argv[2], argv[3], argv[4]);
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  return amfrac_test::failures;
}

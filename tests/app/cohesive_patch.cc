// Cohesive patch tests on a stack of blocks (one ply each), pulled or pushed
// through the thickness, with roller supports on x = 0 and y = 0 so that the
// stress is uniform:
// 1. Two blocks bonded by an intact interface with a high penalty carry the
//    same force as the same stack without interfaces (to 1e-6 relative: the
//    interface adds the compliance 1/K), with Gauss and with Lobatto points,
//    and the stress is uniform (sigma_zz = force / area in both blocks).
// 2. Three blocks, the upper interface fully pre-cracked: in tension the top
//    block transmits nothing (reaction 0 to round-off) and the interface
//    output shows every point of it debonded, open by the whole opening;
//    in compression the contact penalty carries the load like the intact
//    bond of the same stiffness (equal reactions to the Newton tolerance,
//    1e-7) and every point is in contact.
// 3. The same pre-crack with the Camanho-Davila law and Coulomb friction,
//    pressed and then slid: shear force = mu x normal force.
// 4. Two blocks pulled apart through the whole softening of the
//    Camanho-Davila law: the peak force is strength x area, the dissipated
//    energy G_Ic x area, the debonded area the whole face and the force 0.
// With the argument "prism" every case runs on wedges (the ply interfaces
// are triangles): P2 with Gauss points, P1 with the nodal rule (a
// quadratic triangle has none with positive weights).
#include "../check.h"

#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/mpi.h>
#include <sstream>

using namespace amfrac;

namespace
{
  bool prisms = false;

  std::string
  stack(const unsigned int n_blocks,
        const double       opening,
        const std::string &cohesive)
  {
    std::ostringstream s;
    s << "set Dimension = 3\n"
      << "subsection Geometry\n  set Stacking sequence = [0_" << n_blocks
      << "]\n  set Ply thickness = 0.5\n  set Length = 1\n  set Width = 1\n"
      << "  set Elements along length = 2\n  set Elements along width = 2\n"
      << (prisms ? "  set Element shape = prism\n" : "") << "end\n"
      << "subsection Discretization\n  set Finite element degree = "
      << (prisms && cohesive.find("lobatto") != std::string::npos ? 1 : 2)
      << "\nend\n"
      << "subsection Boundary conditions\n"
      << "  subsection x-\n    set Type = displacement\n"
      << "    set Components = x\n  end\n"
      << "  subsection y-\n    set Type = displacement\n"
      << "    set Components = y\n  end\n"
      << "  subsection z-\n    set Type = displacement\n"
      << "    set Components = z\n  end\n"
      << "  subsection z+\n    set Type = displacement\n"
      << "    set Components = z\n    set Displacement = 0; 0; " << opening
      << " * t\n  end\nend\n"
      << "subsection Output\n  set Field format = none\n"
      << "  set Directory = cohesive_patch_output\n"
      << "  set Point values = 0.3, 0.6, 0.2; 0.7, 0.2, 0.8\nend\n"
      << cohesive;
    return s.str();
  }

  struct Result
  {
    double force, stress_low, stress_high;
    /** Points of interface 1: how many have each status, and the largest
     * deviation of their opening and mean z displacement from @p opening
     * and @p opening / 2 (the lower block does not move in z). */
    unsigned int status_count[4] = {0, 0, 0, 0};
    double       opening_error = 0, displacement_error = 0;
    double       max_damage_interface_0 = 0;
  };

  Result
  run(const std::string &text, const double opening = 0)
  {
    Simulator<3> simulator(parameters::Parameters::from_string(text),
                           MPI_COMM_WORLD);
    simulator.run();
    const History &h = simulator.history();
    Result         result{h.value(0, "reaction_z+_z"),
                  h.value(0, "p0_stress_zz"),
                  h.value(0, "p1_stress_zz")};
    for (const auto &p : simulator.interface_points())
      {
        if (p.interface == 0)
          {
            result.max_damage_interface_0
              = std::max(result.max_damage_interface_0, p.damage);
            continue;
          }
        ++result.status_count[p.status];
        result.opening_error
          = std::max(result.opening_error, std::abs(p.gap[0] - opening));
        result.displacement_error
          = std::max(result.displacement_error,
                     std::abs(p.displacement[2] - opening / 2));
      }
    return result;
  }

  std::string
  bond(const std::string &quadrature, const std::string &extra = "")
  {
    return "subsection Cohesive interfaces\n  set Interfaces = all\n"
           "  set Normal stiffness = 1e12\n  set Normal strength = 1e6\n"
           "  set Shear strength = 1e6\n  set Mode I fracture energy = 1e6\n"
           "  set Mode II fracture energy = 1e6\n  set Quadrature = "
           + quadrature + "\n" + extra + "end\n";
  }
  /** 3. The pre-cracked stack with Law = camanho-davila and Friction
   * coefficient 0.3, pressed together and its top block then moved along
   * x (the x- roller holds the two lower blocks only): the debonded faces
   * slide with a shear force of 0.3 times the normal force; the friction
   * is in the interface's ledger and the balance holds. */
  void
  check_friction(const double opening, const std::string &cracked)
  {
    const std::string friction
      = "  set Law = camanho-davila\n  set Friction coefficient = 0.3\n";
    const std::string slide
      = "subsection Boundary conditions\n  subsection x-\n"
        "    set Where = z < 0.9\n  end\n  subsection z+\n"
        "    set Components = x, z\n"
        "    set Displacement = 10*max(t - 0.5, 0)*1e-3; 0; -2e-3*min(t, "
        "0.5)\n  end\nend\nsubsection Time\n  set Number of steps = 4\nend\n";
    Simulator<3> simulator(
      parameters::Parameters::from_string(
        stack(3, -opening, bond("lobatto", cracked + friction)) + slide),
      MPI_COMM_WORLD);
    simulator.run();
    const History &h      = simulator.history();
    const auto     last   = h.n_rows() - 1;
    const double   normal = h.value(last, "reaction_z+_z");
    const double   shear  = h.value(last, "reaction_z+_x");
    std::cout << "pre-crack with friction: normal force " << normal
              << ", shear force " << shear << ", friction "
              << h.value(last, "friction_i1") << std::endl;
    CHECK(normal < 0);
    CHECK_CLOSE(std::abs(shear) / std::abs(normal), 0.3, 1e-6);
    CHECK(h.value(last, "friction_i1") > 0.1 * 0.3 * std::abs(normal) * 5e-3);
    CHECK(std::abs(h.value(last, "balance_error"))
          < 1e-6 * h.value(last, "external_work"));
  }
  /** 4. Two 1 x 1 mm blocks pulled to 0.15 mm, beyond the final opening
   * 2 G_Ic / strength = 0.1 mm of the bilinear law. */
  void
  check_separation(const std::string &quadrature)
  {
    const double      strength = 10, G_Ic = 0.5, area = 1;
    const std::string law
      = "subsection Cohesive interfaces\n  set Interfaces = all\n"
        "  set Law = camanho-davila\n"
        "  set Normal stiffness = 1e5\n  set Normal strength = 10\n"
        "  set Shear strength = 10\n  set Mode I fracture energy = 0.5\n"
        "  set Mode II fracture energy = 1\n  set Quadrature = "
        + quadrature
        + "\nend\nsubsection Time\n  set Number of steps = 150\nend\n";
    Simulator<3> simulator(
      parameters::Parameters::from_string(stack(2, 0.15, law)), MPI_COMM_WORLD);
    simulator.run();
    const History &h    = simulator.history();
    const auto     last = h.n_rows() - 1;
    double         peak = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      peak = std::max(peak, h.value(r, "reaction_z+_z"));
    std::cout << quadrature << " separation: peak force " << peak
              << ", dissipated " << h.value(last, "dissipated_i0")
              << ", debonded " << h.value(last, "debonded_i0")
              << ", force at the end " << h.value(last, "reaction_z+_z")
              << std::endl;
    // The peak falls between two steps (the blocks take 9e-4 mm of the
    // first step's 1e-3 mm), and the ledger integrates the work of a step
    // by the trapezoidal rule: it misses the corner of the peak inside
    // that step (8.3e-4 of G_Ic here).
    CHECK_CLOSE(peak / (strength * area), 1, 0.01);
    CHECK_CLOSE(h.value(last, "dissipated_i0") / (G_Ic * area), 1, 2e-3);
    CHECK_CLOSE(h.value(last, "debonded_i0"), area, 1e-12);
    CHECK(std::abs(h.value(last, "reaction_z+_z")) < 1e-9 * strength);
    CHECK(std::abs(h.value(last, "balance_error"))
          < 1e-6 * h.value(last, "external_work"));
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     opening = 1e-3;
  prisms = argc > 1 && std::string(argv[1]) == "prism";

  const Result continuum = run(stack(2, opening, ""));
  for (const std::string quadrature : {"gauss", "lobatto"})
    {
      const Result bonded = run(stack(2, opening, bond(quadrature)));
      std::cout << quadrature << ": force " << bonded.force << " (continuum "
                << continuum.force << ")" << std::endl;
      CHECK_CLOSE(bonded.force / continuum.force, 1, 1e-6);
      CHECK_CLOSE(bonded.stress_low / bonded.force, 1, 1e-6);
      CHECK_CLOSE(bonded.stress_high / bonded.force, 1, 1e-6);
    }

  // The upper interface (1) is open everywhere from the start.
  const std::string cracked = "  set Pre-crack interfaces = 1\n"
                              "  set Pre-crack region = 1\n";
  const Result      pulled
    = run(stack(3, opening, bond("lobatto", cracked)), opening);
  std::cout << "open pre-crack in tension: force " << pulled.force << std::endl;
  CHECK(std::abs(pulled.force) < 1e-10 * std::abs(continuum.force));
  // The interface output: every point of interface 1 debonded and open by
  // the whole opening, its mean displacement half of it; interface 0
  // carries nothing and stays intact. (3x3 Lobatto points on 4 faces, or
  // the 3 vertices of 8 triangles.)
  using Record                  = InterfacePointRecord<3>;
  const unsigned int n_points_1 = prisms ? 24 : 36;
  CHECK(pulled.status_count[Record::debonded] == n_points_1);
  CHECK(pulled.status_count[Record::intact] == 0);
  CHECK(pulled.opening_error < 1e-12);
  CHECK(pulled.displacement_error < 1e-12);
  CHECK(pulled.max_damage_interface_0 == 0);

  const Result pushed = run(stack(3, -opening, bond("lobatto", cracked)));
  const Result intact = run(stack(3, -opening, bond("lobatto")));
  std::cout << "in compression: force " << pushed.force << " (intact "
            << intact.force << ")" << std::endl;
  CHECK(pushed.force < 0);
  CHECK(pushed.status_count[Record::contact] == n_points_1);
  CHECK_CLOSE(pushed.force / intact.force, 1, 1e-7);

  check_friction(opening, cracked);
  for (const std::string quadrature : {"gauss", "lobatto"})
    check_separation(quadrature);
  return amfrac_test::summary();
}

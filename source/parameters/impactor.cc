#include <amfrac/parameters/impactor.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/utilities.h>

namespace amfrac
{
  namespace parameters
  {
    void
    Impactor::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Impactor");
      prm.declare_entry(
        "Face",
        "none",
        Patterns::Selection("none|x-|x+|y-|y+|z-|z+"),
        "A rigid sphere strikes or indents this face of the laminate: the "
        "face's nodes inside the sphere are pushed out by a penalty "
        "pressure, and the sphere feels the opposite force. In 2D (the "
        "cross-section, plane strain) it is a cylinder along the width, "
        "x and y the first two components of Center and Velocity (the third "
        "is not used), its forces per unit width. none: no impactor.");
      prm.declare_entry(
        "Motion",
        "free",
        Patterns::Selection("free|prescribed"),
        "free: the sphere has a Mass and starts at Center with Velocity, and "
        "moves with the explicit time integration (Time/Time integration = "
        "explicit). prescribed: its centre is Center + Velocity t, an "
        "indenter driven through a static run (Time/Time integration = "
        "static; the contact tangent enters Newton's matrix); the Mass is "
        "not used.");
      prm.declare_entry("Radius",
                        "5",
                        Patterns::Double(0),
                        "Radius of the sphere [mm].");
      prm.declare_entry("Mass",
                        "1e-6",
                        Patterns::Double(0),
                        "Mass of the sphere as modelled [t]: in a quarter "
                        "model with two symmetry planes through the "
                        "sphere's path, a quarter of its mass (a steel "
                        "sphere of 5 mm radius: 4.1e-6 t). In 2D, the "
                        "cylinder's mass per unit width [t/mm].");
      prm.declare_entry("Center",
                        "0, 0, 7",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Position of the centre at t = 0 [mm]; the sphere "
                        "must not overlap the laminate then.");
      prm.declare_entry("Velocity",
                        "0, 0, -10000",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Velocity of the sphere at t = 0 [mm/s] "
                        "(-10000: 10 m/s towards -z); with Motion = "
                        "prescribed its constant velocity [mm per unit of "
                        "the load parameter t].");
      prm.declare_entry(
        "Penalty",
        "5e5",
        Patterns::Double(0),
        "Contact pressure per unit penetration [N/mm^3], the "
        "convention of the cohesive penalties: each face node takes it "
        "times its share of the face area (the integral of its shape "
        "function). It enters the stable time step, and the run logs how "
        "many time steps a face node's contact oscillation takes (below 10, "
        "a warning: the contact chatter of single nodes then gains energy; "
        "the seed's plate gained 38 % of the sphere's energy in 100 us "
        "with 5e6 on 1 mm cells, and 2e-6 with 5e5).");
      prm.leave_subsection();
    }



    void
    Impactor::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      const std::string path = "Impactor/";
      prm.enter_subsection("Impactor");
      face   = prm.get("Face");
      active = face != "none";
      radius = prm.get_double("Radius");
      mass   = prm.get_double("Mass");
      center = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Center")));
      velocity = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Velocity")));
      penalty    = prm.get_double("Penalty");
      prescribed = prm.get("Motion") == "prescribed";
      prm.leave_subsection();
      if (!active)
        return;
      // In 2D (the cross-section, plane strain) the sphere is a cylinder
      // along the laminate's width: a circle in the x-y plane.
      require(dim == 3 || face[0] != 'z',
              path + "Face",
              "a 2D laminate has the faces x-, x+, y- and y+ (y is its "
              "thickness)");
      boundary_id = 2 * (face[0] - 'x') + (face[1] == '+' ? 1 : 0);
      require(radius > 0, path + "Radius", "must be positive");
      require(mass > 0, path + "Mass", "must be positive");
      require(penalty > 0, path + "Penalty", "must be positive");
    }
  } // namespace parameters
} // namespace amfrac

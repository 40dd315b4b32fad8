#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/impactor.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/parameters/parameters.h>
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
        "A rigid sphere (or cylinder, see Shape) strikes or indents this "
        "face of the laminate: the face's nodes inside it are pushed out by "
        "a penalty pressure, and it feels the opposite force. In 2D (the "
        "cross-section, plane strain) it is a cylinder along the width, "
        "x and y the first two components of Center and Velocity (the third "
        "is not used), its forces per unit width. none: no impactor.");
      prm.declare_entry(
        "Motion",
        "free",
        Patterns::Selection("free|prescribed"),
        "free: the sphere has a Mass and starts at Center with Velocity, and "
        "moves with the explicit time integration (Time/Time integration = "
        "explicit). prescribed: its centre is Center + Velocity t, or "
        "Center + Path(t) if a Path is given (Velocity is then not used): "
        "an indenter driven through a static run (the contact tangent "
        "enters Newton's matrix) or an explicit one (a striker at a "
        "prescribed speed); the work it does is external work, and the Mass "
        "and Guided are not used.");
      prm.declare_entry("Radius",
                        "5",
                        Patterns::Double(0),
                        "Radius of the sphere or cylinder [mm].");
      prm.declare_entry(
        "Shape",
        "sphere",
        Patterns::Selection("sphere|cylinder"),
        "sphere: a ball (a point contact). cylinder: a roller or a "
        "cylindrical loading nose along Axis, unbounded in length (a line "
        "contact across the whole laminate: give it the length of the "
        "modelled width). Center is a point of its axis. In 2D both are "
        "the cylinder along the width.");
      prm.declare_entry(
        "Axis",
        "0, 1, 0",
        Patterns::List(Patterns::Double(), 3, 3),
        "Shape = cylinder in 3D: the direction of the cylinder's axis (any "
        "length), which must lie in the plane of Face (e.g. 0, 1, 0 on a "
        "z+ face: a line load across y; 1, 1, 0: at 45 degrees).");
      prm.declare_entry("Mass",
                        "1e-6",
                        Patterns::Double(0),
                        "Mass of the sphere as modelled [t]: in a quarter "
                        "model with two symmetry planes through the "
                        "sphere's path, a quarter of its mass (a steel "
                        "sphere of 5 mm radius: 4.1e-6 t). A 3D cylinder: "
                        "the mass of the striker that it models. In 2D, the "
                        "cylinder's mass per unit width [t/mm].");
      prm.declare_entry("Center",
                        "0, 0, 7",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Position of the sphere's centre (a point of the "
                        "cylinder's axis) at t = 0 [mm] (with a Path, "
                        "Center + Path(0)); the impactor must not overlap "
                        "the laminate then.");
      prm.declare_entry("Velocity",
                        "0, 0, -10000",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Velocity of the impactor at t = 0 [mm/s] "
                        "(-10000: 10 m/s towards -z); with Motion = "
                        "prescribed its constant velocity [mm per unit of "
                        "t: the load parameter of a static run, mm/s in an "
                        "explicit one].");
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
      prm.declare_entry(
        "Guided",
        "true",
        Patterns::Bool(),
        "Motion = free only. true: the sphere moves along the face's "
        "normal only, like the guided striker of a drop-weight tower; a "
        "guide takes the force across the normal. A quarter or half model "
        "with symmetry planes through the sphere's path needs it: there "
        "the model's half of the contact pushes the sphere sideways, which "
        "the other half would cancel. false: it moves in every direction "
        "(an oblique impact on a whole model); its rotation is held "
        "either way.");
      prm.declare_entry(
        "Path",
        "",
        Patterns::Anything(),
        "Motion = prescribed only: the centre's displacement from Center "
        "[mm] as three expressions of t (the load parameter of a static "
        "run, the time [s] of an explicit one) separated by ';' "
        "(e.g. '0; 0; -min(t, 0.03)' presses the sphere 0.03 mm into a z+ "
        "face, then '0.5*max(t - 0.03, 0); 0; -min(t, 0.03)' also slides "
        "it along x). The centre is Center + Path(t) from t = 0 on (a "
        "Path that is not zero at t = 0 starts the sphere off the "
        "Center). Empty: Velocity t.");
      prm.declare_entry(
        "Friction coefficient",
        "0",
        Patterns::Double(0),
        "Coulomb friction coefficient mu between the sphere and the face: "
        "a node in contact sticks to the sphere's surface while its "
        "tangential force is below mu times its normal force, and slides "
        "at that force otherwise (dissipating). The sphere does not "
        "rotate: it is a guided striker whose rotation is held.");
      prm.declare_entry("Tangential penalty factor",
                        "1",
                        Patterns::Double(0),
                        "Stick stiffness over the normal penalty: a "
                        "sticking node's tangential force grows by this "
                        "times its normal stiffness per unit slip.");
      prm.leave_subsection();
    }



    void
    Impactor::check_axis(const unsigned int dim)
    {
      // In 2D the circle already is the cylinder along the width.
      if (!cylinder || dim == 2)
        {
          axis.assign(3, 0.);
          return;
        }
      const double length
        = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      require(length > 0, "Impactor/Axis", "must not be the zero vector");
      for (double &a : axis)
        a /= length;
      // A cylinder standing on the face would touch it with its flat end,
      // which this contact (the curved side only) does not model.
      require(std::abs(axis[boundary_id / 2]) < 1e-12,
              "Impactor/Axis",
              "must lie in the plane of Impactor/Face " + face
                + " (its component along the face's normal must be 0)");
    }



    void
    Impactor::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      const std::string section = "Impactor/";
      prm.enter_subsection("Impactor");
      face     = prm.get("Face");
      active   = face != "none";
      radius   = prm.get_double("Radius");
      cylinder = prm.get("Shape") == "cylinder";
      axis     = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Axis")));
      mass   = prm.get_double("Mass");
      center = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Center")));
      velocity = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Velocity")));
      penalty                     = prm.get_double("Penalty");
      prescribed                  = prm.get("Motion") == "prescribed";
      const std::string path_text = prm.get("Path");
      path                        = split_expressions(path_text);
      if (Utilities::trim(path_text).empty())
        path.clear();
      guided            = prm.get_bool("Guided");
      friction          = prm.get_double("Friction coefficient");
      tangential_factor = prm.get_double("Tangential penalty factor");
      prm.leave_subsection();
      if (!active)
        return;
      // In 2D (the cross-section, plane strain) the sphere is a cylinder
      // along the laminate's width: a circle in the x-y plane.
      require(dim == 3 || face[0] != 'z',
              section + "Face",
              "a 2D laminate has the faces x-, x+, y- and y+ (y is its "
              "thickness)");
      boundary_id = 2 * (face[0] - 'x') + (face[1] == '+' ? 1 : 0);
      require(radius > 0, section + "Radius", "must be positive");
      check_axis(dim);
      require(mass > 0, section + "Mass", "must be positive");
      require(penalty > 0, section + "Penalty", "must be positive");
      if (guided && !prescribed)
        for (unsigned int d = 0; d < dim; ++d)
          require(d == boundary_id / 2 || velocity[d] == 0,
                  section + "Velocity",
                  "a guided impactor (Guided = true) moves along the face's "
                  "normal: its velocity across it must be 0, or set "
                  "Guided = false");
      require(friction == 0 || tangential_factor > 0,
              section + "Tangential penalty factor",
              "must be positive with friction");
      require(path.empty() || prescribed,
              section + "Path",
              "a path prescribes the centre: set Motion = prescribed");
      require(path.empty() || path.size() == 3,
              section + "Path",
              "needs three expressions separated by ';' (x; y; z of the "
              "centre's displacement), found "
                + std::to_string(path.size()));
      // Malformed expressions fail here, before anything is written.
      if (!path.empty())
        {
          if (dim == 2)
            make_expression_function<2>(path, 3, "", section + "Path");
          else
            make_expression_function<3>(path, 3, "", section + "Path");
        }
    }
  } // namespace parameters
} // namespace amfrac

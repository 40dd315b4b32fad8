#include <amfrac/parameters/input_error.h>
#include <amfrac/parameters/parameters.h>

namespace amfrac
{
  namespace parameters
  {
    void
    Contact::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry(
        "Enable",
        "false",
        Patterns::Bool(),
        "Contact between the laminate's bodies: every node of a surface "
        "(the outer faces, both sides of cohesive interfaces and cracks, "
        "unbonded interfaces) is kept out of every surface face it was not "
        "paired with in the undeformed laminate, by a penalty along the "
        "face's normal and Coulomb friction. A paired interface or crack "
        "face keeps its own contact (the cohesive law's). Explicit and "
        "static runs (Newton with the contact tangent).");
      prm.declare_entry(
        "Penalty",
        "5e5",
        Patterns::Double(0),
        "Contact pressure per unit penetration [N/mm^3], the convention of "
        "the cohesive penalties. Node-to-face contact is evaluated from "
        "both surfaces (two passes), each node with half of Penalty times "
        "its share of the face area, so that two matching meshes pressed "
        "together penetrate by pressure / Penalty. It enters the stable "
        "time step.");
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Double(0),
                        "Coulomb friction coefficient mu of the contact: a "
                        "node sticks while its tangential force is below mu "
                        "times its normal force, and slides (dissipating) "
                        "at that force otherwise.");
      prm.declare_entry("Tangential penalty factor",
                        "1",
                        Patterns::Double(0),
                        "Stick stiffness over the normal penalty: a "
                        "sticking node's tangential force grows by this "
                        "times its normal stiffness per unit slip.");
      prm.declare_entry(
        "Unbonded interfaces",
        "",
        Patterns::Anything(),
        "Ply interfaces released without a cohesive law (empty for none, "
        "'all', or a list of indices as in Cohesive interfaces/Interfaces): "
        "the plies on both sides are separate bodies that touch by contact "
        "only. Needs Enable = true.");
      prm.leave_subsection();
    }



    void
    Contact::parse_parameters(ParameterHandler &prm, const unsigned int n_plies)
    {
      const std::string section = "Contact/";
      prm.enter_subsection("Contact");
      active            = prm.get_bool("Enable");
      penalty           = prm.get_double("Penalty");
      friction          = prm.get_double("Friction coefficient");
      tangential_factor = prm.get_double("Tangential penalty factor");
      unbonded_interfaces
        = parse_interface_list(prm.get("Unbonded interfaces"),
                               n_plies - 1,
                               section + "Unbonded interfaces");
      prm.leave_subsection();
      require(penalty > 0, section + "Penalty", "must be positive");
      require(friction == 0 || tangential_factor > 0,
              section + "Tangential penalty factor",
              "must be positive when there is friction");
      require(active || unbonded_interfaces.empty(),
              section + "Unbonded interfaces",
              "unbonded plies touch by contact only: set Contact/Enable = "
              "true");
    }
  } // namespace parameters
} // namespace amfrac

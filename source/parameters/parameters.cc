#include <algorithm>
#include <amfrac/cohesive/camanho_davila_law.h>
#include <amfrac/geometry/stacking_sequence.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/parameters/parameters.h>
#include <cctype>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace amfrac
{
  namespace parameters
  {
    std::vector<std::string>
    split_expressions(const std::string &text)
    {
      std::vector<std::string> parts = Utilities::split_string_list(text, ';');
      for (auto &p : parts)
        p = Utilities::trim(p);
      return parts;
    }



    void
    Geometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Stacking sequence",
                        "[0/90]s",
                        Patterns::Anything(),
                        "Ply angles in degrees from the bottom (smallest "
                        "thickness coordinate) up, e.g. [0/90/45/-45]s, "
                        "[0_4/0_16], [(0/90)_2]s, [+-45], [0@glass/90].");
      prm.declare_entry("Ply thickness",
                        "0.125",
                        Patterns::List(Patterns::Double()),
                        "Thickness of each ply in mm: one value for all "
                        "plies or one value per ply.");
      prm.declare_entry("Total thickness",
                        "0",
                        Patterns::Double(0),
                        "If positive, the laminate thickness in mm, split "
                        "into plies of equal thickness (overrides Ply "
                        "thickness).");
      prm.declare_entry("Length",
                        "10",
                        Patterns::Double(),
                        "Extent along x in mm (the 0-degree direction).");
      prm.declare_entry("Width",
                        "10",
                        Patterns::Double(),
                        "Extent along y in mm (in a 2D cross-section the "
                        "width is the out-of-plane direction of plane "
                        "strain and not meshed).");
      prm.declare_entry("Elements along length",
                        "8",
                        Patterns::Integer(1),
                        "Number of elements along x.");
      prm.declare_entry("Elements along width",
                        "8",
                        Patterns::Integer(1),
                        "Number of elements along y (3D and 2D in-plane).");
      prm.declare_entry(
        "Edge grading",
        "1",
        Patterns::Double(1, 1000),
        "Ratio of the largest to the smallest element length along x (and "
        "y in 3D and 2D in-plane) of the box mesh: 1 is uniform; above 1 "
        "the elements shrink geometrically from the middle towards both "
        "ends, where a simply supported or clamped edge has its boundary "
        "layer and, in 3D, the singular stress of a support next to a "
        "loaded face. The number of elements stays Elements along "
        "length/width (an axis of one or two elements stays uniform). Box "
        "meshes of hexahedra only (no Hole radius, Mesh file or prisms).");
      prm.declare_entry("Elements per ply",
                        "1",
                        Patterns::Integer(1),
                        "Number of elements through the thickness of each "
                        "ply (not used by a 2D in-plane model).");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 10),
                        "Uniform refinements of the structured mesh.");
      prm.declare_entry("Mesh distortion",
                        "0",
                        Patterns::Double(0, 0.4),
                        "Random interior-vertex perturbation as a fraction "
                        "of the element size (for patch tests); ply "
                        "interfaces stay planar.");
      prm.declare_entry(
        "Element shape",
        "hexahedron",
        Patterns::Selection("hexahedron|prism"),
        "hexahedron: the box is meshed with structured hexahedra. prism "
        "(Dimension = 3): every in-plane cell of the same structured grid "
        "is split into two triangles (the diagonals alternate like a "
        "chessboard) and extruded through the element layers of the "
        "plies, so each hexahedron becomes two wedges on the same "
        "vertices; Global refinements multiply the numbers of elements "
        "instead of refining (deal.II cannot refine wedges). Prisms take "
        "linear static scenes (adaptive ones by global remeshing with "
        "Gmsh, see Adaptivity/Refinement cycles), cohesive ply "
        "interfaces (triangular interface faces) on the Newton path, "
        "where a load history is remeshed when Adaptivity/Error "
        "threshold or Refine every fires, and in explicit runs with "
        "Finite element degree = 1 (remeshed the same way); patch loads; "
        "in static runs also linear buckling, total Lagrangian kinematics "
        "and plastic plies (remeshed too, but not with an Imperfection "
        "mode); VTU output; no crack "
        "insertion, contact, impactor or Refinement region so far. With a "
        "Hole "
        "radius the in-plane mesh is Gmsh's (unstructured triangles, see "
        "Elements around hole) and P2 wedges map the hole as a circle; a "
        "Mesh file brings its own.");
      prm.declare_entry("2D model",
                        "cross-section",
                        Patterns::Selection("cross-section|in-plane"),
                        "What a Dimension = 2 scene models. cross-section: "
                        "the (x, thickness) plane of the laminate in plane "
                        "strain; plies are layers of elements, ply "
                        "interfaces can be cohesive; forces and energies "
                        "are per mm of the out-of-plane width. in-plane: "
                        "the (x, y) plane of a thin laminate in plane "
                        "stress; the stacking sequence is homogenized "
                        "through the thickness by classical lamination "
                        "theory (membrane stiffness A/h; a symmetric "
                        "stacking is required so that membrane and bending "
                        "do not couple); stresses are thickness averages, "
                        "and the ply stresses (and the Hoffman index of the "
                        "most loaded ply) follow from the common strain; "
                        "forces and energies are per mm of laminate "
                        "thickness. Ignored in 3D.");
      prm.declare_entry(
        "Hole radius",
        "0",
        Patterns::Double(0),
        "If positive, a circular hole through the thickness "
        "at the centre of the plate [mm] (3D, or 2D with 2D "
        "model = in-plane): an open-hole laminate. The in-plane mesh is then deal.II's "
        "plate with a hole (the hole on a cylindrical "
        "manifold, transfinite interpolation around it), "
        "refined until about Elements along width cells "
        "span the width; Elements along length is not used. "
        "The hole's boundary id is 6 (traction free).");
      prm.declare_entry(
        "Elements around hole",
        "32",
        Patterns::Integer(4),
        "Element shape = prism with a Hole radius: the in-plane mesh is "
        "made by Gmsh (unstructured triangles) with this many elements "
        "around the hole, growing linearly away from it (by a quarter of "
        "the distance) to Width / Elements along width; Global "
        "refinements halve both sizes.");
      prm.declare_entry(
        "Mesh file",
        "",
        Patterns::Anything(),
        "A 2D Gmsh file of the laminate's in-plane outline in the plane z "
        "= 0 (3D only), relative to the parameter file's folder: a .geo "
        "(meshed by Gmsh with its own sizes, halved per Global "
        "refinement) or a .msh (taken as it is, each Global refinement "
        "splits every element into four). Its triangles are extruded "
        "through the element layers of the plies into wedges (Element "
        "shape = prism), its quadrilaterals into hexahedra (Element shape "
        "= hexahedron); a mesh of both is refused. Physical curves named "
        "x-, x+, y-, y+ are the faces of those names in Boundary "
        "conditions (a condition on a side the file does not name is an "
        "input error), the bottom and top of the laminate are z- and z+; "
        "every other curve (a hole, a notch) is traction free (boundary "
        "id 6). Length, Width and Elements along length/width are not "
        "used. A 3D file (a .msh of 3D elements, or a .geo with volumes, "
        "meshed by Gmsh) is the laminate's volume mesh instead: 8-node hexahedra (Element shape = hexahedron) or 6-node "
        "wedges (prism), each Global refinement splitting every element "
        "into eight. The ply of an element is its physical volume named "
        "'ply k', k = 1 .. the number of plies from the bottom of the "
        "Stacking sequence (a ply's material axes turn about z; Ply "
        "thickness and Elements per ply are not used); physical surfaces "
        "named x-, x+, y-, y+, z-, z+ are the faces of those names, every "
        "other boundary face is traction free.");
      prm.declare_entry("Refinement region",
                        "",
                        Patterns::Anything(),
                        "Cells whose centre makes this expression of x, y, "
                        "(z) and h, the cell's longest edge [mm], nonzero "
                        "are refined, Region refinements times, after the "
                        "distortion (hanging nodes), e.g. x < 2. With h "
                        "the refinement grades: sqrt(x^2 + y^2) < 0.5 + "
                        "3*h refines every cell within 0.5 mm of the z "
                        "axis and, outside, those within three of their "
                        "own sizes of that cylinder. "
                        "In 3D scenes that adapt during their load history "
                        "(Adaptivity/Refine every, Error threshold, Process "
                        "zone elements) along the plies only, as that "
                        "adaptivity refines (an expression of x and y then "
                        "refines every ply alike).");
      prm.declare_entry("Region refinements",
                        "1",
                        Patterns::Integer(0, 8),
                        "How often the Refinement region is refined.");
      prm.declare_entry(
        "Imperfection",
        "",
        Patterns::Anything(),
        "A geometric imperfection [mm]: the vertices of the mesh are moved "
        "by this displacement, one expression of x, y, (z) per component "
        "separated by ';' (empty: none), e.g. for the first mode of a "
        "clamped strip of length 100 and 1 % of its thickness h = 1 in 2D: "
        "0; 0.005*(1-cos(2*pi*x/100)). Applied after the global "
        "refinements and the distortion, before the Refinement region "
        "(whose new vertices follow the cells' straight edges); a hole's "
        "boundary stays on its circle. The ply faces move with the "
        "vertices: an imperfection is stress free.");
      prm.declare_entry(
        "Imperfection mode",
        "0",
        Patterns::Integer(0, 50),
        "If positive, also move the vertices by this buckling mode (1: the "
        "lowest) of the small-strain state at Time/End time, scaled to a "
        "largest displacement of Imperfection amplitude: the usual seed of "
        "a post-buckling run. The linear solve and eigenvalue analysis use "
        "the Linear solver and Buckling subsections (Block size, Tolerance, "
        "Max basis size); nothing is written. Applied after Imperfection, "
        "on the initial mesh.");
      prm.declare_entry("Imperfection amplitude",
                        "0",
                        Patterns::Double(),
                        "The largest displacement [mm] of the Imperfection "
                        "mode (its sign picks the direction: positive along "
                        "the mode's largest component).");
      prm.leave_subsection();
    }



    void
    Geometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      stacking_sequence = prm.get("Stacking sequence");
      ply_thickness     = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Ply thickness")));
      total_thickness        = prm.get_double("Total thickness");
      length                 = prm.get_double("Length");
      width                  = prm.get_double("Width");
      elements_along_length  = prm.get_integer("Elements along length");
      elements_along_width   = prm.get_integer("Elements along width");
      elements_per_ply       = prm.get_integer("Elements per ply");
      edge_grading           = prm.get_double("Edge grading");
      global_refinements     = prm.get_integer("Global refinements");
      mesh_distortion        = prm.get_double("Mesh distortion");
      prisms                 = prm.get("Element shape") == "prism";
      hole_radius            = prm.get_double("Hole radius");
      elements_around_hole   = prm.get_integer("Elements around hole");
      mesh_file              = Utilities::trim(prm.get("Mesh file"));
      in_plane               = prm.get("2D model") == "in-plane";
      refinement_region      = Utilities::trim(prm.get("Refinement region"));
      region_refinements     = prm.get_integer("Region refinements");
      imperfection           = Utilities::trim(prm.get("Imperfection"));
      imperfection_mode      = prm.get_integer("Imperfection mode");
      imperfection_amplitude = prm.get_double("Imperfection amplitude");
      prm.leave_subsection();

      // Lengths are in mm: a value beyond a kilometre is a units mistake
      // (or overflows the element geometry: found by the fuzzer).
      const double largest = 1e6;
      const auto   in_range
        = [&](const double value) { return value > 0 && value <= largest; };
      const std::string range = "must be positive and at most 1e6 mm (1 km): "
                                "lengths are in mm";
      require(in_range(length), "Geometry/Length", range);
      require(in_range(width), "Geometry/Width", range);
      require(hole_radius < 0.45 * std::min(length, width),
              "Geometry/Hole radius",
              "must be below 0.45 times the smaller of Length and Width");
      require(hole_radius == 0 || mesh_distortion == 0,
              "Geometry/Mesh distortion",
              "is for the box mesh: set it to 0 with a Hole radius");
      require(edge_grading == 1
                || (!prisms && hole_radius == 0 && mesh_file.empty()),
              "Geometry/Edge grading",
              "grades the structured box of hexahedra: set it to 1 with "
              "prisms, a Hole radius or a Mesh file");
      require(imperfection_mode == 0
                || (imperfection_amplitude != 0
                    && std::abs(imperfection_amplitude) <= largest),
              "Geometry/Imperfection amplitude",
              "must be nonzero (and at most 1e6 mm) with an Imperfection "
              "mode");
      try
        {
          plies = parse_stacking_sequence(stacking_sequence);
        }
      catch (const std::exception &e)
        {
          throw InputError("Geometry/Stacking sequence", e.what());
        }
      if (total_thickness > 0)
        ply_thickness.assign(plies.size(), total_thickness / plies.size());
      require(ply_thickness.size() == 1 || ply_thickness.size() == plies.size(),
              "Geometry/Ply thickness",
              "give one value or one per ply (" + std::to_string(plies.size())
                + " plies), got " + std::to_string(ply_thickness.size()));
      if (ply_thickness.size() == 1)
        ply_thickness.assign(plies.size(), ply_thickness[0]);
      for (const double t : ply_thickness)
        require(in_range(t),
                total_thickness > 0 ? "Geometry/Total thickness" :
                                      "Geometry/Ply thickness",
                range);
    }



    namespace
    {
      /** The entries of `subsection Materials`, with defaults for a
       * carbon/epoxy ply (MPa, t/mm^3). */
      const std::vector<std::pair<const char *, const char *>> material_entries
        = {{"E1", "135000"},      {"E2", "10000"}, {"E3", "10000"},
           {"G12", "5000"},       {"G13", "5000"}, {"G23", "3448"},
           {"nu12", "0.3"},       {"nu13", "0.3"}, {"nu23", "0.45"},
           {"Density", "1.6e-9"}, {"Xt", "2000"},  {"Xc", "1200"},
           {"Yt", "50"},          {"Yc", "200"},   {"Zt", "50"},
           {"Zc", "200"},         {"S12", "80"},   {"S13", "80"},
           {"S23", "60"},         {"Gc", "0.3"}};
    } // namespace



    void
    Materials::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      prm.declare_entry("Names",
                        "cfrp",
                        Patterns::List(Patterns::Anything(), 1),
                        "Names of the materials; a ply refers to one with "
                        "'angle@name' in the stacking sequence, the first is "
                        "the default. Every entry below is a list with one "
                        "value per name, or a single value for all.");
      for (const auto &[name, value] : material_entries)
        {
          const std::string n(name);
          const std::string unit
            = n == "Density" ? "t/mm^3" :
              n == "Gc"      ? "N/mm" :
                               (n.rfind("nu", 0) == 0 ? "-" : "MPa");
          const std::string what
            = n == "Gc" ?
                "fracture energy of a crack inserted inside the "
                "ply (Crack insertion), any mode" :
              n.rfind("nu", 0) == 0 ?
                "Poisson ratio" :
                (n == "Density" ? "mass density" :
                                  (n[0] == 'E' || n[0] == 'G' ?
                                     "elastic modulus in material axes" :
                                     "Hoffman strength (positive magnitude)"));
          prm.declare_entry(n,
                            value,
                            Patterns::List(Patterns::Double()),
                            what + " [" + unit + "]");
        }
      prm.declare_entry(
        "Plasticity",
        "none",
        Patterns::List(Patterns::Selection("none|hoffman"), 1),
        "none: the material is elastic at any stress (its strengths only "
        "enter the Hoffman index and crack insertion). hoffman: Hoffman "
        "anisotropic plasticity, the seed's nonlinear ply: the Hoffman "
        "criterion of the strengths above is the initial yield surface "
        "(so tension and compression yield at different stresses), "
        "associative flow, isotropic hardening by Hardening, a backward-"
        "Euler return mapping with its consistent tangent on the static "
        "Newton path (with Kinematics = total Lagrangian, of the second "
        "Piola-Kirchhoff stress and the Green-Lagrange strain). A plastic "
        "ply pays for a return mapping at every "
        "quadrature point and iteration; elastic plies pay nothing.");
      prm.declare_entry("Hardening",
                        "0",
                        Patterns::List(Patterns::Double(0)),
                        "isotropic hardening of Plasticity = hoffman: the "
                        "strengths of the yield surface grow by the factor "
                        "1 + Hardening x kappa, kappa the equivalent "
                        "plastic strain (the accumulated length of the "
                        "plastic strain increments, engineering shear); 0 "
                        "is perfectly plastic [-]");
      prm.leave_subsection();
    }



    void
    Materials::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      const std::vector<std::string> names
        = Utilities::split_string_list(prm.get("Names"));
      std::map<std::string, std::vector<double>> values;
      for (const auto &[name, value] : material_entries)
        {
          (void)value;
          values[name] = Utilities::string_to_double(
            Utilities::split_string_list(prm.get(name)));
          require(values[name].size() == 1
                    || values[name].size() == names.size(),
                  std::string("Materials/") + name,
                  "give one value or one per material name ("
                    + std::to_string(names.size()) + ")");
        }
      const std::vector<std::string> plasticity
        = Utilities::split_string_list(prm.get("Plasticity"));
      const std::vector<double> hardening = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Hardening")));
      prm.leave_subsection();
      require(plasticity.size() == 1 || plasticity.size() == names.size(),
              "Materials/Plasticity",
              "give one value or one per material name ("
                + std::to_string(names.size()) + ")");
      require(hardening.size() == 1 || hardening.size() == names.size(),
              "Materials/Hardening",
              "give one value or one per material name ("
                + std::to_string(names.size()) + ")");

      for (const std::string &name : names)
        require(!name.empty()
                  && std::all_of(name.begin(),
                                 name.end(),
                                 [](const char c) {
                                   return std::isalnum(
                                            static_cast<unsigned char>(c))
                                          || c == '-' || c == '.';
                                 }),
                "Materials/Names",
                "'" + name
                  + "': a material name may contain letters, digits, '-' "
                    "and '.' (so that '@name' can refer to it)");
      const auto get = [&](const char *key, const unsigned int m) {
        const auto &v = values[key];
        return v.size() == 1 ? v[0] : v[m];
      };
      materials.clear();
      for (unsigned int m = 0; m < names.size(); ++m)
        {
          OrthotropicMaterial mat;
          mat.name            = names[m];
          ElasticConstants &e = mat.elastic;
          e.E1                = get("E1", m);
          e.E2                = get("E2", m);
          e.E3                = get("E3", m);
          e.G12               = get("G12", m);
          e.G13               = get("G13", m);
          e.G23               = get("G23", m);
          e.nu12              = get("nu12", m);
          e.nu13              = get("nu13", m);
          e.nu23              = get("nu23", m);
          e.density           = get("Density", m);
          Strengths &s        = mat.strengths;
          s.Xt                = get("Xt", m);
          s.Xc                = get("Xc", m);
          s.Yt                = get("Yt", m);
          s.Yc                = get("Yc", m);
          s.Zt                = get("Zt", m);
          s.Zc                = get("Zc", m);
          s.S12               = get("S12", m);
          s.S13               = get("S13", m);
          s.S23               = get("S23", m);
          mat.fracture_energy = get("Gc", m);
          mat.plastic = plasticity[plasticity.size() == 1 ? 0 : m] == "hoffman";
          mat.hardening        = hardening[hardening.size() == 1 ? 0 : m];
          const std::string at = " (material '" + mat.name + "')";
          // Moduli beyond 1e8 MPa (80 times diamond's) or densities beyond
          // 1e-6 t/mm^3 (40 times osmium's) are unit mistakes (Pa, kg/m^3),
          // and would overflow the element matrices.
          for (const char *key : {"E1", "E2", "E3", "G12", "G13", "G23"})
            {
              std::ostringstream value;
              value << get(key, m);
              require(std::abs(get(key, m)) <= 1e8,
                      std::string("Materials/") + key,
                      value.str()
                        + " is above 1e8 MPa: moduli are in MPa "
                          "(N/mm^2)"
                        + at);
            }
          require(e.density <= 1e-6,
                  "Materials/Density",
                  "above 1e-6 t/mm^3: densities are in t/mm^3 (1600 kg/m^3 "
                  "is 1.6e-9)"
                    + at);
          try
            {
              stiffness_in_material_axes(e);
            }
          catch (const std::invalid_argument &error)
            {
              throw InputError("Materials", error.what() + at);
            }
          require(e.density >= 0, "Materials/Density", "negative" + at);
          require(mat.fracture_energy > 0,
                  "Materials/Gc",
                  "must be positive" + at);
          for (const auto &[key, value] : material_entries)
            if (key[0] == 'X' || key[0] == 'Y' || key[0] == 'Z'
                || key[0] == 'S')
              {
                (void)value;
                require(get(key, m) > 0,
                        std::string("Materials/") + key,
                        "strengths must be positive" + at);
              }
          materials.push_back(mat);
        }
    }



    unsigned int
    Materials::index_of(const std::string &name) const
    {
      if (name.empty())
        return 0;
      for (unsigned int m = 0; m < materials.size(); ++m)
        if (materials[m].name == name)
          return m;
      throw InputError("Geometry/Stacking sequence",
                       "unknown material '" + name
                         + "' (not in Materials/Names)");
    }



    void
    Discretization::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      prm.declare_entry("Finite element degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Polynomial degree of the displacement (1 = "
                        "trilinear hexahedra, 2 = triquadratic).");
      prm.leave_subsection();
    }



    void
    Discretization::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      degree = prm.get_integer("Finite element degree");
      prm.leave_subsection();
    }



    const std::array<const char *, 6> BoundaryConditions::face_names
      = {{"x-", "x+", "y-", "y+", "z-", "z+"}};



    void
    BoundaryConditions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Function constants",
                        "",
                        Patterns::Anything(),
                        "Constants for all expressions below, as "
                        "'name=value, name=value'; pi is always defined.");
      prm.declare_entry("Body force",
                        "0",
                        Patterns::Anything(),
                        "Force per volume [N/mm^3]: one expression for all "
                        "components or one per component separated by ';', "
                        "in x, y, (z,) t.");
      for (const char *face : face_names)
        {
          prm.enter_subsection(face);
          prm.declare_entry(
            "Type",
            "free",
            Patterns::Selection("free|displacement|traction|pressure"),
            "Boundary condition on this face of the laminate box. The "
            "thickness axis is z in 3D and y in 2D.");
          prm.declare_entry("Components",
                            "x, y, z",
                            Patterns::List(Patterns::Selection("x|y|z")),
                            "Displacement components prescribed (Type = "
                            "displacement).");
          prm.declare_entry("Displacement",
                            "0",
                            Patterns::Anything(),
                            "Prescribed displacement [mm]: expressions in "
                            "x, y, (z,) t separated by ';' (one for all "
                            "components or one per component).");
          prm.declare_entry("Where",
                            "",
                            Patterns::Anything(),
                            "Optional condition: a component is prescribed "
                            "only at the nodes of this face where its "
                            "expression is nonzero, e.g. abs(z-1)<1e-6 (one "
                            "expression for all components or one per "
                            "component separated by ';'). Evaluated once, at "
                            "t = 0: the supported nodes do not change during "
                            "a run.");
          prm.declare_entry("Traction",
                            "0",
                            Patterns::Anything(),
                            "Traction vector [MPa] (Type = traction), "
                            "expressions separated by ';'. With Type = "
                            "displacement it loads the components that are "
                            "not prescribed (on prescribed ones it only "
                            "changes the reaction).");
          prm.declare_entry("Pressure",
                            "0",
                            Patterns::Anything(),
                            "Pressure [MPa] acting against the outward "
                            "normal (Type = pressure; with Type = "
                            "displacement on the components that are not "
                            "prescribed, e.g. an edge held in z and "
                            "compressed in x).");
          prm.leave_subsection();
        }
      declare_lever(prm);
      declare_patch(prm);
      prm.leave_subsection();
    }



    void
    BoundaryConditions::declare_patch(ParameterHandler &prm)
    {
      prm.enter_subsection("Patch load");
      prm.declare_entry("Face",
                        "none",
                        Patterns::Selection("none|x-|x+|y-|y+|z-|z+"),
                        "Face of the laminate box that carries a patch "
                        "load: a total force spread uniformly over a "
                        "circle or rectangle on it (an impact pulse, an "
                        "indenter). With a Geometry/Mesh file: z- or z+. "
                        "none: no patch load.");
      prm.declare_entry("Shape",
                        "circle",
                        Patterns::Selection("circle|rectangle"),
                        "Shape of the patch.");
      prm.declare_entry("Center",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Center of the patch [mm], x, y (, z); the "
                        "coordinate along the face normal is ignored.");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0),
                        "Radius of a circular patch [mm] (in 2D the half "
                        "length of the loaded segment).");
      prm.declare_entry("Size",
                        "1, 1",
                        Patterns::List(Patterns::Double(0), 1, 2),
                        "Side lengths of a rectangular patch [mm] along the "
                        "face's in-plane axes in x, y, z order (one length "
                        "in 2D).");
      prm.declare_entry("Force",
                        "0",
                        Patterns::Anything(),
                        "Total force [N; N/mm in 2D] as an expression of t, "
                        "e.g. the triangular pulse 5000*max(0, 1 - abs(t - "
                        "2.5e-6)/2.5e-6). It is spread uniformly over the "
                        "patch area, whatever the mesh.");
      prm.declare_entry("Direction",
                        "normal",
                        Patterns::Anything(),
                        "'normal' (the inward normal of the face, i.e. "
                        "pressing on it) or a vector x, y (, z).");
      prm.leave_subsection();
    }



    void
    BoundaryConditions::parse_patch(ParameterHandler  &prm,
                                    const unsigned int dim)
    {
      const std::string path = "Boundary conditions/Patch load/";
      prm.enter_subsection("Patch load");
      const std::string face = prm.get("Face");
      patch                  = PatchLoad();
      if (face != "none")
        {
          patch.face   = face;
          patch.circle = prm.get("Shape") == "circle";
          patch.center = Utilities::string_to_double(
            Utilities::split_string_list(prm.get("Center")));
          patch.radius = prm.get_double("Radius");
          patch.size   = Utilities::string_to_double(
            Utilities::split_string_list(prm.get("Size")));
          patch.force                 = prm.get("Force");
          const std::string direction = Utilities::trim(prm.get("Direction"));
          if (direction != "normal")
            {
              try
                {
                  patch.direction = Utilities::string_to_double(
                    Utilities::split_string_list(direction));
                }
              catch (...)
                {
                  patch.direction.clear();
                }
              double norm = 0;
              for (const double c : patch.direction)
                norm += c * c;
              require(patch.direction.size() == dim && norm > 0,
                      path + "Direction",
                      "'" + direction
                        + "' is neither 'normal' nor a "
                          "nonzero vector of "
                        + std::to_string(dim) + " components");
            }
        }
      prm.leave_subsection();
      if (patch.face.empty())
        return;
      require(patch.face[0] - 'x' < int(dim),
              path + "Face",
              "face '" + patch.face + "' does not exist in "
                + std::to_string(dim) + "D");
      require(patch.center.size() == dim,
              path + "Center",
              "needs " + std::to_string(dim) + " coordinates");
      if (patch.circle)
        require(patch.radius > 0, path + "Radius", "must be positive");
      else
        require(patch.size.size() == dim - 1
                  && *std::min_element(patch.size.begin(), patch.size.end())
                       > 0,
                path + "Size",
                "needs " + std::to_string(dim - 1)
                  + " positive side length(s)");
    }



    void
    BoundaryConditions::declare_lever(ParameterHandler &prm)
    {
      prm.enter_subsection("Lever");
      prm.declare_entry(
        "Hinge face",
        "none",
        Patterns::Selection("none|x-|x+|y-|y+|z-|z+"),
        "A rigid, weightless lever loads the laminate along the thickness "
        "axis, as in the mixed-mode bending (MMB) test: it is pinned to the "
        "hinge nodes (this face, where Hinge where is nonzero), rests on the "
        "saddle nodes and is pushed at the load point, Lever length beyond "
        "the saddle on the side away from the hinge. Hinge and saddle "
        "positions are the mean coordinates of their nodes along the "
        "laminate length (x). The lever is a linear constraint: the hinge "
        "nodes move together, the saddle follows the lever line, so the "
        "hinge and saddle forces keep the lever's ratio at every crack "
        "length. none: no lever.");
      prm.declare_entry("Hinge where",
                        "",
                        Patterns::Anything(),
                        "Condition in x, y, (z) selecting the hinge nodes "
                        "of the hinge face (empty: all).");
      prm.declare_entry("Saddle face",
                        "none",
                        Patterns::Selection("none|x-|x+|y-|y+|z-|z+"),
                        "Face on which the lever rests on the laminate.");
      prm.declare_entry("Saddle where",
                        "",
                        Patterns::Anything(),
                        "Condition in x, y, (z) selecting the saddle nodes "
                        "of the saddle face (empty: all).");
      prm.declare_entry("Lever length",
                        "0",
                        Patterns::Double(0),
                        "Distance c from the saddle to the load point [mm] "
                        "(0: the load acts on the saddle).");
      prm.declare_entry("Displacement",
                        "-t",
                        Patterns::Anything(),
                        "Displacement of the load point along the "
                        "thickness axis [mm], an expression in t "
                        "proportional to t for dissipation control. "
                        "history.csv reports the force conjugate to t as "
                        "force_lever and the hinge and saddle displacements "
                        "as lever_hinge and lever_saddle.");
      prm.leave_subsection();
    }



    void
    BoundaryConditions::parse_lever(ParameterHandler  &prm,
                                    const unsigned int dim)
    {
      prm.enter_subsection("Lever");
      const std::string path  = "Boundary conditions/Lever/";
      const std::string hinge = prm.get("Hinge face");
      lever.hinge_face        = hinge == "none" ? "" : hinge;
      lever.hinge_where       = Utilities::trim(prm.get("Hinge where"));
      lever.saddle_face       = prm.get("Saddle face");
      lever.saddle_where      = Utilities::trim(prm.get("Saddle where"));
      lever.length            = prm.get_double("Lever length");
      lever.displacement      = Utilities::trim(prm.get("Displacement"));
      prm.leave_subsection();
      if (!lever.active())
        return;
      const auto exists = [dim](const std::string &face) {
        return face[0] - 'x' < static_cast<int>(dim);
      };
      require(exists(lever.hinge_face),
              path + "Hinge face",
              "face '" + lever.hinge_face + "' does not exist in "
                + std::to_string(dim) + "D");
      require(lever.saddle_face != "none",
              path + "Saddle face",
              "a lever needs a saddle face");
      require(exists(lever.saddle_face),
              path + "Saddle face",
              "face '" + lever.saddle_face + "' does not exist in "
                + std::to_string(dim) + "D");
    }



    void
    BoundaryConditions::parse_parameters(ParameterHandler  &prm,
                                         const unsigned int dim)
    {
      prm.enter_subsection("Boundary conditions");
      constants  = prm.get("Function constants");
      body_force = split_expressions(prm.get("Body force"));
      faces.clear();
      for (unsigned int f = 0; f < face_names.size(); ++f)
        {
          prm.enter_subsection(face_names[f]);
          BoundaryFace face;
          face.name               = face_names[f];
          const std::string &type = prm.get("Type");
          face.type               = type == "displacement" ?
                                      BoundaryFace::Type::displacement :
                                    type == "traction" ? BoundaryFace::Type::traction :
                                    type == "pressure" ? BoundaryFace::Type::pressure :
                                                         BoundaryFace::Type::free;
          face.components         = {{false, false, false}};
          for (const std::string &c :
               Utilities::split_string_list(prm.get("Components")))
            face.components[c[0] - 'x'] = true;
          // The default "x, y, z" means all components, also in 2D.
          const bool default_components
            = Utilities::split_string_list(prm.get("Components")).size() == 3
              && face.components[0] && face.components[1];
          if (dim == 2 && default_components)
            face.components[2] = false;
          face.displacement = split_expressions(prm.get("Displacement"));
          face.traction     = split_expressions(prm.get("Traction"));
          face.pressure     = Utilities::trim(prm.get("Pressure"));
          face.where        = Utilities::trim(prm.get("Where"));
          prm.leave_subsection();

          const std::string path
            = std::string("Boundary conditions/") + face.name;
          if (f >= 2 * dim)
            require(face.type == BoundaryFace::Type::free,
                    path + "/Type",
                    "boundary face '" + face.name + "' does not exist in "
                      + std::to_string(dim) + "D (faces are x-, x+, y-, y+"
                      + (dim == 3 ? ", z-, z+)" : ")"));
          if (face.type == BoundaryFace::Type::displacement)
            for (unsigned int c = dim; c < 3; ++c)
              require(!face.components[c],
                      path + "/Components",
                      "component z does not exist in 2D");
          faces.push_back(face);
        }
      parse_lever(prm, dim);
      parse_patch(prm, dim);
      prm.leave_subsection();
    }



    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Solver",
                        "direct",
                        Patterns::Selection("direct|cg-amg"),
                        "direct: sparse LU through Trilinos Amesos; cg-amg: "
                        "conjugate gradients with Trilinos ML algebraic "
                        "multigrid given the rigid-body modes.");
      prm.declare_entry("Direct package",
                        "mumps",
                        Patterns::Selection("mumps|klu"),
                        "Amesos package for Solver = direct.");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Patterns::Double(0),
                        "Relative residual tolerance of CG.");
      prm.declare_entry("Max iterations",
                        "2000",
                        Patterns::Integer(1),
                        "Iteration limit of CG.");
      prm.declare_entry("AMG smoother sweeps",
                        "2",
                        Patterns::Integer(1),
                        "Pre- and post-smoothing sweeps per level.");
      prm.declare_entry("AMG smoother type",
                        "Chebyshev",
                        Patterns::Selection(
                          "Chebyshev|symmetric Gauss-Seidel|ILU"),
                        "ML smoother.");
      prm.declare_entry("AMG auxiliary aggregation threshold",
                        "0",
                        Patterns::Double(0),
                        "If positive, ML aggregates by the distance "
                        "Laplacian of the node coordinates with this drop "
                        "tolerance. On thin plates 0.1 cut CG iterations "
                        "from 413 to 29 on one mesh but diverged on others: "
                        "see doc/benchmarks/README.md before using it.");
      prm.declare_entry("AMG aggregation threshold",
                        "1e-4",
                        Patterns::Double(0),
                        "ML aggregation threshold (drop tolerance for "
                        "the strength of connection).");
      prm.leave_subsection();
    }



    void
    LinearSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      type = prm.get("Solver") == "direct" ? Type::direct : Type::cg_amg;
      direct_package        = prm.get("Direct package");
      tolerance             = prm.get_double("Tolerance");
      max_iterations        = prm.get_integer("Max iterations");
      smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
      smoother_type         = prm.get("AMG smoother type");
      aggregation_threshold = prm.get_double("AMG aggregation threshold");
      auxiliary_threshold
        = prm.get_double("AMG auxiliary aggregation threshold");
      prm.leave_subsection();
    }



    void
    Time::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(0),
                        "Pseudo-time at the end of the load history; "
                        "expressions see it as t.");
      prm.declare_entry("Number of steps",
                        "1",
                        Patterns::Integer(1),
                        "Number of load steps from t = 0 to End time; "
                        "under explicit dynamics, the number of output "
                        "intervals (history rows and field files).");
      prm.declare_entry("Time integration",
                        "static",
                        Patterns::Selection("static|explicit"),
                        "static: load steps in pseudo-time t (linear "
                        "solve, or Newton with cohesive interfaces). "
                        "explicit: central differences (velocity Verlet) "
                        "with a lumped mass in physical time t [s]; no "
                        "stiffness matrix and no linear solver are built.");
      prm.declare_entry("Safety factor",
                        "0.8",
                        Patterns::Double(0, 1),
                        "Explicit: the time step is this times the "
                        "estimated stable step 2 / omega_max.");
      prm.declare_entry("Time step",
                        "0",
                        Patterns::Double(0),
                        "Explicit: a fixed time step in s; 0 takes Safety "
                        "factor times the estimated stable step. A fixed "
                        "step above the estimate is an input error unless "
                        "Allow unstable time step is set.");
      prm.declare_entry("Allow unstable time step",
                        "false",
                        Patterns::Bool(),
                        "Explicit: accept a fixed Time step above the "
                        "estimated stable step (for stability studies; the "
                        "run stops when its energy blows up).");
      prm.declare_entry("Initial velocity",
                        "0",
                        Patterns::Anything(),
                        "Explicit: initial velocity [mm/s] as expressions "
                        "in x, y, (z) separated by ';' (one for all "
                        "components or one per component). Supported "
                        "nodes move as prescribed instead.");
      prm.declare_entry("Mass scaling time step",
                        "0",
                        Patterns::Double(0),
                        "Explicit: run with this time step [s], adding "
                        "nodal mass where the estimated stable step is "
                        "shorter than it over Safety factor: at the nodes "
                        "of the interface penalty springs first, and all "
                        "masses uniformly if the elements alone need it. "
                        "The added mass is logged (total, share, largest "
                        "factor and where). 0: no mass scaling.");
      prm.declare_entry("Rayleigh mass damping",
                        "0",
                        Patterns::Double(0),
                        "Explicit: alpha [1/s] of the damping force alpha M "
                        "v; its work is the ledger column damping_work.");
      prm.declare_entry("Rayleigh stiffness damping",
                        "0",
                        Patterns::Double(0),
                        "Explicit: beta [s] of the damping force beta K v "
                        "(K of the plies, not of the interfaces); it "
                        "shortens the stable step by sqrt(1 + xi^2) - xi, "
                        "xi = beta omega_max / 2.");
      prm.leave_subsection();
    }



    void
    Time::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      end_time          = prm.get_double("End time");
      n_steps           = prm.get_integer("Number of steps");
      explicit_dynamics = prm.get("Time integration") == "explicit";
      safety_factor     = prm.get_double("Safety factor");
      time_step         = prm.get_double("Time step");
      allow_unstable    = prm.get_bool("Allow unstable time step");
      initial_velocity  = split_expressions(prm.get("Initial velocity"));
      mass_scaling_step = prm.get_double("Mass scaling time step");
      rayleigh_alpha    = prm.get_double("Rayleigh mass damping");
      rayleigh_beta     = prm.get_double("Rayleigh stiffness damping");
      prm.leave_subsection();
      require(!(mass_scaling_step > 0 && time_step > 0),
              "Time/Mass scaling time step",
              "set either Time step or Mass scaling time step, not both");
      require(end_time > 0, "Time/End time", "must be positive");
      require(safety_factor > 0, "Time/Safety factor", "must be positive");
    }



    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Folder for all output (created if missing).");
      prm.declare_entry("Base name",
                        "solution",
                        Patterns::Anything(),
                        "Prefix of the field files.");
      prm.declare_entry("Field format",
                        "vtu",
                        Patterns::Selection("vtu|xdmf|vtu+xdmf|none"),
                        "vtu: VTU per rank with PVTU/PVD records (and, "
                        "with cohesive interfaces, the interface points in "
                        "<Base name>-interfaces.pvd: status, damage, "
                        "opening, sliding, tractions); xdmf: one HDF5 file "
                        "per step with an XDMF record (bulk fields only).");
      prm.declare_entry("Write every",
                        "1",
                        Patterns::Integer(1),
                        "Write fields every this many steps (and at the "
                        "last).");
      prm.declare_entry("Damage maps",
                        "true",
                        Patterns::Bool(),
                        "3D with cohesive interfaces and a field format: "
                        "with every field output, a PNG top view of each "
                        "interface, damage-interface-<k>-<step>.png "
                        "(white intact, yellow to red softening, black "
                        "debonded, blue debonded and in contact).");
      prm.declare_entry("Point values",
                        "",
                        Patterns::Anything(),
                        "Points [mm] whose displacement and stress go to "
                        "the CSV history, as 'x,y,z; x,y,z' (x,y in 2D).");
      prm.leave_subsection();
    }



    void
    Output::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Output");
      directory                = prm.get("Directory");
      base_name                = prm.get("Base name");
      const std::string format = prm.get("Field format");
      write_vtu                = format == "vtu" || format == "vtu+xdmf";
      write_xdmf               = format == "xdmf" || format == "vtu+xdmf";
      every_n_steps            = prm.get_integer("Write every");
      damage_maps              = prm.get_bool("Damage maps");
      const std::string text   = prm.get("Point values");
      prm.leave_subsection();

      require(!directory.empty(), "Output/Directory", "must not be empty");
      require(!base_name.empty() && base_name.find('/') == std::string::npos,
              "Output/Base name",
              "must be a plain file name");
      points.clear();
      for (const std::string &p : split_expressions(text))
        {
          if (p.empty())
            continue;
          std::vector<double> c;
          try
            {
              c = Utilities::string_to_double(
                Utilities::split_string_list(p, ','));
            }
          catch (...)
            {
              c.clear();
            }
          require(c.size() == dim,
                  "Output/Point values",
                  "each point needs " + std::to_string(dim)
                    + " numbers separated by ',', got '" + p + "'");
          Point<3> point;
          for (unsigned int d = 0; d < dim; ++d)
            point[d] = c[d];
          points.push_back(point);
        }
    }



    void
    CohesiveInterfaces::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cohesive interfaces");
      prm.declare_entry("Interfaces",
                        "",
                        Patterns::Anything(),
                        "Ply interfaces bonded by the cohesive law (each ply "
                        "becomes a discrete body): empty for none, 'all', or "
                        "a list of indices, where interface k lies between "
                        "ply k and ply k+1 (plies counted from 0 at the "
                        "bottom).");
      prm.declare_entry("Law",
                        "seed",
                        Patterns::Selection("seed|camanho-davila"),
                        "Traction-separation law: 'seed' is the bilinear "
                        "mixed-mode law of Mohammadi & Forouzan-sepehr, eqs. "
                        "(1)-(13), with penalty contact and Coulomb "
                        "friction after debonding; 'camanho-davila' is the "
                        "bilinear law of Camanho, Davila & de Moura (2003) "
                        "with the quadratic onset criterion and "
                        "Benzeggagh-Kenane propagation (BK exponent), one "
                        "penalty (Normal stiffness) in all modes, contact "
                        "in compression and, once fully debonded, the same "
                        "Coulomb friction (Friction coefficient).");
      prm.declare_entry("BK exponent",
                        "2",
                        Patterns::Double(),
                        "Benzeggagh-Kenane eta of Law = camanho-davila: "
                        "G_c = G_Ic + (G_IIc - G_Ic) (G_II/G)^eta.");
      prm.declare_entry("Normal strength",
                        "60",
                        Patterns::Double(),
                        "Mode I onset traction sigma_N in MPa.");
      prm.declare_entry("Shear strength",
                        "90",
                        Patterns::Double(),
                        "Mode II onset traction sigma_T in MPa.");
      prm.declare_entry("Mode I fracture energy",
                        "0.3",
                        Patterns::Double(),
                        "G_Ic in N/mm (= kJ/m^2).");
      prm.declare_entry("Mode II fracture energy",
                        "0.8",
                        Patterns::Double(),
                        "G_IIc in N/mm (= kJ/m^2).");
      prm.declare_entry("Normal stiffness",
                        "1e5",
                        Patterns::Double(),
                        "Penalty stiffness E_N of the intact bond in "
                        "N/mm^3 (Turon et al.: about 50 E3 / ply "
                        "thickness).");
      prm.declare_entry("Shear stiffness",
                        "0",
                        Patterns::Double(),
                        "E_T in N/mm^3; 0 means equal to Normal stiffness.");
      prm.declare_entry("Contact penalty",
                        "0",
                        Patterns::Double(),
                        "alpha_N in N/mm^3 against interpenetration; 0 "
                        "means equal to Normal stiffness.");
      prm.declare_entry("Stick penalty",
                        "0",
                        Patterns::Double(),
                        "alpha_T in N/mm^3 of the stick phase of friction "
                        "after debonding; 0 means equal to Shear "
                        "stiffness (Normal stiffness with Law = "
                        "camanho-davila).");
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Double(),
                        "Coulomb mu between debonded faces in contact.");
      prm.declare_entry("Viscosity",
                        "0",
                        Patterns::Double(0),
                        "Viscous regularization (Gao & Bower 2004) of the "
                        "bonded phase, in MPa per (mm per unit of time t): "
                        "adds the traction Viscosity * (g - g_old) / dt. "
                        "A small value lets cut-back steps pass the local "
                        "snap-backs of a softening interface; its "
                        "dissipation is reported apart (viscous_i<k>).");
      prm.declare_entry("Quadrature",
                        "lobatto",
                        Patterns::Selection("lobatto|gauss"),
                        "Interface integration: 'lobatto' (nodal, "
                        "Newton-Cotes-like) avoids the traction "
                        "oscillations of stiff penalties; 'gauss' is the "
                        "usual Gauss rule.");
      prm.declare_entry("Pre-crack interfaces",
                        "",
                        Patterns::Anything(),
                        "Cohesive interfaces that carry an initial "
                        "delamination (list of indices).");
      prm.declare_entry("Pre-crack region",
                        "",
                        Patterns::Anything(),
                        "Expression of x, y, (z): nonzero where the "
                        "pre-crack interfaces are fully debonded from the "
                        "start (contact and friction stay active), e.g. "
                        "x < 30.");
      prm.leave_subsection();
    }



    std::vector<unsigned int>
    parse_interface_list(const std::string &text,
                         const unsigned int n_interfaces,
                         const std::string &parameter)
    {
      std::vector<unsigned int> result;
      if (Utilities::trim(text) == "all")
        {
          for (unsigned int k = 0; k < n_interfaces; ++k)
            result.push_back(k);
          return result;
        }
      for (const std::string &entry : Utilities::split_string_list(text))
        {
          std::size_t end   = 0;
          long        value = -1;
          try
            {
              value = std::stol(entry, &end);
            }
          catch (...)
            {
              end = 0;
            }
          require(end == entry.size() && value >= 0,
                  parameter,
                  "'" + entry + "' is not an interface index");
          require(value < long(n_interfaces),
                  parameter,
                  "interface " + entry + " does not exist: the laminate "
                    + "has " + std::to_string(n_interfaces)
                    + " ply interfaces (0 to "
                    + std::to_string(long(n_interfaces) - 1) + ")");
          result.push_back(value);
        }
      std::sort(result.begin(), result.end());
      result.erase(std::unique(result.begin(), result.end()), result.end());
      return result;
    }



    void
    CohesiveInterfaces::check_camanho_davila(const std::string &section) const
    {
      require(bk_exponent > 0, section + "BK exponent", "must be positive");
      require(shear_stiffness == 0 || shear_stiffness == normal_stiffness,
              section + "Shear stiffness",
              "Law = camanho-davila has one penalty (Normal stiffness) in "
              "all modes: leave Shear stiffness at 0");
      cohesive::CamanhoDavilaProperties p;
      p.normal_strength = normal_strength;
      p.shear_strength  = shear_strength;
      p.G_Ic            = G_Ic;
      p.G_IIc           = G_IIc;
      p.bk_exponent     = bk_exponent;
      p.stiffness       = normal_stiffness;
      p.contact_penalty = contact_penalty > 0 ? contact_penalty : 1;
      try
        {
          p.validate();
        }
      catch (const std::invalid_argument &e)
        {
          require(false, section + "Mode I fracture energy", e.what());
        }
    }



    void
    CohesiveInterfaces::parse_parameters(ParameterHandler  &prm,
                                         const unsigned int n_plies)
    {
      const std::string section = "Cohesive interfaces/";
      prm.enter_subsection("Cohesive interfaces");
      interfaces       = parse_interface_list(prm.get("Interfaces"),
                                        n_plies - 1,
                                        section + "Interfaces");
      normal_strength  = prm.get_double("Normal strength");
      shear_strength   = prm.get_double("Shear strength");
      G_Ic             = prm.get_double("Mode I fracture energy");
      G_IIc            = prm.get_double("Mode II fracture energy");
      normal_stiffness = prm.get_double("Normal stiffness");
      shear_stiffness  = prm.get_double("Shear stiffness");
      contact_penalty  = prm.get_double("Contact penalty");
      stick_penalty    = prm.get_double("Stick penalty");
      friction         = prm.get_double("Friction coefficient");
      viscosity        = prm.get_double("Viscosity");
      camanho_davila   = prm.get("Law") == "camanho-davila";
      bk_exponent      = prm.get_double("BK exponent");
      lobatto          = prm.get("Quadrature") == "lobatto";
      precrack_interfaces
        = parse_interface_list(prm.get("Pre-crack interfaces"),
                               n_plies - 1,
                               section + "Pre-crack interfaces");
      precrack_region = Utilities::trim(prm.get("Pre-crack region"));
      prm.leave_subsection();

      const std::pair<const char *, double> positive[]
        = {{"Normal strength", normal_strength},
           {"Shear strength", shear_strength},
           {"Mode I fracture energy", G_Ic},
           {"Mode II fracture energy", G_IIc},
           {"Normal stiffness", normal_stiffness}};
      for (const auto &[name, value] : positive)
        require(value > 0, section + name, "must be positive");
      const std::pair<const char *, double> optional[]
        = {{"Shear stiffness", shear_stiffness},
           {"Contact penalty", contact_penalty},
           {"Stick penalty", stick_penalty}};
      for (const auto &[name, value] : optional)
        require(value >= 0,
                section + name,
                "must be positive (or 0 for the default)");
      require(friction >= 0,
              section + "Friction coefficient",
              "must not be negative");
      if (camanho_davila)
        check_camanho_davila(section);
      if (shear_stiffness == 0)
        shear_stiffness = normal_stiffness;
      if (contact_penalty == 0)
        contact_penalty = normal_stiffness;
      if (stick_penalty == 0)
        stick_penalty = shear_stiffness;
      require(2 * G_Ic / normal_strength > normal_strength / normal_stiffness,
              section + "Mode I fracture energy",
              "the final opening 2 G_Ic / Normal strength must exceed the "
              "onset opening Normal strength / Normal stiffness: raise "
              "G_Ic or Normal stiffness");
      require(2 * G_IIc / shear_strength > shear_strength / shear_stiffness,
              section + "Mode II fracture energy",
              "the final sliding 2 G_IIc / Shear strength must exceed the "
              "onset sliding Shear strength / Shear stiffness: raise "
              "G_IIc or Shear stiffness");
      for (const unsigned int k : precrack_interfaces)
        require(std::binary_search(interfaces.begin(), interfaces.end(), k),
                section + "Pre-crack interfaces",
                "interface " + std::to_string(k)
                  + " is not listed in Interfaces");
      require(precrack_interfaces.empty() || !precrack_region.empty(),
              section + "Pre-crack region",
              "is empty, but Pre-crack interfaces are given");
    }



    void
    NonlinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Max iterations",
                        "20",
                        Patterns::Integer(1),
                        "Newton iterations per load step before the step "
                        "is cut back.");
      prm.declare_entry("Residual tolerance",
                        "1e-8",
                        Patterns::Double(0),
                        "Converged when the residual norm of the free "
                        "unknowns is below this times the norm of the "
                        "external forces (reactions and loads), or of the "
                        "step's first residual if that is larger.");
      prm.declare_entry("Line search",
                        "true",
                        Patterns::Bool(),
                        "Backtrack along the Newton direction until the "
                        "residual decreases.");
      prm.declare_entry("Minimum step fraction",
                        "1e-3",
                        Patterns::Double(0, 1),
                        "Smallest load step, as a fraction of End time / "
                        "Number of steps; a step that fails below it ends "
                        "the run with an error (the last converged state "
                        "is written).");
      prm.declare_entry("Easy step iterations",
                        "4",
                        Patterns::Integer(1),
                        "After a cut-back, the step doubles again (up to "
                        "the nominal step) when a step converges in at "
                        "most this many iterations.");
      prm.declare_entry(
        "Control",
        "displacement",
        Patterns::Selection("displacement|dissipation|opening|arc-length"),
        "displacement: steps of the load parameter t. dissipation: as "
        "displacement while the structure is (nearly) elastic, then steps of "
        "the dissipated energy (Gutierrez 2004, Verhoosel et al. 2009), which "
        "follows snap-backs of a softening interface that no displacement "
        "step can pass; t may then decrease. Needs prescribed displacements "
        "proportional to t and no applied loads. opening: as dissipation, "
        "but the steps past the switch prescribe the increase of the "
        "summed normal opening of the still bonded interface points "
        "(Opening increment), an indirect displacement control in the "
        "spirit of Alfano & Crisfield's local arc-length: it stays "
        "monotonic through the local snap-backs of single points. "
        "arc-length: Crisfield's arc-length method from the first step, "
        "for limit points and snap-backs of the whole structure (buckling, "
        "snap-through): each step has the length |du|^2 + psi^2 q^2 dt^2 = "
        "l^2 (Arc-length psi = 0: cylindrical, > 0: spherical; q = |du/dt| "
        "of the first step), the first step as long as a nominal step of t, "
        "later ones halved on failure and doubled back after easy steps; "
        "the root of the constraint is the one continuing the previous "
        "step's direction. t may decrease; the run ends when t reaches "
        "End time or after Maximum arc-length steps. Needs loads "
        "and prescribed displacements proportional to t.");
      prm.declare_entry("Dissipation increment",
                        "0.01",
                        Patterns::Double(0),
                        "Energy dissipated per step under dissipation "
                        "control, in N mm (N mm per mm of width in 2D); "
                        "also the threshold at which a displacement step "
                        "switches to it (or to opening control): the "
                        "fracture energy the cohesive interfaces dissipate "
                        "in that step, from their own ledger.");
      prm.declare_entry("Arc-length psi",
                        "0",
                        Patterns::Double(0),
                        "Control = arc-length: the weight of the load "
                        "parameter in the step length (0: cylindrical "
                        "arc-length, displacements only; 1: the load "
                        "parameter counts as much as the displacement it "
                        "produced in the first step).");
      prm.declare_entry("Maximum arc-length steps",
                        "1000",
                        Patterns::Integer(1),
                        "Control = arc-length: the run ends after this "
                        "many steps even if t has not reached End time "
                        "(a path that turns back).");
      prm.declare_entry("Maximum steps",
                        "0",
                        Patterns::Integer(0),
                        "Static runs on the Newton path, any Control: the "
                        "run ends after this many converged steps even if "
                        "t has not reached End time (0: no limit). Under "
                        "dissipation or opening control t may stay nearly "
                        "constant while a delamination grows; this ends "
                        "such a run after a chosen number of steps.");
      prm.declare_entry("Opening increment",
                        "0.01",
                        Patterns::Double(0),
                        "Under opening control: the increase per step of "
                        "the integral of the normal opening over the "
                        "bonded interface points, in mm^3 (mm^2 per mm of "
                        "width in 2D).");
      prm.leave_subsection();
    }



    void
    NonlinearSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      max_iterations        = prm.get_integer("Max iterations");
      tolerance             = prm.get_double("Residual tolerance");
      line_search           = prm.get_bool("Line search");
      minimum_step_fraction = prm.get_double("Minimum step fraction");
      easy_iterations       = prm.get_integer("Easy step iterations");
      opening_control       = prm.get("Control") == "opening";
      dissipation_control
        = prm.get("Control") == "dissipation" || opening_control;
      dissipation_increment = prm.get_double("Dissipation increment");
      opening_increment     = prm.get_double("Opening increment");
      arc_length            = prm.get("Control") == "arc-length";
      arc_length_psi        = prm.get_double("Arc-length psi");
      max_arc_length_steps  = prm.get_integer("Maximum arc-length steps");
      max_steps             = prm.get_integer("Maximum steps");
      prm.leave_subsection();
      require(tolerance > 0,
              "Nonlinear solver/Residual tolerance",
              "must be positive");
      require(!opening_control || opening_increment > 0,
              "Nonlinear solver/Opening increment",
              "must be positive under opening control");
      require(!dissipation_control || dissipation_increment > 0,
              "Nonlinear solver/Dissipation increment",
              "must be positive under dissipation control");
      require(minimum_step_fraction > 0,
              "Nonlinear solver/Minimum step fraction",
              "must be positive");
    }



    void
    Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "3",
                        Patterns::Integer(2, 3),
                        "2: plane strain in the (x, thickness) plane; 3: "
                        "full 3D laminate.");
      prm.declare_entry(
        "Kinematics",
        "small strain",
        Patterns::Selection("small strain|total Lagrangian"),
        "small strain: linear strain, the bulk stiffness assembled once. "
        "total Lagrangian: Green-Lagrange strain and second Piola-Kirchhoff "
        "stress (St Venant-Kirchhoff plies with the small-strain "
        "stiffness), for large rotations and buckling; the load steps are "
        "solved by Newton-Raphson with the consistent tangent (material and "
        "geometric stiffness), with or without cohesive interfaces. Loads "
        "are dead loads on the undeformed configuration (a pressure keeps "
        "its initial direction); the field output and the point values "
        "give the Green-Lagrange strain and the second Piola-Kirchhoff "
        "stress. Plastic plies (Materials/Plasticity) return S to the "
        "Hoffman surface with E = E_e + E_p (large rotations, small "
        "strains).");
      Geometry::declare_parameters(prm);
      Materials::declare_parameters(prm);
      Discretization::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      LinearSolver::declare_parameters(prm);
      CohesiveInterfaces::declare_parameters(prm);
      NonlinearSolver::declare_parameters(prm);
      Time::declare_parameters(prm);
      Output::declare_parameters(prm);
      Adaptivity::declare_parameters(prm);
      Buckling::declare_parameters(prm);
      Checkpoint::declare_parameters(prm);
      CrackInsertion::declare_parameters(prm);
      Impactor::declare_parameters(prm);
      Contact::declare_parameters(prm);
    }



    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      dimension        = prm.get_integer("Dimension");
      total_lagrangian = prm.get("Kinematics") == "total Lagrangian";
      geometry.parse_parameters(prm);
      geometry.in_plane = geometry.in_plane && dimension == 2;
      if (dimension == 2 && geometry.hole_radius > 0 && !geometry.in_plane)
        throw InputError("Geometry/Hole radius",
                         "an open hole goes through the thickness: it needs "
                         "Dimension = 3 or Geometry/2D model = in-plane");
      materials.parse_parameters(prm);
      plastic_plies = false;
      for (const Ply &ply : geometry.plies)
        plastic_plies
          = plastic_plies
            || materials.materials[materials.index_of(ply.material)].plastic;
      discretization.parse_parameters(prm);
      boundary_conditions.parse_parameters(prm, dimension);
      linear_solver.parse_parameters(prm);
      cohesive.parse_parameters(prm, geometry.plies.size());
      if (geometry.in_plane && !cohesive.interfaces.empty())
        throw InputError("Cohesive interfaces/Interfaces",
                         "Geometry/2D model = in-plane homogenizes the plies "
                         "through the thickness, so there are no ply "
                         "interfaces to make cohesive; use 2D model = "
                         "cross-section or Dimension = 3");
      nonlinear_solver.parse_parameters(prm);
      time.parse_parameters(prm);
      output.parse_parameters(prm, dimension);
      adaptivity.parse_parameters(prm);
      if (adaptivity.active() && !cohesive.interfaces.empty())
        throw InputError("Adaptivity/Refinement cycles",
                         "a scene with cohesive interfaces adapts during its "
                         "load history (Refine every, Error threshold, "
                         "Process zone elements), not by cycles of whole "
                         "runs; set Refinement cycles = 0");
      buckling.parse_parameters(prm);
      check_buckling_input();
      check_kinematics_input();
      if (geometry.imperfection_mode > 0
          && (time.explicit_dynamics || geometry.in_plane))
        throw InputError("Geometry/Imperfection mode",
                         "a buckling mode is computed for a static scene "
                         "with an out-of-plane direction: it needs "
                         "Time/Time integration = static and not 2D model "
                         "= in-plane");
      checkpoint.parse_parameters(prm, output.directory);
      cracks.parse_parameters(prm, geometry.plies.size());
      // Before the checks of the Newton path: a prescribed sphere puts a
      // static run on it, and refuses what it cannot follow with its own
      // reason.
      impactor.parse_parameters(prm, dimension);
      check_impactor_input();
      // Contact between the bodies puts a static run on the Newton path
      // (and makes a scene nonlinear for arc-length).
      contact.parse_parameters(prm, geometry.plies.size());
      check_arc_length_input();
      // Only the Newton path counts its steps against the limit; a linear
      // or explicit run would silently ignore it.
      if (nonlinear_solver.max_steps > 0
          && (time.explicit_dynamics
              || (cohesive.interfaces.empty() && !cracks.active
                  && !total_lagrangian && !plastic_plies && !impactor.active
                  && !contact.active)))
        throw InputError("Nonlinear solver/Maximum steps",
                         "ends runs on the static Newton path (cohesive "
                         "interfaces, crack insertion, total Lagrangian "
                         "kinematics, plastic plies, a prescribed "
                         "impactor or contact between the bodies), and "
                         "this run is not one: shorten Time/End time "
                         "instead");
      if (adaptivity.during_history() && cohesive.interfaces.empty()
          && ((!cracks.active && !time.explicit_dynamics && !plastic_plies
               && !contact.active && !impactor.active)
              || adaptivity.process_zone_elements > 0))
        throw InputError(
          adaptivity.process_zone_elements > 0 ?
            "Adaptivity/Process zone elements" :
          adaptivity.refine_every > 0 ? "Adaptivity/Refine every" :
                                        "Adaptivity/Error threshold",
          "refinement during a load history is for explicit runs and for "
          "scenes with cohesive interfaces, crack insertion, plastic "
          "plies, an impactor or contact between the bodies (the "
          "process-zone rule for scenes with cohesive interfaces); a linear "
          "static scene adapts by Refinement cycles");
      if (dimension == 2 && adaptivity.process_zone_axes == 2)
        throw InputError("Adaptivity/Process zone directions",
                         "y is the thickness of a 2D laminate; the process-"
                         "zone rule refines along the plies (x)");
      if (dimension == 3 && adaptivity.process_zone_axes != 3
          && adaptivity.by_estimator())
        throw InputError("Adaptivity/Process zone directions",
                         "the estimator's marks during the load history "
                         "(Refine every, Error threshold) refine along x "
                         "and y, and one of the two cannot be kept from "
                         "the process zone's cells; use xy with them");
      check_crack_input();
      if (adaptivity.active() && checkpoint.by_count_or_stop())
        throw InputError(checkpoint.every_n_steps > 0 ?
                           "Checkpoint/Every n steps" :
                           "Checkpoint/Stop after step",
                         "refinement cycles (Adaptivity/Refinement cycles) "
                         "repeat the whole run per mesh and cannot be "
                         "resumed; a run that adapts during its load "
                         "history (cohesive interfaces) can");
      if (time.explicit_dynamics)
        check_explicit_adaptivity_input();
      check_contact_input();
      check_plasticity_input();
      check_prism_input();
      check_mesh_file_input();
    }



    void
    Parameters::check_prism_input() const
    {
      if (!geometry.prisms)
        return;
      const std::string name = "Geometry/Element shape";
      const auto refuse = [&](const bool condition, const std::string &what) {
        if (condition)
          throw InputError(name,
                           "a prism mesh cannot be combined yet with " + what);
      };
      refuse(dimension != 3,
             "Dimension = 2 (prisms are the 3D extrusion of triangles)");
      refuse(!geometry.refinement_region.empty(),
             "a Geometry/Refinement region (deal.II cannot refine wedges)");
      // Wedges adapt by global remeshing (deal.II cannot refine them):
      // between the cycles of a static run, or when the estimator's
      // triggers fire during the load history of a Newton or explicit
      // run.
      // The process-zone rule remeshes to its own size field.
      const bool process_zone = adaptivity.process_zone_elements > 0;
      refuse(process_zone && adaptivity.by_estimator(),
             "Adaptivity/Process zone elements together with Refine every "
             "or Error threshold (a remeshing meshes to one size field, the "
             "process zone's or the ZZ estimate's)");
      refuse(process_zone && adaptivity.process_zone_axes != 3,
             "Adaptivity/Process zone directions = x or y (a remeshing "
             "meshes to an in-plane size, the same along x and y)");
      refuse(process_zone && time.explicit_dynamics,
             "Adaptivity/Process zone elements in an explicit run (not yet: "
             "use Error threshold)");
      // Cycles and the estimator's triggers remesh to the ZZ size field;
      // every remeshing (the process-zone rule's too) extrudes the plane.
      const bool by_estimate = adaptivity.active() || adaptivity.by_estimator();
      const bool remeshing = adaptivity.active() || adaptivity.during_history();
      refuse(by_estimate
               && adaptivity.estimator == Adaptivity::Estimator::kelly,
             "Adaptivity/Estimator = kelly (prisms are remeshed by the ZZ "
             "estimator)");
      refuse(by_estimate
               && adaptivity.strategy != Adaptivity::Strategy::error_target
               && adaptivity.strategy != Adaptivity::Strategy::uniform,
             "Adaptivity/Strategy = fixed fraction or fixed number (prisms "
             "are remeshed to a size field: Strategy = error target, or "
             "uniform to halve every size)");
      refuse(remeshing && geometry.mesh_distortion > 0,
             "adaptivity with a Geometry/Mesh distortion");
      refuse(remeshing && !geometry.imperfection.empty(),
             "adaptivity with a Geometry/Imperfection (remeshing sizes the "
             "columns of an extruded mesh)");
      // A remeshing meshes the outline again: the vertices a mode moved
      // would lose their imperfection.
      refuse(remeshing && geometry.imperfection_mode > 0,
             "adaptivity with a Geometry/Imperfection mode (a remeshing "
             "would mesh the laminate without its imperfection)");
      refuse(remeshing && geometry.mesh_file.empty()
               && geometry.hole_radius == 0 && geometry.global_refinements > 0,
             "adaptivity on the box with Global refinements > 0 (they also "
             "split the plies through the thickness, which a remeshing "
             "would lose: set Elements per ply instead)");
      refuse(remeshing && geometry.mesh_file.size() > 4
               && geometry.mesh_file.substr(geometry.mesh_file.size() - 4)
                    == ".msh",
             "adaptivity on a Geometry/Mesh file that is a .msh (a mesh "
             "without its geometry cannot be remeshed: give the .geo of the "
             "in-plane outline)");
      // Ply interfaces are the triangles between the layers of wedges.
      const bool interfaces = !cohesive.interfaces.empty();
      if (interfaces && cohesive.lobatto && discretization.degree > 1)
        throw InputError("Cohesive interfaces/Quadrature",
                         "lobatto (nodal) integration needs Finite element "
                         "degree = 1 on prisms: a quadratic triangle has no "
                         "nodal rule with positive weights; set Quadrature = "
                         "gauss");
      refuse(cracks.active, "Crack insertion/Criterion");
      refuse(contact.active, "Contact/Enable");
      refuse(impactor.active, "an impactor (Impactor/Radius > 0)");
      refuse(time.explicit_dynamics && discretization.degree != 1,
             "Time/Time integration = explicit with Discretization/Finite "
             "element degree = 2 (the lumped mass of a quadratic wedge is "
             "not positive)");
      refuse(output.write_xdmf,
             "Output/Field format = xdmf or vtu+xdmf (deal.II 9.4 writes "
             "wedges into XDMF as tetrahedra); use vtu");
      refuse(time.explicit_dynamics && time.mass_scaling_step > 0,
             "Time/Mass scaling time step > 0");
    }



    void
    Parameters::check_mesh_file_input() const
    {
      if (geometry.mesh_file.empty())
        return;
      const std::string name = "Geometry/Mesh file";
      const auto refuse = [&](const bool condition, const std::string &what) {
        if (condition)
          throw InputError(name, "cannot be combined with " + what);
      };
      refuse(dimension != 3,
             "Dimension = 2 (the file's outline is extruded through the "
             "plies)");
      refuse(geometry.hole_radius > 0,
             "a Geometry/Hole radius (a hole belongs in the mesh file)");
      refuse(geometry.mesh_distortion > 0,
             "a Geometry/Mesh distortion (it is for the box mesh)");
      // The bottom and the top are planes of the extrusion; the sides are
      // whatever curves the file names x-, x+, y-, y+.
      const std::string &patch_face = boundary_conditions.patch.face;
      refuse(!patch_face.empty() && patch_face[0] != 'z',
             "a Boundary conditions/Patch load on a side face (Face = z- or "
             "z+ only: the sides of a mesh file need not be planes)");
    }



    void
    Parameters::check_contact_input() const
    {
      if (!contact.active)
        return;
      const std::string enable = "Contact/Enable";
      if (!time.explicit_dynamics)
        check_static_contact_input();
      require(discretization.degree == 1,
              enable,
              "node-to-face contact needs Discretization/Finite element "
              "degree = 1 (bilinear faces)");
      require(!geometry.in_plane || contact.unbonded_interfaces.empty(),
              "Contact/Unbonded interfaces",
              "Geometry/2D model = in-plane homogenizes the plies through "
              "the thickness, so there are no ply interfaces to release; "
              "use 2D model = cross-section or Dimension = 3");
      for (const unsigned int k : contact.unbonded_interfaces)
        require(!std::binary_search(cohesive.interfaces.begin(),
                                    cohesive.interfaces.end(),
                                    k),
                "Contact/Unbonded interfaces",
                "interface " + std::to_string(k)
                  + " is also in Cohesive interfaces/Interfaces: an "
                    "interface is either bonded or not");
    }



    void
    Parameters::check_static_contact_input() const
    {
      // What the static path does not evaluate with contact yet.
      // The dissipated energy of a step, (P0 t - P t0) / 2, holds for
      // secant (unload-to-origin) laws only: the contact's stored energy
      // and its friction are neither.
      require(!nonlinear_solver.dissipation_control,
              "Nonlinear solver/Control",
              "dissipation or opening control measures the energy of a "
              "step as that of secant laws, which contact between the "
              "bodies and its friction are not; use Control = displacement "
              "or arc-length with Contact/Enable");
      require(!buckling.active() && geometry.imperfection_mode == 0,
              "Buckling/Number of modes",
              "a linear buckling analysis does not include the contact "
              "between the bodies; set it to 0 with Contact/Enable");
      require(!adaptivity.active(),
              "Adaptivity/Refinement cycles",
              "the contact surfaces are those of the initial mesh in a "
              "static run; set Refinement cycles = 0 with Contact/Enable");
      require(!total_lagrangian || !adaptivity.during_history(),
              "Contact/Enable",
              "contact between the bodies on a mesh that adapts during a "
              "static run has been tested with small-strain kinematics "
              "only: switch Refine every, Error threshold and Process "
              "zone elements off with Kinematics = total Lagrangian");
    }



    void
    Parameters::check_impactor_input() const
    {
      if (!impactor.active)
        return;
      const std::string face = "Impactor/Face";
      require(impactor.prescribed || time.explicit_dynamics,
              "Impactor/Motion",
              "a free impactor moves with the explicit time integration: set "
              "Time/Time integration = explicit, or Motion = prescribed for "
              "a static indentation");
      require(!geometry.in_plane,
              face,
              "the in-plane 2D model has no thickness to indent; use "
              "Dimension = 3 or the cross-section (2D model = "
              "cross-section)");
      if (impactor.prescribed)
        {
          require(!nonlinear_solver.arc_length
                    && !nonlinear_solver.dissipation_control,
                  "Nonlinear solver/Control",
                  "a prescribed impactor is driven by t: use Control = "
                  "displacement with an Impactor");
          require(!buckling.active(),
                  "Buckling/Number of modes",
                  "a linear buckling analysis does not include the "
                  "impactor's contact yet; set it to 0 with an Impactor");
          require(!adaptivity.active(),
                  "Adaptivity/Refinement cycles",
                  "the impactor's contact nodes are those of the initial "
                  "mesh; refine the contact zone with Geometry/Refinement "
                  "region instead");
        }
      require(time.mass_scaling_step == 0,
              face,
              "mass scaling (Time/Mass scaling time step) would change the "
              "momentum the impactor exchanges; set it to 0");
    }



    void
    Parameters::check_explicit_adaptivity_input() const
    {
      if (adaptivity.active())
        throw InputError("Adaptivity/Refinement cycles",
                         "an explicit run adapts during its history (Refine "
                         "every, Error threshold, Process zone elements, "
                         "checked at output steps), not by cycles of whole "
                         "runs; set Refinement cycles = 0");
      if (!adaptivity.during_history())
        return;
      const std::string why = "an explicit run that adapts its mesh (Refine "
                              "every, Error threshold, Process zone "
                              "elements) chooses its step on every new mesh";
      if (time.time_step > 0)
        throw InputError("Time/Time step",
                         why
                           + "; set Time step = 0 (the stable step times "
                             "Safety factor)");
      if (time.mass_scaling_step > 0)
        throw InputError("Time/Mass scaling time step",
                         why + " from the real masses; set it to 0");
      if (cracks.active)
        throw InputError("Crack insertion/Criterion",
                         "crack insertion in explicit runs chooses the "
                         "step for every crack pattern of the initial mesh, "
                         "and cannot be combined yet with an adaptive mesh "
                         "(Refine every, Error threshold, Process zone "
                         "elements)");
    }



    void
    Parameters::check_arc_length_input() const
    {
      if (!nonlinear_solver.arc_length)
        return;
      const std::string name = "Nonlinear solver/Control";
      if (time.explicit_dynamics)
        throw InputError(name,
                         "arc-length follows a static equilibrium path: it "
                         "needs Time/Time integration = static");
      if (!total_lagrangian && cohesive.interfaces.empty() && !plastic_plies
          && !contact.active)
        throw InputError(name,
                         "arc-length follows a nonlinear path, and this "
                         "scene is linear: set Kinematics = total "
                         "Lagrangian, make interfaces cohesive, plies "
                         "plastic or enable Contact");
      if (adaptivity.during_history())
        throw InputError(name,
                         "arc-length with refinement during the load "
                         "history is not available yet; switch Refine "
                         "every, Error threshold and Process zone elements "
                         "off");
    }



    void
    Parameters::check_crack_input() const
    {
      if (!cracks.active)
        return;
      const std::string name = "Crack insertion/Criterion";
      const auto refuse = [&](const bool condition, const std::string &what) {
        if (condition)
          throw InputError(name,
                           "crack insertion runs on the static Newton path "
                           "with displacement or load control and on the "
                           "explicit path so far; it cannot be combined "
                           "with "
                             + what);
      };
      refuse(total_lagrangian, "Kinematics = total Lagrangian");
      refuse(geometry.in_plane,
             "Geometry/2D model = in-plane (a homogenized laminate has no "
             "plies to crack)");
      refuse(adaptivity.active(),
             "Adaptivity/Refinement cycles (cycles of a linear scene; "
             "refinement during the load history, Refine every, Error "
             "threshold, works with cracks)");
      refuse(nonlinear_solver.arc_length
               || nonlinear_solver.dissipation_control,
             "Nonlinear solver/Control = "
               + std::string(nonlinear_solver.arc_length ? "arc-length" :
                                                           "dissipation or "
                                                           "opening"));
      refuse(buckling.active(), "Buckling/Number of modes > 0");
      if (time.explicit_dynamics && time.mass_scaling_step > 0)
        throw InputError("Time/Mass scaling time step",
                         "mass scaling is not available with crack "
                         "insertion (the mass a node gets would change when "
                         "it splits); set it to 0");
    }



    void
    Parameters::check_plasticity_input() const
    {
      if (!plastic_plies)
        return;
      const auto refuse = [&](const bool condition, const std::string &what) {
        if (condition)
          throw InputError("Materials/Plasticity",
                           "plastic plies run on the static Newton path "
                           "so far; they cannot be combined "
                           "with "
                             + what);
      };
      refuse(time.explicit_dynamics,
             "Time/Time integration = explicit (the explicit path's "
             "internal force is the elastic one)");
      refuse(geometry.in_plane,
             "Geometry/2D model = in-plane (a laminate homogenized "
             "through its thickness has no plies to yield)");
      refuse(cracks.active,
             "Crack insertion/Criterion (the same Hoffman surface would "
             "be the yield surface and the crack criterion)");
      // Imperfection mode is the elastic state's mode: the plies have not
      // yielded at the set-up.
      refuse(buckling.active(),
             "a linear buckling analysis (Buckling/Number of modes): the "
             "tangent of a yielded state differs between loading and "
             "unloading");
      refuse(adaptivity.active(),
             "Adaptivity/Refinement cycles (cycles repeat a linear run; a "
             "plastic run adapts during its load history: Refine every, "
             "Error threshold)");
      refuse(nonlinear_solver.dissipation_control
               && cohesive.interfaces.empty(),
             "Nonlinear solver/Control = dissipation or opening without "
             "cohesive interfaces (they control what the interfaces "
             "dissipate or open); use displacement or arc-length");
    }



    void
    Parameters::check_kinematics_input() const
    {
      if (!total_lagrangian)
        return;
      const std::string why = "Kinematics = total Lagrangian ";
      if (time.explicit_dynamics)
        throw InputError("Kinematics",
                         why
                           + "is for static (load-stepped) runs so far: "
                             "the explicit path has the small-strain "
                             "internal force; set Time/Time integration = "
                             "static or Kinematics = small strain");
      if (adaptivity.active())
        throw InputError("Kinematics",
                         why
                           + "runs the Newton path, and refinement cycles "
                             "are for linear scenes; set Adaptivity/"
                             "Refinement cycles = 0");
      if (nonlinear_solver.dissipation_control && cohesive.interfaces.empty())
        throw InputError("Nonlinear solver/Control",
                         "Control = dissipation or opening follows what the "
                         "cohesive interfaces dissipate or open, and this "
                         "scene has none; use Control = displacement");
    }



    void
    Parameters::check_buckling_input() const
    {
      if (!buckling.active())
        return;
      const std::string name = "Buckling/Number of modes";
      if (time.explicit_dynamics)
        throw InputError(name,
                         "linear buckling analyses a static state: it needs "
                         "Time/Time integration = static");
      if (geometry.in_plane)
        throw InputError(name,
                         "Geometry/2D model = in-plane has no out-of-plane "
                         "displacement to buckle into; use Dimension = 3 or "
                         "2D model = cross-section");
      const auto &times = buckling.analysis_times;
      if (!times.empty() && times.back() > time.end_time * (1 + 1e-12))
        throw InputError("Buckling/Analysis times",
                         "the last, " + number_text(times.back())
                           + ", lies past Time/End time ("
                           + number_text(time.end_time) + ")");
      if (!times.empty() && adaptivity.active())
        throw InputError("Buckling/Analysis times",
                         "refinement cycles analyse each mesh after its last "
                         "step; leave Analysis times empty with Adaptivity/"
                         "Refinement cycles");
    }



    void
    Checkpoint::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      prm.declare_entry("Every n steps",
                        "0",
                        Patterns::Integer(0),
                        "Write a checkpoint every this many load steps (0: "
                        "not by count), and after the last one. Explicit "
                        "runs count output steps (rows of history.csv). "
                        "SIGTERM or SIGINT always ends a load-stepped run "
                        "after the current step with a checkpoint.");
      prm.declare_entry("Every minutes",
                        "30",
                        Patterns::Double(0),
                        "Also write one when this much wall time [min] has "
                        "passed since the last (0: not by time).");
      prm.declare_entry("Keep",
                        "2",
                        Patterns::Integer(1),
                        "Number of newest complete checkpoints kept; older "
                        "ones are deleted.");
      prm.declare_entry("Directory",
                        "",
                        Patterns::Anything(),
                        "Folder of the checkpoints (empty: <Output "
                        "directory>/checkpoints). A run that does not "
                        "resume deletes the checkpoints it finds there.");
      prm.declare_entry("Resume",
                        "false",
                        Patterns::Bool(),
                        "Continue from the newest complete checkpoint in "
                        "Directory if there is one (else start from the "
                        "beginning), with this file's parameters; "
                        "amfrac --resume DIR does the same with the "
                        "parameters stored in the checkpoint.");
      prm.declare_entry("Stop after step",
                        "0",
                        Patterns::Integer(0),
                        "Write a checkpoint after this step and stop with "
                        "exit status 75, as on SIGTERM (0: run to the "
                        "end); splits a long run into jobs.");
      prm.leave_subsection();
    }



    void
    Checkpoint::parse_parameters(ParameterHandler  &prm,
                                 const std::string &output)
    {
      prm.enter_subsection("Checkpoint");
      every_n_steps   = prm.get_integer("Every n steps");
      every_minutes   = prm.get_double("Every minutes");
      keep            = prm.get_integer("Keep");
      directory       = prm.get("Directory");
      resume          = prm.get_bool("Resume");
      stop_after_step = prm.get_integer("Stop after step");
      prm.leave_subsection();
      require(std::isfinite(every_minutes),
              "Checkpoint/Every minutes",
              "must be a finite number");
      if (directory.empty())
        directory = output + "/checkpoints";
    }



    void
    Buckling::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Buckling");
      prm.declare_entry(
        "Number of modes",
        "0",
        Patterns::Integer(0, 100),
        "After the last load step of a static run, the lowest positive load "
        "factors lambda of (K + lambda K_G) v = 0 and their modes, with K_G "
        "the geometric stiffness of the stress of that step (0: no "
        "buckling analysis). lambda multiplies the whole load of the last "
        "step, prescribed displacements included. With Kinematics = total "
        "Lagrangian, the linearized pre-buckling of the state at t instead: "
        "the lowest positive mu of (K_T + mu dK_T/dt) v = 0, K_T the "
        "tangent and dK_T/dt its derivative along the path tangent du/dt; "
        "lambda = (t + mu) / t, and the critical loads are extrapolated "
        "along the path tangent (loads and prescribed displacements must "
        "be proportional to t). Written to buckling.csv "
        "and, with VTU output, to buckling_modes.pvd. With Adaptivity/"
        "Refinement cycles, every cycle analyses its mesh (a cycle column "
        "in buckling.csv, lambda_1 in the convergence table).");
      prm.declare_entry("Block size",
                        "0",
                        Patterns::Integer(0, 32),
                        "Vectors per block of the block Lanczos iteration "
                        "(0: min(k, 2) for k modes). A block of at least "
                        "m finds a load factor of multiplicity m (equal "
                        "modes of a symmetric structure) reliably; a "
                        "smaller one finds the copies only through "
                        "rounding, after more solves.");
      prm.declare_entry("Tolerance",
                        "1e-8",
                        Patterns::Double(0),
                        "Relative residual |B v - mu K v| / |B v| (B = "
                        "-K_G, mu = 1/lambda) of every wanted mode; the "
                        "load factor's error is about its square.");
      prm.declare_entry("Max basis size",
                        "240",
                        Patterns::Integer(2),
                        "Largest Lanczos basis (vectors) before the "
                        "analysis gives up with an error; each vector "
                        "costs two solution vectors of memory.");
      prm.declare_entry(
        "Analysis times",
        "",
        Patterns::List(Patterns::Double(0)),
        "Load parameters t at which to analyse during the load history "
        "instead of after the last step: the first converged step at or "
        "past each (comma-separated, increasing, at most End time). Each "
        "analysis adds its rows to buckling.csv (its time column the "
        "state's t) and, with VTU output, its modes as "
        "buckling_modes-N.pvd (N: the analysis, from 1).");
      prm.leave_subsection();
    }



    void
    Buckling::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Buckling");
      n_modes        = prm.get_integer("Number of modes");
      block_size     = prm.get_integer("Block size");
      tolerance      = prm.get_double("Tolerance");
      max_basis_size = prm.get_integer("Max basis size");
      analysis_times.clear();
      for (const auto &entry :
           Utilities::split_string_list(prm.get("Analysis times")))
        analysis_times.push_back(Utilities::string_to_double(entry));
      prm.leave_subsection();
      for (unsigned int i = 1; i < analysis_times.size(); ++i)
        if (!(analysis_times[i] > analysis_times[i - 1]))
          throw InputError("Buckling/Analysis times", "must increase");
      if (!analysis_times.empty() && !(analysis_times[0] > 0))
        throw InputError("Buckling/Analysis times",
                         "must be positive (t = 0 is the unloaded state)");
      if (!analysis_times.empty() && n_modes == 0)
        throw InputError("Buckling/Analysis times",
                         "need Buckling/Number of modes > 0");
      // A block of 2 finds the pairs of equal modes of symmetric plates
      // for 1.5 times the solves of single-vector Lanczos (4: 2.4 times).
      if (block_size == 0)
        block_size = std::max(std::min(n_modes, 2u), 1u);
      if (n_modes > 0 && max_basis_size < n_modes + 2 * block_size)
        throw InputError("Buckling/Max basis size",
                         "must be at least Number of modes plus two blocks ("
                           + std::to_string(n_modes + 2 * block_size) + ")");
      if (!(tolerance > 0))
        throw InputError("Buckling/Tolerance", "must be positive");
    }



    void
    Adaptivity::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      prm.declare_entry("Refinement cycles",
                        "0",
                        Patterns::Integer(0, 30),
                        "Number of solve-estimate-refine cycles after the "
                        "first solve (0: no adaptivity). Each cycle solves "
                        "all load steps on the current mesh, estimates the "
                        "error at the last step and refines. Prism meshes "
                        "are regenerated by Gmsh instead (the seed's global "
                        "remeshing): the in-plane size of a cell becomes h "
                        "(eta_target / eta_K)^(1/p), between h / 4 and 2 h, "
                        "with eta_target the equal share of Target error, "
                        "and the solution is carried to the new mesh as "
                        "the first guess of an iterative solver.");
      prm.declare_entry("Estimator",
                        "zz",
                        Patterns::Selection("zz|kelly"),
                        "zz: Zienkiewicz-Zhu, stress recovered ply by ply "
                        "(superconvergent patch recovery), error in the "
                        "energy norm "
                        "[sqrt(N mm)]; kelly: traction jumps across faces "
                        "(none across ply interfaces with continuous "
                        "traction) and traction residuals on unsupported "
                        "boundary faces. The relative ZZ error is reported "
                        "with either.");
      prm.declare_entry("Strategy",
                        "fixed fraction",
                        Patterns::Selection(
                          "uniform|fixed fraction|fixed number|error target"),
                        "uniform: refine every cell; fixed fraction: refine "
                        "the cells holding Refine fraction of the total "
                        "squared error (coarsen those holding Coarsen "
                        "fraction); fixed number: refine Refine fraction of "
                        "the cells (coarsen Coarsen fraction); error target: "
                        "refine every cell whose ZZ error exceeds its equal "
                        "share of Target error and stop once the relative "
                        "ZZ error is below Target error.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "Fraction of the squared error (fixed fraction) or "
                        "of the cells (fixed number) to refine.");
      prm.declare_entry("Coarsen fraction",
                        "0",
                        Patterns::Double(0, 1),
                        "Fraction of the squared error or of the cells to "
                        "coarsen (never below the initial mesh).");
      prm.declare_entry("Target error",
                        "0.01",
                        Patterns::Double(0, 1),
                        "Strategy = error target: the relative ZZ error "
                        "||e*|| / sqrt(||u_h||^2 + ||e*||^2) to reach.");
      prm.declare_entry("Maximum refinement level",
                        "10",
                        Patterns::Integer(1, 30),
                        "Cells of this level (0: the initial structured "
                        "mesh before global refinements) are not refined.");
      prm.declare_entry("Refine every",
                        "0",
                        Patterns::Integer(0),
                        "Scenes with cohesive interfaces or crack "
                        "insertion, and explicit runs: estimate, mark by "
                        "Strategy and refine after every this many "
                        "converged load steps (explicit: output steps, "
                        "rows of history.csv), moving the state to the new "
                        "mesh (0: never; prisms are remeshed instead). "
                        "Explicit runs then choose a new stable step.");
      prm.declare_entry("Error threshold",
                        "0",
                        Patterns::Double(0, 1),
                        "Scenes with cohesive interfaces or crack "
                        "insertion, and explicit runs: also refine after a "
                        "converged step (explicit: an output step) whose "
                        "relative ZZ error exceeds this (the seed's "
                        "criterion; 0: off). Prisms are remeshed "
                        "instead, to the size field of Strategy "
                        "= error target or uniform; if the first estimate "
                        "on a new mesh is not a tenth below the error that "
                        "made it (the size bounds stop the remeshing from "
                        "reaching Target error), the next remeshing waits "
                        "until the error has grown by a tenth beyond that "
                        "estimate.");
      prm.declare_entry("Process zone elements",
                        "0",
                        Patterns::Integer(0, 100),
                        "Scenes with cohesive interfaces: keep at least "
                        "this many elements (in-plane size) across the "
                        "cohesive-zone length l_cz = 0.88 E_zz G_Ic / "
                        "sigma_N^2 [mm] around every delamination front, "
                        "i.e. within l_cz of the bonded points that lie "
                        "within l_cz of a damaged or debonded point: then "
                        "cells within 2 l_cz are refined along the plies "
                        "(never through the thickness) and cells farther "
                        "than 3 l_cz coarsened (never below the initial "
                        "mesh). Checked after every converged step and "
                        "before the first; in explicit runs after every "
                        "output step (0: off). Prisms (Newton runs) are "
                        "remeshed instead when a cell within l_cz of a "
                        "front is coarser than 1.5 l_cz / n: to l_cz / n "
                        "within 2 l_cz of the fronts, growing by half the "
                        "distance beyond up to the first mesh's size.");
      prm.declare_entry("Process zone directions",
                        "xy",
                        Patterns::Selection("xy|x|y"),
                        "3D: the in-plane directions along which the "
                        "process-zone rule measures the element size and "
                        "refines. xy for fronts of any shape; x when every "
                        "front runs across the width (y) and advances along "
                        "x, as in a DCB, ENF or MMB strip: the cells then "
                        "keep their size across the width, which the rule "
                        "does not need to resolve (and y likewise). 2D: "
                        "only x, the one direction along the plies.");
      prm.declare_entry("Maximum cells",
                        "0",
                        Patterns::Integer(0),
                        "Prism meshes (global remeshing): the element size "
                        "field of a remeshing is scaled up so that the new "
                        "mesh is predicted to have at most this many cells "
                        "(0: no limit).");
      prm.declare_entry("Minimum element size",
                        "0",
                        Patterns::Double(0),
                        "Prism meshes (global remeshing): the smallest "
                        "in-plane element size a remeshing may ask of Gmsh "
                        "[mm] (0: no bound besides, for the ZZ size field, "
                        "a quarter of the old size per remeshing; the "
                        "process-zone rule asks for l_cz / n at once, and "
                        "takes this size as fine enough where l_cz / n is "
                        "smaller).");
      prm.declare_entry(
        "Plastic history transfer",
        "nearest point",
        Patterns::Selection("nearest point|projection"),
        "Prism meshes (global remeshing) with plastic plies: how the "
        "plastic strain moves to the Gauss points of the new mesh. nearest "
        "point: each new point takes the plastic strain of the nearest old "
        "Gauss point of the old cell that holds it. projection: the seed's "
        "tau_1, projected to the old vertices ply by ply and interpolated; "
        "it smooths the plastic zone, which then yields again after every "
        "remeshing (on prm/plastic_beam_prism.prm the plastic work comes "
        "out 5.4 % above the uniform meshes' against 0.2 % with nearest "
        "point). Either way kappa is injected from the nearest old point, "
        "or is the largest inside the new cell if that is larger.");
      prm.leave_subsection();
    }



    void
    Adaptivity::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      cycles    = prm.get_integer("Refinement cycles");
      estimator = prm.get("Estimator") == "kelly" ? Estimator::kelly :
                                                    Estimator::zienkiewicz_zhu;
      const std::string name = prm.get("Strategy");
      strategy               = name == "uniform"        ? Strategy::uniform :
                               name == "fixed fraction" ? Strategy::fixed_fraction :
                               name == "fixed number" ? Strategy::fixed_number :
                                                        Strategy::error_target;
      refine_fraction        = prm.get_double("Refine fraction");
      coarsen_fraction       = prm.get_double("Coarsen fraction");
      target_error           = prm.get_double("Target error");
      max_level              = prm.get_integer("Maximum refinement level");
      refine_every           = prm.get_integer("Refine every");
      error_threshold        = prm.get_double("Error threshold");
      process_zone_elements  = prm.get_integer("Process zone elements");
      max_cells              = prm.get_integer("Maximum cells");
      min_element_size       = prm.get_double("Minimum element size");
      plastic_nearest_point
        = prm.get("Plastic history transfer") == "nearest point";
      const std::string axes = prm.get("Process zone directions");
      process_zone_axes      = axes == "x" ? 1 : axes == "y" ? 2 : 3;
      prm.leave_subsection();
      if (strategy == Strategy::error_target && estimator == Estimator::kelly)
        throw InputError("Adaptivity/Strategy",
                         "error target needs Estimator = zz: the Kelly "
                         "indicator is not a relative error");
      if (strategy == Strategy::fixed_fraction
          && refine_fraction + coarsen_fraction > 1)
        throw InputError("Adaptivity/Coarsen fraction",
                         "Refine fraction + Coarsen fraction must not exceed "
                         "1");
    }



    namespace
    {
      /** deal.II's message of a parser exception, on one line. */
      std::string
      one_line(const ExceptionBase &e)
      {
        std::ostringstream out;
        e.print_info(out);
        std::string text = out.str(), result;
        for (const char c : text)
          if (c == '\n')
            result += ' ';
          else
            result += c;
        return Utilities::trim(result);
      }

      template <typename Reader>
      Parameters
      read_parameters(const Reader &reader)
      {
        ParameterHandler prm;
        Parameters::declare_parameters(prm);
        try
          {
            reader(prm);
          }
        catch (const ExceptionBase &e)
          {
            throw InputError(one_line(e));
          }
        Parameters parameters;
        parameters.parse_parameters(prm);
        std::ostringstream text;
        prm.print_parameters(text, ParameterHandler::ShortPRM);
        parameters.text = text.str();
        return parameters;
      }
    } // namespace



    Parameters
    Parameters::from_file(const std::string &filename)
    {
      if (!std::ifstream(filename))
        throw InputError("cannot open parameter file '" + filename + "'");
      return read_parameters([&](ParameterHandler &prm) {
        prm.parse_input(filename);
        // A mesh file is found next to the parameter file, wherever the
        // run starts (and a checkpoint keeps the absolute path).
        prm.enter_subsection("Geometry");
        const std::filesystem::path mesh
          = Utilities::trim(prm.get("Mesh file"));
        if (!mesh.empty() && mesh.is_relative())
          prm.set("Mesh file",
                  std::filesystem::absolute(
                    std::filesystem::path(filename).parent_path() / mesh)
                    .lexically_normal()
                    .string());
        prm.leave_subsection();
      });
    }



    Parameters
    Parameters::from_string(const std::string &text)
    {
      return read_parameters(
        [&](ParameterHandler &prm) { prm.parse_input_from_string(text); });
    }
  } // namespace parameters
} // namespace amfrac

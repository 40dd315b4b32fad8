#pragma once

#include <amfrac/geometry/stacking_sequence.h>
#include <amfrac/material/orthotropic.h>
#include <amfrac/parameters/contact.h>
#include <amfrac/parameters/crack_insertion.h>
#include <amfrac/parameters/impactor.h>
#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <string>
#include <vector>

namespace amfrac
{
  namespace parameters
  {
    using namespace dealii;

    /** Parse a list of ply interface indices below @p n_interfaces
     * ('all', empty or comma separated; sorted, unique); InputError for
     * @p parameter otherwise. */
    std::vector<unsigned int>
    parse_interface_list(const std::string &text,
                         const unsigned int n_interfaces,
                         const std::string &parameter);

    /** `subsection Geometry`: the laminate box and its structured mesh. */
    struct Geometry
    {
      std::string stacking_sequence;
      /** The plies of the stacking sequence, bottom first. */
      std::vector<Ply>    plies;
      std::vector<double> ply_thickness;
      double              total_thickness;
      double              length;
      double              width;
      unsigned int        elements_along_length;
      unsigned int        elements_along_width;
      unsigned int        elements_per_ply;
      /** Ratio of the largest to the smallest in-plane element length of
       * the box, smallest at both ends (1: uniform). */
      double       edge_grading = 1;
      unsigned int global_refinements;
      double       mesh_distortion;
      /** Geometry/Element shape = prism (3D): each in-plane cell of the
       * structured mesh is split into two triangles and extruded, so the
       * plies are layers of wedges. */
      bool prisms = false;
      /** 2D only: the model plane is the laminate's (x, y) plane (plane
       * stress, the stacking homogenized through the thickness) instead
       * of the (x, thickness) cross-section (plane strain). */
      bool in_plane = false;
      /** A through-thickness hole at the plate centre (0: none; 3D, or 2D
       * in-plane). */
      double hole_radius;
      /** Prisms with a hole: the Gmsh mesh's elements around it. */
      unsigned int elements_around_hole = 32;
      /** A 2D Gmsh .geo or .msh of the in-plane outline, extruded ply by
       * ply (empty: the box); an absolute path once parsed from a file. */
      std::string  mesh_file;
      std::string  refinement_region;
      unsigned int region_refinements;
      /** A displacement of the mesh's vertices (dim expressions of x, y,
       * [z]; empty: none): a geometric imperfection. */
      std::string imperfection;
      /** The mode (1: the lowest) of the linear buckling analysis of the
       * small-strain state at End time added to the vertices, scaled to a
       * largest displacement of imperfection_amplitude (0: none). */
      unsigned int imperfection_mode;
      double       imperfection_amplitude;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** `subsection Materials`: named orthotropic materials, given as
     * lists with one value per name (or one value for all). */
    struct Materials
    {
      std::vector<OrthotropicMaterial> materials;

      /** Index of the material called @p name ("" is the first one). */
      unsigned int
      index_of(const std::string &name) const;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** `subsection Discretization`. */
    struct Discretization
    {
      unsigned int degree;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** One named face of the laminate box with its boundary condition. */
    struct BoundaryFace
    {
      enum class Type
      {
        free,
        displacement,
        traction,
        pressure
      };
      std::string              name;
      Type                     type = Type::free;
      std::array<bool, 3>      components{{true, true, true}};
      std::vector<std::string> displacement;
      std::vector<std::string> traction;
      std::string              pressure;
      std::string              where;

      /** Whether Traction or Pressure is other than the default 0. */
      bool
      has_traction() const
      {
        return !(traction.size() == 1 && traction[0] == "0");
      }
      bool
      has_pressure() const
      {
        return pressure != "0";
      }
    };

    /** `subsection Boundary conditions/Patch load`: a total force (a
     * function of t) spread uniformly over a circle or rectangle on one
     * face of the laminate box, e.g. an impact pulse. */
    struct PatchLoad
    {
      /** Boundary face name; empty: no patch load. */
      std::string         face;
      bool                circle = true;
      std::vector<double> center;
      double              radius = 0;
      /** Side lengths along the face's in-plane axes (x, y, z order). */
      std::vector<double> size;
      std::string         force;
      /** Unit direction; empty: the inward normal of the face. */
      std::vector<double> direction;
    };

    /** `subsection Boundary conditions/Lever`: the rigid, weightless
     * loading lever of a mixed-mode bending test (see Lever<dim>). */
    struct Lever
    {
      /** Boundary face names; an empty hinge face means no lever. */
      std::string hinge_face;
      std::string hinge_where;
      std::string saddle_face;
      std::string saddle_where;
      /** Distance c from the saddle to the load point [mm]. */
      double length = 0;
      /** Load-point displacement along the thickness axis, in t. */
      std::string displacement;

      bool
      active() const
      {
        return !hinge_face.empty();
      }
    };

    /** `subsection Boundary conditions` with one subsection per face
     * (x-, x+, y-, y+, z-, z+; the thickness axis is z in 3D and y in 2D),
     * the loading lever and the body force. */
    struct BoundaryConditions
    {
      std::vector<BoundaryFace> faces;
      Lever                     lever;
      PatchLoad                 patch;
      std::vector<std::string>  body_force;
      std::string               constants;

      static const std::array<const char *, 6> face_names;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);

    private:
      static void
      declare_lever(ParameterHandler &prm);
      void
      parse_lever(ParameterHandler &prm, const unsigned int dim);
      static void
      declare_patch(ParameterHandler &prm);
      void
      parse_patch(ParameterHandler &prm, const unsigned int dim);
    };

    /** `subsection Linear solver`. */
    struct LinearSolver
    {
      enum class Type
      {
        direct,
        cg_amg
      };
      Type         type;
      std::string  direct_package;
      double       tolerance;
      unsigned int max_iterations;
      unsigned int smoother_sweeps;
      double       aggregation_threshold;
      double       auxiliary_threshold;
      std::string  smoother_type;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** `subsection Time`: load steps of a (quasi-)static run. */
    struct Time
    {
      double       end_time;
      unsigned int n_steps;
      /** Central differences with a lumped mass instead of static steps. */
      bool   explicit_dynamics;
      double safety_factor;
      /** Explicit: a fixed time step (0: the estimated stable one). */
      double time_step;
      /** Explicit: accept a fixed step above the estimate (stability
       * studies). */
      bool allow_unstable;
      /** Explicit: initial velocity expressions in x, y, (z). */
      std::vector<std::string> initial_velocity;
      /** Explicit: add nodal mass so that this step is stable (0: off). */
      double mass_scaling_step;
      /** Explicit: Rayleigh damping C = alpha M + beta K (bulk K). */
      double rayleigh_alpha;
      double rayleigh_beta;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** `subsection Output`. */
    struct Output
    {
      std::string  directory;
      std::string  base_name;
      bool         write_vtu;
      bool         write_xdmf;
      unsigned int every_n_steps;
      /** PNG top views of the interface damage with every field output. */
      bool                     damage_maps;
      std::vector<Point<3>>    points;
      std::vector<std::string> point_names;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };

    /** `subsection Cohesive interfaces`: which ply interfaces are bonded
     * by the seed's cohesive law, its data, and the pre-crack. */
    struct CohesiveInterfaces
    {
      /** Interface k lies between ply k and ply k + 1 (plies are counted
       * from 0 at the bottom). Sorted, unique. */
      std::vector<unsigned int> interfaces;
      double                    normal_strength;
      double                    shear_strength;
      double                    G_Ic;
      double                    G_IIc;
      double                    normal_stiffness;
      double                    shear_stiffness;
      double                    contact_penalty;
      double                    stick_penalty;
      double                    friction;
      /** Law = camanho-davila (else the seed's law) and its BK eta. */
      bool   camanho_davila;
      double bk_exponent;
      /** Gao-Bower viscosity of the bonded phase (0: none). */
      double viscosity;
      /** Gauss-Lobatto (nodal) interface quadrature instead of Gauss. */
      bool lobatto;
      /** Interfaces that carry the pre-crack, and where it is. */
      std::vector<unsigned int> precrack_interfaces;
      std::string               precrack_region;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int n_plies);

    private:
      void
      check_camanho_davila(const std::string &section) const;
    };

    /** `subsection Nonlinear solver`: Newton-Raphson for the load steps of
     * a scene with cohesive interfaces. */
    struct NonlinearSolver
    {
      unsigned int max_iterations;
      double       tolerance;
      bool         line_search;
      double       minimum_step_fraction;
      unsigned int easy_iterations;
      /** Path following by the dissipated energy (Gutierrez 2004) once a
       * displacement step dissipates more than dissipation_increment. */
      bool   dissipation_control;
      double dissipation_increment;
      /** Control = opening: the steps past the switch prescribe the
       * increase of the summed normal opening of the bonded interface
       * points (opening_increment) instead of the dissipated energy. */
      bool   opening_control = false;
      double opening_increment;
      /** Control = arc-length: Crisfield's method from the first step,
       * with the load parameter's weight psi and a step limit. */
      bool         arc_length = false;
      double       arc_length_psi;
      unsigned int max_arc_length_steps;
      /** Any control on the Newton path: the run ends after this many
       * converged steps (0: no limit). */
      unsigned int max_steps = 0;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** `subsection Adaptivity`: the refinement cycle of static scenes. */
    struct Adaptivity
    {
      enum class Estimator
      {
        zienkiewicz_zhu,
        kelly
      };
      enum class Strategy
      {
        uniform,
        fixed_fraction,
        fixed_number,
        error_target
      };
      Estimator    estimator;
      Strategy     strategy;
      unsigned int cycles;
      double       refine_fraction;
      double       coarsen_fraction;
      double       target_error;
      unsigned int max_level;
      /** Adaptivity during a load history (scenes with cohesive
       * interfaces). */
      unsigned int refine_every;
      double       error_threshold;
      unsigned int process_zone_elements;
      /** The in-plane axes along which the process-zone rule measures and
       * refines cells in 3D: bit a for axis a (x = 1, y = 2, both = 3).
       * In 2D only x, the one axis along the plies. */
      unsigned int process_zone_axes;
      /** Global remeshing (prisms): the cell budget (0: none) and the
       * smallest in-plane size [mm] (0: none). */
      unsigned int max_cells;
      double       min_element_size;
      /** Global remeshing of plastic plies: the plastic strain at a new
       * Gauss point is that of the nearest old point (true) or the seed's
       * projection to the old vertices (false). */
      bool plastic_nearest_point;

      bool
      active() const
      {
        return cycles > 0;
      }

      /** Refinement between the steps of a load history. */
      bool
      during_history() const
      {
        return refine_every > 0 || error_threshold > 0
               || process_zone_elements > 0;
      }

      /** Marking by the estimator (not only by the process-zone rule). */
      bool
      by_estimator() const
      {
        return refine_every > 0 || error_threshold > 0;
      }

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** `subsection Buckling`: linear buckling of the final state of a
     * static run. */
    struct Buckling
    {
      unsigned int n_modes;
      unsigned int block_size;
      double       tolerance;
      unsigned int max_basis_size;
      /** Load parameters at which the converged state is analysed during
       * the load history, increasing (empty: after the last step). */
      std::vector<double> analysis_times;

      bool
      active() const
      {
        return n_modes > 0;
      }

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** `subsection Checkpoint`: when to write the state of a run for a
     * restart, how many to keep, and whether to resume. */
    struct Checkpoint
    {
      /** Every this many steps (0: never by count); explicit runs count
       * output steps (rows of history.csv). */
      unsigned int every_n_steps;
      /** Every this many minutes of wall time (0: never by time). */
      double       every_minutes;
      unsigned int keep;
      /** Folder of the checkpoints (resolved: never empty). */
      std::string directory;
      bool        resume;
      /** Write a checkpoint after this step and stop (0: never). */
      unsigned int stop_after_step;

      bool
      by_count_or_stop() const
      {
        return every_n_steps > 0 || stop_after_step > 0;
      }

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &output);
    };

    /** All parameters of a run. */
    struct Parameters
    {
      unsigned int dimension;
      /** Kinematics = total Lagrangian: Green-Lagrange strain and St
       * Venant-Kirchhoff plies on the Newton path; false: small strain. */
      bool total_lagrangian;
      /** Some ply's material has Materials/Plasticity = hoffman: the
       * static Newton path with the plies' return mapping. */
      bool               plastic_plies = false;
      Geometry           geometry;
      Materials          materials;
      Discretization     discretization;
      BoundaryConditions boundary_conditions;
      LinearSolver       linear_solver;
      CohesiveInterfaces cohesive;
      NonlinearSolver    nonlinear_solver;
      Time               time;
      Output             output;
      Adaptivity         adaptivity;
      Buckling           buckling;
      Checkpoint         checkpoint;
      CrackInsertion     cracks;
      Impactor           impactor;
      Contact            contact;
      /** Every parameter with its value (ShortPRM), as read: the text a
       * checkpoint stores so that a restart can rebuild the run. */
      std::string text;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /** Declare, read @p filename, parse and validate. Throws InputError
       * with the parameter (and the file and line where deal.II knows
       * it). */
      static Parameters
      from_file(const std::string &filename);

      /** The same from the text of a parameter file (for tests). */
      static Parameters
      from_string(const std::string &text);

    private:
      /** Inputs an impactor cannot take (InputError). */
      void
      check_impactor_input() const;
      /** Inputs contact between the bodies cannot take (InputError). */
      void
      check_contact_input() const;
      /** Contact between the bodies in a static run. */
      void
      check_static_contact_input() const;
      /** Inputs a linear buckling analysis cannot take (InputError). */
      void
      check_buckling_input() const;
      /** Inputs plastic plies cannot take yet (InputError). */
      void
      check_plasticity_input() const;
      /** Inputs total Lagrangian kinematics cannot take yet (InputError). */
      void
      check_kinematics_input() const;
      /** Scenes arc-length control cannot follow (InputError). */
      void
      check_arc_length_input() const;
      /** What an explicit run's adaptivity cannot take (InputError). */
      void
      check_explicit_adaptivity_input() const;
      /** What crack insertion cannot be combined with yet (InputError). */
      void
      check_crack_input() const;
      /** What a prism (wedge) mesh cannot be combined with yet
       * (InputError). */
      void
      check_prism_input() const;
      /** Refuse what a Geometry/Mesh file cannot be combined with. */
      void
      check_mesh_file_input() const;
    };

    /** Split "a; b; c" into trimmed expressions. */
    std::vector<std::string>
    split_expressions(const std::string &text);
  } // namespace parameters
} // namespace amfrac

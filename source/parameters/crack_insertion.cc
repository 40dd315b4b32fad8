#include <algorithm>
#include <amfrac/parameters/crack_insertion.h>
#include <amfrac/parameters/input_error.h>

namespace amfrac
{
  namespace parameters
  {
    void
    CrackInsertion::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Crack insertion");
      prm.declare_entry(
        "Criterion",
        "none",
        Patterns::Selection("none|hoffman"),
        "none: plies never crack. hoffman: after every converged load step, "
        "interior faces of a ply whose stress (the mean of the two cells at "
        "the face centre, in ply axes) reaches Hoffman index 1 become "
        "cohesive faces: their nodes are duplicated and an extrinsic "
        "bilinear law takes over from the current traction, softening to "
        "zero after the ply's Materials/Gc is dissipated. Among the failing "
        "faces of a cell the one whose normal is closest to the largest "
        "principal stress direction is inserted; the step is then solved "
        "again. In explicit runs the check follows every time step, and "
        "every cell's chosen face is inserted in that step (Faces per "
        "round, Rounds per step and Onset tolerance are for the static "
        "path); the time step is chosen once so that it holds for any "
        "crack pattern of the candidate faces. Every insertion event is a "
        "row of cracks.csv.");
      prm.declare_entry("Candidate faces",
                        "all",
                        Patterns::Selection("all|through thickness|matrix"),
                        "Which faces may crack: all interior faces of a ply; "
                        "through thickness: faces whose normal lies in the "
                        "ply plane (transverse cracks); matrix: through-"
                        "thickness faces parallel to the fibres (normal "
                        "within 6 degrees of the ply's transverse axis).");
      prm.declare_entry("Plies",
                        "all",
                        Patterns::Anything(),
                        "Plies (counted from 0 at the bottom) whose faces may "
                        "crack: 'all' or a comma-separated list.");
      prm.declare_entry("Region",
                        "1",
                        Patterns::Anything(),
                        "Expression of x, y, z (and Boundary conditions/"
                        "Function constants): faces whose centre gives 0 "
                        "never crack.");
      prm.declare_entry(
        "Strength scale",
        "1",
        Patterns::Anything(),
        "Expression of x, y, z: the ply strengths at a face centre are "
        "multiplied by it (a flaw, a weakened section, or a random "
        "strength field with rand_seed(s)); must be positive. Evaluated once "
        "per face when the scene is set up, in the same order on every "
        "rank, so a random field is one fixed field on any number of "
        "ranks; after a mesh change faces keep their value, children of a "
        "face take their parent's, and only new faces are evaluated.");
      prm.declare_entry("Penalty stiffness",
                        "1e6",
                        Patterns::Double(0),
                        "Stiffness of an inserted face before and after "
                        "softening, and in contact [N/mm^3]. The faces "
                        "overlap by traction / stiffness at zero traction, "
                        "so make it large against E / element size.");
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Double(0),
                        "Coulomb mu between the faces of a crack once it "
                        "has fully softened and its faces are pressed "
                        "together (stick spring: Penalty stiffness); 0: "
                        "they slide freely.");
      prm.declare_entry(
        "Faces per round",
        "1",
        Patterns::Integer(1),
        "At most this many faces (the most critical first) are inserted "
        "before the step is solved again, so that the crack pattern does "
        "not depend on the order of insertion.");
      prm.declare_entry(
        "Onset tolerance",
        "0.02",
        Patterns::Double(0),
        "A load step after which the most critical face exceeds Hoffman "
        "index 1 + this (before any insertion in the step) is cut back, "
        "down to Nonlinear solver/Minimum step fraction, so that cracks "
        "start at their strength and not at what a long step overshoots.");
      prm.declare_entry(
        "Balance inserted tractions",
        "true",
        Patterns::Bool(),
        "Static runs: the traction a new crack starts from (the stress of "
        "the two cells times the normal, point by point) is corrected by "
        "the smallest change (least squares, weighted by area) that puts "
        "the copies of the split nodes back in balance, so that the "
        "insertion does no work (cracks.csv residual_before, "
        "residual_after). false: start from the stress as it is and book "
        "the work of the imbalance in insertion_energy. Explicit runs "
        "start from the stress as it is.");
      prm.declare_entry("Rounds per step",
                        "100",
                        Patterns::Integer(1),
                        "At most this many insert-and-solve rounds per load "
                        "step; faces still failing then wait for the next "
                        "step (logged).");
      prm.leave_subsection();
    }



    void
    CrackInsertion::parse_parameters(ParameterHandler  &prm,
                                     const unsigned int n_plies)
    {
      prm.enter_subsection("Crack insertion");
      active                 = prm.get("Criterion") == "hoffman";
      const std::string kind = prm.get("Candidate faces");
      candidates             = kind == "all"    ? Candidates::all :
                               kind == "matrix" ? Candidates::matrix :
                                                  Candidates::through_thickness;
      region                 = prm.get("Region");
      strength_scale         = prm.get("Strength scale");
      penalty                = prm.get_double("Penalty stiffness");
      friction               = prm.get_double("Friction coefficient");
      faces_per_round        = prm.get_integer("Faces per round");
      rounds_per_step        = prm.get_integer("Rounds per step");
      onset_tolerance        = prm.get_double("Onset tolerance");
      balance_tractions      = prm.get_bool("Balance inserted tractions");
      const std::string list = prm.get("Plies");
      prm.leave_subsection();
      plies.clear();
      require(!list.empty(),
              "Crack insertion/Plies",
              "give 'all' or a list of ply indices");
      if (list != "all")
        {
          for (const std::string &entry : Utilities::split_string_list(list))
            {
              int ply = -1;
              try
                {
                  ply = Utilities::string_to_int(entry);
                }
              catch (...)
                {}
              require(ply >= 0 && ply < static_cast<int>(n_plies),
                      "Crack insertion/Plies",
                      "'" + entry + "' is not a ply index from 0 to "
                        + std::to_string(n_plies - 1));
              plies.push_back(ply);
            }
          std::sort(plies.begin(), plies.end());
          plies.erase(std::unique(plies.begin(), plies.end()), plies.end());
        }
      require(!active || penalty > 0,
              "Crack insertion/Penalty stiffness",
              "must be positive");
    }
  } // namespace parameters
} // namespace amfrac

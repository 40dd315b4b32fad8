#pragma once

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace amfrac
{
  namespace parameters
  {
    using namespace dealii;

    /** `subsection Crack insertion`: intra-ply cracks inserted by node
     * duplication where the Hoffman criterion fails (doc/tutorials
     * step-11). */
    struct CrackInsertion
    {
      enum class Candidates
      {
        all,               ///< every interior face inside a ply
        through_thickness, ///< faces whose normal lies in the ply plane
        matrix             ///< through-thickness faces parallel to the fibres
      };
      bool        active = false;
      Candidates  candidates;
      std::string region;
      std::string strength_scale;
      /** Plies whose faces may crack (sorted; empty: all). */
      std::vector<unsigned int> plies;
      double                    penalty;
      /** Coulomb mu between the faces of a fully softened crack. */
      double       friction = 0;
      unsigned int faces_per_round;
      unsigned int rounds_per_step;
      /** A step whose most critical face exceeds Hoffman index 1 + this
       * before any insertion is cut back. */
      double onset_tolerance;
      /** Static runs: correct the tractions a round's new crack points
       * start from so that the split copies stay in balance. */
      bool balance_tractions = true;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int n_plies);
    };
  } // namespace parameters
} // namespace amfrac

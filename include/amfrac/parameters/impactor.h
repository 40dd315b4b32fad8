#pragma once

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace amfrac
{
  namespace parameters
  {
    using namespace dealii;

    /** `subsection Impactor`: a rigid sphere with a mass and an initial
     * velocity that strikes one face of the laminate through penalty
     * contact (explicit runs; RigidImpactor). */
    struct Impactor
    {
      bool active = false;
      /** The laminate face it may touch (x-, ..., z+) and its boundary id. */
      std::string  face;
      unsigned int boundary_id = 0;
      double       radius      = 0;
      double       mass        = 0;
      /** Initial centre and velocity (3 components). */
      std::vector<double> center, velocity;
      /** Contact pressure per unit penetration [N/mm^3]. */
      double penalty = 0;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };
  } // namespace parameters
} // namespace amfrac

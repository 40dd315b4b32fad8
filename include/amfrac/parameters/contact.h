#pragma once

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace amfrac
{
  namespace parameters
  {
    using namespace dealii;

    /** `subsection Contact`: contact between the laminate's own bodies
     * (outer surfaces, crack faces, interface faces, unbonded plies), for
     * explicit runs (BodyContact). */
    struct Contact
    {
      bool   active   = false;
      double penalty  = 0;
      double friction = 0;
      /** Tangential (stick) penalty over the normal one. */
      double tangential_factor = 1;
      /** Ply interfaces released without a cohesive law: the plies on
       * both sides touch by contact only. Sorted, unique. */
      std::vector<unsigned int> unbonded_interfaces;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int n_plies);
    };
  } // namespace parameters
} // namespace amfrac

#pragma once

#include <deal.II/base/tensor.h>

namespace amfrac
{
  namespace cohesive
  {
    using namespace dealii;

    /** History of one interface point: damage and frictional slip. */
    template <int dim>
    struct PointHistory
    {
      /** Largest damage measure reached so far: kappa of
       * eq. (6) for the seed's law, the damage variable d for
       * Camanho-Davila. */
      double kappa = 0;
      /** True once fully debonded (seed: S_T(kappa) >= 1, the friction
       * phase; Camanho-Davila: d = 1). */
      bool debonded = false;
      /** Tangential slip (the stick reference) in the friction phase. */
      Tensor<1, dim - 1> slip;
    };

    /** Traction, consistent tangent and updated history at one point. */
    template <int dim>
    struct LawResponse
    {
      /** (sigma_N, sigma_T...) in the local frame (normal first). */
      Tensor<1, dim> traction;
      /** d traction / d gap (not symmetric in the friction phase). */
      Tensor<2, dim>    tangent;
      PointHistory<dim> history;
    };

  } // namespace cohesive
} // namespace amfrac

#pragma once

#include <amfrac/cohesive/law_state.h>

namespace amfrac
{
  namespace cohesive
  {
    using namespace dealii;

    /**
     * Data of the seed paper's bilinear mixed-mode interface law (Mohammadi
     * & Forouzan-sepehr, eqs. (1)-(13), after Mi et al. 1998). Units: MPa,
     * N/mm, MPa/mm.
     */
    struct SeedLawProperties
    {
      double normal_strength;  ///< sigma_N-bar
      double shear_strength;   ///< sigma_T-bar
      double G_Ic;             ///< mode I fracture energy
      double G_IIc;            ///< mode II fracture energy
      double normal_stiffness; ///< E_N of the intact bond
      double shear_stiffness;  ///< E_T of the intact bond
      double contact_penalty;  ///< alpha_N, in compression
      double stick_penalty;    ///< alpha_T, tangential stick after debonding
      double friction;         ///< Coulomb mu

      /** g_0 = strength / stiffness (onset), eqs. (2)-(3) for g_max. */
      double
      g0_N() const
      {
        return normal_strength / normal_stiffness;
      }
      double
      g0_T() const
      {
        return shear_strength / shear_stiffness;
      }
      double
      gmax_N() const
      {
        return 2 * G_Ic / normal_strength;
      }
      double
      gmax_T() const
      {
        return 2 * G_IIc / shear_strength;
      }

      /** Throws std::invalid_argument naming the datum if the law is not
       * well posed (non-positive data, mu < 0, g_max <= g_0). */
      void
      validate() const;
    };

    /**
     * The seed's law at one point: gap g = (g_N, g_T...) in the local
     * interface frame, the history of the last converged state in, the
     * traction, the tangent and the new history out. A pure function.
     *
     * - Damage: kappa = sqrt(<g_N/g0N>^2 + (|g_T|/g0T)^2) - 1 (eq. 6),
     *   irreversible (kappa = max over history); D_N = (1 - S_N) E_N in
     *   tension and D_T = (1 - S_T) E_T with S_N, S_T of eqs. (9)-(10):
     *   unloading goes back to the origin with the damaged secant.
     * - Compression: sigma_N = alpha_N g_N at every damage level (eq. 12).
     * - Friction phase (S_T >= 1, eq. 13): Coulomb friction with limit
     *   sigma_f = mu <-sigma_N> (eq. 4). The seed writes it as a secant
     *   D_T that rises with alpha_T from the tangential gap at debonding
     *   (g*_Tu) to sigma_f; we keep the slip as history (a stick/slip
     *   return map), which is the same curve under monotonic sliding and
     *   makes friction dissipative under reversal.
     */
    /** A damage index in [0, 1] for output: the larger of the softening
     * variables S_N, S_T of eqs. (9)-(10) at @p kappa. */
    double
    seed_damage(const double kappa, const SeedLawProperties &properties);

    template <int dim>
    LawResponse<dim>
    seed_law(const Tensor<1, dim>    &gap,
             const PointHistory<dim> &history,
             const SeedLawProperties &properties);
  } // namespace cohesive
} // namespace amfrac

#pragma once

#include <amfrac/cohesive/law_state.h>

namespace amfrac
{
  namespace cohesive
  {
    /**
     * Data of the Camanho-Davila bilinear interface law (Camanho, Davila &
     * de Moura 2003, NASA/TM-2002-211737) with the Benzeggagh-Kenane
     * mixed-mode propagation criterion. One penalty stiffness K in all
     * modes. Units: MPa, N/mm, MPa/mm.
     */
    struct CamanhoDavilaProperties
    {
      double normal_strength; ///< N, mode I onset traction
      double shear_strength;  ///< S, mode II onset traction
      double G_Ic;
      double G_IIc;
      double bk_exponent;     ///< eta of Benzeggagh-Kenane
      double stiffness;       ///< K
      double contact_penalty; ///< in compression
      /** Coulomb mu between fully debonded faces in contact (0: none). */
      double friction = 0;
      /** alpha_T of the stick phase of that friction. */
      double stick_penalty = 0;

      /** Onset and final mixed-mode displacement of the mode mix
       * B = G_shear / G_total (0: mode I, 1: mode II). */
      double
      onset(const double B) const;
      double
      final(const double B) const;
      /** G_c = G_Ic + (G_IIc - G_Ic) B^eta. */
      double
      fracture_energy(const double B) const;

      /** Throws std::invalid_argument naming the datum if the law is not
       * well posed: non-positive data, or a mode mix for which the final
       * displacement does not exceed the onset. */
      void
      validate() const;
    };

    /**
     * The Camanho-Davila law at one point, a pure function like seed_law():
     * gap (normal first) and the last converged history in, traction,
     * consistent tangent and new history out. history.kappa holds the
     * damage variable d in [0, 1].
     *
     * With delta_m = sqrt(<g_N>^2 + |g_T|^2) and the mode mix
     * B = |g_T|^2 / delta_m^2, damage starts at the quadratic onset
     * delta_0(B) and is complete at delta_f(B) = 2 G_c(B) / (K delta_0(B));
     * d = delta_f (delta_m - delta_0) / (delta_m (delta_f - delta_0)).
     * Camanho-Davila keep the largest delta_m; we keep the largest d instead,
     * which is the same under a fixed mode mix and never heals a point whose
     * mode mix changes. Traction (1 - d) K g, except the normal part in
     * compression, which is the contact penalty at any damage. Once fully
     * debonded (d = 1), faces in contact slide with Coulomb friction
     * (coulomb_friction(), as in the seed's law) if friction > 0.
     */
    template <int dim>
    LawResponse<dim>
    camanho_davila_law(const Tensor<1, dim>          &gap,
                       const PointHistory<dim>       &history,
                       const CamanhoDavilaProperties &properties);
  } // namespace cohesive
} // namespace amfrac

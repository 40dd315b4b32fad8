#pragma once

#include <amfrac/cohesive/law_state.h>

namespace amfrac
{
  namespace cohesive
  {
    /**
     * Coulomb friction between debonded faces, the friction phase of the
     * seed's eq. (13), shared by every law that reaches full debonding (the
     * seed's law, Camanho-Davila and the inserted cracks):
     * an elastic stick spring @p stick_penalty (g_T - slip) capped at
     * sigma_f = mu <-sigma_N>, with the slip as history so that reversed
     * sliding dissipates.
     *
     * On entry, r holds the normal response (r.traction[0], r.tangent[0][0]:
     * the contact penalty in compression, nothing in tension) and
     * r.history.slip the converged stick reference; the tangential rows of
     * r.traction and r.tangent are filled here and the slip updated.
     * @p just_debonded: the bond broke in this evaluation, so the stick
     * reference starts at the current tangential gap and the tangential
     * traction starts from zero (the seed's g*_Tu).
     */
    template <int dim>
    void
    coulomb_friction(const Tensor<1, dim> &gap,
                     const bool            just_debonded,
                     const double          friction,
                     const double          stick_penalty,
                     LawResponse<dim>     &r);
  } // namespace cohesive
} // namespace amfrac

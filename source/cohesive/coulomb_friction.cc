#include <algorithm>
#include <amfrac/cohesive/coulomb_friction.h>

namespace amfrac
{
  namespace cohesive
  {
    template <int dim>
    void
    coulomb_friction(const Tensor<1, dim> &gap,
                     const bool            just_debonded,
                     const double          friction,
                     const double          stick_penalty,
                     LawResponse<dim>     &r)
    {
      Tensor<1, dim - 1> gT;
      for (unsigned int i = 0; i < dim - 1; ++i)
        gT[i] = gap[i + 1];
      if (just_debonded)
        r.history.slip = gT;
      for (unsigned int i = 1; i < dim; ++i)
        {
          r.traction[i] = 0;
          for (unsigned int j = 0; j < dim; ++j)
            r.tangent[i][j] = 0;
        }
      const double sigma_f = friction * std::max(-r.traction[0], 0.);
      const double dsigma_f_dgN
        = r.traction[0] < 0 ? -friction * r.tangent[0][0] : 0.;
      const Tensor<1, dim - 1> trial = stick_penalty * (gT - r.history.slip);
      const double             norm  = trial.norm();
      if (sigma_f == 0)
        {
          // Open or unloaded crack: no friction, the faces slide freely.
          r.history.slip = gT;
          return;
        }
      if (norm <= sigma_f)
        {
          for (unsigned int i = 0; i < dim - 1; ++i)
            {
              r.traction[i + 1]       = trial[i];
              r.tangent[i + 1][i + 1] = stick_penalty;
            }
          return;
        }
      const Tensor<1, dim - 1> direction = trial / norm;
      for (unsigned int i = 0; i < dim - 1; ++i)
        {
          r.traction[i + 1]   = sigma_f * direction[i];
          r.tangent[i + 1][0] = dsigma_f_dgN * direction[i];
          for (unsigned int j = 0; j < dim - 1; ++j)
            r.tangent[i + 1][j + 1]
              = sigma_f / norm * stick_penalty
                * ((i == j ? 1. : 0.) - direction[i] * direction[j]);
        }
      r.history.slip = gT - sigma_f * direction / stick_penalty;
    }

    template void
    coulomb_friction<2>(const Tensor<1, 2> &,
                        bool,
                        double,
                        double,
                        LawResponse<2> &);
    template void
    coulomb_friction<3>(const Tensor<1, 3> &,
                        bool,
                        double,
                        double,
                        LawResponse<3> &);
  } // namespace cohesive
} // namespace amfrac

#include <algorithm>
#include <amfrac/cohesive/coulomb_friction.h>
#include <amfrac/cohesive/seed_law.h>
#include <cmath>
#include <stdexcept>
#include <string>

namespace amfrac
{
  namespace cohesive
  {
    void
    SeedLawProperties::validate() const
    {
      const std::pair<const char *, double> positive[]
        = {{"normal strength", normal_strength},
           {"shear strength", shear_strength},
           {"G_Ic", G_Ic},
           {"G_IIc", G_IIc},
           {"normal stiffness", normal_stiffness},
           {"shear stiffness", shear_stiffness},
           {"contact penalty", contact_penalty},
           {"stick penalty", stick_penalty}};
      for (const auto &[name, value] : positive)
        if (!(value > 0))
          throw std::invalid_argument(std::string(name) + " must be positive");
      if (!(friction >= 0))
        throw std::invalid_argument("friction coefficient mu must be >= 0");
      if (!(gmax_N() > g0_N()))
        throw std::invalid_argument(
          "mode I: g_max = 2 G_Ic/strength must exceed g_0 = "
          "strength/stiffness (raise G_Ic or the normal stiffness)");
      if (!(gmax_T() > g0_T()))
        throw std::invalid_argument(
          "mode II: g_max = 2 G_IIc/strength must exceed g_0 = "
          "strength/stiffness (raise G_IIc or the shear stiffness)");
    }



    namespace
    {
      /** S(kappa) of eqs. (9)-(10), clamped to [0, 1], and dS/dkappa. */
      std::pair<double, double>
      softening(const double kappa, const double g0, const double gmax)
      {
        if (kappa <= 0)
          return {0., 0.};
        const double ratio = gmax / (gmax - g0);
        const double S     = kappa / (1 + kappa) * ratio;
        if (S >= 1)
          return {1., 0.};
        return {S, ratio / ((1 + kappa) * (1 + kappa))};
      }
    } // namespace



    double
    seed_damage(const double kappa, const SeedLawProperties &p)
    {
      return std::max(softening(kappa, p.g0_N(), p.gmax_N()).first,
                      softening(kappa, p.g0_T(), p.gmax_T()).first);
    }



    template <int dim>
    LawResponse<dim>
    seed_law(const Tensor<1, dim>    &gap,
             const PointHistory<dim> &history,
             const SeedLawProperties &p)
    {
      const double       g0N = p.g0_N(), g0T = p.g0_T();
      const double       gN = gap[0];
      Tensor<1, dim - 1> gT;
      for (unsigned int i = 0; i < dim - 1; ++i)
        gT[i] = gap[i + 1];

      // Damage measure kappa (eq. 6) and its gradient w.r.t. the gap.
      const double open = std::max(gN, 0.);
      const double root
        = std::sqrt(open * open / (g0N * g0N) + gT.norm_square() / (g0T * g0T));
      const double   kappa_now = root - 1;
      Tensor<1, dim> dkappa;
      if (root > 0)
        {
          dkappa[0] = open / (g0N * g0N * root);
          for (unsigned int i = 0; i < dim - 1; ++i)
            dkappa[i + 1] = gT[i] / (g0T * g0T * root);
        }
      // At kappa = kappa_max (e.g. the converged state itself) the tangent
      // is the one of continued loading: the predictor of the next step and
      // the dissipation constraint need the softening slope there, not the
      // secant of unloading.
      const bool loading = kappa_now >= history.kappa && kappa_now > 0;

      LawResponse<dim> r;
      r.history              = history;
      r.history.kappa        = std::max(history.kappa, kappa_now);
      const auto [S_N, dS_N] = softening(r.history.kappa, g0N, p.gmax_N());
      const auto [S_T, dS_T] = softening(r.history.kappa, g0T, p.gmax_T());

      // Normal: penalty contact in compression, damaged bond in tension. A
      // closed gap (g_N = 0) counts as open, so that a pre-crack at rest has
      // no normal stiffness and Newton does not start from a bonded crack.
      if (gN < 0)
        {
          r.traction[0]   = p.contact_penalty * gN;
          r.tangent[0][0] = p.contact_penalty;
        }
      else
        {
          r.traction[0]   = (1 - S_N) * p.normal_stiffness * gN;
          r.tangent[0][0] = (1 - S_N) * p.normal_stiffness;
          if (loading)
            for (unsigned int j = 0; j < dim; ++j)
              r.tangent[0][j] -= p.normal_stiffness * gN * dS_N * dkappa[j];
        }

      const bool was_debonded = history.debonded;
      r.history.debonded      = was_debonded || S_T >= 1;
      if (!r.history.debonded)
        {
          // Adhesion phase: damaged secant (eq. 13, first two branches).
          const double D_T = (1 - S_T) * p.shear_stiffness;
          for (unsigned int i = 0; i < dim - 1; ++i)
            {
              r.traction[i + 1] = D_T * gT[i];
              r.tangent[i + 1][i + 1] += D_T;
              if (loading)
                for (unsigned int j = 0; j < dim; ++j)
                  r.tangent[i + 1][j]
                    -= p.shear_stiffness * gT[i] * dS_T * dkappa[j];
            }
          return r;
        }

      // Friction phase. The stick reference starts where the bond broke,
      // so the tangential traction starts from zero (the seed's g*_Tu).
      coulomb_friction(gap, !was_debonded, p.friction, p.stick_penalty, r);
      return r;
    }

    template LawResponse<2>
    seed_law<2>(const Tensor<1, 2> &,
                const PointHistory<2> &,
                const SeedLawProperties &);
    template LawResponse<3>
    seed_law<3>(const Tensor<1, 3> &,
                const PointHistory<3> &,
                const SeedLawProperties &);
  } // namespace cohesive
} // namespace amfrac

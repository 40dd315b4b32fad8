#include <algorithm>
#include <amfrac/cohesive/camanho_davila_law.h>
#include <amfrac/cohesive/coulomb_friction.h>
#include <cmath>
#include <stdexcept>
#include <string>

namespace amfrac
{
  namespace cohesive
  {
    double
    CamanhoDavilaProperties::fracture_energy(const double B) const
    {
      return G_Ic + (G_IIc - G_Ic) * std::pow(B, bk_exponent);
    }



    double
    CamanhoDavilaProperties::onset(const double B) const
    {
      // delta_0 = d3 d1 sqrt((1 + beta^2) / (d1^2 + beta^2 d3^2)) with the
      // pure-mode onsets d3 = N/K, d1 = S/K and beta^2 = B / (1 - B).
      const double d3 = normal_strength / stiffness;
      const double d1 = shear_strength / stiffness;
      return d3 * d1 / std::sqrt((1 - B) * d1 * d1 + B * d3 * d3);
    }



    double
    CamanhoDavilaProperties::final(const double B) const
    {
      return 2 * fracture_energy(B) / (stiffness * onset(B));
    }



    void
    CamanhoDavilaProperties::validate() const
    {
      const std::pair<const char *, double> positive[]
        = {{"normal strength", normal_strength},
           {"shear strength", shear_strength},
           {"G_Ic", G_Ic},
           {"G_IIc", G_IIc},
           {"BK exponent eta", bk_exponent},
           {"stiffness", stiffness},
           {"contact penalty", contact_penalty}};
      for (const auto &[name, value] : positive)
        if (!(value > 0))
          throw std::invalid_argument(std::string(name) + " must be positive");
      if (!(friction >= 0))
        throw std::invalid_argument("friction coefficient mu must be >= 0");
      if (friction > 0 && !(stick_penalty > 0))
        throw std::invalid_argument(
          "stick penalty must be positive with friction");
      for (unsigned int i = 0; i <= 200; ++i)
        {
          const double B = i / 200.;
          if (!(final(B) > onset(B)))
            throw std::invalid_argument(
              "at the mode mix G_II/G = " + std::to_string(B)
              + " the final displacement 2 G_c/(K delta_0) does not exceed "
                "the onset delta_0: raise the fracture energies or the "
                "stiffness");
        }
    }



    namespace
    {
      /** A number with its gradient w.r.t. the gap (forward-mode automatic
       * differentiation): the damage depends on the gap through delta_m and
       * through the mode mix, and this keeps the tangent exact without
       * writing out the chain rule. */
      template <int dim>
      struct Dual
      {
        double         v;
        Tensor<1, dim> d;
      };

      template <int dim>
      Dual<dim>
      operator+(const Dual<dim> &a, const Dual<dim> &b)
      {
        return {a.v + b.v, a.d + b.d};
      }
      template <int dim>
      Dual<dim>
      operator-(const Dual<dim> &a, const Dual<dim> &b)
      {
        return {a.v - b.v, a.d - b.d};
      }
      template <int dim>
      Dual<dim>
      operator*(const Dual<dim> &a, const Dual<dim> &b)
      {
        return {a.v * b.v, a.d * b.v + b.d * a.v};
      }
      template <int dim>
      Dual<dim>
      operator/(const Dual<dim> &a, const Dual<dim> &b)
      {
        return {a.v / b.v, (a.d * b.v - b.d * a.v) / (b.v * b.v)};
      }
      template <int dim>
      Dual<dim>
      constant(const double v)
      {
        return {v, Tensor<1, dim>()};
      }
      template <int dim>
      Dual<dim>
      sqrt(const Dual<dim> &a)
      {
        const double s = std::sqrt(a.v);
        return {s, a.d / (2 * s)};
      }
      template <int dim>
      Dual<dim>
      pow(const Dual<dim> &a, const double p)
      {
        // B^eta at B = 0 (pure mode I) has a zero (eta > 1) or unbounded
        // (eta < 1) slope; take the one-sided zero, as B >= 0 there.
        if (a.v == 0)
          return {0, Tensor<1, dim>()};
        return {std::pow(a.v, p), p * std::pow(a.v, p - 1) * a.d};
      }

      /** d(gap) before the max with the history (0 below the onset). */
      template <int dim>
      Dual<dim>
      trial_damage(const Tensor<1, dim> &gap, const CamanhoDavilaProperties &p)
      {
        Dual<dim> open = constant<dim>(0), shear2 = constant<dim>(0);
        if (gap[0] > 0)
          open.v = gap[0], open.d[0] = 1;
        for (unsigned int i = 1; i < dim; ++i)
          {
            shear2.v += gap[i] * gap[i];
            shear2.d[i] = 2 * gap[i];
          }
        const Dual<dim> m2 = open * open + shear2;
        if (m2.v == 0)
          return constant<dim>(0);
        const Dual<dim> B  = shear2 / m2;
        const double    d3 = p.normal_strength / p.stiffness;
        const double    d1 = p.shear_strength / p.stiffness;
        const Dual<dim> delta0
          = constant<dim>(d3 * d1)
            / sqrt((constant<dim>(1) - B) * constant<dim>(d1 * d1)
                   + B * constant<dim>(d3 * d3));
        const Dual<dim> Gc
          = constant<dim>(p.G_Ic)
            + constant<dim>(p.G_IIc - p.G_Ic) * pow(B, p.bk_exponent);
        const Dual<dim> deltaf
          = constant<dim>(2) * Gc / (constant<dim>(p.stiffness) * delta0);
        const Dual<dim> deltam = sqrt(m2);
        if (deltam.v <= delta0.v)
          return constant<dim>(0);
        if (deltam.v >= deltaf.v)
          return constant<dim>(1);
        return deltaf * (deltam - delta0) / (deltam * (deltaf - delta0));
      }
    } // namespace



    template <int dim>
    LawResponse<dim>
    camanho_davila_law(const Tensor<1, dim>          &gap,
                       const PointHistory<dim>       &history,
                       const CamanhoDavilaProperties &p)
    {
      LawResponse<dim> r;
      r.history = history;
      // A pre-crack (or any debonded point) has d = 1 whatever is stored.
      const Dual<dim> trial
        = history.debonded ? constant<dim>(1) : trial_damage(gap, p);
      const double d     = std::max(history.kappa, trial.v);
      r.history.kappa    = history.debonded ? 1. : d;
      r.history.debonded = history.debonded || d >= 1;
      // As for the seed's law, the tangent at d = d_max is the one of
      // continued loading (the predictor needs the softening slope).
      const bool loading = !r.history.debonded && trial.v >= history.kappa
                           && trial.v > 0 && trial.v < 1;
      const double secant = (1 - r.history.kappa) * p.stiffness;

      Tensor<1, dim> damaged_gap; // the part of the gap that d acts on
      for (unsigned int i = 0; i < dim; ++i)
        {
          const bool contact = i == 0 && gap[0] < 0;
          if (!contact)
            damaged_gap[i] = gap[i];
          r.traction[i]
            = contact ? p.contact_penalty * gap[0] : secant * gap[i];
          r.tangent[i][i] = contact ? p.contact_penalty : secant;
        }
      if (loading)
        r.tangent -= p.stiffness * outer_product(damaged_gap, trial.d);
      if (r.history.debonded && p.friction > 0)
        coulomb_friction(
          gap, !history.debonded, p.friction, p.stick_penalty, r);
      return r;
    }

    template LawResponse<2>
    camanho_davila_law<2>(const Tensor<1, 2> &,
                          const PointHistory<2> &,
                          const CamanhoDavilaProperties &);
    template LawResponse<3>
    camanho_davila_law<3>(const Tensor<1, 3> &,
                          const PointHistory<3> &,
                          const CamanhoDavilaProperties &);
  } // namespace cohesive
} // namespace amfrac

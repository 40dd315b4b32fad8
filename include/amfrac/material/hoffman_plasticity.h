#pragma once

#include <amfrac/material/orthotropic.h>
#include <array>

namespace amfrac
{
  /**
   * Hoffman anisotropic plasticity at one point, in the ply's material
   * axes (the seed's "non-linear material properties using the Hoffman
   * anisotropic yield criterion"). Stresses and strains are Voigt vectors
   * (11, 22, 33, 23, 13, 12) with engineering shear strains.
   *
   * Yield function, the Hoffman index with the strengths scaled by the
   * isotropic hardening factor s = 1 + h kappa (kappa the equivalent
   * plastic strain, |d eps_p| summed) and multiplied by s^2:
   *
   *   f(sigma, s) = sigma . P sigma / 2 + s q . sigma - s^2,
   *
   * with P and q from the Hoffman coefficients
   * (../shared/reference/README.md section 4), so that f = 0 exactly when
   * the Hoffman index of sigma / s is 1: a uniaxial stress yields at s Xt
   * in tension and -s Xc in compression. Associative flow
   * d eps_p = d lambda n, n = df/dsigma = P sigma + s q, and
   * d kappa = d lambda |n|. The return mapping is backward Euler, solved
   * by Newton on (sigma, d lambda, kappa) with the consistent tangent
   * d sigma / d eps from the same Jacobian.
   */
  class HoffmanPlasticity
  {
  public:
    using Voigt     = std::array<double, 6>;
    using Stiffness = std::array<std::array<double, 6>, 6>;

    /** The history of a point. */
    struct State
    {
      Voigt  plastic_strain{};
      double kappa = 0;
    };

    struct Response
    {
      Voigt     stress{};
      Stiffness tangent{};
      State     state;
      bool      plastic = false;
      /** False if the local Newton did not converge (the caller cuts the
       * step). */
      bool converged = true;
    };

    /** @p C the elastic stiffness in material axes, @p hardening h. */
    HoffmanPlasticity(const SymmetricTensor<4, 3> &C,
                      const Strengths             &strengths,
                      const double                 hardening);

    /** The stress, tangent and new history for the total strain
     * @p strain from the converged history @p old. A point that stays
     * elastic returns C (strain - plastic strain) and C, computed exactly
     * as without plasticity. */
    Response
    respond(const Voigt &strain, const State &old) const;

    /** f(sigma, s). */
    double
    yield_function(const Voigt &stress, const double s) const;

  private:
    Stiffness D;
    Stiffness P;
    Voigt     q{};
    double    h;

    Voigt
    flow_direction(const Voigt &stress, const double s) const;
  };
} // namespace amfrac

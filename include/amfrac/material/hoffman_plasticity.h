#pragma once

#include <amfrac/material/orthotropic.h>
#include <array>

namespace amfrac
{
  /** a . b of two Voigt vectors. */
  inline double
  voigt_dot(const std::array<double, 6> &a, const std::array<double, 6> &b)
  {
    double sum = 0;
    for (unsigned int i = 0; i < 6; ++i)
      sum += a[i] * b[i];
    return sum;
  }

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
      /** An elastic response of a point that has yielded and sits on its
       * yield surface (-1e-8 s^2 <= f <= 1e-10 s^2): the tangent is the
       * continuum elastic-plastic one, d sigma / d eps of further
       * loading, so that a predictor from a converged plastic state
       * continues plastically. */
      bool on_surface = false;
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
     * elastic (its trial stress within f <= 1e-10 s^2, a margin over the
     * local Newton's tolerance 1e-13 s^2 of a point returned to the
     * surface before) returns C (strain - plastic strain) and C, computed
     * exactly as without plasticity. */
    Response
    respond(const Voigt &strain, const State &old) const;

    /** C (strain - plastic strain of @p state), whatever the yield
     * function says. */
    Voigt
    elastic_stress(const Voigt &strain, const State &state) const;

    /** The continuum elastic-plastic tangent at @p stress on the yield
     * surface of hardening state @p kappa:
     * D - D n (D n)^T / (n.D n - df/dkappa |n|). */
    Stiffness
    continuum_tangent(const Voigt &stress, const double kappa) const;

    /** f(sigma, s). */
    double
    yield_function(const Voigt &stress, const double s) const;

  private:
    Stiffness D;
    Stiffness P;
    /** D P and D q, which every local Newton iteration needs. */
    Stiffness DP;
    Voigt     q{};
    Voigt     Dq{};
    double    h;

    Voigt
    flow_direction(const Voigt &stress, const double s) const;
  };
} // namespace amfrac

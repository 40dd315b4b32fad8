#include <amfrac/material/hoffman_plasticity.h>
#include <cmath>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace amfrac
{
  namespace
  {
    using Voigt     = HoffmanPlasticity::Voigt;
    using Stiffness = HoffmanPlasticity::Stiffness;

    Voigt
    multiply(const Stiffness &A, const Voigt &x)
    {
      Voigt y{};
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          y[i] += A[i][j] * x[j];
      return y;
    }

    double
    dot(const Voigt &a, const Voigt &b)
    {
      double sum = 0;
      for (unsigned int i = 0; i < 6; ++i)
        sum += a[i] * b[i];
      return sum;
    }
  } // namespace



  HoffmanPlasticity::HoffmanPlasticity(const SymmetricTensor<4, 3> &C,
                                       const Strengths             &f,
                                       const double                 hardening)
    : D{}
    , P{}
    , h(hardening)
  {
    // Engineering shear strains: sigma_I = C_ijkl gamma_kl for a shear
    // pair kl, so the Voigt matrix holds C_ijkl unscaled.
    for (unsigned int I = 0; I < 6; ++I)
      for (unsigned int J = 0; J < 6; ++J)
        D[I][J] = C[voigt_pairs[I][0]][voigt_pairs[I][1]][voigt_pairs[J][0]]
                   [voigt_pairs[J][1]];
    // The Hoffman coefficients; P is the Hessian of the quadratic part.
    const double XX = 1. / (f.Xt * f.Xc), YY = 1. / (f.Yt * f.Yc),
                 ZZ = 1. / (f.Zt * f.Zc);
    const double C1 = 0.5 * (YY + ZZ - XX);
    const double C2 = 0.5 * (ZZ + XX - YY);
    const double C3 = 0.5 * (XX + YY - ZZ);
    P[0][0]         = 2 * (C2 + C3);
    P[1][1]         = 2 * (C1 + C3);
    P[2][2]         = 2 * (C1 + C2);
    P[0][1] = P[1][0] = -2 * C3;
    P[0][2] = P[2][0] = -2 * C2;
    P[1][2] = P[2][1] = -2 * C1;
    P[3][3]           = 2. / (f.S23 * f.S23);
    P[4][4]           = 2. / (f.S13 * f.S13);
    P[5][5]           = 2. / (f.S12 * f.S12);
    q[0]              = 1. / f.Xt - 1. / f.Xc;
    q[1]              = 1. / f.Yt - 1. / f.Yc;
    q[2]              = 1. / f.Zt - 1. / f.Zc;
  }



  double
  HoffmanPlasticity::yield_function(const Voigt &stress, const double s) const
  {
    return 0.5 * dot(stress, multiply(P, stress)) + s * dot(q, stress) - s * s;
  }



  HoffmanPlasticity::Voigt
  HoffmanPlasticity::flow_direction(const Voigt &stress, const double s) const
  {
    Voigt n = multiply(P, stress);
    for (unsigned int i = 0; i < 6; ++i)
      n[i] += s * q[i];
    return n;
  }



  HoffmanPlasticity::Response
  HoffmanPlasticity::respond(const Voigt &strain, const State &old) const
  {
    Response response;
    Voigt    elastic_strain;
    for (unsigned int i = 0; i < 6; ++i)
      elastic_strain[i] = strain[i] - old.plastic_strain[i];
    const Voigt trial = multiply(D, elastic_strain);
    response.stress   = trial;
    response.tangent  = D;
    response.state    = old;
    if (yield_function(trial, 1 + h * old.kappa) <= 0)
      return response;

    // Backward Euler: R1 = sigma - trial + dlambda D n, R2 = f,
    // R3 = kappa - kappa_old - dlambda |n|, unknowns (sigma, dlambda,
    // kappa), Newton with the exact Jacobian J.
    response.plastic           = true;
    Voigt              sigma   = trial;
    double             dlambda = 0, kappa = old.kappa;
    FullMatrix<double> J(8, 8);
    Vector<double>     R(8), delta(8);
    const double       scale = std::sqrt(dot(trial, trial));
    bool               done  = false;
    for (unsigned int it = 0; it < 50 && !done; ++it)
      {
        const double s      = 1 + h * kappa;
        const Voigt  n      = flow_direction(sigma, s);
        const double length = std::sqrt(dot(n, n));
        const Voigt  Dn = multiply(D, n), Dq = multiply(D, q),
                    Pn = multiply(P, n);
        for (unsigned int i = 0; i < 6; ++i)
          R(i) = sigma[i] - trial[i] + dlambda * Dn[i];
        R(6)      = yield_function(sigma, s);
        R(7)      = kappa - old.kappa - dlambda * length;
        double r1 = 0;
        for (unsigned int i = 0; i < 6; ++i)
          r1 += R(i) * R(i);
        done = it > 0 && std::sqrt(r1) <= 1e-13 * scale
               && std::abs(R(6)) <= 1e-13 && std::abs(R(7)) <= 1e-15;
        J = 0;
        for (unsigned int i = 0; i < 6; ++i)
          {
            for (unsigned int j = 0; j < 6; ++j)
              {
                double DP = 0;
                for (unsigned int k = 0; k < 6; ++k)
                  DP += D[i][k] * P[k][j];
                J(i, j) = (i == j ? 1. : 0.) + dlambda * DP;
              }
            J(i, 6) = Dn[i];
            J(i, 7) = dlambda * h * Dq[i];
            J(6, i) = n[i];
            J(7, i) = -dlambda * Pn[i] / length;
          }
        J(6, 7) = h * (dot(q, sigma) - 2 * s);
        J(7, 6) = -length;
        J(7, 7) = 1 - dlambda * h * dot(n, q) / length;
        J.gauss_jordan();
        if (done)
          break;
        J.vmult(delta, R);
        for (unsigned int i = 0; i < 6; ++i)
          sigma[i] -= delta(i);
        dlambda -= delta(6);
        kappa -= delta(7);
      }
    response.converged = done && dlambda >= 0;
    const double s     = 1 + h * kappa;
    const Voigt  n     = flow_direction(sigma, s);
    response.stress    = sigma;
    for (unsigned int i = 0; i < 6; ++i)
      response.state.plastic_strain[i] = old.plastic_strain[i] + dlambda * n[i];
    response.state.kappa = kappa;
    // d sigma / d eps = (J^-1)_{sigma sigma} D: the residual depends on
    // the strain only through the trial stress D (eps - eps_p,old). J holds
    // the inverse of the converged state's Jacobian.
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        {
          double sum = 0;
          for (unsigned int k = 0; k < 6; ++k)
            sum += J(i, k) * D[k][j];
          response.tangent[i][j] = sum;
        }
    return response;
  }
} // namespace amfrac

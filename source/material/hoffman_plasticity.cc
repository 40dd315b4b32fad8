#include <algorithm>
#include <amfrac/material/hoffman_plasticity.h>
#include <cmath>

namespace amfrac
{
  namespace
  {
    using Voigt     = HoffmanPlasticity::Voigt;
    using Stiffness = HoffmanPlasticity::Stiffness;

    /** A x for the matrices of an orthotropic material in its axes (D,
     * P and D P): a block of the normal components and a diagonal of the
     * shear ones, nothing coupling the two (checked by the constructor). */
    Voigt
    multiply(const Stiffness &A, const Voigt &x)
    {
      Voigt y{};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          y[i] += A[i][j] * x[j];
      for (unsigned int i = 3; i < 6; ++i)
        y[i] = A[i][i] * x[i];
      return y;
    }

    /** Whether @p A has the structure multiply() assumes: couplings of
     * shear and other components within round-off (a stiffness rotated
     * into the ply axes and back), which are then set to zero. */
    bool
    make_orthotropic(Stiffness &A)
    {
      double largest = 0;
      for (const auto &row : A)
        for (const double a : row)
          largest = std::max(largest, std::abs(a));
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          if ((i >= 3 || j >= 3) && i != j)
            {
              if (std::abs(A[i][j]) > 1e-10 * largest)
                return false;
              A[i][j] = 0;
            }
      return true;
    }

    double
    dot(const Voigt &a, const Voigt &b)
    {
      return voigt_dot(a, b);
    }

    using Vector8 = std::array<double, 8>;

    /** LU with partial pivoting of the 8 x 8 Jacobian of the return
     * mapping, in place and without allocation. */
    struct DenseLU
    {
      std::array<Vector8, 8>      matrix;
      std::array<unsigned int, 8> pivot;

      /** False if the matrix is singular. */
      bool
      factorize()
      {
        for (unsigned int k = 0; k < 8; ++k)
          {
            unsigned int p = k;
            for (unsigned int i = k + 1; i < 8; ++i)
              if (std::abs(matrix[i][k]) > std::abs(matrix[p][k]))
                p = i;
            if (matrix[p][k] == 0)
              return false;
            pivot[k] = p;
            std::swap(matrix[k], matrix[p]);
            for (unsigned int i = k + 1; i < 8; ++i)
              {
                matrix[i][k] /= matrix[k][k];
                for (unsigned int j = k + 1; j < 8; ++j)
                  matrix[i][j] -= matrix[i][k] * matrix[k][j];
              }
          }
        return true;
      }

      /** b := J^-1 b. */
      void
      solve(Vector8 &b) const
      {
        for (unsigned int k = 0; k < 8; ++k)
          std::swap(b[k], b[pivot[k]]);
        for (unsigned int i = 1; i < 8; ++i)
          for (unsigned int j = 0; j < i; ++j)
            b[i] -= matrix[i][j] * b[j];
        for (unsigned int i = 8; i-- > 0;)
          {
            for (unsigned int j = i + 1; j < 8; ++j)
              b[i] -= matrix[i][j] * b[j];
            b[i] /= matrix[i][i];
          }
      }
    };
  } // namespace



  HoffmanPlasticity::HoffmanPlasticity(const SymmetricTensor<4, 3> &C,
                                       const Strengths             &f,
                                       const double                 hardening)
    : D{}
    , P{}
    , DP{}
    , h(hardening)
  {
    // Engineering shear strains: sigma_I = C_ijkl gamma_kl for a shear
    // pair kl, so the Voigt matrix holds C_ijkl unscaled.
    for (unsigned int I = 0; I < 6; ++I)
      for (unsigned int J = 0; J < 6; ++J)
        D[I][J] = C[voigt_pairs[I][0]][voigt_pairs[I][1]][voigt_pairs[J][0]]
                   [voigt_pairs[J][1]];
    AssertThrow(make_orthotropic(D),
                ExcMessage("Hoffman plasticity needs the stiffness in the "
                           "material's own (orthotropic) axes"));
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
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int k = 0; k < 6; ++k)
          DP[i][j] += D[i][k] * P[k][j];
    Dq = multiply(D, q);
  }



  HoffmanPlasticity::Voigt
  HoffmanPlasticity::elastic_stress(const Voigt &strain,
                                    const State &state) const
  {
    Voigt elastic_strain;
    for (unsigned int i = 0; i < 6; ++i)
      elastic_strain[i] = strain[i] - state.plastic_strain[i];
    return multiply(D, elastic_strain);
  }



  HoffmanPlasticity::Stiffness
  HoffmanPlasticity::continuum_tangent(const Voigt &stress,
                                       const double kappa) const
  {
    const double s           = 1 + h * kappa;
    const Voigt  n           = flow_direction(stress, s);
    const Voigt  Dn          = multiply(D, n);
    const double f_kappa     = h * (dot(q, stress) - 2 * s);
    const double denominator = dot(n, Dn) - f_kappa * std::sqrt(dot(n, n));
    Stiffness    tangent     = D;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        tangent[i][j] -= Dn[i] * Dn[j] / denominator;
    return tangent;
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
    Response    response;
    const Voigt trial = elastic_stress(strain, old);
    response.stress   = trial;
    response.tangent  = D;
    response.state    = old;
    // A point returned to the surface before sits on it to the local
    // Newton's tolerance (1e-13 s^2): reloading it by a margin of 1e-10
    // s^2 is not yielding. f scales with s^2 = (1 + h kappa)^2.
    const double s_old = 1 + h * old.kappa;
    const double f     = yield_function(trial, s_old);
    if (f <= 1e-10 * s_old * s_old)
      {
        if (old.kappa > 0 && f >= -1e-8 * s_old * s_old)
          {
            response.on_surface = true;
            response.tangent    = continuum_tangent(trial, old.kappa);
          }
        return response;
      }

    // Backward Euler: R1 = sigma - trial + dlambda D n, R2 = f,
    // R3 = kappa - kappa_old - dlambda |n|, unknowns (sigma, dlambda,
    // kappa), Newton with the exact Jacobian J (8 x 8, factorized in
    // place: this runs at every plastic point of every iteration).
    response.plastic     = true;
    Voigt        sigma   = trial;
    double       dlambda = 0, kappa = old.kappa;
    DenseLU      J;
    Vector8      R;
    const double scale = std::sqrt(dot(trial, trial));
    bool         done  = false;
    for (unsigned int it = 0; it < 50 && !done; ++it)
      {
        const double s      = 1 + h * kappa;
        const Voigt  n      = flow_direction(sigma, s);
        const double length = std::sqrt(dot(n, n));
        const Voigt  Dn = multiply(D, n), Pn = multiply(P, n);
        for (unsigned int i = 0; i < 6; ++i)
          R[i] = sigma[i] - trial[i] + dlambda * Dn[i];
        R[6]      = yield_function(sigma, s);
        R[7]      = kappa - old.kappa - dlambda * length;
        double r1 = 0;
        for (unsigned int i = 0; i < 6; ++i)
          r1 += R[i] * R[i];
        // Relative tolerances: f scales with s^2, kappa grows.
        done = it > 0 && std::sqrt(r1) <= 1e-13 * scale
               && std::abs(R[6]) <= 1e-13 * s * s
               && std::abs(R[7]) <= 1e-15 * std::max(1., kappa);
        auto &a = J.matrix;
        for (unsigned int i = 0; i < 6; ++i)
          {
            for (unsigned int j = 0; j < 6; ++j)
              a[i][j] = (i == j ? 1. : 0.) + dlambda * DP[i][j];
            a[i][6] = Dn[i];
            a[i][7] = dlambda * h * Dq[i];
            a[6][i] = n[i];
            a[7][i] = -dlambda * Pn[i] / length;
          }
        a[6][6] = 0;
        a[6][7] = h * (dot(q, sigma) - 2 * s);
        a[7][6] = -length;
        a[7][7] = 1 - dlambda * h * dot(n, q) / length;
        if (!J.factorize())
          {
            done = false;
            break;
          }
        if (done)
          break;
        J.solve(R);
        for (unsigned int i = 0; i < 6; ++i)
          sigma[i] -= R[i];
        dlambda -= R[6];
        kappa -= R[7];
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
    // the factors of the converged state's Jacobian.
    for (unsigned int j = 0; j < 6 && response.converged; ++j)
      {
        Vector8 column{};
        for (unsigned int i = 0; i < 6; ++i)
          column[i] = D[i][j];
        J.solve(column);
        for (unsigned int i = 0; i < 6; ++i)
          response.tangent[i][j] = column[i];
      }
    return response;
  }
} // namespace amfrac

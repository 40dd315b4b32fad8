#include <algorithm>
#include <amfrac/solvers/buckling_eigensolver.h>
#include <cmath>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace amfrac
{
  namespace
  {
    using Vector = BucklingEigensolver::Vector;
    using Matrix = BucklingEigensolver::Matrix;

    /** A start vector that depends on the global index only (the same on
     * any number of ranks), zero on constrained rows. */
    void
    fill_start_vector(
      const unsigned int                                  seed,
      const std::function<bool(types::global_dof_index)> &is_free,
      Vector                                             &x)
    {
      for (const auto i : x.locally_owned_elements())
        {
          const double s
            = std::sin(12.9898 * (i + 1) + 78.233 * (seed + 1)) * 43758.5453;
          x(i) = is_free(i) ? s - std::floor(s) - 0.5 : 0.;
        }
      x.compress(VectorOperation::insert);
    }

    /**
     * A K-orthonormal basis V with B V (B = -K_G) and the projection
     * H = V^T B V, grown one vector at a time.
     */
    class KrylovBasis
    {
    public:
      KrylovBasis(const Matrix &K, const Matrix &K_G, const Vector &layout)
        : K(K)
        , K_G(K_G)
        , K_w(layout)
      {}

      /** Orthogonalize @p w against the basis in the K inner product
       * (classical Gram-Schmidt twice, which is enough in floating point)
       * and append it normalized; its coordinates in the basis go to
       * @p coordinates (the projections, then its norm). False if nothing
       * independent was left of it. */
      bool
      append(Vector &w, std::vector<double> &coordinates)
      {
        coordinates.assign(V.size() + 1, 0.);
        double before = 0;
        for (unsigned int pass = 0; pass < 2; ++pass)
          {
            K.vmult(K_w, w);
            if (pass == 0)
              before = std::sqrt(std::max(K_norm_squared(w), 0.));
            for (unsigned int i = 0; i < V.size(); ++i)
              {
                const double c = V[i] * K_w;
                coordinates[i] += c;
                w.add(-c, V[i]);
              }
          }
        K.vmult(K_w, w);
        const double norm = std::sqrt(std::max(K_norm_squared(w), 0.));
        if (!(norm > 1e-10 * before))
          return false;
        coordinates.back() = norm;
        w /= norm;
        V.push_back(w);
        BV.push_back(w);
        K_G.vmult(BV.back(), w);
        BV.back() *= -1.;
        const unsigned int n = V.size();
        H.grow_or_shrink(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double h = 0.5 * (V[i] * BV[n - 1] + V[n - 1] * BV[i]);
            H(i, n - 1)    = h;
            H(n - 1, i)    = h;
          }
        return true;
      }

      /** w . K w with K w in K_w; throws if it is clearly negative: K
       * is not positive definite (a state past a bifurcation or limit
       * point), and the K inner product of the iteration is no inner
       * product. Collective (global dot products). */
      double
      K_norm_squared(const Vector &w) const
      {
        const double w_K_w = w * K_w;
        if (w_K_w < -1e-10 * w.l2_norm() * K_w.l2_norm())
          throw std::runtime_error(
            "the stiffness matrix is not positive definite (the Lanczos "
            "iteration met a direction of negative energy): the state lies "
            "past a bifurcation or limit point, or is not stable; analyse "
            "an earlier state");
        return w_K_w;
      }

      /** x = V s and its B x (s: column @p column of @p S, whose rows
       * are the first basis vectors). */
      void
      combine(const dealii::FullMatrix<double> &S,
              const unsigned int                column,
              Vector                           &x,
              Vector                           &B_x) const
      {
        x   = 0;
        B_x = 0;
        for (unsigned int i = 0; i < S.m(); ++i)
          {
            x.add(S(i, column), V[i]);
            B_x.add(S(i, column), BV[i]);
          }
      }

      const Matrix            &K;
      const Matrix            &K_G;
      Vector                   K_w;
      std::vector<Vector>      V;
      std::vector<Vector>      BV;
      LAPACKFullMatrix<double> H;
    };
  } // namespace



  BucklingEigensolver::BucklingEigensolver(const Settings &settings)
    : settings(settings)
  {}



  BucklingEigensolver::Result
  BucklingEigensolver::solve(
    const Solve                                        &solve_with_K,
    const Matrix                                       &K,
    const Matrix                                       &K_G,
    const std::function<bool(types::global_dof_index)> &is_free,
    const Vector                                       &layout) const
  {
    const unsigned int  k = settings.n_modes;
    const unsigned int  p = std::max(settings.block_size, 1u);
    KrylovBasis         basis(K, K_G, layout);
    std::vector<Vector> block(p, layout), rhs(p, layout);
    std::vector<double> coordinates;
    unsigned int        seed = 0;
    // Append w, or fresh start vectors in its place if it is dependent
    // (the Krylov space became invariant); throws if even those add
    // nothing (the free space is exhausted).
    const auto append_or_restart = [&](Vector &w) {
      if (basis.append(w, coordinates))
        return;
      std::vector<double> ignored;
      for (unsigned int attempt = 0; attempt < 3; ++attempt)
        {
          fill_start_vector(seed++, is_free, w);
          if (basis.append(w, ignored))
            {
              // Nothing of the dependent vector was left: no residual.
              coordinates.assign(basis.V.size(), 0.);
              return;
            }
        }
      throw std::runtime_error(
        "the buckling eigenvalue iteration ran out of independent vectors: "
        "the model has fewer free unknowns than Buckling/Number of modes "
        "and Block size ask for");
    };
    for (unsigned int j = 0; j < p; ++j)
      {
        fill_start_vector(seed++, is_free, block[j]);
        append_or_restart(block[j]);
      }

    Result                     result;
    dealii::Vector<double>     theta;
    dealii::FullMatrix<double> S;
    dealii::FullMatrix<double> R(p, p);
    unsigned int               n = 0;
    while (true)
      {
        // Rayleigh-Ritz on the basis so far: theta ascending, the columns
        // of S orthonormal.
        n = basis.V.size();
        LAPACKFullMatrix<double> H(basis.H);
        const double             huge = std::numeric_limits<double>::max();
        H.compute_eigenvalues_symmetric(-huge, huge, 0., theta, S);
        if (n + p > settings.max_basis_size)
          {
            std::ostringstream message;
            message << "the buckling eigenvalue iteration did not converge "
                       "with "
                    << n << " basis vectors (relative residual "
                    << (result.residuals.empty() ?
                          std::numeric_limits<double>::infinity() :
                          *std::max_element(result.residuals.begin(),
                                            result.residuals.end()))
                    << "); raise Buckling/Max basis size";
            throw std::runtime_error(message.str());
          }
        // The next block, K^-1 B applied to the last one, K-orthogonal to
        // the basis: W = V_next R. With K^-1 B V = V H + W E^T, the Ritz
        // pair (theta, x = V s) has the residual K^-1 B x - theta x =
        // V_next R s_last, of K-norm |R s_last| (s_last: the entries of s
        // on the last block), relative to |theta x|_K = |theta|.
        for (unsigned int j = 0; j < p; ++j)
          rhs[j] = basis.BV[n - p + j];
        solve_with_K(block, rhs);
        result.n_solves += p;
        R = 0;
        for (unsigned int j = 0; j < p; ++j)
          {
            append_or_restart(block[j]);
            for (unsigned int l = 0; l <= j; ++l)
              R(l, j) = coordinates[n + l];
          }
        const unsigned int wanted = std::min(k, n);
        result.residuals.assign(wanted, 0.);
        bool converged = n >= k;
        for (unsigned int j = 0; j < wanted; ++j)
          {
            const unsigned int ritz = n - 1 - j;
            double             norm = 0;
            for (unsigned int l = 0; l < p; ++l)
              {
                double entry = 0;
                for (unsigned int m = l; m < p; ++m)
                  entry += R(l, m) * S(n - p + m, ritz);
                norm += entry * entry;
              }
            result.residuals[j]
              = std::sqrt(norm) / std::max(std::abs(theta(ritz)), 1e-300);
            converged = converged && result.residuals[j] <= settings.tolerance;
          }
        if (converged)
          break;
      }

    Vector x(layout), B_x(layout);
    for (unsigned int j = 0; j < std::min(k, n); ++j)
      if (theta(n - 1 - j) > 0)
        {
          basis.combine(S, n - 1 - j, x, B_x);
          result.load_factors.push_back(1. / theta(n - 1 - j));
          result.modes.push_back(x);
        }
    result.residuals.resize(result.load_factors.size());
    return result;
  }
} // namespace amfrac

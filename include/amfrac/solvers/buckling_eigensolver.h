#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /**
   * The lowest positive load factors lambda of the linear buckling problem
   * (K + lambda K_G) v = 0, with K symmetric positive definite (given with
   * a solve) and K_G symmetric indefinite. With B = -K_G it is the
   * symmetric-definite problem B v = mu K v, mu = 1 / lambda, whose largest
   * mu are wanted, i.e. the largest eigenvalues of K^-1 B, which is
   * self-adjoint in the K inner product.
   *
   * Block Lanczos with full reorthogonalization: a K-orthonormal basis V of
   * the block Krylov space of K^-1 B, grown by one block of solves at a
   * time, with the Rayleigh-Ritz problem (V^T B V) s = theta s solved after
   * each block. B V is kept, so that the residual B x - theta K x of a Ritz
   * pair costs one product with K. A block of p vectors finds eigenvalues
   * of multiplicity up to p (a symmetric plate's pairs of equal modes).
   * Everything is in the parallel vectors of the scene: the answer does not
   * depend on the number of ranks beyond rounding.
   */
  class BucklingEigensolver
  {
  public:
    using Matrix = TrilinosWrappers::SparseMatrix;
    using Vector = TrilinosWrappers::MPI::Vector;
    /** x_j = K^-1 b_j for every j, with x_j zero on constrained rows if
     * b_j is. */
    using Solve = std::function<void(std::vector<Vector>       &x,
                                     const std::vector<Vector> &b)>;

    struct Settings
    {
      unsigned int n_modes = 1;
      /** Vectors per block (at least 1). */
      unsigned int block_size = 2;
      double       tolerance  = 1e-8;
      /** The largest basis (vectors) before giving up. */
      unsigned int max_basis_size = 240;
    };

    struct Result
    {
      /** The load factors lambda_1 <= lambda_2 <= ... that are positive
       * (at most n_modes). */
      std::vector<double> load_factors;
      /** The modes, K-normalized (v . K v = 1). */
      std::vector<Vector> modes;
      /** The relative residual |B v - mu K v| / |B v| of each mode. */
      std::vector<double> residuals;
      unsigned int        n_solves = 0;
    };

    explicit BucklingEigensolver(const Settings &settings);

    /** @p is_free(i) is false for constrained rows (owned index i); @p K is
     * the matrix @p solve_with_K inverts. Throws std::runtime_error naming
     * the cause if the wanted modes do not converge within
     * Settings::max_basis_size vectors. */
    Result
    solve(const Solve                                        &solve_with_K,
          const Matrix                                       &K,
          const Matrix                                       &K_G,
          const std::function<bool(types::global_dof_index)> &is_free,
          const Vector                                       &layout) const;

  private:
    const Settings settings;
  };
} // namespace amfrac

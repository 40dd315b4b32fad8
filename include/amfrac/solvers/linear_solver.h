#pragma once

#include <amfrac/parameters/parameters.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace amfrac
{
  using namespace dealii;

  /**
   * The linear solver of a scene: a sparse direct solver (Trilinos Amesos:
   * MUMPS or KLU) or CG preconditioned by Trilinos ML smoothed-aggregation
   * AMG with the rigid-body modes as near null space. The factorization or
   * the AMG hierarchy is set up once per matrix and reused for every
   * right-hand side.
   */
  class LinearSolver
  {
  public:
    using Matrix = TrilinosWrappers::SparseMatrix;
    using Vector = TrilinosWrappers::MPI::Vector;

    explicit LinearSolver(const parameters::LinearSolver &parameters);
    ~LinearSolver();

    /**
     * Factorize @p matrix, or build the AMG hierarchy from it and from
     * @p near_null_space: one vector per mode, each holding the locally
     * owned rows. @p node_coordinates (one array per axis, one entry per
     * owned node) serve the auxiliary aggregation
     * that thin laminates need. Returns the wall time it took.
     */
    double
    initialize(const Matrix                           &matrix,
               const std::vector<std::vector<double>> &near_null_space,
               const unsigned int                      n_pde_equations,
               const std::vector<std::vector<double>> &node_coordinates);

    /** Forget the factorization (or the AMG hierarchy) and the matrix.
     * Call it before that matrix is reinitialized or destroyed: Amesos'
     * MUMPS reads the matrix (its communicator) when it is destroyed, and
     * a matrix freed first makes that a read of freed memory (it crashed
     * after two mesh changes in a row). The next solve needs
     * initialize(). */
    void
    release();

    /** Redo the factorization (or the AMG hierarchy on the old
     * aggregates) after the values of the last matrix changed, its pattern
     * not. Returns the wall time it took. */
    double
    update_values();

    /** Whether a direct solve checks its residual (a singular matrix can
     * factorize with tiny pivots). Newton loops that test their own
     * residual switch it off. */
    void
    set_check_residual(const bool value)
    {
      check_residual = value;
    }
    bool
    checks_residual() const
    {
      return check_residual;
    }

    /** Whether the matrices are symmetric (CG) or not (GMRES); only the
     * iterative solver cares. */
    void
    set_symmetric(const bool value)
    {
      symmetric = value;
    }

    struct Report
    {
      unsigned int iterations = 0;
      double       seconds    = 0;
    };

    /** Solve with the matrix of the last initialize(). Throws
     * std::runtime_error naming the cause if CG does not converge. */
    Report
    solve(Vector &x, const Vector &b);

    /** x_j = A^-1 b_j for every j: one forward and backward substitution
     * sweep over all right-hand sides with the direct solver (faster per
     * vector than one by one), one CG solve each otherwise. The residual
     * check of set_check_residual() applies to each. */
    Report
    solve(std::vector<Vector> &x, const std::vector<Vector> &b);

    std::string
    name() const;

  private:
    const parameters::LinearSolver                     parameters;
    const Matrix                                      *matrix = nullptr;
    std::unique_ptr<Epetra_LinearProblem>              direct_problem;
    std::unique_ptr<Amesos_BaseSolver>                 direct;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    std::vector<double>                                null_space_storage;
    std::vector<std::vector<double>>                   coordinates;
    bool                                               symmetric      = true;
    bool                                               check_residual = true;

    /** Throws CollectiveError if A x = b is far from satisfied (only if
     * check_residual). */
    void
    check_direct_residual(const Vector &x, const Vector &b) const;

    /** Numeric factorization; throws CollectiveError if singular. */
    void
    factorize();
  };
} // namespace amfrac

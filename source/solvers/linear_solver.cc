#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/solvers/linear_solver.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_gmres.h>
#include <exception>
#include <ml_MultiLevelPreconditioner.h>
#include <sstream>

namespace amfrac
{
  LinearSolver::LinearSolver(const parameters::LinearSolver &parameters)
    : parameters(parameters)
  {}



  LinearSolver::~LinearSolver()
  {
    // MUMPS (and ML) free their communicators collectively. When an error
    // on this rank alone unwinds the stack, the other ranks wait elsewhere
    // and would never join: leave the solver objects to the process's end
    // (main() aborts the job) instead of hanging in their destructors.
    if (std::uncaught_exceptions() > 0)
      {
        direct.release();
        direct_problem.release();
        amg.release();
      }
  }



  void
  LinearSolver::release()
  {
    direct.reset();
    direct_problem.reset();
    amg.reset();
    matrix = nullptr;
  }



  std::string
  LinearSolver::name() const
  {
    if (parameters.type == parameters::LinearSolver::Type::direct)
      return "direct (Amesos " + parameters.direct_package + ")";
    return "CG + ML AMG (" + parameters.smoother_type + ")";
  }



  double
  LinearSolver::initialize(
    const Matrix                           &system_matrix,
    const std::vector<std::vector<double>> &near_null_space,
    const unsigned int                      n_pde_equations,
    const std::vector<std::vector<double>> &node_coordinates)
  {
    Timer timer;
    release(); // the old solver refers to its problem
    matrix = &system_matrix;
    if (parameters.type == parameters::LinearSolver::Type::direct)
      {
        // Amesos directly rather than deal.II's SolverDirect, so that a
        // singular stiffness (a laminate free to move) gets a message that
        // names the likely cause. (MatrixProperty = SPD and the METIS
        // ordering were tried: no change in MUMPS' flops or time here.)
        direct_problem = std::make_unique<Epetra_LinearProblem>();
        direct_problem->SetOperator(
          const_cast<Epetra_CrsMatrix *>(&system_matrix.trilinos_matrix()));
        Amesos factory;
        direct.reset(factory.Create(parameters.direct_package == "mumps" ?
                                      "Amesos_Mumps" :
                                      "Amesos_Klu",
                                    *direct_problem));
        AssertThrow(direct != nullptr,
                    ExcMessage("Amesos package " + parameters.direct_package
                               + " is not available"));
        AssertThrow(direct->SymbolicFactorization() == 0,
                    ExcMessage("symbolic factorization failed"));
        factorize();
        return timer.wall_time();
      }

    // ML smoothed aggregation; the null space is handed over directly since
    // deal.II's AdditionalData only takes constant modes.
    Teuchos::ParameterList ml;
    ML_Epetra::SetDefaults("SA", ml);
    ml.set("ML output", 0);
    ml.set("PDE equations", static_cast<int>(n_pde_equations));
    ml.set("aggregation: threshold", parameters.aggregation_threshold);
    ml.set("smoother: sweeps", static_cast<int>(parameters.smoother_sweeps));
    ml.set("smoother: type",
           parameters.smoother_type == "ILU" ? "IFPACK" :
                                               parameters.smoother_type);
    if (parameters.smoother_type == "ILU")
      ml.set("smoother: ifpack type", "ILU");
    // Thin plies make elements much wider than thick; ML's auxiliary
    // aggregation (by the distance Laplacian) needs the node coordinates.
    coordinates = node_coordinates;
    const char *axis_names[3]
      = {"x-coordinates", "y-coordinates", "z-coordinates"};
    for (unsigned int d = 0; d < coordinates.size(); ++d)
      ml.set(axis_names[d], coordinates[d].data());
    if (parameters.auxiliary_threshold > 0)
      {
        ml.set("aggregation: aux: enable", true);
        ml.set("aggregation: aux: threshold", parameters.auxiliary_threshold);
      }
    ml.set("coarse: type", "Amesos-KLU");
    ml.set("coarse: max size", 2000);
    const std::size_t n_owned = system_matrix.local_size();
    null_space_storage.assign(n_owned * near_null_space.size(), 0.);
    for (unsigned int m = 0; m < near_null_space.size(); ++m)
      std::copy(near_null_space[m].begin(),
                near_null_space[m].end(),
                null_space_storage.begin() + m * n_owned);
    ml.set("null space: type", "pre-computed");
    ml.set("null space: dimension", static_cast<int>(near_null_space.size()));
    ml.set("null space: vectors", null_space_storage.data());
    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    amg->initialize(system_matrix.trilinos_matrix(), ml);
    return timer.wall_time();
  }



  void
  LinearSolver::factorize()
  {
    const int status = direct->NumericFactorization();
    if (status != 0)
      throw CollectiveError(
        "the stiffness matrix could not be factorized (error "
        + std::to_string(status)
        + "): is the laminate (or a ply cut loose by a debonded interface) "
          "free to move as a rigid body? Check the prescribed "
          "displacements.");
  }



  double
  LinearSolver::update_values()
  {
    Assert(matrix != nullptr, ExcInternalError());
    Timer timer;
    if (direct)
      factorize();
    else
      amg->reinit();
    return timer.wall_time();
  }



  LinearSolver::Report
  LinearSolver::solve(std::vector<Vector> &x, const std::vector<Vector> &b)
  {
    AssertDimension(x.size(), b.size());
    if (!direct || x.empty())
      {
        Report total;
        for (unsigned int j = 0; j < x.size(); ++j)
          {
            const Report report = solve(x[j], b[j]);
            total.iterations += report.iterations;
            total.seconds += report.seconds;
          }
        return total;
      }
    Timer                 timer;
    std::vector<double *> x_columns, b_columns;
    for (unsigned int j = 0; j < x.size(); ++j)
      {
        x_columns.push_back(x[j].trilinos_vector()[0]);
        b_columns.push_back(const_cast<double *>(b[j].trilinos_vector()[0]));
      }
    const auto        &map = x[0].trilinos_vector().Map();
    Epetra_MultiVector x_block(View, map, x_columns.data(), x.size());
    Epetra_MultiVector b_block(View, map, b_columns.data(), b.size());
    direct_problem->SetLHS(&x_block);
    direct_problem->SetRHS(&b_block);
    AssertThrow(direct->Solve() == 0, ExcMessage("the direct solver failed"));
    for (unsigned int j = 0; j < x.size(); ++j)
      check_direct_residual(x[j], b[j]);
    return {static_cast<unsigned int>(x.size()), timer.wall_time()};
  }



  void
  LinearSolver::check_direct_residual(const Vector &x, const Vector &b) const
  {
    // A singular stiffness can pass the factorization with tiny pivots;
    // the residual tells (a Newton loop checks its own residual).
    if (!check_residual)
      return;
    Vector residual(b);
    matrix->vmult(residual, x);
    residual -= b;
    const double relative = residual.l2_norm() / std::max(b.l2_norm(), 1e-300);
    if (!(relative < 1e-6))
      {
        std::ostringstream message;
        message << "the direct solve is inaccurate (relative residual "
                << relative
                << "): the stiffness matrix is singular or nearly so. Is "
                   "the laminate free to move as a rigid body? Check the "
                   "prescribed displacements.";
        throw CollectiveError(message.str());
      }
  }



  LinearSolver::Report
  LinearSolver::solve(Vector &x, const Vector &b)
  {
    Timer  timer;
    Report report;
    if (direct)
      {
        direct_problem->SetLHS(&x.trilinos_vector());
        direct_problem->SetRHS(
          const_cast<Epetra_MultiVector *>(&b.trilinos_vector()));
        AssertThrow(direct->Solve() == 0,
                    ExcMessage("the direct solver failed"));
        report.iterations = 1;
        check_direct_residual(x, b);
      }
    else
      {
        const double norm_b = b.l2_norm();
        if (norm_b == 0)
          {
            // A zero load has the zero solution; CG could not reach a
            // relative target of 0.
            x              = 0;
            report.seconds = timer.wall_time();
            return report;
          }
        SolverControl control(parameters.max_iterations,
                              parameters.tolerance * norm_b);
        try
          {
            if (symmetric)
              SolverCG<Vector>(control).solve(*matrix, x, b, *amg);
            else
              SolverGMRES<Vector>(control).solve(*matrix, x, b, *amg);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            std::ostringstream message;
            message << "linear solver (" << (symmetric ? "CG" : "GMRES")
                    << " + AMG) did not converge in " << e.last_step
                    << " iterations: residual " << e.last_residual
                    << " against the target " << control.tolerance()
                    << " (raise Linear solver/Max iterations or use Solver "
                       "= direct)";
            throw CollectiveError(message.str());
          }
        report.iterations = control.last_step();
      }
    report.seconds = timer.wall_time();
    return report;
  }
} // namespace amfrac

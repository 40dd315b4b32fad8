// Linear buckling of the last converged static state (subsection
// Buckling): K_G from its stress, the lowest positive load factors of
// (K + lambda K_G) v = 0 with the factorization of K the static solve left,
// buckling.csv and the modes as a VTU series.
#include <algorithm>
#include <amfrac/parameters/input_error.h>
#include <amfrac/postprocess/vtu_series.h>
#include <amfrac/simulator/simulator.h>
#include <amfrac/solvers/buckling_eigensolver.h>
#include <array>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>
#include <limits>
#include <optional>
#include <sstream>

namespace amfrac
{
  namespace
  {
    std::optional<double>
    find_column(const std::vector<std::pair<std::string, double>> &row,
                const std::string                                 &name)
    {
      for (const auto &[key, value] : row)
        if (key == name)
          return value;
      return std::nullopt;
    }



    /* The entry that scales a mode to a shape (largest displacement 1,
     * positive): the largest in magnitude, and among the entries within a
     * relative 1e-6 of it the one whose support point comes first in
     * (x, y, z, component) order. A symmetric or antisymmetric mode has two
     * such entries of opposite sign, equal up to the eigensolver's
     * round-off, which differs with the number of ranks: the position, not
     * the round-off, must pick the sign. */
    template <int dim>
    double
    shape_scale(const TrilinosWrappers::MPI::Vector &mode,
                const TiedCopyDoFs<dim>             &dofs,
                const MPI_Comm                       comm)
    {
      const double largest = mode.linfty_norm();
      // Support point, component, then minus the value (coincident copies
      // of a cracked node: the positive one).
      std::vector<double> first(dim + 2, std::numeric_limits<double>::max());
      for (const auto i : dofs.locally_owned_dofs())
        if (std::abs(mode(i)) >= (1 - 1e-6) * largest)
          {
            std::vector<double> key(dim + 2);
            for (unsigned int d = 0; d < dim; ++d)
              key[d] = dofs.support_point(i)[d];
            key[dim]     = dofs.component(i);
            key[dim + 1] = -mode(i);
            first        = std::min(first, key);
          }
      const auto all = Utilities::MPI::all_gather(comm, first);
      const auto key = *std::min_element(all.begin(), all.end());
      return key[dim + 1] > 0 ? -largest : largest;
    }
  } // namespace



  template <int dim>
  std::string
  Simulator<dim>::interfaces_refuse_buckling(const double t, const bool report)
  {
    // K must be symmetric positive definite: the tangent of an elastic
    // interface state (intact bonds, open cracks, frictionless contact).
    // The interface points read the neighbours' values: a ghosted copy.
    const auto points = interfaces->output_points(relevant_solution);
    using Record      = InterfacePointRecord<dim>;
    std::array<std::size_t, 4> count{};
    for (const auto &point : points)
      ++count[point.status];
    for (auto &n : count)
      n = Utilities::MPI::sum(n, comm);
    if (report)
      pcout << "  buckling of the Newton state at t=" << t
            << ": interface points " << count[Record::intact] << " bonded, "
            << count[Record::debonded] << " open, " << count[Record::contact]
            << " in contact, " << count[Record::softening] << " softening"
            << std::endl;
    const std::size_t softening = count[Record::softening];
    const std::size_t rubbing
      = parameters.cohesive.friction > 0 ? count[Record::contact] : 0;
    if (softening == 0 && rubbing == 0)
      return "";
    std::ostringstream message;
    message << "linear buckling needs a symmetric, positive definite "
               "tangent, but at t="
            << t << " " << softening << " interface point(s) soften and "
            << rubbing
            << " are in frictional contact: analyse a state before "
               "damage starts (a shorter Time/End time or earlier "
               "Buckling/Analysis times), or set Cohesive interfaces/"
               "Friction coefficient = 0";
    return message.str();
  }



  template <int dim>
  bool
  Simulator<dim>::buckling_due(const double t)
  {
    const auto &times = parameters.buckling.analysis_times;
    bool        due   = false;
    while (next_analysis_time < times.size()
           && t >= times[next_analysis_time] * (1 - 1e-12))
      {
        ++next_analysis_time;
        due = true;
      }
    return due;
  }



  template <int dim>
  void
  Simulator<dim>::skip_failed_analysis(const std::function<void()> &analysis,
                                       const double                 t)
  {
    try
      {
        analysis();
      }
    catch (const CollectiveError &e)
      {
        pcout << "  buckling: warning: the analysis at t=" << t
              << " is skipped: " << e.what() << std::endl;
      }
  }



  template <int dim>
  void
  Simulator<dim>::analyse_during_history(LinearSolver &solver, const double t)
  {
    // An analysis that cannot be done (a softening front, a tangent that
    // is no longer positive definite past a bifurcation) must not end the
    // run: it is reported and skipped. The failures are collective (global
    // counts, global norms of the Lanczos basis).
    // The converged step's residual (with the hanging dofs' share handed
    // on) is part of the state a checkpoint saves: kept as it was.
    const Vector residual = newton->residual;
    relevant_solution     = newton->converged_solution;
    const std::string refused
      = interfaces ? interfaces_refuse_buckling(t) : std::string();
    if (refused.empty())
      skip_failed_analysis([&]() { analyse_newton_state(solver, t); }, t);
    else
      pcout << "  buckling: warning: the analysis at t=" << t
            << " is skipped: " << refused << std::endl;
    // Its factorization is of the analysed tangent; the Newton path
    // factorizes its own again.
    solver_ready      = false;
    solution          = newton->converged_solution;
    relevant_solution = solution;
    newton->residual  = residual;
  }



  template <int dim>
  void
  Simulator<dim>::analyse_newton_buckling(LinearSolver &solver, const double t)
  {
    relevant_solution = newton->converged_solution;
    if (interfaces)
      {
        const std::string failure = interfaces_refuse_buckling(t);
        if (!failure.empty())
          throw CollectiveError(failure);
      }
    analyse_newton_state(solver, t);
  }



  template <int dim>
  void
  Simulator<dim>::analyse_newton_state(LinearSolver &solver, const double t)
  {
    if (finite_strain)
      {
        analyse_prebuckled_state(solver, t);
        return;
      }
    update_residual(newton->converged_solution, &system_matrix);
    solver.initialize(system_matrix,
                      rigid_body_modes(),
                      dim,
                      owned_node_coordinates());
    solution          = newton->converged_solution;
    relevant_solution = solution;
    analyse_buckling(solver, newton->increment_constraints, t);
  }



  template <int dim>
  void
  Simulator<dim>::analyse_prebuckled_state(LinearSolver &solver, const double t)
  {
    // Linearized pre-buckling (Brendel and Ramm 1980): along the path,
    // K_T(t + mu) ~ K_T(t) + mu dK_T/dt, singular at the lowest positive
    // mu of (K_T + mu dK_T/dt) v = 0. dK_T/dt is the derivative along the
    // path tangent d = du/dt, by central differences: exact up to rounding
    // for St Venant-Kirchhoff plies, whose tangent is quadratic in u.
    TimerOutput::Scope scope(timer, "buckling");
    Timer              watch;
    NewtonState       &n = *newton;
    if (!(t > 0))
      throw CollectiveError("linear buckling of a pre-buckled state needs a "
                            "loaded state: Time/End time must be positive");
    setup_prebuckling_pattern();
    const Vector u = n.converged_solution;
    update_residual(u, &system_matrix);
    solver.initialize(system_matrix,
                      rigid_body_modes(),
                      dim,
                      owned_node_coordinates());
    // The path tangent: K_T d = f(1) with d = g(1) on the supports, and
    // the rate K_T d - f(1) of the residual, whose entries on supports are
    // the rates of the reactions.
    pattern_derivative(u);
    n.pattern_condensed *= -1;
    solver.solve(n.pattern_increment, n.pattern_condensed);
    Vector direction(n.pattern_increment);
    n.increment_constraints.distribute(direction);
    direction += n.load_pattern;
    Vector rate(direction);
    tangent_product(direction, rate);
    rate -= n.load_unit;
    if (n.hanging)
      n.hanging->condense(rate);
    const auto rates = load_columns(t, rate);

    // The difference of the two tangents is small against their entries,
    // and a bending mode's quadratic form cancels most of them: rounding
    // in dK_T/dt grows like 1/h (the strip of buckling_strip_2d.prm, t_c
    // from t = 1: 3.5e-6 at h = 1e-3 t, 3e-7 at 1e-2 t, 1e-8 at 0.1 t),
    // while the interfaces' frame, the only part not quadratic in u,
    // changes t_c by 1e-8 between 1e-3 t and 0.1 t (the panel). 0.02 t
    // also keeps the two states near the analysed one.
    const double                   h = 0.02 * t;
    TrilinosWrappers::SparseMatrix derivative, behind;
    derivative.reinit(system_matrix);
    behind.reinit(system_matrix);
    Vector state(u);
    state.add(h, direction);
    update_residual(state, &derivative);
    refuse_softening_ahead(t + h);
    state = u;
    state.add(-h, direction);
    update_residual(state, &behind);
    derivative.add(-1., behind);
    derivative *= 1. / (2 * h);
    // Back to the converged state (its trial history and tangent).
    update_residual(u, &system_matrix);
    relevant_solution = u;
    solution          = u;

    const auto result = solve_buckling_problem(solver,
                                               system_matrix,
                                               derivative,
                                               n.increment_constraints,
                                               buckling_settings());
    pcout << "  buckling of the pre-buckled state at t=" << t << ": "
          << result.load_factors.size() << " critical t from "
          << result.n_solves << " solves, " << watch.wall_time() << " s"
          << std::endl;
    if (result.load_factors.empty())
      pcout << "  buckling: warning: the tangent along the path does not "
               "become singular ahead of t="
            << t << " for the lowest " << parameters.buckling.n_modes
            << " mode(s)" << std::endl;
    std::vector<double> factors;
    for (const double mu : result.load_factors)
      factors.push_back((t + mu) / t);
    lowest_load_factor = factors.empty() ? 0. : factors.front();
    write_buckling_modes(factors, result.modes, result.residuals, t, &rates);
  }



  template <int dim>
  void
  Simulator<dim>::refuse_softening_ahead(const double t_ahead)
  {
    // The tangent ahead on the path enters dK_T/dt: a point that starts to
    // soften there would put its softening tangent into the derivative.
    if (!interfaces)
      return;
    const std::string refused = interfaces_refuse_buckling(t_ahead, false);
    if (!refused.empty())
      throw CollectiveError(
        "linear buckling of the pre-buckled state differentiates the "
        "tangent over 2 % of the load ahead, and there "
        + refused);
  }



  template <int dim>
  void
  Simulator<dim>::setup_prebuckling_pattern()
  {
    setup_load_pattern(true,
                       "linear buckling of a total Lagrangian state (it "
                       "follows the load path)",
                       "Buckling/Number of modes");
  }



  template <int dim>
  BucklingEigensolver::Settings
  Simulator<dim>::buckling_settings() const
  {
    const auto                   &b = parameters.buckling;
    BucklingEigensolver::Settings settings;
    settings.n_modes        = b.n_modes;
    settings.block_size     = b.block_size;
    settings.tolerance      = b.tolerance;
    settings.max_basis_size = b.max_basis_size;
    return settings;
  }



  template <int dim>
  BucklingEigensolver::Result
  Simulator<dim>::small_strain_buckling(const double       t,
                                        const unsigned int n_modes)
  {
    TimerOutput::Scope scope(timer, "buckling");
    // K outlives the solver, whose factorization refers to it.
    TrilinosWrappers::SparseMatrix K;
    LinearSolver                   solver(parameters.linear_solver);
    AffineConstraints<double>      fixed;
    make_constraints(t, fixed, false);
    const IndexSet &owned = dof_layer.locally_owned_dofs();
    Vector          state(owned, comm), rhs(owned, comm);
    const IndexSet &relevant = dof_layer.locally_relevant_dofs();
    {
      TrilinosWrappers::SparsityPattern pattern(owned, owned, relevant, comm);
      assembler.add_couplings(fixed, pattern);
      if (interfaces)
        interfaces->add_couplings(fixed, pattern);
      pattern.compress();
      K.reinit(pattern);
    }
    assembler.assemble_matrix(fixed, K);
    if (interfaces)
      {
        // The interface tangent at zero displacement: bonded points and
        // open pre-cracks. Both copies of a supported node carry the same
        // prescribed value, so the interfaces add nothing to the load.
        Vector zero(owned, relevant, comm), force;
        force.reinit(owned, relevant, comm, true);
        interfaces->assemble(zero, force, fixed, &K);
        K.compress(VectorOperation::add);
      }
    solver.initialize(K, rigid_body_modes(), dim, owned_node_coordinates());
    assembler.assemble_rhs(loads, t, fixed, rhs);
    solver.solve(state, rhs);
    fixed.distribute(state);
    Vector ghosted(owned, relevant, comm);
    ghosted = state;
    BucklingEigensolver::Settings settings;
    settings.n_modes        = n_modes;
    settings.block_size     = std::min(std::max(n_modes, 1u), 2u);
    settings.tolerance      = parameters.buckling.tolerance;
    settings.max_basis_size = std::max(parameters.buckling.max_basis_size,
                                       n_modes + 2 * settings.block_size);
    return buckling_eigenpairs(solver, K, fixed, ghosted, settings);
  }



  template <int dim>
  BucklingEigensolver::Result
  Simulator<dim>::buckling_eigenpairs(
    LinearSolver                         &solver,
    const TrilinosWrappers::SparseMatrix &K,
    const AffineConstraints<double>      &fixed,
    const Vector                         &state,
    const BucklingEigensolver::Settings  &settings)
  {
    TrilinosWrappers::SparseMatrix geometric;
    assembler.reinit_matrix(fixed, geometric);
    assembler.assemble_geometric_matrix(state, fixed, geometric);
    return solve_buckling_problem(solver, K, geometric, fixed, settings);
  }



  template <int dim>
  BucklingEigensolver::Result
  Simulator<dim>::solve_buckling_problem(
    LinearSolver                         &solver,
    const TrilinosWrappers::SparseMatrix &K,
    const TrilinosWrappers::SparseMatrix &B,
    const AffineConstraints<double>      &fixed,
    const BucklingEigensolver::Settings  &settings)
  {
    // The eigensolver checks its own residuals. Its failures are
    // decided on global quantities: collective.
    const bool checked = solver.checks_residual();
    solver.set_check_residual(false);
    try
      {
        const auto result = BucklingEigensolver(settings).solve(
          [&](std::vector<Vector> &x, const std::vector<Vector> &b) {
            solver.solve(x, b);
          },
          K,
          B,
          [&](const types::global_dof_index i) {
            return !fixed.is_constrained(i);
          },
          Vector(dof_layer.locally_owned_dofs(), comm));
        solver.set_check_residual(checked);
        return result;
      }
    catch (const CollectiveError &)
      {
        throw;
      }
    catch (const std::runtime_error &e)
      {
        throw CollectiveError(e.what());
      }
  }



  template <int dim>
  void
  Simulator<dim>::seed_imperfection_from_mode()
  {
    const unsigned int k = parameters.geometry.imperfection_mode;
    const double       t = parameters.time.end_time;
    collect_supports();
    const auto result = small_strain_buckling(t, k);
    if (result.load_factors.size() < k)
      throw InputError("Geometry/Imperfection mode",
                       "the small-strain state at End time has "
                         + std::to_string(result.load_factors.size())
                         + " positive buckling load factor(s) among the lowest "
                         + std::to_string(k)
                         + ": its load does not buckle the laminate into mode "
                         + std::to_string(k));
    // The mode on every rank (all vertices move identically everywhere),
    // hanging nodes interpolated, scaled to the amplitude with its largest
    // component positive (an eigenvector's sign is arbitrary).
    Vector                    mode = result.modes[k - 1];
    AffineConstraints<double> homogeneous;
    make_constraints(t, homogeneous, true);
    homogeneous.distribute(mode);
    mode *= parameters.geometry.imperfection_amplitude
            / shape_scale(mode, dof_layer, comm);
    Vector everywhere(dof_layer.locally_owned_dofs(),
                      complete_index_set(dof_layer.n_dofs()),
                      comm);
    everywhere = mode;
    move_vertices(everywhere);
    pcout << "amfrac: imperfection: buckling mode " << k
          << " of the small-strain state at t=" << t << " (load factor "
          << result.load_factors[k - 1] << "), largest displacement "
          << parameters.geometry.imperfection_amplitude << " mm" << std::endl;
    rebuild_after_mesh_change();
    if (interfaces)
      interfaces->setup(dof_layer, parameters.boundary_conditions.constants);
  }



  template <int dim>
  void
  Simulator<dim>::move_vertices(const Vector &displacement)
  {
    // Each vertex by the mean of the values its cells give it (the copies
    // of a duplicated node may differ).
    const auto                          &fe = dof_layer.get_fe();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    std::vector<Tensor<1, dim>>          shift(triangulation.n_vertices());
    std::vector<unsigned int>            count(triangulation.n_vertices());
    for (const auto &cell : dof_layer.copy_handler().active_cell_iterators())
      {
        dof_layer.get_dof_indices(cell, indices);
        for (const unsigned int v : cell->vertex_indices())
          {
            for (unsigned int c = 0; c < dim; ++c)
              shift[cell->vertex_index(v)][c]
                += displacement(indices[fe.component_to_system_index(c, v)]);
            ++count[cell->vertex_index(v)];
          }
      }
    std::vector<bool> moved(triangulation.n_vertices());
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const unsigned int index = cell->vertex_index(v);
          if (moved[index])
            continue;
          cell->vertex(v) += shift[index] / count[index];
          moved[index] = true;
        }
  }



  template <int dim>
  void
  Simulator<dim>::analyse_buckling(LinearSolver                    &solver,
                                   const AffineConstraints<double> &fixed,
                                   const double                     t)
  {
    TimerOutput::Scope scope(timer, "buckling");
    Timer              watch;
    const auto        &b      = parameters.buckling;
    const auto         result = buckling_eigenpairs(
      solver, system_matrix, fixed, relevant_solution, buckling_settings());
    pcout << "  buckling: " << result.load_factors.size()
          << " positive load factor(s) from " << result.n_solves << " solves, "
          << watch.wall_time() << " s" << std::endl;
    if (result.load_factors.empty())
      pcout << "  buckling: warning: no positive load factor among the "
            << b.n_modes
            << " wanted: the load of the last step does not buckle the "
               "laminate (reversed, it may)"
            << std::endl;
    lowest_load_factor
      = result.load_factors.empty() ? 0. : result.load_factors.front();
    write_buckling_modes(result.load_factors,
                         result.modes,
                         result.residuals,
                         t);
  }



  template <int dim>
  void
  Simulator<dim>::write_buckling_modes(
    const std::vector<double>                         &factors,
    std::vector<Vector>                                modes,
    const std::vector<double>                         &residuals,
    const double                                       t,
    const std::vector<std::pair<std::string, double>> *rates)
  {
    AffineConstraints<double> homogeneous;
    make_constraints(t, homogeneous, true);
    // One table for the run: refinement cycles add their rows.
    if (!buckling_summary)
      buckling_summary = std::make_unique<History>(
        parameters.output.directory + "/buckling.csv",
        Utilities::MPI::this_mpi_process(comm) == 0);
    const bool cycles = parameters.adaptivity.active();
    // Analyses during the load history: a series per analysis.
    const bool during = !parameters.buckling.analysis_times.empty();
    ++buckling_analyses;
    const std::string number = Utilities::int_to_string(buckling_analyses, 2);
    const std::string prefix
      = cycles ? "buckling_mode-c" + Utilities::int_to_string(cycle, 2) + "-" :
        during ? "buckling_mode-a" + number + "-" :
                 "buckling_mode-";
    const std::string series
      = during ? "buckling_modes-" + number + ".pvd" : "buckling_modes.pvd";
    std::vector<std::pair<double, std::string>> records;
    Vector                 relevant(dof_layer.locally_owned_dofs(),
                    dof_layer.locally_relevant_dofs(),
                    comm);
    dealii::Vector<double> copies;
    const char            *axis = "xyz";
    for (unsigned int k = 0; k < factors.size(); ++k)
      {
        homogeneous.distribute(modes[k]);
        // Largest displacement 1, positive: a shape, not an amplitude.
        modes[k] /= shape_scale(modes[k], dof_layer, comm);
        relevant = modes[k];
        dof_layer.expand(relevant, copies);

        std::vector<std::pair<std::string, double>> row
          = {{"mode", k + 1},
             {"load_factor", factors[k]},
             {"residual", residuals[k]},
             {"critical_time", factors[k] * t},
             {"time", t}};
        if (cycles)
          row.insert(row.begin(), {"cycle", cycle});
        // The loads at buckling from each force of the last step's
        // history row: scaled, or extrapolated along the path tangent.
        for (const auto &[name, value] : last_row)
          if (name.rfind("force_", 0) == 0 || name.rfind("reaction_", 0) == 0)
            {
              if (!rates)
                row.emplace_back("critical_" + name, factors[k] * value);
              else if (const auto rate = find_column(*rates, name))
                row.emplace_back("critical_" + name,
                                 value + (factors[k] - 1) * t * *rate);
            }
        const auto values = probe->evaluate(copies);
        for (unsigned int p = 0; p < values.size(); ++p)
          for (unsigned int d = 0; d < dim; ++d)
            row.emplace_back("p" + std::to_string(p) + "_u" + axis[d],
                             values[p].displacement[d]);
        buckling_summary->add_row(row);
        pcout << "    mode " << k + 1 << ": load factor " << factors[k]
              << " (residual " << residuals[k] << ")" << std::endl;

        if (!parameters.output.write_vtu)
          continue;
        DataOut<dim> data_out;
        data_out.set_flags(fast_vtk_flags());
        data_out.attach_dof_handler(dof_layer.copy_handler());
        data_out.add_data_vector(
          copies,
          std::vector<std::string>(dim, "mode"),
          DataOut<dim>::type_dof_data,
          std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            dim, DataComponentInterpretation::component_is_part_of_vector));
        data_out.build_patches(dof_layer.get_mapping(),
                               dof_layer.get_fe().degree,
                               DataOut<dim>::curved_boundary);
        // The series' "time" is the mode number.
        write_vtu_step(data_out,
                       parameters.output.directory,
                       prefix + Utilities::int_to_string(k + 1, 3),
                       series,
                       k + 1,
                       records,
                       comm);
      }
  }



  template void
  Simulator<2>::analyse_buckling(LinearSolver &,
                                 const AffineConstraints<double> &,
                                 const double);
  template void
  Simulator<3>::analyse_buckling(LinearSolver &,
                                 const AffineConstraints<double> &,
                                 const double);
  template bool
  Simulator<2>::buckling_due(const double);
  template bool
  Simulator<3>::buckling_due(const double);
  template void
  Simulator<2>::analyse_during_history(LinearSolver &, const double);
  template void
  Simulator<3>::analyse_during_history(LinearSolver &, const double);
  template void
  Simulator<2>::skip_failed_analysis(const std::function<void()> &,
                                     const double);
  template void
  Simulator<3>::skip_failed_analysis(const std::function<void()> &,
                                     const double);
  template void
  Simulator<2>::setup_prebuckling_pattern();
  template void
  Simulator<3>::setup_prebuckling_pattern();
  template void
  Simulator<2>::analyse_newton_buckling(LinearSolver &, const double);
  template void
  Simulator<3>::analyse_newton_buckling(LinearSolver &, const double);
  template void
  Simulator<2>::seed_imperfection_from_mode();
  template void
  Simulator<3>::seed_imperfection_from_mode();
} // namespace amfrac

// The quasi-static Newton-Raphson path of Simulator: scenes with cohesive
// interfaces or total Lagrangian kinematics. A small-strain bulk is linear,
// so its matrix is assembled once (condensed for the Newton increments, and
// unconstrained for residuals and reactions) and each iteration adds only
// the interface tangent; a total Lagrangian bulk is assembled with its
// tangent in every iteration.
#include <algorithm>
#include <amfrac/parameters/input_error.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <limits>
#include <sstream>

namespace amfrac
{
  namespace
  {
    /** The locally owned dofs of all supports, each once: a dof that two
     * conditions hold (the corner of the x- and y- faces) must count once
     * in sums of reactions. */
    template <int dim>
    std::vector<types::global_dof_index>
    owned_support_dofs(
      const std::vector<std::vector<types::global_dof_index>> &supports,
      const TiedCopyDoFs<dim>                                 &dofs)
    {
      std::vector<types::global_dof_index> held;
      for (const auto &support : supports)
        for (const auto i : support)
          if (dofs.locally_owned_dofs().is_element(i))
            held.push_back(i);
      std::sort(held.begin(), held.end());
      held.erase(std::unique(held.begin(), held.end()), held.end());
      return held;
    }

    /** Newton cycling between branches of the law (a local snap-back)
     * rather than converging: give up early and cut the step or switch to
     * dissipation control. Not while the contact set of debonded faces
     * still changes: semi-smooth Newton then decreases the residual slowly
     * until the set settles. */
    template <int dim>
    bool
    stagnates(const std::vector<double>     &residuals,
              const CohesiveInterfaces<dim> *interfaces,
              const MPI_Comm                 comm)
    {
      const std::size_t n = residuals.size();
      // Collective: every rank evaluates the contact count.
      const bool settled
        = !interfaces || interfaces->contact_changes(comm) == 0;
      return n >= 6 && residuals[n - 1] > 0.5 * residuals[n - 3] && settled;
    }

    /** The root x of a x^2 + b x + c = 0 with the larger x * preference
     * (the one that continues the path); false if there is none. */
    bool
    arc_length_root(const double a,
                    const double b,
                    const double c,
                    const double preference,
                    double      &x)
    {
      const double discriminant = b * b - 4 * a * c;
      if (!(a > 0) || !(discriminant >= 0))
        return false;
      // The cancellation-free pair of roots.
      const double q  = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
      const double x1 = q / a;
      const double x2 = q != 0 ? c / q : -x1;
      x               = x1 * preference >= x2 * preference ? x1 : x2;
      return std::isfinite(x);
    }

    /** " |r|: r0 r1 ..." for the log. */
    std::string
    residual_list(const std::vector<double> &residuals)
    {
      std::ostringstream line;
      line << ", |r|:";
      for (const double r : residuals)
        line << ' ' << std::setprecision(2) << r;
      return line.str();
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::setup_newton(const bool mesh_change)
  {
    TimerOutput::Scope scope(timer, "setup Newton");
    // A new state for a new mesh or numbering keeps the run's totals.
    const auto         fresh            = std::make_unique<NewtonState>();
    const NewtonState &old              = newton ? *newton : *fresh;
    const double       external_work    = old.external_work;
    const double       remeshing_energy = old.remeshing_energy;
    const double       insertion_energy = old.insertion_energy;
    // A transferred state not yet settled (a mesh change, then a crack
    // insertion before the next step's ledger): its out-of-balance work,
    // and the insertion's with it, goes to remeshing_energy.
    const bool   settling     = old.settling;
    const double plastic_work = old.plastic_work;
    // A prescribed impactor's last converged force and centre start the
    // trapezoidal work of the step solved again after a crack insertion.
    const Tensor<1, dim> sphere_force  = old.sphere_force;
    const Tensor<1, dim> sphere_center = old.sphere_center;
    newton                             = std::make_unique<NewtonState>();
    newton->external_work              = external_work;
    newton->remeshing_energy           = remeshing_energy;
    newton->insertion_energy           = insertion_energy;
    newton->settling                   = settling;
    newton->plastic_work               = plastic_work;
    newton->sphere_force               = sphere_force;
    newton->sphere_center              = sphere_center;
    make_constraints(0., newton->increment_constraints, true);
    const IndexSet &owned    = dof_layer.locally_owned_dofs();
    const IndexSet &relevant = dof_layer.locally_relevant_dofs();
    if (parameters.contact.active)
      setup_static_contact(mesh_change);
    build_newton_matrix(Vector(owned, comm));
    AffineConstraints<double> none;
    none.close();
    assembler.reinit_matrix(none, newton->bulk_unconstrained);
    if (!finite_strain)
      assembler.assemble_matrix(none, newton->bulk_unconstrained);

    for (Vector *v : {&solution,
                      &newton->converged_solution,
                      &newton->external_load,
                      &newton->residual,
                      &newton->condensed_residual,
                      &newton->increment,
                      &newton->previous_residual,
                      &newton->previous_load,
                      &newton->load_pattern,
                      &newton->pattern_response,
                      &newton->pattern_condensed,
                      &newton->pattern_increment,
                      &newton->load_unit,
                      &newton->arc_previous})
      v->reinit(owned, comm);
    if (body_contact)
      newton->body_contact_force.reinit(owned, comm);
    if (parameters.impactor.active && !parameters.time.explicit_dynamics)
      {
        newton->contact_force.reinit(owned, comm);
        // After a crack insertion or a mesh change the same impactor
        // moves the friction history of the last converged step to the
        // new nodes (RigidImpactor::setup()).
        if (!impactor)
          impactor
            = std::make_unique<RigidImpactor<dim>>(parameters.impactor, comm);
        impactor->setup(dof_layer);
      }
    newton->interface_force.reinit(owned, relevant, comm, true);
    if (plasticity)
      newton->plastic_force.reinit(owned, relevant, comm, true);
    relevant_solution.reinit(owned, relevant, comm);
    auto hanging = std::make_unique<HangingCondensation<dim>>(dof_layer, comm);
    if (!hanging->empty())
      newton->hanging = std::move(hanging);
  }



  template <int dim>
  void
  Simulator<dim>::setup_static_contact(const bool mesh_change)
  {
    if (!body_contact)
      body_contact
        = std::make_unique<BodyContact<dim>>(parameters.contact, comm);
    body_contact->set_static();
    if (parameters.total_lagrangian)
      body_contact->set_deformed_areas();
    body_contact->setup(dof_layer,
                        released_faces(),
                        paired_faces(),
                        mesh_change);
  }



  template <int dim>
  void
  Simulator<dim>::build_newton_matrix(const Vector &u)
  {
    // The matrix's pattern: the bulk, the interfaces and the pairs of
    // nodes and faces that may come into contact (as found at @p u).
    const IndexSet &owned    = dof_layer.locally_owned_dofs();
    const IndexSet &relevant = dof_layer.locally_relevant_dofs();
    TrilinosWrappers::SparsityPattern pattern(owned, owned, relevant, comm);
    assembler.add_couplings(newton->increment_constraints, pattern);
    if (interfaces)
      interfaces->add_couplings(newton->increment_constraints, pattern);
    if (body_contact)
      body_contact->add_couplings(u, newton->increment_constraints, pattern);
    pattern.compress();
    // The solver refers to the matrix: it goes first.
    if (newton_solver)
      newton_solver->release();
    solver_ready = false;
    system_matrix.reinit(pattern);
    // A total Lagrangian bulk is assembled per iteration (update_residual).
    if (!finite_strain)
      {
        newton->bulk_condensed.reinit(pattern);
        assembler.assemble_matrix(newton->increment_constraints,
                                  newton->bulk_condensed);
      }
  }



  template <int dim>
  double
  Simulator<dim>::update_residual(const Vector                   &trial,
                                  TrilinosWrappers::SparseMatrix *tangent)
  {
    NewtonState &n    = *newton;
    relevant_solution = trial;
    if (body_contact)
      {
        {
          TimerOutput::Scope scope(timer, "body contact");
          body_contact->evaluate(trial, n.body_contact_force);
        }
        // A node met a face the matrix does not couple it to.
        if (tangent && body_contact->couplings_outdated())
          {
            TimerOutput::Scope scope(timer, "setup Newton");
            build_newton_matrix(trial);
          }
      }
    if (finite_strain)
      {
        // F_int(u) into the residual and, with a tangent, K_T condensed
        // into it and unconstrained into bulk_unconstrained.
        TimerOutput::Scope scope(timer, "bulk (total Lagrangian)");
        n.strain_energy
          = finite_strain->assemble(relevant_solution,
                                    n.increment_constraints,
                                    n.residual,
                                    tangent,
                                    tangent ? &n.bulk_unconstrained : nullptr);
      }
    else
      {
        TimerOutput::Scope scope(timer, "residual");
        n.bulk_unconstrained.vmult(n.residual, trial);
        if (tangent)
          tangent->copy_from(n.bulk_condensed);
      }
    bool plastic_ok = true;
    if (plasticity)
      {
        TimerOutput::Scope scope(timer, "plastic plies");
        n.plastic_force = 0;
        plastic_ok      = add_plastic_correction(tangent);
        n.residual += n.plastic_force;
      }
    if (impactor)
      {
        // The sphere pushes the nodes it overlaps out: -k g n on them, so
        // +k g n in the residual.
        TimerOutput::Scope scope(timer, "impactor");
        impactor->evaluate(trial, n.contact_force);
        n.residual -= n.contact_force;
        if (tangent)
          {
            impactor->add_tangent(trial, n.increment_constraints, *tangent);
            tangent->compress(VectorOperation::add);
          }
      }
    if (body_contact)
      {
        // Contact forces push the bodies apart, as the sphere's do.
        n.residual -= n.body_contact_force;
        if (tangent)
          {
            TimerOutput::Scope scope(timer, "body contact");
            body_contact->add_tangent(*tangent);
            tangent->compress(VectorOperation::add);
          }
      }
    if (interfaces)
      {
        TimerOutput::Scope scope(timer, "interfaces");
        n.interface_force = 0;
        interfaces->assemble(relevant_solution,
                             n.interface_force,
                             n.increment_constraints,
                             tangent);
        n.interface_force.compress(VectorOperation::add);
        if (tangent)
          tangent->compress(VectorOperation::add);
        n.residual += n.interface_force;
      }
    n.residual -= n.external_load;
    const double norm = condense_residual();
    // A return mapping that failed makes the step fail (and be cut).
    return plastic_ok ? norm : std::numeric_limits<double>::quiet_NaN();
  }



  template <int dim>
  bool
  Simulator<dim>::add_plastic_correction(
    TrilinosWrappers::SparseMatrix *tangent)
  {
    NewtonState &n         = *newton;
    const bool   converged = plasticity->add_correction(relevant_solution,
                                                      n.increment_constraints,
                                                      n.plastic_force,
                                                      tangent,
                                                      !as_transferred);
    n.plastic_force.compress(VectorOperation::add);
    plastic_failure.clear();
    if (Utilities::MPI::min(converged ? 1 : 0, comm) == 1)
      return true;
    // The first failing rank's place, on every rank (for the message of
    // a run that cannot go on).
    for (const auto &failure :
         Utilities::MPI::all_gather(comm, plasticity->failure()))
      if (!failure.empty())
        {
          plastic_failure = failure;
          break;
        }
    return false;
  }



  template <int dim>
  double
  Simulator<dim>::condense_residual()
  {
    NewtonState &n = *newton;
    // A hanging dof next to a support hands part of its residual to the
    // supported dof (increment_constraints resolve that chain, so
    // condense() cannot): without it the reactions and the external work
    // miss that part.
    if (n.hanging)
      n.hanging->condense(n.residual);
    const double reactions = condense(n.residual, n.condensed_residual);
    n.force_scale
      = std::sqrt(reactions + std::pow(n.external_load.l2_norm(), 2));
    return n.condensed_residual.l2_norm();
  }



  template <int dim>
  double
  Simulator<dim>::condense(const Vector &full, Vector &condensed)
  {
    NewtonState &n = *newton;
    // The residual of the free unknowns is C^T R: a hanging unknown hands
    // its residual to the unknowns it interpolates; supported ones carry
    // reactions, which the scale of the convergence test measures.
    const AffineConstraints<double> &C     = n.increment_constraints;
    const IndexSet                  &owned = dof_layer.locally_owned_dofs();
    n.interface_force                      = 0; // reused as the transfer
    for (const auto &line : C.get_lines())
      if (owned.is_element(line.index))
        for (const auto &[j, w] : line.entries)
          n.interface_force(j) += w * full(line.index);
    n.interface_force.compress(VectorOperation::add);
    condensed = full;
    condensed += n.interface_force;
    double constrained = 0;
    for (const auto i : owned)
      if (C.is_constrained(i))
        {
          constrained += full(i) * full(i);
          condensed(i) = 0;
        }
    return Utilities::MPI::sum(constrained, comm);
  }



  template <int dim>
  void
  Simulator<dim>::tangent_product(const Vector &direction, Vector &product)
  {
    // K_T d = K_bulk d + K_plastic(relevant_solution) d
    // + K_interfaces(relevant_solution) d, unconstrained.
    NewtonState &n = *newton;
    n.bulk_unconstrained.vmult(product, direction);
    if (impactor)
      impactor->add_tangent_product(relevant_solution, direction, product);
    if (body_contact)
      body_contact->add_tangent_product(direction, product);
    if (!interfaces && !plasticity)
      return;
    Vector relevant_direction(dof_layer.locally_owned_dofs(),
                              dof_layer.locally_relevant_dofs(),
                              comm);
    relevant_direction = direction;
    if (plasticity)
      {
        n.plastic_force = 0;
        plasticity->add_tangent_product(relevant_solution,
                                        relevant_direction,
                                        n.plastic_force);
        n.plastic_force.compress(VectorOperation::add);
        product += n.plastic_force;
      }
    if (!interfaces)
      return;
    n.interface_force = 0;
    interfaces->add_tangent_product(relevant_solution,
                                    relevant_direction,
                                    n.interface_force);
    n.interface_force.compress(VectorOperation::add);
    product += n.interface_force;
  }



  template <int dim>
  double
  Simulator<dim>::predictor_residual()
  {
    NewtonState &n = *newton;
    Vector       jump(solution);
    jump -= n.converged_solution;
    // A return mapping that failed at the converged state (a state moved
    // to a new mesh may lie outside the yield surface) fails the step.
    if (!std::isfinite(update_residual(n.converged_solution, &system_matrix)))
      return std::numeric_limits<double>::quiet_NaN();
    Vector product(jump);
    tangent_product(jump, product);
    n.residual += product;
    return condense_residual();
  }



  template <int dim>
  double
  Simulator<dim>::load_force(const Vector &residual) const
  {
    double force = 0;
    for (const auto i : owned_support_dofs(supports, dof_layer))
      force += newton->load_pattern(i) * residual(i);
    return Utilities::MPI::sum(force, comm);
  }



  template <int dim>
  double
  Simulator<dim>::pattern_derivative(const Vector &state)
  {
    NewtonState &n    = *newton;
    relevant_solution = state;
    // dR/dt = K_T g(1) - f(1).
    tangent_product(n.load_pattern, n.pattern_response);
    n.pattern_response -= n.load_unit;
    condense(n.pattern_response, n.pattern_condensed);
    return load_force(n.pattern_response);
  }



  template <int dim>
  void
  Simulator<dim>::linear_solve(LinearSolver &solver, Vector &x, const Vector &b)
  {
    TimerOutput::Scope scope(timer, "linear solve");
    // The pattern never changes: analyse it once, refactorize the values
    // afterwards.
    // The bulk never changes: if no interface point changed its tangent
    // since the last factorization (elastic steps, open cracks), reuse it.
    // A total Lagrangian bulk changes with every iteration.
    // Plastic plies: likewise if no point was plastic in this tangent nor
    // in the factorized one.
    // Contact: likewise if no node touches now nor did then. The sphere's
    // tangent changes with every iterate.
    const bool unchanged
      = !finite_strain && !impactor
        && (interfaces || plasticity || body_contact)
        && Utilities::MPI::min(
             (!interfaces || interfaces->tangent_unchanged())
                 && (!plasticity || plasticity->tangent_unchanged())
                 && (!body_contact || body_contact->tangent_unchanged()) ?
               1 :
               0,
             comm)
             == 1;
    if (!solver_ready)
      solver.initialize(system_matrix,
                        rigid_body_modes(),
                        dim,
                        owned_node_coordinates());
    else if (!unchanged)
      solver.update_values();
    if (!solver_ready || !unchanged)
      ++n_factorizations;
    if ((!solver_ready || !unchanged) && interfaces)
      interfaces->mark_factorized();
    if ((!solver_ready || !unchanged) && plasticity)
      plasticity->mark_factorized();
    if ((!solver_ready || !unchanged) && body_contact)
      body_contact->mark_factorized();
    solver_ready = true;
    solver.solve(x, b);
  }



  template <int dim>
  void
  Simulator<dim>::setup_load_pattern(const bool         with_loads,
                                     const std::string &control,
                                     const std::string &name)
  {
    // Path following scales the prescribed displacements (and loads) with
    // t: check that they are proportional to t.
    if (!with_loads && !loads.empty())
      throw InputError(name,
                       control
                         + " needs all loads to be "
                           "prescribed displacements (this scene has "
                           "tractions, pressures or a body force)");
    const double              end = parameters.time.end_time;
    AffineConstraints<double> at_end, halfway;
    make_constraints(1., at_end, false);
    make_constraints(0.5 * end, halfway, false);
    bool proportional = true;
    for (const auto &line : at_end.get_lines())
      if (at_end.is_inhomogeneously_constrained(line.index))
        proportional = proportional
                       && std::abs(halfway.get_inhomogeneity(line.index)
                                   - 0.5 * end * line.inhomogeneity)
                            <= 1e-10 * end * std::abs(line.inhomogeneity);
    if (Utilities::MPI::min(proportional ? 1 : 0, comm) == 0)
      throw InputError(name,
                       control
                         + " needs prescribed displacements "
                           "proportional to t (g(t) = t g(1))");
    newton->load_pattern = 0;
    at_end.distribute(newton->load_pattern);
    newton->load_unit = 0;
    if (!with_loads || loads.empty())
      return;
    assembler.assemble_load(loads, 1., newton->load_unit);
    Vector half(newton->load_unit);
    assembler.assemble_load(loads, 0.5 * end, half);
    half.add(-0.5 * end, newton->load_unit);
    if (!(half.l2_norm() <= 1e-10 * end * newton->load_unit.l2_norm()))
      throw InputError(name,
                       control
                         + " needs loads proportional to t "
                           "(f(t) = t f(1))");
  }



  template <int dim>
  bool
  Simulator<dim>::solve_both_directions(LinearSolver &solver,
                                        NewtonReport &report)
  {
    NewtonState &n = *newton;
    n.condensed_residual *= -1;
    n.pattern_condensed *= -1;
    try
      {
        linear_solve(solver, n.increment, n.condensed_residual);
        solver.solve(n.pattern_increment, n.pattern_condensed);
      }
    catch (const CollectiveError &e)
      {
        report.failure = std::string("the linear solver said: ") + e.what();
        return false;
      }
    return true;
  }



  template <int dim>
  typename Simulator<dim>::NewtonReport
  Simulator<dim>::solve_dissipation_step(const double  t0,
                                         const double  increment,
                                         double       &t,
                                         LinearSolver &solver)
  {
    // Unknowns (u, t) with the constraint that the step dissipates
    // `increment`: for a secant (unload-to-origin) law the dissipated
    // energy of a step is (P0 t - P t0) / 2, P the force conjugate to t.
    // Each iteration solves K du_I = -r and K du_II = -dR/dt with one
    // factorization and picks dt from the linearized constraint.
    NewtonState                       &n  = *newton;
    const parameters::NonlinearSolver &p  = parameters.nonlinear_solver;
    const double                       P0 = n.converged_force;
    t                                     = t0;
    solution                              = n.converged_solution;
    NewtonReport report;
    for (unsigned int it = 0;; ++it)
      {
        const double norm = update_residual(solution, &system_matrix);
        const double constraint
          = 0.5 * (P0 * t - load_force(n.residual) * t0) - increment;
        report.residuals.push_back(norm);
        if (it > 0 && norm <= p.tolerance * n.force_scale
            && std::abs(constraint) <= 1e-6 * increment)
          {
            report.converged = true;
            return report;
          }
        if (it == p.max_iterations || !std::isfinite(norm)
            || stagnates(report.residuals, interfaces.get(), comm))
          return report;
        const double stiffness = pattern_derivative(solution);
        if (!solve_both_directions(solver, report))
          return report;
        // pattern_condensed now holds -dR/dt; dP/du = (dR/dt)^T for the
        // symmetric couplings of the supported nodes.
        const double slope
          = stiffness + n.pattern_condensed * n.pattern_increment * -1;
        const double denominator = 0.5 * (P0 - t0 * slope);
        if (!(std::abs(denominator) > 0))
          return report;
        const double dt
          = -(constraint + 0.5 * t0 * (n.pattern_condensed * n.increment))
            / denominator;
        n.increment.add(dt, n.pattern_increment);
        n.increment_constraints.distribute(n.increment);
        n.increment.add(dt, n.load_pattern);
        solution += n.increment;
        t += dt;
        // The first iterate, linearized at the converged state, may
        // overshoot and come back.
        if (it > 0 && std::abs(t - t0) > 4 * path_step_bound())
          return report;
      }
  }



  template <int dim>
  bool
  Simulator<dim>::path_directions(LinearSolver &solver,
                                  NewtonReport &report,
                                  Vector       &direction)
  {
    NewtonState &n = *newton;
    pattern_derivative(solution);
    if (!solve_both_directions(solver, report))
      return false;
    n.increment_constraints.distribute(n.increment);
    direction = n.pattern_increment;
    n.increment_constraints.distribute(direction);
    direction += n.load_pattern;
    return true;
  }



  template <int dim>
  typename Simulator<dim>::NewtonReport
  Simulator<dim>::solve_arc_length_step(const double  t0,
                                        double       &radius,
                                        double       &t,
                                        LinearSolver &solver)
  {
    // Unknowns (u, t) with the constraint |du|^2 + psi^2 q^2 dt^2 = l^2
    // on the step from the converged state (Crisfield 1981). Each
    // iteration solves K du_I = -r and K du_II = -dR/dt with one
    // factorization; the correction du_I + x d (d = du_II with the
    // prescribed part g(1)) keeps the constraint, x the root that
    // continues the path.
    NewtonState                       &n = *newton;
    const parameters::NonlinearSolver &p = parameters.nonlinear_solver;
    t                                    = t0;
    solution                             = n.converged_solution;
    Vector step(solution), base(solution), direction(solution);
    step                = 0;
    double       step_t = 0; // t - t0
    double       psi2   = 0; // psi^2 q^2
    NewtonReport report;
    for (unsigned int it = 0;; ++it)
      {
        n.external_load = n.load_unit;
        n.external_load *= t;
        const double norm = update_residual(solution, &system_matrix);
        report.residuals.push_back(norm);
        const double length2 = step * step + psi2 * step_t * step_t;
        if (it > 0 && norm <= p.tolerance * n.force_scale
            && std::abs(length2 - radius * radius) <= 1e-8 * radius * radius)
          {
            report.converged = true;
            return report;
          }
        // Contact between the bodies creeps before it converges, as in
        // solve_newton_step(): the iteration limit ends it, not the
        // stagnation test.
        if (it == p.max_iterations || !std::isfinite(norm)
            || (!body_contact
                && stagnates(report.residuals, interfaces.get(), comm))
            || !path_directions(solver, report, direction))
          return report;
        const double dd = direction * direction;
        if (n.arc_scale == 0)
          {
            // The first step of the run: q = |du/dt|, and the nominal
            // length that of a nominal step of t.
            n.arc_scale   = std::sqrt(dd);
            n.arc_nominal = std::sqrt(1 + std::pow(p.arc_length_psi, 2))
                            * n.arc_scale * parameters.time.end_time
                            / parameters.time.n_steps;
          }
        if (radius == 0)
          radius = n.arc_nominal;
        psi2 = std::pow(p.arc_length_psi * n.arc_scale, 2);
        // The predictor follows the previous step (the first: t grows);
        // corrections stay closest to the step so far.
        double preference = 1;
        if (it == 0)
          preference = n.arc_previous * direction < 0 ? -1 : 1;
        else
          preference = direction * step + psi2 * step_t;
        base = step;
        base += n.increment;
        double x;
        if (!arc_length_root(dd + psi2,
                             2 * (base * direction + psi2 * step_t),
                             base * base + psi2 * step_t * step_t
                               - radius * radius,
                             preference,
                             x))
          {
            report.failure = "the arc-length constraint has no real root";
            return report;
          }
        n.increment.add(x, direction);
        step += n.increment;
        solution += n.increment;
        step_t += x;
        t += x;
      }
  }



  template <int dim>
  typename Simulator<dim>::NewtonReport
  Simulator<dim>::solve_opening_step(const double  t0,
                                     const double  increment,
                                     double       &t,
                                     LinearSolver &solver)
  {
    // Unknowns (u, t) with the linear constraint a . (u - u0) = increment,
    // a the gradient of the summed normal opening of the points bonded at
    // the start of the step: each iteration solves K du_I = -r and
    // K du_II = -dR/dt with one factorization and takes dt from the
    // constraint (Alfano & Crisfield's local arc-length, linear form).
    NewtonState                       &n = *newton;
    const parameters::NonlinearSolver &p = parameters.nonlinear_solver;
    Vector                             gradient;
    gradient.reinit(dof_layer.locally_owned_dofs(),
                    dof_layer.locally_relevant_dofs(),
                    comm,
                    true);
    {
      // At the converged state (the frame of total Lagrangian interfaces
      // depends on it).
      Vector converged(dof_layer.locally_owned_dofs(),
                       dof_layer.locally_relevant_dofs(),
                       comm);
      converged = n.converged_solution;
      interfaces->add_opening_gradient(converged, gradient);
    }
    gradient.compress(VectorOperation::add);
    Vector a(dof_layer.locally_owned_dofs(), comm);
    a                  = gradient;
    const double start = a * n.converged_solution;
    t                  = t0;
    solution           = n.converged_solution;
    NewtonReport report;
    Vector       direction(a);
    for (unsigned int it = 0;; ++it)
      {
        const double norm       = update_residual(solution, &system_matrix);
        const double constraint = a * solution - start - increment;
        report.residuals.push_back(norm);
        if (it > 0 && norm <= p.tolerance * n.force_scale
            && std::abs(constraint) <= 1e-8 * increment)
          {
            report.converged = true;
            return report;
          }
        // Contact between the bodies creeps before it converges, as in
        // solve_newton_step(): the iteration limit ends it, not the
        // stagnation test.
        if (it == p.max_iterations || !std::isfinite(norm)
            || (!body_contact
                && stagnates(report.residuals, interfaces.get(), comm))
            || !path_directions(solver, report, direction))
          return report;
        const double slope = a * direction;
        if (!(std::abs(slope) > 0))
          return report;
        const double dt = -(constraint + a * n.increment) / slope;
        n.increment.add(dt, direction);
        solution += n.increment;
        t += dt;
        // The first iterate, linearized at the converged state, may
        // overshoot and come back.
        if (it > 0 && std::abs(t - t0) > 4 * path_step_bound())
          return report;
      }
  }



  template <int dim>
  typename Simulator<dim>::NewtonReport
  Simulator<dim>::solve_newton_step(const double t, LinearSolver &solver)
  {
    NewtonState                       &n = *newton;
    const parameters::NonlinearSolver &p = parameters.nonlinear_solver;
    NewtonReport                       report;
    try
      {
        TimerOutput::Scope scope(timer, "constraints");
        make_constraints(t, constraints, false);
        if (impactor)
          impactor->move_to(t);
        assembler.assemble_load(loads, t, n.external_load);
        solution = n.converged_solution;
        constraints.distribute(solution);
      }
    catch (const NonFiniteValue &e)
      {
        // A shorter step may stay where the expression is defined.
        report.failure = e.what();
        return report;
      }
    // Predictor: the converged state's tangent applied to the new
    // prescribed values, R(u_old) + K_T(u_old) (u_jump - u_old). Starting
    // from u_jump itself would put the whole step's displacement jump into
    // the elements next to the supports, damage their interfaces on the way
    // and cost several iterations even in an elastic step.
    double norm = predictor_residual();
    report.residuals.push_back(norm);
    if (!std::isfinite(norm))
      return report;
    // Relative to the external forces, or to the predictor's residual when
    // these vanish (a ply pulled off an open crack carries no load).
    const double first = norm;
    const auto   converged
      = [&]() { return norm <= p.tolerance * std::max(n.force_scale, first); };
    for (unsigned int it = 0; it < p.max_iterations; ++it)
      {
        if (it > 0)
          {
            if (converged())
              break;
            update_residual(solution, &system_matrix);
          }
        n.condensed_residual *= -1;
        try
          {
            linear_solve(solver, n.increment, n.condensed_residual);
          }
        catch (const CollectiveError &e)
          {
            // E.g. a singular tangent: cut back.
            report.failure = std::string("the linear solver said: ") + e.what();
            return report;
          }
        n.increment_constraints.distribute(n.increment);

        // Backtracking line search on the residual norm; the best point
        // seen is kept if none satisfies the decrease condition. Contact
        // between the bodies takes the full step when it is finite: its
        // penalty times the second-order change of the gaps (slip times
        // rotation) makes the residual norm a poor merit function, under
        // which Newton creeps (measured on prm/contact_stack_2d.prm: 3 and
        // 4 iterations with full steps, a failed step without).
        const bool   full_steps = static_cast<bool>(body_contact);
        const Vector start      = solution;
        double       alpha = 1, best_alpha = 1, best_norm = 0;
        for (unsigned int trial = 0;; ++trial)
          {
            solution = start;
            solution.add(alpha, n.increment);
            const double trial_norm = update_residual(solution, nullptr);
            // A residual that is not finite (a return mapping that
            // failed) is worse than any finite one.
            if (trial == 0 || trial_norm < best_norm
                || (!std::isfinite(best_norm) && std::isfinite(trial_norm)))
              best_norm = trial_norm, best_alpha = alpha;
            if (!p.line_search || (full_steps && std::isfinite(trial_norm))
                || trial_norm < (1 - 1e-4 * alpha) * norm || trial == 5)
              break;
            alpha *= 0.5;
          }
        if (best_alpha != alpha)
          {
            solution = start;
            solution.add(best_alpha, n.increment);
            update_residual(solution, nullptr);
          }
        norm = best_norm;
        report.residuals.push_back(norm);
        // Contact between the bodies: a node sliding along a face that
        // turns changes its gap at second order (slip times rotation),
        // which the penalty makes large against the loads; Newton then
        // creeps under the line search before it converges, and the
        // iteration limit alone ends it.
        if (!std::isfinite(norm)
            || (!body_contact
                && stagnates(report.residuals, interfaces.get(), comm)))
          return report;
      }
    report.converged = converged();
    return report;
  }



  template <int dim>
  std::vector<std::pair<std::string, double>>
  Simulator<dim>::energy_ledger()
  {
    NewtonState &n = *newton;
    // External work by the trapezoidal rule: reactions on the supports and
    // the applied loads, times the displacement increment.
    Vector delta = solution;
    delta -= n.converged_solution;
    double work = 0;
    for (const auto i : owned_support_dofs(supports, dof_layer))
      work += 0.5 * (n.previous_residual(i) + n.residual(i)) * delta(i);
    work = Utilities::MPI::sum(work, comm);
    if (n.settling || n.insertion_settling)
      {
        // A state moved to a new mesh or onto new cracks is out of balance
        // at its free dofs; the work of those forces while it settles
        // belongs to the mesh change or to the insertion.
        Vector residual_sum = n.previous_residual;
        residual_sum += n.residual;
        const double settling_work = 0.5 * (residual_sum * delta) - work;
        (n.settling ? n.remeshing_energy : n.insertion_energy) += settling_work;
        n.settling = n.insertion_settling = false;
      }
    Vector load_sum = n.previous_load;
    load_sum += n.external_load;
    work += 0.5 * (load_sum * delta);
    n.external_work += work;

    // The sphere's driver adds its work to the external work.
    std::vector<std::pair<std::string, double>> sphere_columns;
    double                                      contact_energy
      = impactor ? add_static_impactor_columns(sphere_columns) : 0.;
    if (body_contact)
      contact_energy += add_static_contact_columns(sphere_columns);
    const double strain_energy = bulk_strain_energy(solution);

    std::vector<std::pair<std::string, double>> columns
      = {{"external_work", n.external_work}, {"strain_energy", strain_energy}};
    if (plasticity)
      {
        columns.emplace_back("plastic_work", n.plastic_work);
        columns.emplace_back("yielding_points",
                             Utilities::MPI::sum(plasticity->yielding_points(),
                                                 comm));
        columns.emplace_back("max_equivalent_plastic_strain",
                             plasticity->max_kappa());
      }
    const double interface_work = add_interface_columns(columns);
    columns.insert(columns.end(), sphere_columns.begin(), sphere_columns.end());
    // Only scenes whose mesh changes during the history have the term.
    if (parameters.adaptivity.during_history())
      columns.emplace_back("remeshing_energy", n.remeshing_energy);
    if (parameters.cracks.active)
      columns.emplace_back("insertion_energy", n.insertion_energy);
    columns.emplace_back("balance_error",
                         n.external_work + n.remeshing_energy
                           + n.insertion_energy - strain_energy - n.plastic_work
                           - interface_work - contact_energy);
    n.previous_residual = n.residual;
    n.previous_load     = n.external_load;
    return columns;
  }



  template <int dim>
  void
  Simulator<dim>::start_static_impactor(const double t)
  {
    NewtonState &n = *newton;
    impactor->move_to(t);
    impactor->evaluate(n.converged_solution, n.contact_force);
    // Touching is allowed: a sphere placed on the face may overlap it by
    // the round-off of its centre's coordinates.
    if (t == 0
        && impactor->penetration_depth() > 1e-12 * parameters.impactor.radius)
      throw InputError("Impactor/Center",
                       "the impactor overlaps the laminate at t = 0 (by "
                         + number_text(impactor->penetration_depth())
                         + " mm); start it clear of the face");
    n.sphere_force  = impactor->force_on_laminate();
    n.sphere_center = impactor->position();
    // The friction's slips count from the start of the path (a Path need
    // not start at Center).
    if (t == 0)
      impactor->commit();
  }



  template <int dim>
  double
  Simulator<dim>::add_static_impactor_columns(
    std::vector<std::pair<std::string, double>> &columns)
  {
    NewtonState &n = *newton;
    // What drives the sphere holds it in balance with the
    // laminate's push back, so it does the work F . dc by the trapezoidal
    // rule. At the converged state (the last evaluation may be a line
    // search's), whose friction history the next step starts from.
    impactor->evaluate(solution, n.contact_force);
    impactor->commit();
    const Tensor<1, dim> force = impactor->force_on_laminate();
    n.external_work += 0.5 * (n.sphere_force + force)
                       * (impactor->position() - n.sphere_center);
    n.sphere_force  = force;
    n.sphere_center = impactor->position();
    columns.emplace_back("impactor_position", impactor->normal_position());
    columns.emplace_back("contact_force", impactor->normal_force());
    columns.emplace_back("contact_energy", impactor->contact_energy());
    columns.emplace_back("contact_nodes", impactor->contact_nodes());
    columns.emplace_back("penetration", impactor->penetration_depth());
    const auto more = impactor->friction_columns();
    columns.insert(columns.end(), more.begin(), more.end());
    return impactor->contact_energy() + impactor->friction_dissipation();
  }



  template <int dim>
  double
  Simulator<dim>::add_static_contact_columns(
    std::vector<std::pair<std::string, double>> &columns)
  {
    // At the converged state (the last evaluation may be a line search's),
    // whose friction history the next step starts from.
    body_contact->evaluate(solution, newton->body_contact_force);
    body_contact->commit();
    columns.emplace_back("body_contact_energy", body_contact->contact_energy());
    columns.emplace_back("friction_dissipation",
                         body_contact->friction_dissipation());
    const auto more = body_contact->columns();
    columns.insert(columns.end(), more.begin(), more.end());
    return body_contact->contact_energy()
           + body_contact->friction_dissipation();
  }



  template <int dim>
  double
  Simulator<dim>::bulk_strain_energy(const Vector &u) const
  {
    // A total Lagrangian run has int E : C : E / 2 from its last residual,
    // which every caller has just evaluated at u.
    double elastic = newton->strain_energy;
    if (!finite_strain)
      {
        Vector Ku = u;
        newton->bulk_unconstrained.vmult(Ku, u);
        elastic = 0.5 * (Ku * u);
      }
    if (!plasticity)
      return elastic;
    // The plastic strain takes its part out of the stored energy.
    Vector relevant(dof_layer.locally_owned_dofs(),
                    dof_layer.locally_relevant_dofs(),
                    comm);
    relevant = u;
    return elastic + plasticity->stored_energy_correction(relevant);
  }



  template <int dim>
  void
  Simulator<dim>::commit_plastic_state()
  {
    NewtonState &n    = *newton;
    relevant_solution = solution;
    Vector previous(dof_layer.locally_owned_dofs(),
                    dof_layer.locally_relevant_dofs(),
                    comm);
    previous = n.converged_solution;
    n.plastic_work += plasticity->commit(relevant_solution, previous);
  }



  template <int dim>
  double
  Simulator<dim>::path_step_bound() const
  {
    return 8 * parameters.time.end_time / parameters.time.n_steps;
  }



  template <int dim>
  double
  Simulator<dim>::interface_dissipation() const
  {
    double dissipated = 0;
    if (interfaces)
      for (const auto &l : interfaces->ledger(comm))
        dissipated += l.dissipated;
    return dissipated;
  }



  template <int dim>
  double
  Simulator<dim>::add_interface_columns(
    std::vector<std::pair<std::string, double>> &columns)
  {
    if (!interfaces)
      return 0;
    const auto ledger            = interfaces->ledger(comm);
    double     interface_work    = 0;
    double     interface_storage = 0;
    for (unsigned int k = 0; k < ledger.size(); ++k)
      {
        // Ply interface k gives the columns "..._ik", the inserted cracks
        // "..._cracks".
        const bool        crack = k == interfaces->interfaces().size();
        const std::string name
          = crack ? "_cracks" :
                    "_i" + std::to_string(interfaces->interfaces()[k]);
        interface_work += ledger[k].work;
        interface_storage += ledger[k].stored;
        columns.emplace_back("dissipated" + name, ledger[k].dissipated);
        columns.emplace_back("friction" + name, ledger[k].friction);
        columns.emplace_back("viscous" + name, ledger[k].viscous);
        columns.emplace_back("debonded" + name, ledger[k].debonded);
        columns.emplace_back("damaged" + name, ledger[k].damaged);
        columns.emplace_back("min_opening" + name, ledger[k].min_opening);
        if (crack)
          {
            columns.emplace_back("inserted_energy_cracks", ledger[k].inserted);
            columns.emplace_back("crack_faces", interfaces->n_crack_faces());
            columns.emplace_back("fragments", count_fragments());
          }
      }
    columns.emplace_back("interface_stored", interface_storage);
    return interface_work;
  }



  template <int dim>
  void
  Simulator<dim>::run_newton()
  {
    setup_newton();
    newton_solver = std::make_unique<LinearSolver>(parameters.linear_solver);
    LinearSolver &solver = *newton_solver;
    // Softening and friction make the tangent unsymmetric.
    solver.set_symmetric(false);
    // A singular tangent shows up as a Newton step that does not converge.
    solver.set_check_residual(false);

    const parameters::NonlinearSolver &p       = parameters.nonlinear_solver;
    const double                       end     = parameters.time.end_time;
    const double                       nominal = end / parameters.time.n_steps;
    double                             t = 0, dt = nominal;
    unsigned int                       step = 0, total_iterations = 0;
    std::vector<unsigned int>          iterations;
    const auto set_interface_time_step = [&](const double step_length) {
      if (interfaces)
        interfaces->set_time_step(step_length);
    };
    // Dissipation control takes over when a displacement step dissipates
    // more than the target or cannot converge (a snap-back), and hands
    // back when the structure stores rather than dissipates.
    if (p.dissipation_control)
      setup_load_pattern(false, "dissipation or opening control");
    if (p.arc_length)
      setup_load_pattern(true, "arc-length control");
    // Refused before the load steps rather than after them.
    if (finite_strain && parameters.buckling.active())
      setup_prebuckling_pattern();
    // Arc-length: the step length (0: nominal, set by the first step).
    double arc = 0;
    if (impactor && !restart)
      start_static_impactor(0.);
    const bool adaptive = parameters.adaptivity.during_history();
    if (adaptive && !restart)
      adapt_during_history(0, 0.);
    // Dissipation or opening control, past the switch.
    bool              by_dissipation = false;
    const std::string control = p.opening_control ? "opening" : "dissipation";
    const double      target
      = p.opening_control ? p.opening_increment : p.dissipation_increment;
    double dtau = target;
    // Crack insertion: faces still failing after the last step's rounds.
    bool failures_left = false;
    // Steps done before a restart (to tell whether this run did any).
    std::size_t progress_at_restart = 0;
    if (restart)
      {
        NewtonProgress progress;
        restore_newton(progress);
        progress_at_restart = progress.iterations.size();
        t                   = progress.t;
        dt                  = progress.dt;
        dtau                = progress.dtau;
        if (p.arc_length)
          arc = progress.dtau;
        step             = progress.step;
        total_iterations = progress.total_iterations;
        by_dissipation   = progress.by_dissipation;
        iterations       = progress.iterations;
        failures_left    = progress.failures_left;
        if (impactor)
          start_static_impactor(t);
        // The analyses up to t are in the restored buckling table.
        buckling_due(t);
      }
    const auto save = [&](CheckpointData &run, CheckpointData &part) {
      // Arc-length keeps its step length where dissipation control keeps
      // its increment.
      save_newton({t,
                   dt,
                   p.arc_length ? arc : dtau,
                   step,
                   total_iterations,
                   by_dissipation,
                   iterations,
                   failures_left},
                  run,
                  part);
    };
    while (t < end * (1 - 1e-12))
      {
        if (p.arc_length && step >= p.max_arc_length_steps)
          {
            pcout << "  arc-length: stopped after " << step
                  << " steps (Nonlinear solver/Maximum arc-length steps) "
                     "at t="
                  << t << ", before End time" << std::endl;
            break;
          }
        if (p.max_steps > 0 && step >= p.max_steps)
          {
            pcout << "  stopped after " << step
                  << " steps (Nonlinear solver/Maximum steps) at t=" << t
                  << ", before End time" << std::endl;
            break;
          }
        double       trial_t = t;
        NewtonReport report;
        // Whether the step was taken by dissipation or opening control
        // (not by the displacement step that replaces a failed one).
        bool path_step = false;
        if (p.arc_length)
          {
            arc = arc == 0 ? newton->arc_nominal : arc;
            set_interface_time_step(nominal);
            report = solve_arc_length_step(t, arc, trial_t, solver);
          }
        else if (by_dissipation)
          {
            set_interface_time_step(nominal);
            report = p.opening_control ?
                       solve_opening_step(t, dtau, trial_t, solver) :
                       solve_dissipation_step(t, dtau, trial_t, solver);
            // Where the structure stores rather than dissipates (elastic
            // reloading, the end of the crack) the constraint is nearly
            // singular and its step is huge or lands on a spurious branch
            // (t < 0), or moves t by more than path_step_bound(): take a
            // displacement step instead.
            const bool regular = report.converged && trial_t >= 0
                                 && std::abs(trial_t - t) <= path_step_bound();
            path_step = regular && trial_t <= end;
            if (!path_step)
              {
                pcout << "  t=" << trial_t << ": " << control
                      << " control did not converge or left the path"
                      << residual_list(report.residuals)
                      << "; trying a displacement step" << std::endl;
                trial_t = std::min(t + dt, end);
                set_interface_time_step(trial_t - t);
                report = solve_newton_step(trial_t, solver);
                // A regular step that crossed End time, and End time on a
                // snap-back that displacement steps cannot follow: the run
                // ends with the step that crossed it. (Not when the
                // displacement step failed for a reason, a NaN load say:
                // the failure path names it.)
                if (regular && !report.converged && report.failure.empty()
                    && std::all_of(report.residuals.begin(),
                                   report.residuals.end(),
                                   [](const double r) {
                                     return std::isfinite(r);
                                   }))
                  {
                    pcout << "  t=" << trial_t << ": End time lies on a "
                          << "snap-back of the path; the run ends with the "
                          << control << " step that crosses it" << std::endl;
                    set_interface_time_step(nominal);
                    report    = p.opening_control ?
                                  solve_opening_step(t, dtau, trial_t, solver) :
                                  solve_dissipation_step(t, dtau, trial_t, solver);
                    path_step = true;
                  }
              }
          }
        else
          {
            trial_t = std::min(t + dt, end);
            set_interface_time_step(trial_t - t);
            report = solve_newton_step(trial_t, solver);
          }
        // Crack insertion: insert the most critical faces and solve the
        // step again, until no face fails or the rounds run out.
        unsigned int rounds    = 0;
        bool         overshoot = false;
        while (parameters.cracks.active && report.converged)
          {
            if (rounds == parameters.cracks.rounds_per_step)
              {
                pcout << "  t=" << trial_t << ": " << rounds
                      << " insertion rounds (Crack insertion/Rounds per "
                         "step); faces still failing wait for the next step"
                      << std::endl;
                failures_left = true;
                break;
              }
            // The first round may ask for a shorter step, so that a crack
            // starts at its strength; later rounds follow what the
            // inserted cracks set off.
            // Not when faces were left failing at t (Rounds per step):
            // they fail at any step length.
            const bool can_cut
              = rounds == 0 && !failures_left
                && 0.5 * (trial_t - t) >= p.minimum_step_fraction * nominal;
            const auto inserted = insert_cracks(t, trial_t, can_cut);
            if (inserted.overshoot)
              {
                overshoot = true;
                dt        = 0.5 * (trial_t - t);
                pcout << "  t=" << trial_t << ": Hoffman index "
                      << inserted.hoffman
                      << " beyond 1 + Crack insertion/Onset tolerance; step "
                         "cut to "
                      << dt << std::endl;
                break;
              }
            if (inserted.inserted == 0)
              {
                failures_left = false;
                break;
              }
            ++rounds;
            report = solve_newton_step(trial_t, solver);
          }
        if (overshoot)
          continue;
        if (!report.converged)
          {
            if (p.dissipation_control && !by_dissipation)
              {
                pcout << "  t=" << trial_t << ": Newton did not converge, "
                      << "switching to " << control << " control" << std::endl;
                by_dissipation = true;
                dtau           = target;
                continue;
              }
            // Under dissipation control both attempts failed: cut both.
            dt *= 0.5;
            if (by_dissipation)
              dtau *= 0.5;
            if (p.arc_length)
              {
                // The minimum step is a fraction of the nominal length.
                arc *= 0.5;
                dt = newton->arc_nominal > 0 ?
                       arc / newton->arc_nominal * nominal :
                       0.5 * dt;
              }
            std::ostringstream line;
            line << "  t=" << trial_t << ": Newton did not converge"
                 << residual_list(report.residuals) << " (force scale "
                 << newton->force_scale << ")";
            if (p.arc_length)
              line << "; arc length cut to " << arc << " mm, a step of about";
            else
              line << "; step cut to";
            pcout << line.str() << " " << dt << (p.arc_length ? " in t" : "")
                  << (by_dissipation ? " (and the " + control + " increment to "
                                         + number_text(dtau) + ")" :
                                       "")
                  << std::endl;
            if (dt < p.minimum_step_fraction * nominal
                && (!by_dissipation || dtau < p.minimum_step_fraction * target))
              {
                relevant_solution = newton->converged_solution;
                write_fields(step, t);
                std::ostringstream message;
                message << "Newton did not converge at t=" << trial_t
                        << " with the smallest step allowed by parameter "
                           "<Nonlinear solver/Minimum step fraction>; the "
                           "last converged state (t="
                        << t << ") is written";
                if (!report.failure.empty())
                  message << "; " << report.failure;
                if (!plastic_failure.empty())
                  message
                    << "; " << plastic_failure
                    << (loads.empty() ?
                          ": a step asks for more plastic flow than the "
                          "local Newton iteration follows" :
                          ": the loads may exceed the limit load of the "
                          "plastic plies (with perfectly plastic plies, "
                          "Materials/Hardening = 0, there is no "
                          "equilibrium beyond it: prescribe displacements "
                          "instead), or a step asks for more plastic flow "
                          "than the local Newton iteration follows");
                if (plastic_failure.empty()
                    && std::any_of(report.residuals.begin(),
                                   report.residuals.end(),
                                   [](const double r) {
                                     return !std::isfinite(r);
                                   }))
                  message << "; the residual was not finite (NaN or inf): "
                             "look for a load or displacement expression "
                             "that is not defined there (a sqrt or log of a "
                             "negative number, a division by zero) or "
                             "material data that overflow";
                throw CollectiveError(message.str());
              }
            continue;
          }
        // The switch to dissipation or opening control measures what the
        // interfaces dissipate, not the secant estimate (P0 t - P t0)/2 of
        // solve_dissipation_step: that one is the dissipation only for a
        // structure that unloads to the origin, and a buckling total
        // Lagrangian panel or a yielded ply "dissipates" by it long before
        // any interface softens.
        const bool   may_switch = p.dissipation_control && !by_dissipation;
        const double dissipated_before
          = may_switch ? interface_dissipation() : 0.;
        if (interfaces)
          interfaces->commit();
        if (plasticity)
          commit_plastic_state();
        const unsigned int its = report.residuals.size() - 1;
        iterations.push_back(its);
        total_iterations += its;
        ++step;
        {
          std::ostringstream line;
          line << "  step " << step << " t=" << trial_t << ": " << its
               << " Newton iteration(s)"
               << (path_step ? " (" + control + " control)" : "")
               << residual_list(report.residuals);
          pcout << line.str() << std::endl;
        }
        const double force = load_force(newton->residual);
        if (may_switch
            && interface_dissipation() - dissipated_before
                 > p.dissipation_increment)
          {
            by_dissipation = true;
            dtau           = target;
          }
        newton->converged_force = force;
        const auto columns      = energy_ledger();
        if (p.arc_length)
          {
            newton->arc_previous = solution;
            newton->arc_previous -= newton->converged_solution;
          }
        newton->converged_solution = solution;
        t                          = trial_t;
        auto row                   = columns;
        row.emplace_back("newton_iterations", its);
        // 0: a displacement step before the switch to dissipation or
        // opening control, 1: a step taken by it, 2: a displacement step
        // after the switch (where the path control failed or left the
        // path).
        if (p.dissipation_control)
          row.emplace_back("path_control", may_switch ? 0 : path_step ? 1 : 2);
        postprocess(step, t, newton->residual, row);
        if (parameters.buckling.active() && buckling_due(t))
          analyse_during_history(solver, t);
        // Not after the last step (End time, Maximum steps or Maximum
        // arc-length steps): a new mesh nothing is solved on, and the
        // buckling analysis after the loop would analyse a transferred
        // state, not a converged one (the explicit path skips its last
        // output step likewise).
        const bool last_step
          = t >= end * (1 - 1e-12) || (p.max_steps > 0 && step >= p.max_steps)
            || (p.arc_length && step >= p.max_arc_length_steps);
        if (adaptive && !last_step)
          adapt_during_history(step, t);
        if (its <= p.easy_iterations)
          {
            dtau = std::min(2 * dtau, target);
            dt   = std::min(2 * dt, nominal);
            arc  = std::min(2 * arc, newton->arc_nominal);
          }
        checkpoint_after_step(step, step, true, t >= end * (1 - 1e-12), save);
      }
    // A run resumed from its last step has nothing left to do; its
    // buckling analysis is in the buckling.csv of the run before.
    if (parameters.buckling.active()
        && parameters.buckling.analysis_times.empty()
        && !(restart && iterations.size() == progress_at_restart))
      analyse_newton_buckling(solver, t);
    if (next_analysis_time < parameters.buckling.analysis_times.size())
      pcout << "  buckling: warning: the run stopped at t=" << t
            << ", before Buckling/Analysis times "
            << parameters.buckling.analysis_times[next_analysis_time]
            << std::endl;
    std::sort(iterations.begin(), iterations.end());
    pcout << "  " << step << " steps, " << total_iterations
          << " Newton iterations, " << n_factorizations
          << " factorizations, median "
          << (iterations.empty() ? 0 : iterations[iterations.size() / 2])
          << " per step" << std::endl;
    timer.print_wall_time_statistics(comm);
  }

  template void
  Simulator<2>::run_newton();
  template void
  Simulator<3>::run_newton();
  // also called by the transfer (history_adaptivity.cc)
  template double
  Simulator<2>::bulk_strain_energy(const Vector &) const;
  template double
  Simulator<3>::bulk_strain_energy(const Vector &) const;
} // namespace amfrac

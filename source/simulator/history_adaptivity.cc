// Adaptivity during the load history of a scene with cohesive interfaces:
// when to refine (every N steps, the seed's ZZ threshold, the process-zone
// rule), and the transfer of the converged state to the new mesh (the
// seed's tau_2 for the displacement, tau_1 for the interface history).
#include <amfrac/adaptivity/history_transfer.h>
#include <amfrac/cohesive/transfer_columns.h>
#include <amfrac/geometry/in_plane_refinement.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/numerics/solution_transfer.h>

namespace amfrac
{
  namespace
  {
    namespace bgi = boost::geometry::index;

    /** Refinement along the in-plane axes of the mask @p axes (bit a for
     * axis a): x in 2D (y is the thickness), x and/or y in 3D. */
    template <int dim>
    RefinementCase<dim>
    in_plane_cut(const unsigned int axes = 3)
    {
      if (dim == 2)
        return RefinementCase<dim>::cut_x;
      return RefinementCase<dim>((axes & 1 ? RefinementCase<3>::cut_x : 0)
                                 | (axes & 2 ? RefinementCase<3>::cut_y : 0));
    }

    /** The largest extent of @p cell along the in-plane axes of the mask
     * @p axes (every reference direction but the last, which is the
     * laminate's thickness). */
    template <typename CellIterator>
    double
    in_plane_size(const CellIterator &cell, const unsigned int axes)
    {
      constexpr int dim = CellIterator::AccessorType::dimension;
      double        h   = 0;
      for (unsigned int a = 0; a + 1 < dim; ++a)
        if (axes & (1U << a))
          h = std::max(h, cell->extent_in_direction(a));
      return h;
    }

    /** deal.II's smoothing of the flags of @p triangulation; false if no
     * flag is left. */
    template <int dim>
    bool
    prepare_flags(Triangulation<dim> &triangulation)
    {
      triangulation.prepare_coarsening_and_refinement();
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->refine_flag_set() || cell->coarsen_flag_set())
          return true;
      return false;
    }
  } // namespace



  template <int dim>
  std::vector<double>
  Simulator<dim>::process_zone_lengths() const
  {
    const auto         &c = parameters.cohesive;
    std::vector<double> lengths;
    for (const unsigned int k : interfaces->interfaces())
      {
        const double E_zz = 1. / invert(plies[k].stiffness_3d)[2][2][2][2];
        lengths.push_back(0.88 * E_zz * c.G_Ic
                          / (c.normal_strength * c.normal_strength));
      }
    return lengths;
  }



  template <int dim>
  void
  Simulator<dim>::mark_process_zone(const bool coarsen)
  {
    const unsigned int n = parameters.adaptivity.process_zone_elements;
    const unsigned int axes
      = dim == 2 ? 1 : parameters.adaptivity.process_zone_axes;

    const auto front = interfaces->front_points(process_zone_lengths(), comm);
    if (front.empty())
      return;
    const auto tree = pack_rtree(front);
    // Per active cell: its distance to the nearest front point, in units
    // of that point's reach, and whether it is coarser than the rule asks.
    std::vector<std::pair<double, bool>> where;
    bool                                 needed = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        std::vector<std::pair<Point<dim>, double>> closest;
        tree.query(bgi::nearest(cell->center(), 1),
                   std::back_inserter(closest));
        const double reach = closest[0].second;
        const double distance
          = cell->center().distance(closest[0].first) - 0.5 * cell->diameter();
        const bool coarse = in_plane_size(cell, axes) > reach / n * (1 + 1e-9);
        where.emplace_back(distance / reach, coarse);
        needed = needed || (coarse && distance <= reach);
      }
    // Only when a cell within l_cz is too coarse; then the band of 2 l_cz
    // is refined, so that the front moves about l_cz before the next
    // change, and cells beyond 3 l_cz are coarsened with it (each change
    // of the mesh costs a transfer, a new matrix and a factorization).
    if (!needed)
      return;
    // Along the plies only (cut_x in 2D, the chosen in-plane axes in 3D):
    // the rule is about the in-plane size, and refining through the
    // thickness as well multiplies the unknowns and the direct solver's
    // fill for nothing.
    const RefinementCase<dim> cut = in_plane_cut<dim>(axes);
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const auto [distance, coarse] = where[cell->active_cell_index()];
        if (distance <= 2 && coarse)
          {
            cell->clear_coarsen_flag();
            // With an estimator's flag too: both cuts.
            cell->set_refine_flag(cell->refine_flag_set() | cut);
          }
        else if (coarsen && distance > 3 && !cell->refine_flag_set())
          cell->set_coarsen_flag();
      }
  }



  template <int dim>
  void
  Simulator<dim>::keep_refinement_in_plane()
  {
    // Parameter checks keep the estimator (both axes) and a one-axis
    // process-zone rule apart, so one cut serves every cell. In 2D the
    // estimators keep refining through the thickness as well.
    amfrac::keep_refinement_in_plane(
      triangulation,
      in_plane_cut<dim>(parameters.adaptivity.process_zone_axes));
  }



  template <int dim>
  void
  Simulator<dim>::adapt_during_history(const unsigned int step, const double t)
  {
    adapt_state(step,
                t,
                newton->converged_solution,
                [&](const bool by_estimate, const double zz_relative) {
                  refine_and_transfer(step, t, by_estimate, zz_relative);
                });
  }



  template <int dim>
  void
  Simulator<dim>::adapt_state(
    const unsigned int                                   step,
    const double                                         t,
    const Vector                                        &state,
    const std::function<void(const bool, const double)> &change)
  {
    const auto &a = parameters.adaptivity;
    bool        by_estimate
      = a.refine_every > 0 && step > 0 && step % a.refine_every == 0;
    double zz_relative = -1;
    if (step > 0 && (by_estimate || a.error_threshold > 0))
      {
        relevant_solution = state;
        estimate_error(t);
        zz_relative = last_zz.relative();
        bool over   = a.error_threshold > 0 && zz_relative > a.error_threshold;
        // The first estimate on a remeshed mesh is what the remeshing
        // reached. If that is not a tenth below the error before it (the
        // size bounds keep the error above the threshold), the threshold
        // fires again only once the error has grown by a tenth, so that the
        // mesh and the history are not moved every step for nothing.
        if (remeshes())
          {
            double &reached = last_remeshing.zz_relative_reached;
            if (std::isnan(reached))
              reached = zz_relative;
            if (reached >= 0
                && reached > 0.9 * last_remeshing.zz_relative_before)
              over = over && zz_relative > 1.1 * reached;
          }
        by_estimate = by_estimate || over;
      }
    // Wedges are remeshed by the estimate's size field or the process
    // zone's (the two are exclusive), not flagged.
    if (remeshes())
      {
        if (cell_budget_spent)
          return;
        if (by_estimate)
          change(true, zz_relative);
        else if (a.process_zone_elements > 0 && plan_process_zone_remeshing())
          change(false, -1);
        return;
      }
    // The process-zone rule refines one level per pass until the fronts
    // have their elements; every pass moves the state.
    for (unsigned int pass = 0; pass < 10; ++pass)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            cell->clear_refine_flag();
            cell->clear_coarsen_flag();
          }
        if (pass == 0 && by_estimate)
          mark_by_estimate();
        if (a.process_zone_elements > 0)
          mark_process_zone(!a.by_estimator());
        if (!limit_flags())
          break;
        // SolutionTransfer needs the flags deal.II will execute: those
        // after its smoothing (match_flags() does it with interfaces).
        // The smoothing and the matching can add flags, isotropic ones
        // among them: keep those in the plane too, until nothing changes.
        bool flagged = false;
        for (unsigned int round = 0; round < 10; ++round)
          {
            keep_refinement_in_plane();
            flagged = interfaces ? interfaces->match_flags(triangulation) :
                                   prepare_flags(triangulation);
            if (!flagged_through_thickness(triangulation))
              break;
          }
        if (!flagged)
          break;
        AssertThrow(!flagged_through_thickness(triangulation),
                    ExcMessage("refinement during a load history stays "
                               "in the plane of the plies, but a cell "
                               "was flagged through the thickness"));

        change(pass == 0 && by_estimate, pass == 0 ? zz_relative : -1);
        if (a.process_zone_elements == 0)
          return;
      }
  }



  template <int dim>
  void
  Simulator<dim>::refine_and_transfer(const unsigned int step,
                                      const double       t,
                                      const bool         by_estimate,
                                      const double       zz_relative)
  {
    using Ledger = typename CohesiveInterfaces<dim>::Ledger;
    typename CohesiveInterfaces<dim>::TransferReport report;
    std::vector<Ledger>                              before, after;
    double kappa_before = 0, kappa_after = 0;
    // The friction force (sum over the contact pairs) of the converged
    // state and of the transferred one: the stick springs carried.
    double     friction_before = 0, friction_after = 0;
    const auto friction_force = [this]() {
      for (const auto &[name, value] : body_contact->columns())
        if (name == "body_contact_friction_force")
          return value;
      return 0.;
    };
    {
      TimerOutput::Scope scope(timer, "refine and transfer");
      if (interfaces)
        before = interfaces->ledger(comm);
      // The contact's energy is that of the converged state (the last
      // row's evaluation, committed); so is the sphere's.
      if (body_contact)
        friction_before = friction_force();
      // With the friction dissipated so far: committing the stick
      // springs at the transferred state may release some (a new node
      // that takes a touching neighbour's spring but lies outside the
      // sphere or off the face), which belongs to the mesh change.
      const auto contact_energies = [this]() {
        return (body_contact ? body_contact->contact_energy()
                                 + body_contact->friction_dissipation() :
                               0.)
               + (impactor ? impactor->contact_energy()
                               + impactor->friction_dissipation() :
                             0.);
      };
      const double stored_before
        = bulk_strain_energy(newton->converged_solution)
          + total(before, &Ledger::work) + contact_energies();
      typename CohesiveInterfaces<dim>::Snapshot snapshot;
      if (interfaces)
        snapshot = interfaces->snapshot(comm);
      dealii::Vector<double> copies, new_copies;
      dof_layer.expand_all(dof_layer.replicate(newton->converged_solution),
                           copies);
      if (plasticity)
        kappa_before = plasticity->max_kappa();
      if (remeshes())
        {
          // tau_1 of the plastic history between unrelated meshes.
          std::vector<std::vector<double>> old_plastic;
          if (plasticity)
            old_plastic = plasticity->gather_field();
          // The nodal transfer last: the count of new points outside the
          // old mesh that the remeshing reports is that of its nodes.
          const auto carried = [&](const auto &transfer, const auto &old) {
            if (plasticity)
              plasticity->set_field(
                transfer.quadrature(old_plastic,
                                    plasticity->get_quadrature(),
                                    plastic_transfer_rules(true),
                                    plasticity->get_quadrature()));
            new_copies = transfer.nodal(old[0]);
          };
          if (!remesh_carrying({copies}, carried))
            {
              stop_remeshing();
              return;
            }
        }
      else
        {
          SolutionTransfer<dim, dealii::Vector<double>> displacement(
            dof_layer.copy_handler());
          displacement.prepare_for_coarsening_and_refinement(copies);
          const auto plastic_history = prepare_plastic_transfer();
          execute_mesh_change();
          setup_after_refinement();
          new_copies.reinit(dof_layer.n_copies());
          displacement.interpolate(copies, new_copies);
          if (plasticity)
            plasticity->set_field(plastic_history->interpolate());
        }
      if (plasticity)
        kappa_after = plasticity->max_kappa();
      if (interfaces)
        interfaces->setup(dof_layer, parameters.boundary_conditions.constants);

      // A new Newton state on the new mesh (with the run's totals).
      setup_newton(true);
      if (parameters.nonlinear_solver.dissipation_control)
        setup_load_pattern(false, "dissipation or opening control");
      newton->settling = true;
      dof_layer.gather(new_copies, newton->converged_solution);
      make_constraints(t, constraints, false);
      constraints.distribute(newton->converged_solution);
      relevant_solution = newton->converged_solution;
      if (interfaces)
        report = remeshes() ?
                   interfaces->relocate(snapshot,
                                        triangulation,
                                        relevant_solution,
                                        comm) :
                   interfaces->transfer(snapshot, relevant_solution, comm);
      solution = newton->converged_solution;
      // copy_solution() follows the mesh.
      dof_layer.expand(relevant_solution, copy_values);
      // The reactions of the transferred state start the trapezoidal rule
      // of the external work of the next step.
      assembler.assemble_load(loads, t, newton->external_load);
      as_transferred = true;
      update_residual(solution, nullptr);
      as_transferred = false;
      // The stick springs carried by place become forces of the new
      // nodes' stiffness at the transferred state, which the next step's
      // slips start from (the tangent knows forces, not stretches); what
      // the springs' energy changed by is the mesh change's.
      if (body_contact)
        {
          body_contact->commit();
          friction_after = friction_force();
        }
      // The sphere's nodes are the new face's (setup_newton()); its force
      // on them at the transferred state starts the trapezoidal work of
      // the next step, and its stick springs' forces are the new nodes'.
      if (impactor)
        {
          impactor->commit();
          newton->sphere_force = impactor->force_on_laminate();
        }
      newton->previous_residual = newton->residual;
      newton->previous_load     = newton->external_load;
      newton->converged_force   = load_force(newton->residual);
      if (interfaces)
        after = interfaces->ledger(comm);
      newton->remeshing_energy += bulk_strain_energy(solution)
                                  + total(after, &Ledger::work)
                                  + contact_energies() - stored_before;
    }
    if (!cycle_summary)
      cycle_summary = std::make_unique<History>(
        parameters.output.directory + "/adaptivity.csv",
        Utilities::MPI::this_mpi_process(comm) == 0);
    std::vector<std::pair<std::string, double>> columns{
      {"step", step},
      {"t", t},
      {"cells", triangulation.n_global_active_cells()},
      {"unknowns", dof_layer.n_dofs()},
      {"by_estimate", by_estimate ? 1. : 0.},
      {"zz_relative_error", zz_relative}};
    if (interfaces)
      {
        const auto transfer = interface_transfer_columns(before, after, report);
        columns.insert(columns.end(), transfer.begin(), transfer.end());
      }
    if (remeshes())
      {
        const auto event_columns = last_remeshing.columns();
        columns.insert(columns.end(),
                       event_columns.begin(),
                       event_columns.end());
      }
    if (plasticity)
      {
        columns.emplace_back("max_equivalent_plastic_strain_before",
                             kappa_before);
        columns.emplace_back("max_equivalent_plastic_strain_after",
                             kappa_after);
      }
    if (body_contact)
      {
        columns.emplace_back("body_contact_friction_before", friction_before);
        columns.emplace_back("body_contact_friction_after", friction_after);
      }
    columns.emplace_back("remeshing_energy", newton->remeshing_energy);
    cycle_summary->add_row(columns);
    pcout << "  adapted after step " << step << ": "
          << triangulation.n_global_active_cells() << " cells, "
          << dof_layer.n_dofs() << " unknowns";
    if (interfaces)
      pcout << "; interface history of " << report.injected
            << " points injected, " << report.aggregated
            << " aggregated; dissipated " << total(before, &Ledger::dissipated)
            << " -> " << total(after, &Ledger::dissipated);
    if (plasticity)
      pcout << "; largest equivalent plastic strain " << kappa_before << " -> "
            << kappa_after;
    pcout << std::endl;
  }



  template <int dim>
  std::vector<typename QuadratureHistoryTransfer<dim>::Rule>
  Simulator<dim>::plastic_transfer_rules(const bool remeshing) const
  {
    // tau_1: the plastic strain by the seed's projection, kappa (an
    // irreversible measure) injected from the nearest old point, the
    // largest where the mesh coarsens. A refinement projects only where
    // cells change; a remeshing moves every point, and the projection's
    // smoothing of the whole plastic zone yields again in the next step
    // (doc/benchmarks/README.md section 28), so it takes the nearest old
    // point's plastic strain unless the seed's way is asked for.
    using Rule = typename QuadratureHistoryTransfer<dim>::Rule;
    const Rule strain
      = remeshing && parameters.adaptivity.plastic_nearest_point ?
          Rule::nearest :
          Rule::smooth;
    std::vector<Rule> rules(PlasticPlies<dim>::n_components - 1, strain);
    rules.push_back(Rule::injected);
    return rules;
  }



  template <int dim>
  std::unique_ptr<QuadratureHistoryTransfer<dim>>
  Simulator<dim>::prepare_plastic_transfer() const
  {
    if (!plasticity)
      return nullptr;
    // Cells the change keeps keep their values exactly.
    auto transfer = std::make_unique<QuadratureHistoryTransfer<dim>>(
      triangulation,
      dof_layer.get_fe().degree,
      plasticity->get_quadrature(),
      plastic_transfer_rules(false),
      true);
    transfer->prepare(plasticity->gather_field());
    return transfer;
  }

  template <int dim>
  typename Simulator<dim>::ExplicitTransferReport
  Simulator<dim>::move_explicit_state(const std::vector<Vector *> &fields,
                                      Vector                      &velocity)
  {
    if (remeshes())
      return remesh_explicit_state(fields, velocity);
    TimerOutput::Scope scope(timer, "refine and transfer");
    typename CohesiveInterfaces<dim>::Snapshot snapshot;
    if (interfaces)
      snapshot = interfaces->snapshot(comm);
    ExplicitStateTransfer<dim> moving(dof_layer, ply_densities(plies), comm);
    moving.prepare(std::vector<const Vector *>(fields.begin(), fields.end()),
                   velocity);
    execute_mesh_change();
    rebuild_after_mesh_change();
    if (interfaces)
      interfaces->setup(dof_layer, parameters.boundary_conditions.constants);
    moving.interpolate(fields, velocity);
    relevant_solution.reinit(dof_layer.locally_owned_dofs(),
                             dof_layer.locally_relevant_dofs(),
                             comm);
    relevant_solution = *fields.front();
    dof_layer.expand(relevant_solution, copy_values);
    ExplicitTransferReport report;
    if (interfaces)
      report.interfaces
        = interfaces->transfer(snapshot, relevant_solution, comm);
    report.coarsened_cells = moving.n_coarsened_cells();
    report.momentum_dofs   = moving.n_momentum_dofs();
    return report;
  }



  namespace
  {
    /** The owned entries of @p reduced: per reduced unknown of @p layer,
     * the sum of @p numerators over its copies divided by that of
     * @p denominators (TiedCopyDoFs::sums_over_copies(), independent of
     * the partition): the momentum rule's momentum and mass give the
     * velocity. */
    template <int dim>
    void
    ratio_of_sums(const TiedCopyDoFs<dim>       &layer,
                  const dealii::Vector<double>  &numerators,
                  const dealii::Vector<double>  &denominators,
                  TrilinosWrappers::MPI::Vector &reduced,
                  const MPI_Comm                 comm)
    {
      const auto top    = layer.sums_over_copies(numerators);
      const auto bottom = layer.sums_over_copies(denominators);
      reduced.reinit(layer.locally_owned_dofs(), comm);
      for (const auto i : layer.locally_owned_dofs())
        reduced[i] = top[i] / bottom[i];
      reduced.compress(VectorOperation::insert);
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::stop_remeshing()
  {
    cell_budget_spent = true;
    pcout << "  the mesh has " << triangulation.n_active_cells()
          << " cells, about Adaptivity/Maximum cells: no more remeshing in "
             "this run"
          << std::endl;
  }



  template <int dim>
  typename Simulator<dim>::ExplicitTransferReport
  Simulator<dim>::remesh_explicit_state(const std::vector<Vector *> &fields,
                                        Vector                      &velocity)
  {
    TimerOutput::Scope scope(timer, "refine and transfer");
    typename CohesiveInterfaces<dim>::Snapshot snapshot;
    if (interfaces)
      snapshot = interfaces->snapshot(comm);
    // The velocity's copies go last: the carry below takes them from
    // there.
    std::vector<dealii::Vector<double>> copies(fields.size() + 1);
    for (unsigned int f = 0; f <= fields.size(); ++f)
      dof_layer.expand_all(dof_layer.replicate(f < fields.size() ? *fields[f] :
                                                                   velocity),
                           copies[f]);
    const std::vector<double>                   density = ply_densities(plies);
    std::vector<dealii::Vector<double>>         carried;
    typename NonMatchingTransfer<dim>::Momentum momentum;
    // The nodal transfer last: n_outside() then counts new nodes, as in
    // Newton runs, not the velocity's quadrature points.
    const auto carry = [&](const auto &transfer, const auto &old) {
      momentum
        = transfer.momentum(old.back(), density, dof_layer.cell_quadrature(2));
      for (unsigned int f = 0; f < fields.size(); ++f)
        carried.push_back(transfer.nodal(old[f]));
    };
    ExplicitTransferReport report;
    if (!remesh_carrying(copies, carry))
      {
        stop_remeshing();
        report.changed = false;
        return report;
      }
    if (interfaces)
      interfaces->setup(dof_layer, parameters.boundary_conditions.constants);
    // The copies of a node are equal only to round-off across a bonded
    // ply face (each is located in its own ply's old cells): their mean.
    for (unsigned int f = 0; f < fields.size(); ++f)
      {
        fields[f]->reinit(dof_layer.locally_owned_dofs(), comm);
        dof_layer.gather(carried[f], *fields[f]);
      }
    ratio_of_sums(dof_layer, momentum.momentum, momentum.mass, velocity, comm);

    relevant_solution.reinit(dof_layer.locally_owned_dofs(),
                             dof_layer.locally_relevant_dofs(),
                             comm);
    relevant_solution = *fields.front();
    dof_layer.expand(relevant_solution, copy_values);
    if (interfaces)
      report.interfaces = interfaces->relocate(snapshot,
                                               triangulation,
                                               relevant_solution,
                                               comm);
    report.momentum_dofs     = dof_layer.n_dofs();
    report.kinetic_old_field = momentum.kinetic_energy;
    return report;
  }



  template void
  Simulator<2>::adapt_state(
    const unsigned int,
    const double,
    const Vector &,
    const std::function<void(const bool, const double)> &);
  template void
  Simulator<3>::adapt_state(
    const unsigned int,
    const double,
    const Vector &,
    const std::function<void(const bool, const double)> &);
  template Simulator<2>::ExplicitTransferReport
  Simulator<2>::move_explicit_state(const std::vector<Vector *> &, Vector &);
  template Simulator<3>::ExplicitTransferReport
  Simulator<3>::move_explicit_state(const std::vector<Vector *> &, Vector &);
  template void
  Simulator<2>::adapt_during_history(const unsigned int, const double);
  template void
  Simulator<3>::adapt_during_history(const unsigned int, const double);
} // namespace amfrac

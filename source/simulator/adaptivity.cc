#include <amfrac/simulator/simulator.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/grid/grid_refinement.h>
#include <set>

namespace amfrac
{
  template <int dim>
  void
  Simulator<dim>::run_adaptive()
  {
    const auto &adaptivity = parameters.adaptivity;
    cycle_summary
      = std::make_unique<History>(parameters.output.directory
                                    + "/adaptivity.csv",
                                  Utilities::MPI::this_mpi_process(comm) == 0);
    ConvergenceTable table;
    for (cycle = 0; cycle <= adaptivity.cycles; ++cycle)
      {
        if (cycle > 0)
          {
            {
              TimerOutput::Scope scope(timer, "refine");
              if (!refine_mesh())
                break;
            }
            // A remeshing has set up its new mesh already (its transfer
            // needs the new layer).
            if (!remeshes())
              setup_after_refinement();
          }
        run_linear();
        report_cycle();
        table.add_value("cycle", cycle);
        table.add_value("cells", triangulation.n_global_active_cells());
        table.add_value("unknowns", dof_layer.n_dofs());
        table.add_value("zz_error", last_zz.error);
        table.add_value("zz_relative", last_zz.relative());
        if (parameters.buckling.active())
          table.add_value("lambda_1", lowest_load_factor);
        if (adaptivity.strategy
              == parameters::Adaptivity::Strategy::error_target
            && last_zz.relative() <= adaptivity.target_error)
          break;
      }
    table.set_scientific("zz_error", true);
    table.set_scientific("zz_relative", true);
    if (parameters.buckling.active())
      table.set_precision("lambda_1", 8);
    table.evaluate_convergence_rates("zz_error",
                                     "unknowns",
                                     ConvergenceTable::reduction_rate_log2,
                                     dim);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      table.write_text(std::cout);
    timer.print_wall_time_statistics(comm);
  }



  template <int dim>
  void
  Simulator<dim>::estimate_error(const double t)
  {
    TimerOutput::Scope scope(timer, "estimate error");
    const auto         estimator    = error_estimator();
    const auto         displacement = estimator.replicate(relevant_solution);
    last_zz                         = estimator.zienkiewicz_zhu(displacement);
    if (parameters.adaptivity.estimator
        == parameters::Adaptivity::Estimator::kelly)
      {
        typename ErrorEstimator<dim>::Boundary boundary;
        for (const auto &condition : prescribed)
          boundary.supported.insert(condition.boundary_id);
        boundary.loads              = &loads;
        boundary.time               = t;
        last_estimate               = estimator.kelly(displacement, boundary);
        last_estimate.solution_norm = last_zz.solution_norm;
      }
    else
      last_estimate = last_zz;
  }



  template <int dim>
  void
  Simulator<dim>::report_cycle()
  {
    std::vector<std::pair<std::string, double>> row
      = {{"cycle", cycle},
         {"cells", triangulation.n_global_active_cells()},
         {"unknowns", dof_layer.n_dofs()},
         {"wall_seconds", clock.wall_time()},
         {"estimate", last_estimate.error},
         {"zz_error", last_zz.error},
         {"zz_relative_error", last_zz.relative()},
         {"energy_norm", last_zz.solution_norm}};
    if (remeshes())
      {
        // The remeshing that made this cycle's mesh (zeros on the first).
        const auto &event = last_remeshing;
        row.emplace_back("zz_relative_before_remeshing",
                         event.zz_relative_before);
        const auto columns = event.columns();
        row.insert(row.end(), columns.begin(), columns.end());
        row.emplace_back("transfer_energy_change", event.energy_change);
      }
    for (const auto &entry : last_row)
      if (entry.first != "step" && entry.first != "cycle")
        row.push_back(entry);
    cycle_summary->add_row(row);
    pcout << "  cycle " << cycle << ": "
          << triangulation.n_global_active_cells() << " cells, "
          << dof_layer.n_dofs() << " unknowns, ZZ error " << last_zz.error
          << " (relative " << last_zz.relative() << ")";
    if (parameters.adaptivity.estimator
        == parameters::Adaptivity::Estimator::kelly)
      pcout << ", Kelly " << last_estimate.error;
    pcout << std::endl;
  }



  template <int dim>
  bool
  Simulator<dim>::refine_mesh()
  {
    if (remeshes())
      return remesh();
    mark_by_estimate();
    if (!limit_flags())
      {
        pcout << "  no cell left to refine (Maximum refinement level "
              << parameters.adaptivity.max_level << "): the cycles stop"
              << std::endl;
        return false;
      }
    triangulation.execute_coarsening_and_refinement();
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::mark_by_estimate()
  {
    using Strategy         = parameters::Adaptivity::Strategy;
    const auto &adaptivity = parameters.adaptivity;
    const auto &errors     = last_estimate.cell_errors;
    switch (adaptivity.strategy)
      {
        case Strategy::uniform:
          for (const auto &cell : triangulation.active_cell_iterators())
            cell->set_refine_flag();
          break;
        case Strategy::fixed_fraction:
          GridRefinement::refine_and_coarsen_fixed_fraction(
            triangulation,
            errors,
            adaptivity.refine_fraction,
            adaptivity.coarsen_fraction);
          break;
        case Strategy::fixed_number:
          GridRefinement::refine_and_coarsen_fixed_number(
            triangulation,
            errors,
            adaptivity.refine_fraction,
            adaptivity.coarsen_fraction);
          break;
          case Strategy::error_target: {
            // Equidistribution: relative error <= target means
            // ||e||^2 <= target^2 ||u||^2 / (1 - target^2); each cell may
            // hold its equal share of that.
            const double target = adaptivity.target_error;
            const double allowed
              = target * target * last_zz.solution_norm * last_zz.solution_norm
                / (1 - target * target) / triangulation.n_global_active_cells();
            for (const auto &cell : triangulation.active_cell_iterators())
              if (std::pow(errors[cell->active_cell_index()], 2) > allowed)
                cell->set_refine_flag();
            break;
          }
      }
  }



  template <int dim>
  bool
  Simulator<dim>::coarsenable(
    const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    // Coarsening makes the parent active: allowed if the parent lies
    // inside a cell of the initial mesh (or is one), not if it contains
    // some (the initial mesh with its global and region refinements is
    // the coarsest the run may go).
    if (cell->level() == 0)
      return false;
    for (auto ancestor = cell->parent();; ancestor = ancestor->parent())
      {
        if (initial_cells.count(ancestor->id()) > 0)
          return true;
        if (ancestor->level() == 0)
          return false;
      }
  }



  template <int dim>
  bool
  Simulator<dim>::limit_flags()
  {
    const auto &adaptivity = parameters.adaptivity;
    // Every rank flags the same cells (the indicators are summed over the
    // ranks), as the shared triangulation requires.
    bool any = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (cell->refine_flag_set()
            && cell->level() >= static_cast<int>(adaptivity.max_level))
          cell->clear_refine_flag();
        if (cell->coarsen_flag_set() && !coarsenable(cell))
          cell->clear_coarsen_flag();
        any = any || cell->refine_flag_set() || cell->coarsen_flag_set();
      }
    return any;
  }



  template <int dim>
  void
  Simulator<dim>::setup_after_refinement()
  {
    TimerOutput::Scope scope(timer, "setup");
    rebuild_after_mesh_change();
  }



  template <int dim>
  void
  Simulator<dim>::rebuild_after_mesh_change(const bool same_mesh)
  {
    if (same_mesh)
      {
        // Crack insertion: only the new cracks' nodes are grouped again.
        std::vector<typename TiedCopyDoFs<dim>::Face> faces;
        const auto &handler = dof_layer.copy_handler();
        for (const auto &[id, f] : interfaces->unbuilt_cracks())
          {
            const auto cell = triangulation.create_cell_iterator(id);
            // A crack face is no candidate of the crack check any more.
            if (!candidate_faces.empty())
              {
                candidate_faces[cell->active_cell_index()] &= ~(1u << f);
                candidate_faces[cell->neighbor(f)->active_cell_index()]
                  &= ~(1u << cell->neighbor_of_neighbor(f));
              }
            faces.emplace_back(
              typename TiedCopyDoFs<dim>::CellIterator(
                &triangulation, cell->level(), cell->index(), &handler),
              f);
          }
        dof_layer.release(faces, released_faces());
      }
    else
      {
        dof_layer.distribute(released_faces());
        forget_crack_candidates();
      }
    if (plasticity)
      plasticity->setup();
    lever.collect(dof_layer);
    dof_layer.add_relevant_dofs(lever.all_dofs());
    for (auto &patch : loads.patches)
      {
        patch.unit_nodal_forces.clear();
        assembler.prepare_patch(patch);
      }
    collect_supports();
    make_probe();
    if (field_output)
      field_output->clear_cell_fields();
    // The solver refers to the matrix: it goes first.
    if (newton_solver)
      newton_solver->release();
    solver_ready = false;
    system_matrix.clear();
  }



  template <int dim>
  ErrorEstimator<dim>
  Simulator<dim>::error_estimator() const
  {
    return ErrorEstimator<dim>(dof_layer,
                               plies,
                               released_faces(),
                               parameters.total_lagrangian);
  }



  template <int dim>
  std::pair<double, double>
  Simulator<dim>::energy_errors(const Function<dim> &exact) const
  {
    const auto estimator    = error_estimator();
    const auto displacement = estimator.replicate(relevant_solution);
    return {estimator.zienkiewicz_zhu(displacement).error,
            estimator.energy_error(displacement, exact)};
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace amfrac

#include <algorithm>
#include <amfrac/base/first_failure.h>
#include <amfrac/checkpoint/stop_signals.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <map>
#include <sstream>

namespace amfrac
{
  namespace
  {
    std::string
    join(const std::vector<std::string> &lines)
    {
      std::string text;
      for (const auto &line : lines)
        text += line + '\n';
      return text;
    }

    std::vector<std::string>
    split_lines(const std::string &text)
    {
      std::vector<std::string> lines;
      std::istringstream       in(text);
      for (std::string line; std::getline(in, line);)
        lines.push_back(line);
      return lines;
    }

    void
    save_table(CheckpointData &run, const std::string &name, const History &h)
    {
      run.put_text(name + ".columns", join(h.column_names()));
      std::vector<double> values;
      for (const auto &row : h.rows())
        values.insert(values.end(), row.begin(), row.end());
      run.put(name + ".values", values);
    }

    void
    restore_table(const CheckpointData &run,
                  const std::string    &name,
                  History              &h)
    {
      const auto columns = split_lines(run.get_text(name + ".columns"));
      const auto values  = run.get(name + ".values");
      std::vector<std::vector<double>> rows;
      if (!columns.empty())
        for (std::size_t i = 0; i + columns.size() <= values.size();
             i += columns.size())
          rows.emplace_back(values.begin() + i,
                            values.begin() + i + columns.size());
      h.restore(columns, rows);
    }

    using Series = std::vector<std::pair<double, std::string>>;

    void
    save_series(CheckpointData &run, const std::string &name, const Series &s)
    {
      std::vector<double>      times;
      std::vector<std::string> files;
      for (const auto &[time, file] : s)
        {
          times.push_back(time);
          files.push_back(file);
        }
      run.put(name + ".times", times);
      run.put_text(name + ".files", join(files));
    }

    Series
    restore_series(const CheckpointData &run, const std::string &name)
    {
      const auto times = run.get(name + ".times");
      const auto files = split_lines(run.get_text(name + ".files"));
      if (files.size() != times.size())
        throw std::runtime_error("the checkpoint's " + name
                                 + " series is inconsistent");
      Series series;
      for (unsigned int i = 0; i < times.size(); ++i)
        series.emplace_back(times[i], files[i]);
      return series;
    }

    /** The CellId of entry @p i of a list of @p stride numbers per cell,
     * the first 4 CellId::to_binary(). Checked first: deal.II reads the
     * dimension from the low bits of the second number and divides by
     * it. */
    template <int dim>
    CellId
    cell_id(const std::vector<std::int64_t> &cells,
            const std::size_t                i,
            const unsigned int               stride = 4)
    {
      CellId::binary_type binary;
      for (unsigned int j = 0; j < 4; ++j)
        binary[j] = cells.at(stride * i + j);
      if ((binary[1] & 3u) != dim)
        throw std::runtime_error("a cell id of the checkpoint is not of a "
                                 + std::to_string(dim) + "D mesh");
      return CellId(binary);
    }

    /** Turn any error of reading a checkpoint into an InputError that
     * names it (and the cause), on every rank: the first failing rank's
     * message. @p action must not call collectives after a point where it
     * may throw on one rank only. */
    template <typename F>
    void
    reading(const std::string &folder, const MPI_Comm comm, const F &action)
    {
      std::string failure;
      try
        {
          action();
        }
      catch (const std::exception &e)
        {
          failure = e.what();
          if (failure.rfind("cannot resume", 0) != 0)
            failure
              = "cannot resume from checkpoint '" + folder + "': " + failure;
        }
      throw_first_failure<InputError>(comm, failure);
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::save_vector(CheckpointData    &part,
                              const std::string &name,
                              const Vector      &v) const
  {
    Vector ghosted(dof_layer.locally_owned_dofs(),
                   dof_layer.locally_relevant_dofs(),
                   comm);
    ghosted = v;
    std::vector<double>                  values;
    std::vector<types::global_dof_index> dofs(
      dof_layer.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_layer.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dof_layer.get_dof_indices(cell, dofs);
          for (const auto i : dofs)
            values.push_back(ghosted(i));
        }
    part.put("vector." + name, values);
  }



  template <int dim>
  void
  Simulator<dim>::restore_vector(const std::string &name, Vector &v) const
  {
    const IndexSet &owned = dof_layer.locally_owned_dofs();
    // A vector already laid out on this numbering keeps its map: vectors
    // that share one assign without an Epetra_Import (the explicit loop's
    // work vectors share the map of `solution`). The decision is taken by
    // all ranks together, since a new map is built collectively.
    const bool laid_out = v.size() == owned.size() && !v.has_ghost_elements()
                          && v.locally_owned_elements() == owned;
    if (Utilities::MPI::min(laid_out ? 1 : 0, comm) == 0)
      v.reinit(owned, comm);
    const unsigned int n_local = dof_layer.get_fe().n_dofs_per_cell();
    // Every saved cell of every part, by id: any number of ranks reads it.
    std::map<CellId, const double *> saved;
    for (const auto &part : restart->parts)
      {
        const auto &cells  = part.get_integers("cells");
        const auto &values = part.get("vector." + name);
        if (values.size() != cells.size() / 4 * n_local)
          throw InputError("checkpoint '" + restart->folder + "': vector "
                           + name + " has the wrong size");
        for (std::size_t c = 0; c < cells.size() / 4; ++c)
          saved[cell_id<dim>(cells, c)] = values.data() + c * n_local;
      }
    std::vector<types::global_dof_index> dofs(n_local);
    std::vector<bool>                    found(owned.n_elements(), false);
    // The owned entries directly (in the order of the owned index set):
    // no compress(), whose bookkeeping would then expect an insertion
    // from the next user of the vector.
    double *const values = v.begin();
    for (const auto &cell : dof_layer.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto entry = saved.find(cell->id());
          if (entry == saved.end())
            throw InputError(
              "checkpoint '" + restart->folder + "' has no values of cell "
              + cell->id().to_string() + ": it was written for another mesh");
          dof_layer.get_dof_indices(cell, dofs);
          for (unsigned int k = 0; k < n_local; ++k)
            if (owned.is_element(dofs[k]))
              {
                const auto local = owned.index_within_set(dofs[k]);
                values[local]    = entry->second[k];
                found[local]     = true;
              }
        }
    if (std::find(found.begin(), found.end(), false) != found.end())
      throw InputError("checkpoint '" + restart->folder
                       + "' does not cover every unknown of vector " + name);
  }



  template <int dim>
  void
  Simulator<dim>::save_common(CheckpointData &run, CheckpointData &part) const
  {
    run.put_text("parameters", parameters.text);
    run.put_integer("ranks", Utilities::MPI::n_mpi_processes(comm));
    run.put_integer("dimension", dim);
    run.put_integer("total_lagrangian", parameters.total_lagrangian ? 1 : 0);
    run.put_integer("unknowns", dof_layer.n_dofs());
    run.put_integer("cycle", cycle);
    run.put_integers("mesh.changes", mesh_changes);
    run.put_integer("mesh.active_cells", triangulation.n_active_cells());
    if (remeshes())
      save_remeshing(run);
    // Inserted cracks: the DoF layer of a restart releases them before
    // the interface history is read back.
    if (interfaces && interfaces->cracks_enabled())
      run.put_integers("cracks", interfaces->crack_keys());
    save_table(run, "history", *summary);
    if (cycle_summary)
      save_table(run, "adaptivity", *cycle_summary);
    if (crack_events)
      save_table(run, "crack_events", *crack_events);
    // Analyses during the load history (Buckling/Analysis times).
    if (buckling_summary)
      {
        save_table(run, "buckling", *buckling_summary);
        run.put_integer("buckling.analyses", buckling_analyses);
      }
    if (field_output)
      {
        save_series(run, "fields", field_output->series());
        run.put_text("fields.xdmf", field_output->xdmf_state());
      }
    if (interface_output)
      save_series(run, "interface_points", interface_output->series());

    std::vector<std::int64_t> cells;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int k : cell->id().template to_binary<dim>())
          cells.push_back(k);
    part.put_integers("cells", cells);
    if (interfaces)
      {
        std::vector<std::int64_t> keys, counters;
        std::vector<double>       states;
        interfaces->save(keys, states, counters, comm);
        part.put_integers("interfaces.keys", keys);
        part.put("interfaces.states", states);
        part.put_integers("interfaces.counters", counters);
      }
  }



  namespace
  {
    void
    append_bits(const std::vector<bool> &bits, std::vector<std::int64_t> &out)
    {
      out.push_back(bits.size());
      for (std::size_t i = 0; i < bits.size(); i += 64)
        {
          std::uint64_t word = 0;
          for (std::size_t j = i; j < std::min(i + 64, bits.size()); ++j)
            word |= std::uint64_t(bits[j]) << (j - i);
          out.push_back(static_cast<std::int64_t>(word));
        }
    }

    std::vector<bool>
    read_bits(const std::vector<std::int64_t> &in, std::size_t &position)
    {
      const std::size_t n = in.at(position++);
      if (n > 64 * (in.size() - position))
        throw std::runtime_error("the mesh changes are truncated");
      std::vector<bool> bits(n);
      for (std::size_t i = 0; i < n; i += 64, ++position)
        {
          const auto word = static_cast<std::uint64_t>(in[position]);
          for (std::size_t j = i; j < std::min(i + 64, n); ++j)
            bits[j] = (word >> (j - i)) & 1u;
        }
      return bits;
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::save_remeshing(CheckpointData &run) const
  {
    run.put_integer("remeshing.budget_spent", cell_budget_spent ? 1 : 0);
    run.put("remeshing.zz_before", last_remeshing.zz_relative_before);
    run.put("remeshing.zz_reached", last_remeshing.zz_relative_reached);
    if (remeshed_plane.points.empty())
      return;
    std::vector<double> points;
    for (const auto &p : remeshed_plane.points)
      points.insert(points.end(), {p[0], p[1]});
    run.put("mesh.plane.points", points);
    const auto integers = [&](const std::string &name, const auto &items) {
      std::vector<std::int64_t> flat;
      for (const auto &item : items)
        flat.insert(flat.end(), item.begin(), item.end());
      run.put_integers("mesh.plane." + name, flat);
    };
    integers("triangles", remeshed_plane.triangles);
    integers("quadrilaterals", remeshed_plane.quadrilaterals);
    integers("edges", remeshed_plane.edges);
    run.put_integers("mesh.plane.edge_ids",
                     std::vector<std::int64_t>(remeshed_plane.edge_ids.begin(),
                                               remeshed_plane.edge_ids.end()));
  }



  namespace
  {
    /** The items of N numbers each of a checkpoint's flat @p numbers. */
    template <std::size_t N>
    std::vector<std::array<unsigned int, N>>
    unflatten(const std::vector<std::int64_t> &numbers)
    {
      std::vector<std::array<unsigned int, N>> items(numbers.size() / N);
      for (std::size_t i = 0; i < items.size(); ++i)
        for (std::size_t k = 0; k < N; ++k)
          items[i][k] = numbers[N * i + k];
      return items;
    }
  } // namespace



  template <int dim>
  bool
  Simulator<dim>::restore_remeshing(const CheckpointData &run)
  {
    if (!run.has("remeshing.budget_spent"))
      return false;
    cell_budget_spent = run.get_integer("remeshing.budget_spent") == 1;
    last_remeshing.zz_relative_before  = run.get_scalar("remeshing.zz_before");
    last_remeshing.zz_relative_reached = run.get_scalar("remeshing.zz_reached");
    if (!run.has("mesh.plane.points"))
      return false;
    PlaneMesh   plane;
    const auto &points = run.get("mesh.plane.points");
    for (std::size_t i = 0; i + 1 < points.size(); i += 2)
      plane.points.emplace_back(points[i], points[i + 1]);
    plane.triangles = unflatten<3>(run.get_integers("mesh.plane.triangles"));
    plane.quadrilaterals
      = unflatten<4>(run.get_integers("mesh.plane.quadrilaterals"));
    plane.edges = unflatten<2>(run.get_integers("mesh.plane.edges"));
    for (const auto id : run.get_integers("mesh.plane.edge_ids"))
      plane.edge_ids.push_back(id);
    // The remeshed mesh replaces the first one (no refinement leads from
    // one to the other).
    triangulation.clear();
    make_laminate_mesh(
      parameters.geometry, laminate, triangulation, false, &plane);
    remeshed_plane = std::move(plane);
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::execute_mesh_change()
  {
    std::vector<bool> refine, coarsen;
    triangulation.save_refine_flags(refine);
    triangulation.save_coarsen_flags(coarsen);
    append_bits(refine, mesh_changes);
    append_bits(coarsen, mesh_changes);
    const bool cracks = interfaces && interfaces->cracks_enabled();
    FaceValues strength;
    if (cracks)
      strength = strength_scale_by_face();
    triangulation.execute_coarsening_and_refinement();
    forget_crack_candidates();
    if (cracks)
      {
        interfaces->follow_mesh_change(triangulation);
        // Faces keep their strength, children take their parent's.
        evaluate_strength_scale(&strength);
      }
  }



  template <int dim>
  void
  Simulator<dim>::restore_mesh(const CheckpointData &run)
  {
    if (run.get_integer("dimension") != dim)
      throw InputError(
        "the checkpoint is of a " + std::to_string(run.get_integer("dimension"))
        + "D run, the parameters are of a " + std::to_string(dim) + "D one");
    if (run.has("mesh.plane.points") && !remeshes())
      throw InputError("Geometry/Element shape",
                       "the checkpoint is of a run on prisms remeshed by "
                       "Gmsh, these parameters make hexahedra: resume with "
                       "the parameters of the run that wrote it");
    // A checkpoint of another wedge mesh is refused by the cell count
    // below.
    const bool  remeshed = remeshes() && restore_remeshing(run);
    const auto &changes  = run.get_integers("mesh.changes");
    std::size_t position = 0;
    while (position < changes.size())
      {
        const auto refine  = read_bits(changes, position);
        const auto coarsen = read_bits(changes, position);
        if (refine.size() != dim * triangulation.n_active_cells()
            || coarsen.size() != triangulation.n_active_cells())
          throw InputError("the mesh changes of the checkpoint do not fit "
                           "the mesh of these parameters: the checkpoint is "
                           "of another scene");
        triangulation.load_refine_flags(refine);
        triangulation.load_coarsen_flags(coarsen);
        execute_mesh_change();
      }
    if (triangulation.n_active_cells()
        != static_cast<unsigned int>(run.get_integer("mesh.active_cells")))
      throw InputError("the checkpoint's mesh has "
                       + std::to_string(run.get_integer("mesh.active_cells"))
                       + " cells, the mesh of these parameters refined like it "
                       + std::to_string(triangulation.n_active_cells())
                       + ": the checkpoint is of another scene");
    const bool cracked = interfaces && interfaces->cracks_enabled()
                         && run.has("cracks")
                         && !run.get_integers("cracks").empty();
    if (cracked)
      interfaces->add_cracks(triangulation, run.get_integers("cracks"));
    if (changes.empty() && !cracked && !remeshed)
      return;
    setup_after_refinement();
    if (interfaces)
      interfaces->setup(dof_layer, parameters.boundary_conditions.constants);
  }



  template <int dim>
  void
  Simulator<dim>::resume(const CheckpointStore::Contents &checkpoint)
  {
    restart = std::make_unique<CheckpointStore::Contents>(checkpoint);
    reading(checkpoint.folder, comm, [&]() {
      check_kinematics(checkpoint.run);
      restore_mesh(checkpoint.run);
      if (checkpoint.run.get_integer("unknowns")
          != static_cast<std::int64_t>(dof_layer.n_dofs()))
        throw InputError(
          "the checkpoint has "
          + std::to_string(checkpoint.run.get_integer("unknowns"))
          + " unknowns, these parameters give "
          + std::to_string(dof_layer.n_dofs())
          + ": the checkpoint is of another scene");
    });
  }



  template <int dim>
  void
  Simulator<dim>::check_kinematics(const CheckpointData &run) const
  {
    // The state means other things in the two kinematics (the plastic
    // strain is eps_p or E_p, the interface history lives in another
    // frame). Checkpoints written before stop 43 do not say.
    if (!run.is_integer("total_lagrangian"))
      return;
    const bool saved = run.get_integer("total_lagrangian") == 1;
    if (saved != parameters.total_lagrangian)
      throw InputError("Kinematics",
                       std::string("the checkpoint is of a run with ")
                         + (saved ? "total Lagrangian" : "small strain")
                         + " kinematics, these parameters ask for "
                         + (saved ? "small strain" : "total Lagrangian")
                         + ": resume with the kinematics of the run "
                           "that wrote it");
  }



  template <int dim>
  void
  Simulator<dim>::restore_common()
  {
    const CheckpointData &run = restart->run;
    // The state first (no collective calls: a failure on one rank is
    // gathered by reading()), then the output files, which rank 0 writes
    // after the collective XDMF record.
    reading(restart->folder, comm, [&]() {
      cycle = run.get_integer("cycle");
      if (!interfaces)
        return;
      std::vector<const std::vector<std::int64_t> *> keys;
      std::vector<const std::vector<double> *>       states;
      for (const auto &part : restart->parts)
        {
          keys.push_back(&part.get_integers("interfaces.keys"));
          states.push_back(&part.get("interfaces.states"));
        }
      interfaces->load(keys,
                       states,
                       restart->parts[0].get_integers("interfaces.counters"),
                       comm);
    });
    reading(restart->folder, comm, [&]() {
      if (field_output && run.has("fields.times"))
        field_output->restore(restore_series(run, "fields"),
                              run.get_text("fields.xdmf"));
      if (interface_output && run.has("interface_points.times"))
        interface_output->restore(restore_series(run, "interface_points"));
      restore_table(run, "history", *summary);
      if (run.has("adaptivity.columns"))
        {
          cycle_summary = std::make_unique<History>(
            parameters.output.directory + "/adaptivity.csv",
            Utilities::MPI::this_mpi_process(comm) == 0);
          restore_table(run, "adaptivity", *cycle_summary);
        }
      if (run.has("crack_events.columns"))
        {
          crack_events = std::make_unique<History>(
            parameters.output.directory + "/cracks.csv",
            Utilities::MPI::this_mpi_process(comm) == 0);
          restore_table(run, "crack_events", *crack_events);
        }
      if (run.has("buckling.columns"))
        {
          buckling_summary = std::make_unique<History>(
            parameters.output.directory + "/buckling.csv",
            Utilities::MPI::this_mpi_process(comm) == 0);
          restore_table(run, "buckling", *buckling_summary);
          buckling_analyses = run.get_integer("buckling.analyses");
        }
    });
    pcout << "  resumed from " << restart->folder << " (step "
          << run.get_integer("step") << ", read in " << restart->read_seconds
          << " s)" << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::prepare_checkpoints()
  {
    const auto &p = parameters.checkpoint;
    checkpoints = std::make_unique<CheckpointStore>(p.directory, p.keep, comm);
    if (!restart && p.resume)
      {
        const std::string folder = CheckpointStore::newest(p.directory, comm);
        if (folder.empty())
          pcout << "  no checkpoint in " << p.directory
                << ": starting from the beginning" << std::endl;
        else
          resume(CheckpointStore::read(folder, comm));
      }
    if (restart)
      {
        restore_common();
        // Checkpoints after the one resumed from belong to a future this
        // run replaces: newest() must not pick them, nor Keep prune the
        // new ones in their favour.
        const unsigned int dropped
          = checkpoints->remove_after(restart->run.get_integer("number"));
        if (dropped > 0)
          pcout << "  removed " << dropped
                << " later checkpoint(s) of the run before" << std::endl;
      }
    else
      checkpoints->clear();
    checkpoint_clock.restart();
  }



  template <int dim>
  void
  Simulator<dim>::checkpoint_after_step(const unsigned int  step,
                                        const unsigned long number,
                                        const bool          at_row,
                                        const bool          last,
                                        const StateWriter  &save)
  {
    if (!checkpoints)
      return;
    const auto  &p       = parameters.checkpoint;
    const bool   root    = Utilities::MPI::this_mpi_process(comm) == 0;
    const double minutes = checkpoint_clock.wall_time() / 60;
    // Rank 0's clock decides, so that all ranks agree.
    const unsigned int local[2]
      = {static_cast<unsigned int>(StopSignals::received()),
         root && p.every_minutes > 0 && minutes >= p.every_minutes ? 1u : 0u};
    unsigned int global[2];
    Utilities::MPI::max(ArrayView<const unsigned int>(local, 2),
                        comm,
                        ArrayView<unsigned int>(global, 2));
    const int  signal = global[0];
    const bool stop
      = at_row && p.stop_after_step > 0 && step == p.stop_after_step;
    const bool due = signal != 0 || stop
                     || (at_row
                         && (global[1] != 0
                             || (p.every_n_steps > 0
                                 && (step % p.every_n_steps == 0 || last))));
    if (!due)
      return;
    std::string folder;
    {
      TimerOutput::Scope scope(timer, "checkpoint");
      Timer              watch;
      CheckpointData     run, part;
      run.put_integer("step", step);
      run.put_integer("number", number);
      save_common(run, part);
      save(run, part);
      try
        {
          folder = checkpoints->write(number, run, part);
        }
      catch (const CollectiveError &e)
        {
          // A routine checkpoint that fails (a full disk) must not end
          // hours of valid computation; one asked for by a signal or
          // Stop after step must.
          if (signal != 0 || stop)
            throw;
          pcout << "amfrac: warning: checkpoint " << number
                << " not written, the run goes on: " << e.what() << std::endl;
          checkpoint_clock.restart();
          return;
        }
      const double bytes = Utilities::MPI::sum(
        double(part.payload_bytes() + (root ? run.payload_bytes() : 0)), comm);
      seconds_in_checkpoints += watch.wall_time();
      pcout << "  checkpoint " << folder << ": " << bytes / 1e6 << " MB in "
            << watch.wall_time() << " s" << std::endl;
    }
    checkpoint_clock.restart();
    const std::string resume_with
      = "; continue with: amfrac --resume " + p.directory;
    if (signal != 0)
      throw RunInterrupted(std::string("stopped by ")
                           + StopSignals::name(signal) + ", state written to "
                           + folder + resume_with);
    if (stop)
      throw RunInterrupted("stopped after step " + std::to_string(step)
                           + " (Checkpoint/Stop after step), state written "
                             "to "
                           + folder + resume_with);
  }



  template <int dim>
  void
  Simulator<dim>::save_newton(const NewtonProgress &progress,
                              CheckpointData       &run,
                              CheckpointData       &part) const
  {
    run.put("newton.t", progress.t);
    run.put("newton.dt", progress.dt);
    run.put("newton.dtau", progress.dtau);
    run.put_integer("newton.step", progress.step);
    run.put_integer("newton.total_iterations", progress.total_iterations);
    run.put_integer("newton.by_dissipation", progress.by_dissipation);
    run.put_integer("newton.failures_left", progress.failures_left);
    run.put_integers("newton.iterations",
                     std::vector<std::int64_t>(progress.iterations.begin(),
                                               progress.iterations.end()));
    run.put_integer("newton.factorizations", n_factorizations);
    run.put("newton.force_scale", newton->force_scale);
    run.put("newton.external_work", newton->external_work);
    run.put("newton.remeshing_energy", newton->remeshing_energy);
    run.put_integer("newton.settling", newton->settling);
    run.put("newton.insertion_energy", newton->insertion_energy);
    run.put_integer("newton.insertion_settling", newton->insertion_settling);
    run.put("newton.converged_force", newton->converged_force);
    save_vector(part, "displacement", newton->converged_solution);
    save_vector(part, "previous_residual", newton->previous_residual);
    save_vector(part, "previous_load", newton->previous_load);
    if (plasticity)
      {
        run.put("newton.plastic_work", newton->plastic_work);
        // Cell by cell in the order of the part's cells.
        part.put("plasticity.states", plasticity->owned_values());
      }
    // The friction history of contact between the bodies.
    if (body_contact)
      run.put("newton.body_contact", body_contact->state());
    // The impactor's friction history (collective).
    if (impactor && impactor->has_friction())
      run.put("newton.impactor_friction", impactor->friction_state());
    if (parameters.nonlinear_solver.arc_length)
      {
        run.put("newton.arc_scale", newton->arc_scale);
        run.put("newton.arc_nominal", newton->arc_nominal);
        save_vector(part, "arc_previous", newton->arc_previous);
      }
  }



  template <int dim>
  void
  Simulator<dim>::restore_plastic_history()
  {
    const unsigned int width
      = plasticity->n_points() * PlasticPlies<dim>::n_components;
    // Every saved cell of every part, by id: any number of ranks reads it.
    std::map<CellId, const double *> saved;
    for (const auto &part : restart->parts)
      {
        const auto &cells  = part.get_integers("cells");
        const auto &values = part.get("plasticity.states");
        if (values.size() != cells.size() / 4 * width)
          throw InputError("checkpoint '" + restart->folder
                           + "': the plastic history has the wrong size");
        for (std::size_t c = 0; c < cells.size() / 4; ++c)
          saved[cell_id<dim>(cells, c)] = values.data() + c * width;
      }
    for (const auto &cell : dof_layer.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto entry = saved.find(cell->id());
          if (entry == saved.end())
            throw InputError("checkpoint '" + restart->folder
                             + "' has no plastic history of cell "
                             + cell->id().to_string()
                             + ": it was written for another mesh");
          plasticity->set_cell_values(cell, entry->second);
        }
  }



  template <int dim>
  void
  Simulator<dim>::restore_newton(NewtonProgress &progress)
  {
    const CheckpointData &run = restart->run;
    reading(restart->folder, comm, [&]() {
      progress.t                = run.get_scalar("newton.t");
      progress.dt               = run.get_scalar("newton.dt");
      progress.dtau             = run.get_scalar("newton.dtau");
      progress.step             = run.get_integer("newton.step");
      progress.total_iterations = run.get_integer("newton.total_iterations");
      progress.by_dissipation   = run.get_integer("newton.by_dissipation");
      // Checkpoints written before stop 48 did not keep it.
      progress.failures_left = run.has("newton.failures_left")
                               && run.get_integer("newton.failures_left") != 0;
      const auto &its = run.get_integers("newton.iterations");
      progress.iterations.assign(its.begin(), its.end());
      n_factorizations         = run.get_integer("newton.factorizations");
      newton->force_scale      = run.get_scalar("newton.force_scale");
      newton->external_work    = run.get_scalar("newton.external_work");
      newton->remeshing_energy = run.get_scalar("newton.remeshing_energy");
      newton->settling         = run.get_integer("newton.settling") != 0;
      // Absent in checkpoints written before the term: none booked.
      if (run.has("newton.insertion_energy"))
        {
          newton->insertion_energy = run.get_scalar("newton.insertion_energy");
          newton->insertion_settling
            = run.get_integer("newton.insertion_settling") != 0;
        }
      newton->converged_force = run.get_scalar("newton.converged_force");
      restore_vector("displacement", newton->converged_solution);
      restore_vector("previous_residual", newton->previous_residual);
      restore_vector("previous_load", newton->previous_load);
      if (plasticity)
        {
          newton->plastic_work = run.get_scalar("newton.plastic_work");
          restore_plastic_history();
        }
      if (body_contact)
        {
          if (!run.has("newton.body_contact"))
            throw InputError("Contact/Enable",
                             "the checkpoint has no contact state: it was "
                             "written by a run without contact");
          body_contact->set_state(run.get("newton.body_contact"));
        }
      if (impactor && !impactor->has_friction()
          && run.has("newton.impactor_friction"))
        throw InputError("Impactor/Friction coefficient",
                         "the checkpoint was written with friction between "
                         "the impactor and the laminate; resume it with the "
                         "same coefficient (its dissipation is in the "
                         "balance)");
      if (impactor && impactor->has_friction())
        {
          if (!run.has("newton.impactor_friction"))
            throw InputError("Impactor/Friction coefficient",
                             "the checkpoint has no friction history of "
                             "the impactor: it was written by a run "
                             "without friction");
          impactor->set_friction_state(run.get("newton.impactor_friction"));
        }
      if (parameters.nonlinear_solver.arc_length)
        {
          newton->arc_scale   = run.get_scalar("newton.arc_scale");
          newton->arc_nominal = run.get_scalar("newton.arc_nominal");
          restore_vector("arc_previous", newton->arc_previous);
        }
    });
    solution          = newton->converged_solution;
    relevant_solution = solution;
    // Entry by entry: an assignment would carry the restored vectors'
    // insert state into the next assembly's compress(add).
    std::copy(newton->previous_residual.begin(),
              newton->previous_residual.end(),
              newton->residual.begin());
    std::copy(newton->previous_load.begin(),
              newton->previous_load.end(),
              newton->external_load.begin());
  }



  template <int dim>
  void
  Simulator<dim>::save_explicit(const ExplicitState &state,
                                CheckpointData      &run,
                                CheckpointData      &part) const
  {
    run.put_integer("explicit.steps", state.steps);
    run.put("explicit.dt", state.dt);
    run.put("explicit.strain_energy", state.strain_energy);
    run.put("explicit.external_work", state.external_work);
    run.put("explicit.damping_work", state.damping_work);
    run.put("explicit.initial_energy", state.initial_energy);
    run.put_integer("explicit.last_good_step", state.last_good_step);
    run.put("explicit.last_good_t", state.last_good_t);
    run.put_integer("explicit.base_steps", state.base_steps);
    run.put_integer("explicit.base_row", state.base_row);
    run.put("explicit.base_t", state.base_t);
    run.put("explicit.remeshing_energy", state.remeshing_energy);
    for (std::size_t k = 0; k < state.impactor.size(); ++k)
      run.put("explicit.impactor." + std::to_string(k), state.impactor[k]);
    if (!state.body_contact.empty())
      run.put("explicit.body_contact", state.body_contact);
    if (!state.impactor_friction.empty())
      run.put("explicit.impactor_friction", state.impactor_friction);
    for (const auto &[name, v] : state.vectors)
      save_vector(part, name, *v);
  }



  template <int dim>
  void
  Simulator<dim>::restore_explicit(ExplicitState &state)
  {
    const CheckpointData &run = restart->run;
    reading(restart->folder, comm, [&]() {
      const double dt = run.get_scalar("explicit.dt");
      if (dt != state.dt)
        throw InputError("the checkpoint's time step is " + number_text(dt, 17)
                         + " s, these parameters give "
                         + number_text(state.dt, 17)
                         + " s: the Time subsection changed");
      state.steps          = run.get_integer("explicit.steps");
      state.strain_energy  = run.get_scalar("explicit.strain_energy");
      state.external_work  = run.get_scalar("explicit.external_work");
      state.damping_work   = run.get_scalar("explicit.damping_work");
      state.initial_energy = run.get_scalar("explicit.initial_energy");
      state.last_good_step = run.get_integer("explicit.last_good_step");
      state.last_good_t    = run.get_scalar("explicit.last_good_t");
      // Checkpoints of explicit runs before mesh changes existed lack
      // these: no change happened.
      if (run.has("explicit.base_steps"))
        {
          state.base_steps       = run.get_integer("explicit.base_steps");
          state.base_row         = run.get_integer("explicit.base_row");
          state.base_t           = run.get_scalar("explicit.base_t");
          state.remeshing_energy = run.get_scalar("explicit.remeshing_energy");
        }
      // The impactor's centre, velocity and acceleration, then its force
      // and impulse (not in checkpoints before stop 54) (the parameters
      // say whether there is one; the run's text is the checkpoint's).
      if (parameters.impactor.active)
        {
          const auto key = [](const std::size_t k) {
            return "explicit.impactor." + std::to_string(k);
          };
          if (!run.has(key(4 * dim)))
            throw InputError("Impactor/Face",
                             "the checkpoint has no impactor state: it "
                             "was written by a run without one");
          state.impactor.clear();
          for (std::size_t k = 0; k < 6 * dim + 1 && run.has(key(k)); ++k)
            state.impactor.push_back(run.get_scalar(key(k)));
        }
      // The impactor's friction history.
      if (parameters.impactor.active && parameters.impactor.friction == 0
          && run.has("explicit.impactor_friction"))
        throw InputError("Impactor/Friction coefficient",
                         "the checkpoint was written with friction between "
                         "the impactor and the laminate; resume it with the "
                         "same coefficient (its dissipation is in the "
                         "balance)");
      if (parameters.impactor.active && parameters.impactor.friction > 0)
        {
          if (!run.has("explicit.impactor_friction"))
            throw InputError("Impactor/Friction coefficient",
                             "the checkpoint has no friction history of "
                             "the impactor: it was written by a run "
                             "without friction");
          state.impactor_friction = run.get("explicit.impactor_friction");
        }
      // The friction history and last positions of the surface nodes.
      if (parameters.contact.active)
        {
          if (!run.has("explicit.body_contact"))
            throw InputError("Contact/Enable",
                             "the checkpoint has no contact state: it was "
                             "written by a run without contact");
          state.body_contact = run.get("explicit.body_contact");
        }
      for (const auto &[name, v] : state.vectors)
        restore_vector(name, *v);
    });
  }



  template void
  Simulator<2>::resume(const CheckpointStore::Contents &);
  template void
  Simulator<3>::resume(const CheckpointStore::Contents &);
  template void
  Simulator<2>::save_vector(CheckpointData &,
                            const std::string &,
                            const Vector &) const;
  template void
  Simulator<3>::save_vector(CheckpointData &,
                            const std::string &,
                            const Vector &) const;
  template void
  Simulator<2>::restore_vector(const std::string &, Vector &) const;
  template void
  Simulator<3>::restore_vector(const std::string &, Vector &) const;
  template void
  Simulator<2>::prepare_checkpoints();
  template void
  Simulator<2>::execute_mesh_change();
  template void
  Simulator<2>::save_newton(const NewtonProgress &,
                            CheckpointData &,
                            CheckpointData &) const;
  template void
  Simulator<2>::restore_newton(NewtonProgress &);
  template void
  Simulator<2>::save_explicit(const ExplicitState &,
                              CheckpointData &,
                              CheckpointData &) const;
  template void
  Simulator<2>::restore_explicit(ExplicitState &);
  template void
  Simulator<3>::prepare_checkpoints();
  template void
  Simulator<3>::execute_mesh_change();
  template void
  Simulator<3>::save_newton(const NewtonProgress &,
                            CheckpointData &,
                            CheckpointData &) const;
  template void
  Simulator<3>::restore_newton(NewtonProgress &);
  template void
  Simulator<3>::save_explicit(const ExplicitState &,
                              CheckpointData &,
                              CheckpointData &) const;
  template void
  Simulator<3>::restore_explicit(ExplicitState &);
  template void
  Simulator<2>::checkpoint_after_step(const unsigned int,
                                      const unsigned long,
                                      const bool,
                                      const bool,
                                      const StateWriter &);
  template void
  Simulator<3>::checkpoint_after_step(const unsigned int,
                                      const unsigned long,
                                      const bool,
                                      const bool,
                                      const StateWriter &);
} // namespace amfrac

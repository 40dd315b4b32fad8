#include <amfrac/adaptivity/remeshing.h>
#include <amfrac/base/first_failure.h>
#include <amfrac/checkpoint/stop_signals.h>
#include <amfrac/geometry/volume_mesh.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/postprocess/damage_map.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/numerics/vector_tools_integrate_difference.h>
#include <filesystem>
#include <sstream>

namespace amfrac
{
  namespace
  {
    /** Throws an InputError naming @p parameter if @p mesh has no
     * boundary face of @p id, the face @p name: a condition or load there
     * would act on nothing (a Geometry/Mesh file without a physical curve
     * or surface of that name). Checked once: a remeshing meshes the same
     * file, with the same names. */
    template <int dim>
    void
    require_boundary_face(const Triangulation<dim> &mesh,
                          const types::boundary_id  id,
                          const std::string        &name,
                          const std::string        &parameter)
    {
      for (const auto &face : mesh.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          return;
      throw InputError(parameter,
                       "the laminate has no face named '" + name
                         + "' (the sides of a Geometry/Mesh file are its "
                           "physical curves named x-, x+, y-, y+, or its "
                           "physical surfaces of those names and z-, z+ "
                           "in a 3D file)");
    }
  } // namespace



  template <int dim>
  typename TiedCopyDoFs<dim>::FaceFilter
  Simulator<dim>::paired_faces() const
  {
    if (!interfaces)
      return typename TiedCopyDoFs<dim>::FaceFilter();
    return interfaces->released_faces();
  }



  template <int dim>
  typename TiedCopyDoFs<dim>::FaceFilter
  Simulator<dim>::released_faces() const
  {
    const std::vector<unsigned int> &unbonded
      = parameters.contact.unbonded_interfaces;
    if (unbonded.empty())
      return paired_faces();
    const auto paired = paired_faces();
    return [this, paired](const auto &cell, const unsigned int face) {
      return is_unbonded(cell, face) || (paired && paired(cell, face));
    };
  }



  template <int dim>
  bool
  Simulator<dim>::is_unbonded(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face) const
  {
    const std::vector<unsigned int> &unbonded
      = parameters.contact.unbonded_interfaces;
    if (unbonded.empty() || cell->at_boundary(face))
      return false;
    const unsigned int a = cell->material_id();
    const unsigned int b = cell->neighbor(face)->material_id();
    return (a + 1 == b || b + 1 == a)
           && std::binary_search(unbonded.begin(),
                                 unbonded.end(),
                                 std::min(a, b));
  }



  template <int dim>
  Simulator<dim>::Simulator(const parameters::Parameters &prm,
                            const MPI_Comm                comm)
    : parameters(prm)
    , comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , triangulation(comm)
    , laminate(prm.geometry, prm.materials)
    , plies(make_ply_table<dim>(laminate, prm.materials))
    , dof_layer(triangulation,
                prm.discretization.degree,
                prm.geometry.prisms ? ReferenceCells::Wedge :
                                      ReferenceCells::get_hypercube<dim>())
    , assembler(dof_layer, plies)
    , lever(prm.boundary_conditions)
  {
    TimerOutput::Scope scope(timer, "setup");
    const bool         plies_from_file
      = make_laminate_mesh(parameters.geometry,
                           laminate,
                           triangulation,
                           parameters.adaptivity.during_history());
    // Wedges adapt by remeshing the in-plane outline, which a 3D file
    // does not have.
    if (plies_from_file && remeshes()
        && (parameters.adaptivity.active()
            || parameters.adaptivity.during_history()))
      throw InputError("Geometry/Mesh file",
                       "a 3D mesh of wedges cannot be combined with "
                       "adaptivity (wedges adapt by remeshing an in-plane "
                       "outline: give a 2D .geo, or hexahedra)");
    if constexpr (dim == 3)
      if (plies_from_file)
        {
          refuse_interfaces_between_distant_plies(
            triangulation,
            parameters.cohesive.interfaces,
            "Cohesive interfaces/Interfaces");
          refuse_interfaces_between_distant_plies(
            triangulation,
            parameters.contact.unbonded_interfaces,
            "Contact/Unbonded interfaces");
        }
    for (const auto &cell : triangulation.active_cell_iterators())
      initial_cells.insert(cell->id());
    if constexpr (dim == 3)
      if (remeshes())
        for (const auto &cell : triangulation.active_cell_iterators())
          first_mesh_size = std::max(first_mesh_size, in_plane_size(cell));
    if (!parameters.cohesive.interfaces.empty() || parameters.cracks.active)
      interfaces
        = std::make_unique<CohesiveInterfaces<dim>>(prm.cohesive,
                                                    prm.total_lagrangian);
    if (parameters.cracks.active)
      {
        interfaces->enable_cracks(parameters.cracks.penalty,
                                  parameters.cracks.friction);
        const std::string &constants = prm.boundary_conditions.constants;
        crack_region = make_expression_function<dim>({parameters.cracks.region},
                                                     1,
                                                     constants,
                                                     "Crack insertion/Region");
        evaluate_strength_scale();
      }
    if (parameters.total_lagrangian)
      finite_strain
        = std::make_unique<TotalLagrangianAssembler<dim>>(dof_layer, plies);
    dof_layer.distribute(released_faces());
    if (parameters.plastic_plies)
      {
        plasticity
          = std::make_unique<PlasticPlies<dim>>(dof_layer,
                                                plies,
                                                parameters.total_lagrangian);
        plasticity->setup();
      }
    // The lever couples distant nodes: every rank sees all of them.
    lever.collect(dof_layer);
    dof_layer.add_relevant_dofs(lever.all_dofs());
    if (interfaces)
      {
        const auto cracked
          = interfaces->setup(dof_layer,
                              parameters.boundary_conditions.constants);
        if (cracked == 0 && !parameters.cohesive.precrack_interfaces.empty())
          pcout << "amfrac: warning: parameter <Cohesive interfaces/Pre-crack "
                   "region> selects no point of the pre-crack interfaces"
                << std::endl;
      }
    build_loads_and_supports();
    if (parameters.geometry.imperfection_mode > 0)
      seed_imperfection_from_mode();

    make_probe();
    summary
      = std::make_unique<History>(parameters.output.directory + "/history.csv",
                                  Utilities::MPI::this_mpi_process(comm) == 0);
    if (parameters.output.write_vtu || parameters.output.write_xdmf)
      field_output = std::make_unique<FieldOutput<dim>>(
        parameters.output, dof_layer, plies, parameters.total_lagrangian);
    if (parameters.output.write_vtu && interfaces)
      interface_output
        = std::make_unique<InterfaceOutput<dim>>(parameters.output, comm);
  }



  template <int dim>
  void
  Simulator<dim>::make_probe()
  {
    std::vector<Point<dim>> points;
    for (const Point<3> &p : parameters.output.points)
      {
        Point<dim> q;
        for (unsigned int d = 0; d < dim; ++d)
          q[d] = p[d];
        points.push_back(q);
      }
    try
      {
        probe = std::make_unique<PointProbe<dim>>(dof_layer,
                                                  plies,
                                                  points,
                                                  parameters.total_lagrangian);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("Output/Point values", e.what());
      }
  }



  template <int dim>
  PatchLoad<dim>
  Simulator<dim>::build_patch_load() const
  {
    const auto    &bc = parameters.boundary_conditions;
    const auto    &in = bc.patch;
    PatchLoad<dim> patch;
    const auto    &names = parameters::BoundaryConditions::face_names;
    patch.boundary_id
      = std::find(names.begin(), names.end(), in.face) - names.begin();
    require_boundary_face(triangulation,
                          patch.boundary_id,
                          in.face,
                          "Boundary conditions/Patch load/Face");
    patch.normal_axis = in.face[0] - 'x';
    for (unsigned int d = 0; d < dim; ++d)
      patch.center[d] = in.center[d];
    patch.circle = in.circle;
    patch.radius = in.radius;
    for (unsigned int k = 0; k < in.size.size() && k < 2; ++k)
      patch.half_size[k] = in.size[k] / 2;
    if (!in.direction.empty())
      {
        for (unsigned int d = 0; d < dim; ++d)
          patch.direction[d] = in.direction[d];
        patch.direction /= patch.direction.norm();
      }
    patch.force = make_expression_function<dim>(
      {in.force}, 1, bc.constants, "Boundary conditions/Patch load/Force");
    assembler.prepare_patch(patch);
    return patch;
  }



  template <int dim>
  void
  Simulator<dim>::build_loads_and_supports()
  {
    const auto &bc        = parameters.boundary_conditions;
    const auto &constants = bc.constants;
    const bool  any_body_force
      = !(bc.body_force.size() == 1 && bc.body_force[0] == "0");
    if (any_body_force)
      loads.body_force = make_expression_function<dim>(
        bc.body_force, dim, constants, "Boundary conditions/Body force");

    if (!bc.patch.face.empty())
      loads.patches.push_back(build_patch_load());

    for (unsigned int id = 0; id < 2 * dim; ++id)
      {
        const parameters::BoundaryFace &face = bc.faces[id];
        const std::string path = "Boundary conditions/" + face.name + "/";
        using Type             = parameters::BoundaryFace::Type;
        if (face.type != Type::free)
          require_boundary_face(triangulation,
                                id,
                                face.name,
                                "Boundary conditions/" + face.name + "/Type");
        // A displacement face may carry a load on its free components as
        // well (an edge held in z and compressed in x).
        const bool supported = face.type == Type::displacement;
        if (face.type == Type::traction || (supported && face.has_traction()))
          loads.tractions[id] = make_expression_function<dim>(
            face.traction, dim, constants, path + "Traction");
        if (face.type == Type::pressure || (supported && face.has_pressure()))
          loads.pressures[id] = make_expression_function<dim>(
            {face.pressure}, 1, constants, path + "Pressure");
        if (supported)
          {
            PrescribedDisplacement<dim> condition;
            condition.name        = face.name;
            condition.boundary_id = id;
            condition.value       = make_expression_function<dim>(
              face.displacement, dim, constants, path + "Displacement");
            for (unsigned int d = 0; d < dim; ++d)
              condition.components[d] = face.components[d];
            if (!face.where.empty())
              condition.where
                = make_expression_function<dim>(parameters::split_expressions(
                                                  face.where),
                                                dim,
                                                constants,
                                                path + "Where");
            prescribed.push_back(condition);
          }
      }
  }



  template <int dim>
  void
  Simulator<dim>::set_body_force(const std::shared_ptr<Function<dim>> &force)
  {
    loads.body_force = force;
  }



  template <int dim>
  void
  Simulator<dim>::set_prescribed_displacements(
    const std::vector<PrescribedDisplacement<dim>> &conditions)
  {
    prescribed = conditions;
  }



  template <int dim>
  void
  Simulator<dim>::collect_supports()
  {
    // Every rank scans all boundary cells of the (replicated) mesh, so that
    // a dof is constrained consistently whichever rank sees it. The set does
    // not change during a run (Where is evaluated at t = 0), so this runs
    // once; each step only evaluates the prescribed values.
    supports.clear();
    for (const auto &condition : prescribed)
      supports.push_back(dof_layer.boundary_dofs(
        condition.boundary_id, [&](const types::global_dof_index dof) {
          const unsigned int c = dof_layer.component(dof);
          return condition.components[c]
                 && (!condition.where
                     || condition.where->value(dof_layer.support_point(dof), c)
                          != 0.);
        }));
    if (!lever.active())
      return;
    auto lever_dofs = lever.all_dofs();
    std::sort(lever_dofs.begin(), lever_dofs.end());
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      for (const auto dof : supports[k])
        if (std::binary_search(lever_dofs.begin(), lever_dofs.end(), dof))
          {
            std::ostringstream where;
            where << dof_layer.support_point(dof);
            throw InputError("Boundary conditions/Lever",
                             "the lever node at (" + where.str()
                               + ") is also prescribed by Boundary "
                                 "conditions/"
                               + prescribed[k].name);
          }
    supports.push_back(lever.all_dofs());
  }



  template <int dim>
  std::string
  Simulator<dim>::prescribed_not_finite(const unsigned int            k,
                                        const types::global_dof_index dof,
                                        const double                  t) const
  {
    std::ostringstream message;
    message << "the prescribed displacement of Boundary conditions/"
            << prescribed[k].name << " is not finite (NaN or inf) at t=" << t
            << " at (" << dof_layer.support_point(dof)
            << "): look for an expression that is not defined there (a sqrt "
               "or log of a negative number, a division by zero)";
    return message.str();
  }



  template <int dim>
  void
  Simulator<dim>::check_finite(const std::string &not_finite) const
  {
    // The first rank that saw a non-finite value says which.
    throw_first_failure<NonFiniteValue>(comm, not_finite);
  }



  template <int dim>
  void
  Simulator<dim>::make_constraints(const double               t,
                                   AffineConstraints<double> &constraints,
                                   const bool                 homogeneous) const
  {
    constraints.clear();
    constraints.reinit(dof_layer.locally_relevant_dofs());
    // Hanging nodes first: a hanging node on a supported face stays
    // constrained to its coarse face (its value follows from the support).
    for (const auto &line : dof_layer.hanging_node_constraints().get_lines())
      if (dof_layer.locally_relevant_dofs().is_element(line.index))
        {
          constraints.add_line(line.index);
          constraints.add_entries(line.index, line.entries);
        }
    std::string not_finite;
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      {
        prescribed[k].value->set_time(t);
        for (const auto dof : supports[k])
          if (dof_layer.locally_relevant_dofs().is_element(dof)
              && !constraints.is_constrained(dof))
            {
              constraints.add_line(dof);
              if (homogeneous)
                continue;
              const double value
                = prescribed[k].value->value(dof_layer.support_point(dof),
                                             dof_layer.component(dof));
              if (std::isfinite(value))
                constraints.set_inhomogeneity(dof, value);
              else if (not_finite.empty())
                not_finite = prescribed_not_finite(k, dof, t);
            }
      }
    check_finite(not_finite);
    lever.add_constraints(t,
                          homogeneous,
                          dof_layer.locally_relevant_dofs(),
                          constraints);
    constraints.close();
  }



  template <int dim>
  std::vector<std::vector<double>>
  Simulator<dim>::rigid_body_modes() const
  {
    const unsigned int               n_modes = dim == 3 ? 6 : 3;
    const IndexSet                  &owned   = dof_layer.locally_owned_dofs();
    std::vector<std::vector<double>> modes(
      n_modes, std::vector<double>(owned.n_elements(), 0.));
    unsigned int local = 0;
    for (const auto i : owned)
      {
        const Point<dim>  &p = dof_layer.support_point(i);
        const unsigned int c = dof_layer.component(i);
        modes[c][local]      = 1;
        if (dim == 2)
          modes[2][local] = (c == 0 ? -p[1] : p[0]);
        else
          {
            // Rotations about x, y and z.
            modes[3][local] = (c == 1 ? -p[dim - 1] : c == 2 ? p[1] : 0.);
            modes[4][local] = (c == 0 ? p[dim - 1] : c == 2 ? -p[0] : 0.);
            modes[5][local] = (c == 0 ? -p[1] : c == 1 ? p[0] : 0.);
          }
        ++local;
      }
    return modes;
  }



  template <int dim>
  std::vector<std::vector<double>>
  Simulator<dim>::owned_node_coordinates() const
  {
    // Owned reduced dofs come node by node, dim components each.
    std::vector<std::vector<double>> coordinates(dim);
    for (const auto i : dof_layer.locally_owned_dofs())
      if (dof_layer.component(i) == 0)
        for (unsigned int d = 0; d < dim; ++d)
          coordinates[d].push_back(dof_layer.support_point(i)[d]);
    return coordinates;
  }



  template <int dim>
  void
  Simulator<dim>::prepare_output_directory() const
  {
    // Rank 0 creates the folder; every rank learns the outcome, so that a
    // failure ends all of them alike.
    std::string failure;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(parameters.output.directory, error);
        if (error)
          failure = "cannot create '" + parameters.output.directory
                    + "': " + error.message();
      }
    failure = Utilities::MPI::broadcast(comm, failure, 0);
    if (!failure.empty())
      throw InputError("Output/Directory", failure);
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    if (prescribed.empty() && !parameters.time.explicit_dynamics)
      throw InputError("Boundary conditions",
                       "no face has Type = displacement, so the laminate "
                       "can move as a rigid body: prescribe displacements "
                       "on at least one face");
    // Refinement cycles repeat the whole run per mesh: they neither
    // checkpoint nor resume (the parameters refuse Every n steps there).
    const bool nonlinear = interfaces || finite_strain || plasticity
                           || parameters.impactor.active
                           || parameters.contact.active;
    const bool resumable = parameters.time.explicit_dynamics || nonlinear
                           || !parameters.adaptivity.active();
    if (restart && !resumable)
      throw InputError("Adaptivity/Refinement cycles",
                       "a run with refinement cycles cannot resume from a "
                       "checkpoint");
    if (resumable && !restart && parameters.checkpoint.resume)
      {
        const std::string folder
          = CheckpointStore::newest(parameters.checkpoint.directory, comm);
        if (!folder.empty())
          resume(CheckpointStore::read(folder, comm));
      }
    pcout << "amfrac: " << dim << "D"
          << (dim == 3          ? "" :
              laminate.in_plane ? " in-plane (plane stress)" :
                                  " cross-section (plane strain)")
          << ", " << laminate.n_plies() << " plies, ";
    if (interfaces)
      pcout << interfaces->interfaces().size() << " cohesive interface(s), ";
    if (parameters.cracks.active)
      pcout << "crack insertion (Hoffman), ";
    if (finite_strain)
      pcout << "total Lagrangian, ";
    if (plasticity)
      pcout << "Hoffman plasticity, ";
    pcout << triangulation.n_active_cells() << " cells, " << dof_layer.n_dofs()
          << " unknowns (" << dof_layer.n_copies() << " node copies), "
          << (dof_layer.reference_cell().is_hyper_cube() ? "Q" : "prisms P")
          << dof_layer.get_fe().degree << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
          << std::endl;
    pcout << "  DoF layer: " << dof_layer.memory_consumption() / 1e6
          << " MB on each rank" << std::endl;
    // Supports first: a lever node that is also supported is an input
    // error, raised before anything is written.
    collect_supports();
    prepare_output_directory();
    clock.restart();
    std::unique_ptr<StopSignals> signals;
    if (resumable)
      {
        prepare_checkpoints();
        signals = std::make_unique<StopSignals>();
      }
    if (parameters.time.explicit_dynamics)
      run_explicit();
    else if (nonlinear)
      run_newton();
    else if (parameters.adaptivity.active())
      run_adaptive();
    else
      {
        run_linear();
        timer.print_wall_time_statistics(comm);
      }
  }



  template <int dim>
  void
  Simulator<dim>::run_linear()
  {
    LinearSolver solver(parameters.linear_solver);
    solution.reinit(dof_layer.locally_owned_dofs(), comm);
    system_rhs.reinit(dof_layer.locally_owned_dofs(), comm);
    relevant_solution.reinit(dof_layer.locally_owned_dofs(),
                             dof_layer.locally_relevant_dofs(),
                             comm);
    // The solution carried from the last mesh (remeshing): an iterative
    // solver starts from it.
    if (first_guess.size() == dof_layer.n_dofs())
      solution = first_guess;
    first_guess.clear();

    const unsigned int n_steps = parameters.time.n_steps;
    const double       dt      = parameters.time.end_time / n_steps;
    // Every step is independent of the others: a restart only skips the
    // steps done.
    const unsigned int first
      = restart ? restart->run.get_integer("step") + 1 : 1;
    // The analyses up to the restored step are in the restored table.
    buckling_due((first - 1) * dt);
    for (unsigned int step = first; step <= n_steps; ++step)
      {
        const double t = step * dt;
        {
          TimerOutput::Scope scope(timer, "constraints");
          make_constraints(t, constraints, false);
        }
        if (step == first)
          {
            // The condensed matrix depends on which dofs are constrained,
            // not on the prescribed values: assemble and factorize once.
            {
              TimerOutput::Scope scope(timer, "assemble matrix");
              assembler.reinit_matrix(constraints, system_matrix);
              assembler.assemble_matrix(constraints, system_matrix);
            }
            TimerOutput::Scope scope(timer, "solver setup");
            const double       seconds = solver.initialize(system_matrix,
                                                     rigid_body_modes(),
                                                     dim,
                                                     owned_node_coordinates());
            pcout << "  " << solver.name() << " set up in " << seconds << " s"
                  << std::endl;
          }
        {
          TimerOutput::Scope scope(timer, "assemble rhs");
          assembler.assemble_rhs(loads, t, constraints, system_rhs);
        }
        {
          TimerOutput::Scope scope(timer, "solve");
          const auto         report = solver.solve(solution, system_rhs);
          constraints.distribute(solution);
          relevant_solution = solution;
          pcout << "  step " << step << " t=" << t << ": " << report.iterations
                << " iteration(s), " << report.seconds << " s" << std::endl;
        }
        if (parameters.adaptivity.active() && step == n_steps)
          {
            estimate_error(t);
            if (field_output)
              field_output->set_cell_field("error_indicator",
                                           last_estimate.cell_errors);
          }
        Vector residual;
        residual.reinit(dof_layer.locally_owned_dofs(),
                        dof_layer.locally_relevant_dofs(),
                        comm,
                        /*vector_writable=*/true);
        const auto energies
          = assembler.compute_residual(loads, t, relevant_solution, residual);
        postprocess(step,
                    t,
                    residual,
                    {{"strain_energy", energies.strain_energy},
                     {"load_work", energies.load_work}});
        if (parameters.buckling.active() && buckling_due(t))
          skip_failed_analysis(
            [&]() { analyse_buckling(solver, constraints, t); }, t);
        checkpoint_after_step(
          step, step, true, step == n_steps, [](auto &, auto &) {});
      }
    // A run resumed from its last step has nothing left to do; its
    // buckling analysis is in the buckling.csv of the run before.
    if (parameters.buckling.active()
        && parameters.buckling.analysis_times.empty() && first <= n_steps)
      analyse_buckling(solver, constraints, n_steps * dt);
  }



  template <int dim>
  std::vector<double>
  Simulator<dim>::conjugate_forces(const double t, const Vector &residual) const
  {
    // dg/dt by a one-sided difference: exact for the usual linear ramps.
    const double        dt = 1e-6 * parameters.time.end_time;
    std::vector<double> forces(prescribed.size(), 0.);
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      {
        Function<dim> &g = *prescribed[k].value;
        for (const auto i : supports[k])
          if (dof_layer.locally_owned_dofs().is_element(i))
            {
              const Point<dim>  &p = dof_layer.support_point(i);
              const unsigned int c = dof_layer.component(i);
              g.set_time(t);
              const double now = g.value(p, c);
              g.set_time(t - dt);
              forces[k] += residual(i) * (now - g.value(p, c)) / dt;
            }
        g.set_time(t);
        forces[k] = Utilities::MPI::sum(forces[k], comm);
      }
    return forces;
  }



  template <int dim>
  std::vector<std::pair<std::string, double>>
  Simulator<dim>::load_columns(const double t, const Vector &residual) const
  {
    std::vector<std::pair<std::string, double>> row;
    const char                                 *axis = "xyz";
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      {
        std::array<double, dim> force{};
        for (const auto i : supports[k])
          if (dof_layer.locally_owned_dofs().is_element(i))
            force[dof_layer.component(i)] += residual(i);
        for (unsigned int d = 0; d < dim; ++d)
          if (prescribed[k].components[d])
            row.emplace_back("reaction_" + prescribed[k].name + "_" + axis[d],
                             Utilities::MPI::sum(force[d], comm));
      }
    // The force conjugate to t is a load factor's force in pseudo-time;
    // in physical time (explicit) it would be a power, so it is left out
    // there (the reactions are reported above).
    if (!parameters.time.explicit_dynamics)
      {
        const auto conjugate = conjugate_forces(t, residual);
        for (unsigned int k = 0; k < prescribed.size(); ++k)
          row.emplace_back("force_" + prescribed[k].name, conjugate[k]);
      }
    return row;
  }



  template <int dim>
  void
  Simulator<dim>::postprocess(
    const unsigned int                                 step,
    const double                                       t,
    const Vector                                      &residual,
    const std::vector<std::pair<std::string, double>> &columns)
  {
    TimerOutput::Scope scope(timer, "postprocess");
    dof_layer.expand(relevant_solution, copy_values);

    std::vector<std::pair<std::string, double>> row
      = {{"step", step}, {"time", t}};
    // Adaptive runs repeat the load steps on every mesh.
    if (parameters.adaptivity.active())
      row.insert(row.begin(), {"cycle", cycle});
    row.insert(row.end(), columns.begin(), columns.end());
    const auto loads = load_columns(t, residual);
    row.insert(row.end(), loads.begin(), loads.end());
    const char *axis = "xyz";
    if (lever.active())
      {
        const auto [hinge, saddle] = lever.displacements(relevant_solution);
        row.emplace_back("force_lever", lever.force(t, residual, comm));
        row.emplace_back("lever_hinge", hinge);
        row.emplace_back("lever_saddle", saddle);
      }
    // Plastic plies: stresses of the elastic strain (the cell means of the
    // plastic strain taken off), and the equivalent plastic strain.
    typename PlasticPlies<dim>::CellMeans plastic;
    if (plasticity)
      {
        plastic = plasticity->cell_means();
        set_plastic_fields(plastic);
      }
    const auto values = probe->evaluate(copy_values, plastic.plastic_strain);
    for (unsigned int p = 0; p < values.size(); ++p)
      {
        const std::string prefix = "p" + std::to_string(p) + "_";
        for (unsigned int d = 0; d < dim; ++d)
          row.emplace_back(prefix + "u" + axis[d], values[p].displacement[d]);
        for (unsigned int k = 0; k < 6; ++k)
          row.emplace_back(
            prefix + "stress_" + voigt_names[k],
            values[p].stress[voigt_pairs[k][0]][voigt_pairs[k][1]]);
      }
    summary->add_row(row);
    last_row = row;

    if (step % parameters.output.every_n_steps == 0
        || t >= parameters.time.end_time * (1 - 1e-12))
      write_fields(step, t, false);
  }



  template <int dim>
  void
  Simulator<dim>::set_plastic_fields(
    const typename PlasticPlies<dim>::CellMeans &means)
  {
    if (!field_output)
      return;
    field_output->set_plastic_strain(means.plastic_strain);
    field_output->set_cell_field("equivalent_plastic_strain",
                                 dealii::Vector<float>(means.kappa.begin(),
                                                       means.kappa.end()));
  }



  template <int dim>
  void
  Simulator<dim>::write_fields(const unsigned int step,
                               const double       t,
                               const bool         update_plastic)
  {
    if (!field_output)
      return;
    // (A mesh change or a restart cleared them; postprocess() has just
    // set them.)
    if (plasticity && update_plastic)
      set_plastic_fields(plasticity->cell_means());
    dof_layer.expand(relevant_solution, copy_values);
    // Adaptive cycles continue the series: cycle c is shown at times
    // c * End time + t.
    const unsigned int n_steps = parameters.time.n_steps;
    field_output->write(cycle * n_steps + step,
                        cycle * parameters.time.end_time + t,
                        copy_values);
    if (!interfaces)
      return;
    const auto points = interfaces->output_points(relevant_solution);
    if (interface_output)
      interface_output->write(step, t, points);
    if (parameters.output.damage_maps)
      write_damage_maps(parameters.output.directory, step, points, comm);
  }



  template <int dim>
  double
  Simulator<dim>::compute_error(const Function<dim>        &exact,
                                const VectorTools::NormType norm) const
  {
    dealii::Vector<float> cellwise(triangulation.n_active_cells());
    VectorTools::integrate_difference(dof_layer.get_mapping(),
                                      dof_layer.copy_handler(),
                                      copy_values,
                                      exact,
                                      cellwise,
                                      dof_layer.cell_quadrature(
                                        dof_layer.get_fe().degree + 3),
                                      norm);
    return VectorTools::compute_global_error(triangulation, cellwise, norm);
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace amfrac

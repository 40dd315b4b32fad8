// The explicit path of Simulator (Time integration = explicit): central
// differences in velocity-Verlet form with a lumped mass. Nothing of the
// static path is built: no stiffness matrix, no linear solver; the bulk
// force comes from the stresses cell by cell and the interface force from
// the current jump and history.
#include <algorithm>
#include <amfrac/assembly/bulk_force.h>
#include <amfrac/base/ghost_import.h>
#include <amfrac/base/mpi_max.h>
#include <amfrac/base/point_order.h>
#include <amfrac/cohesive/transfer_columns.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/simulator/simulator.h>
#include <array>
#include <chrono>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <limits>
#include <set>
#include <sstream>

namespace amfrac
{
  template <int dim>
  void
  Simulator<dim>::check_explicit_input() const
  {
    if (dof_layer.hanging_node_constraints().n_constraints() > 0
        && parameters.time.mass_scaling_step > 0)
      throw InputError("Time/Mass scaling time step",
                       "mass scaling needs a mesh without hanging nodes "
                       "(Geometry/Refinement region makes them); set it to "
                       "0");
    if (lever.active())
      throw InputError("Boundary conditions/Lever",
                       "a lever is a static constraint; it is not "
                       "available with Time integration = explicit");
    for (const auto &ply : plies)
      if (!(ply.density > 0))
        throw InputError("Materials/Density",
                         "explicit dynamics needs a positive density in "
                         "every ply (t/mm^3, e.g. 1.6e-9)");
  }



  template <int dim>
  double
  Simulator<dim>::element_frequency_squared(Point<dim> &where) const
  {
    // By Irons' theorem the largest element omega^2 bounds the mesh's.
    // Each ply's candidates are examined exactly (a dense eigenproblem of
    // the element's M^-1 K): its elements with the shortest edge, the
    // smallest volume and the smallest diameter. One measure alone misses
    // the stiffest elements of an adapted laminate: a cell refined along
    // the plies keeps the ply's thickness as its shortest edge, and so do
    // its coarser neighbours.
    double bulk   = 0;
    using Cell    = typename TiedCopyDoFs<dim>::CellIterator;
    using Measure = double (*)(const Cell &);
    const Measure measures[]
      = {[](const Cell &c) { return c->minimum_vertex_distance(); },
         [](const Cell &c) { return c->measure(); },
         [](const Cell &c) { return c->diameter(); }};
    std::map<unsigned int, std::vector<Cell>> by_ply;
    for (const auto &cell : dof_layer.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        by_ply[cell->material_id()].push_back(cell);
    for (auto &[ply, cells] : by_ply)
      {
        std::set<CellId> examined;
        for (const Measure measure : measures)
          {
            std::vector<std::pair<double, Cell>> sorted;
            for (const auto &cell : cells)
              sorted.emplace_back(measure(cell), cell);
            const std::size_t n = std::min<std::size_t>(4, sorted.size());
            std::partial_sort(sorted.begin(),
                              sorted.begin() + n,
                              sorted.end(),
                              [](const auto &a, const auto &b) {
                                return a.first < b.first;
                              });
            for (std::size_t i = 0; i < n; ++i)
              if (examined.insert(sorted[i].second->id()).second)
                {
                  const double w2
                    = assembler.max_frequency_squared(sorted[i].second);
                  if (w2 > bulk)
                    bulk = w2, where = sorted[i].second->center();
                }
          }
      }
    return max_and_where(bulk, where, comm) / uniform_mass_factor;
  }



  template <int dim>
  void
  Simulator<dim>::penalty_row_sums(Vector &row_sums) const
  {
    Vector with_ghosts;
    with_ghosts.reinit(dof_layer.locally_owned_dofs(),
                       dof_layer.locally_relevant_dofs(),
                       comm,
                       true);
    if (interfaces)
      interfaces->add_penalty_row_sums(with_ghosts);
    with_ghosts.compress(VectorOperation::add);
    row_sums.reinit(dof_layer.locally_owned_dofs(), comm);
    row_sums = with_ghosts;
    if (impactor)
      impactor->add_penalty_rows(row_sums);
    if (body_contact)
      body_contact->add_penalty_rows(row_sums);
  }



  template <int dim>
  double
  Simulator<dim>::stable_time_step(const Vector                   &mass,
                                   const HangingCondensation<dim> &hanging)
  {
    Point<dim>   bulk_where, spring_where;
    const double bulk = element_frequency_squared(bulk_where);
    // Interfaces: Gershgorin's bound on M^-1 K of the penalty springs.
    // Both bounds are Rayleigh quotients in the mass inner product, so
    // omega^2 of the sum is at most the sum.
    double     springs = 0;
    const bool contact = impactor || body_contact;
    if (interfaces || contact)
      {
        Vector rows;
        penalty_row_sums(rows);
        // On a mesh with hanging nodes the springs act on C^T K C: a
        // hanging row goes to its masters, bounded with |c| times the
        // largest sum of |c| of a line.
        if (!hanging.empty())
          {
            hanging.condense(rows, true);
            rows *= hanging.largest_weight_sum();
          }
        for (const auto i : dof_layer.locally_owned_dofs())
          if (mass(i) > 0 && rows(i) / mass(i) > springs)
            springs      = rows(i) / mass(i),
            spring_where = dof_layer.support_point(i);
        springs = max_and_where(springs, spring_where, comm);
      }
    // The sphere's own row (its springs to every candidate node).
    if (impactor)
      {
        const double sphere = impactor->frequency_squared();
        if (sphere > springs)
          springs = sphere, spring_where = Point<dim>();
      }
    // With crack insertion the step is chosen once for the whole run: it
    // must hold for every crack pattern the candidate faces allow.
    if (interfaces && interfaces->cracks_enabled())
      {
        Point<dim>   where;
        const double cracks = crack_frequency_squared(where);
        if (cracks > springs)
          springs = cracks, spring_where = where;
      }
    double stable = 2. / std::sqrt(bulk + springs);
    if (!(stable > 0 && std::isfinite(stable)))
      throw CollectiveError("the stable time step estimate is "
                            + number_text(stable)
                            + ": check the material constants (moduli in "
                              "MPa, densities in t/mm^3) and the mesh");
    pcout << "  stable time step " << stable << " s: elements alone "
          << 2. / std::sqrt(bulk) << " s (at " << bulk_where << ")";
    if (interfaces || contact)
      pcout << ", " << (interfaces ? "interface " : "")
            << (interfaces && contact ? "and " : "")
            << (contact ? "contact " : "") << "penalties"
            << (interfaces && interfaces->cracks_enabled() ?
                  " (and any crack pattern)" :
                  "")
            << " alone " << 2. / std::sqrt(springs) << " s (at " << spring_where
            << "); controlled by the "
            << (springs <= bulk ? "elements" :
                contact         ? "penalties" :
                                  "interfaces");
    pcout << std::endl;
    // Stiffness-proportional damping: central differences are stable up
    // to (2 / omega) (sqrt(1 + xi^2) - xi) at the damping ratio xi of the
    // highest mode.
    const double beta = parameters.time.rayleigh_beta;
    if (beta > 0)
      {
        const double xi = beta * std::sqrt(bulk + springs) / 2;
        stable *= std::sqrt(1 + xi * xi) - xi;
        pcout << "  with Rayleigh stiffness damping (damping ratio " << xi
              << " at omega_max): " << stable << " s" << std::endl;
      }
    return stable;
  }



  template <int dim>
  void
  Simulator<dim>::scale_mass(Vector &mass, const double target)
  {
    const double budget
      = std::pow(2 * parameters.time.safety_factor / target, 2);
    // The elements keep at most half of the budget, by a uniform factor.
    Point<dim>   where;
    const double bulk    = element_frequency_squared(where);
    const double uniform = std::max(1., bulk / (0.5 * budget));
    uniform_mass_factor *= uniform;
    const double springs_budget = budget - bulk / uniform;
    // Each node takes the mass its largest spring row needs; one factor
    // for all its components and for both copies of a split node.
    Vector rows;
    penalty_row_sums(rows);
    std::map<Point<dim>, double, LexicographicLess> needed;
    const IndexSet &owned = dof_layer.locally_owned_dofs();
    for (const auto i : owned)
      {
        double &m = needed[dof_layer.support_point(i)];
        m         = std::max(
          {m, uniform_mass_factor * mass(i), rows(i) / springs_budget});
      }
    double original = 0, largest = 1;
    added_mass = 0;
    for (const auto i : owned)
      {
        const double m = needed[dof_layer.support_point(i)];
        original += mass(i) / dim;
        added_mass += (m - mass(i)) / dim;
        if (m / mass(i) > largest)
          largest = m / mass(i), where = dof_layer.support_point(i);
        mass(i) = m;
      }
    mass.compress(VectorOperation::insert);
    original   = Utilities::MPI::sum(original, comm);
    added_mass = Utilities::MPI::sum(added_mass, comm);
    largest    = max_and_where(largest, where, comm);
    pcout << "  mass scaling to a step of " << target << " s: added "
          << added_mass << " t (" << 100 * added_mass / original
          << " % of the laminate's " << original << " t), largest nodal factor "
          << largest << " at " << where;
    if (uniform_mass_factor > 1)
      pcout << ", all masses times " << uniform_mass_factor;
    pcout << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::report_contact_oscillation(const RigidImpactor<dim> &impactor,
                                             const Vector             &mass,
                                             const double              dt) const
  {
    // Stability does not make an accurate contact: a node whose contact
    // spring swings in a few steps gains energy at every touch (its
    // penetration is sampled too coarsely), the more the fewer.
    const double steps
      = 2 * M_PI / (std::sqrt(impactor.node_frequency_squared(mass)) * dt);
    pcout << "  contact: " << steps
          << " time steps per oscillation of the stiffest face node against "
             "the impactor";
    if (steps < 10)
      pcout << "; WARNING: below 10 the contact chatter of single nodes "
               "gains energy (watch balance_error); a lower Impactor/Penalty "
               "helps (the count grows as 1/sqrt(Penalty) once the contact "
               "no longer sets the time step)";
    pcout << std::endl;
  }



  template <int dim>
  double
  Simulator<dim>::choose_time_step(const double stable) const
  {
    const auto &time = parameters.time;
    if (time.mass_scaling_step > 0)
      return std::min(time.mass_scaling_step, time.safety_factor * stable);
    if (time.time_step == 0)
      return time.safety_factor * stable;
    if (time.time_step > stable && !time.allow_unstable)
      throw InputError("Time/Time step",
                       "the fixed step " + number_text(time.time_step)
                         + " s exceeds the estimated stable step "
                         + number_text(stable)
                         + " s (set Time/Allow unstable time step = "
                           "true to run it anyway)");
    return time.time_step;
  }



  template <int dim>
  void
  Simulator<dim>::impose_prescribed(const double t, Vector &u) const
  {
    std::string not_finite;
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      {
        prescribed[k].value->set_time(t);
        for (const auto i : supports[k])
          if (dof_layer.locally_owned_dofs().is_element(i))
            {
              const double value
                = prescribed[k].value->value(dof_layer.support_point(i),
                                             dof_layer.component(i));
              if (std::isfinite(value))
                u(i) = value;
              else if (not_finite.empty())
                not_finite = prescribed_not_finite(k, i, t);
            }
      }
    u.compress(VectorOperation::insert);
    check_finite(not_finite);
  }



  template <int dim>
  void
  Simulator<dim>::set_initial_velocity(const Vector &free_inverse_mass,
                                       Vector       &velocity) const
  {
    const auto &expressions = parameters.time.initial_velocity;
    velocity                = 0;
    if (expressions.size() == 1 && expressions[0] == "0")
      return;
    const auto v0
      = make_expression_function<dim>(expressions,
                                      dim,
                                      parameters.boundary_conditions.constants,
                                      "Time/Initial velocity");
    for (const auto i : dof_layer.locally_owned_dofs())
      if (free_inverse_mass(i) != 0)
        velocity(i)
          = v0->value(dof_layer.support_point(i), dof_layer.component(i));
    velocity.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  Simulator<dim>::run_explicit()
  {
    check_explicit_input();
    // References to the layer's sets: they follow a crack insertion.
    const IndexSet &owned    = dof_layer.locally_owned_dofs();
    const IndexSet &relevant = dof_layer.locally_relevant_dofs();
    Vector mass, velocity, acceleration, force, load, previous_load, reaction,
      previous_reaction, free_inverse_mass, support_mask, free_mass,
      damping_force, previous_damping, stiffness_velocity, displacement_step,
      momentum, old_solution, last_good, contact, body_force;
    // The work vectors on the current numbering (velocity and last_good
    // are state: a crack insertion or a mesh change carries them, and
    // here they take the map of `solution` with their values). All
    // vectors share that map: deal.II's assignment between vectors of
    // separately built maps, equal or not, builds an Epetra_Import (a pass
    // with hash look-ups over both maps), which made three assignments a
    // step a seventh of an explicit run's time.
    const auto share_map = [&](Vector &v) {
      Vector moved;
      moved.reinit(solution);
      moved = v;
      v.swap(moved);
    };
    const std::vector<Vector *> work_vectors = {&mass,
                                                &acceleration,
                                                &force,
                                                &load,
                                                &previous_load,
                                                &reaction,
                                                &previous_reaction,
                                                &free_inverse_mass,
                                                &support_mask,
                                                &free_mass,
                                                &damping_force,
                                                &previous_damping,
                                                &stiffness_velocity,
                                                &displacement_step,
                                                &momentum,
                                                &old_solution,
                                                &contact,
                                                &body_force};
    const auto                  layout       = [&](const bool with_state) {
      if (with_state)
        {
          solution.reinit(owned, comm);
          velocity.reinit(solution);
          last_good.reinit(solution);
        }
      else
        {
          share_map(velocity);
          share_map(last_good);
        }
      for (Vector *v : work_vectors)
        v->reinit(solution);
      relevant_solution.reinit(owned, relevant, comm);
    };
    layout(true);
    // Hanging nodes (a locally refined mesh): forces and masses act on
    // the masters (C^T), the hanging entries follow them.
    std::unique_ptr<HangingCondensation<dim>> hanging;
    // The masses of the copies, kept while the mesh stays (crack
    // insertion only regroups the copies).
    dealii::Vector<double> copy_masses;
    const auto             lump_mass = [&](const bool same_mesh = false) {
      TimerOutput::Scope scope(timer, "lumped mass");
      if (!same_mesh)
        copy_masses.reinit(0);
      assembler.lumped_mass(mass, copy_masses);
      hanging = std::make_unique<HangingCondensation<dim>>(dof_layer, comm);
      hanging->condense(mass);
    };
    lump_mass();
    if (parameters.impactor.active)
      {
        impactor = std::make_unique<RigidImpactor<dim>>(parameters.impactor,
                                                        comm,
                                                        true);
        impactor->setup(dof_layer);
      }
    if (parameters.contact.active)
      {
        body_contact
          = std::make_unique<BodyContact<dim>>(parameters.contact, comm);
        body_contact->setup(dof_layer, released_faces(), paired_faces());
        pcout << "  contact: " << body_contact->n_faces() << " surface faces, "
              << body_contact->n_nodes() << " surface nodes" << std::endl;
      }
    const double end      = parameters.time.end_time;
    const double interval = end / parameters.time.n_steps;
    double       stable = 0, dt = 0;
    unsigned int substeps = 0;
    // The stable step of the current mesh, and the step: whole steps per
    // output interval, so that output lands on its times.
    const auto choose_step = [&]() {
      {
        TimerOutput::Scope scope(timer, "stable time step");
        stable              = stable_time_step(mass, *hanging);
        const double target = parameters.time.mass_scaling_step;
        if (target > 0 && parameters.time.safety_factor * stable < target)
          {
            scale_mass(mass, target);
            stable = stable_time_step(mass, *hanging);
          }
      }
      estimated_stable_step = stable;
      dt                    = choose_time_step(stable);
      substeps              = std::ceil(interval / dt * (1 - 1e-12));
      dt                    = interval / substeps;
      pcout << "  time step " << dt << " s (" << dt / stable
            << " of the stable step), " << substeps << " steps per output step"
            << std::endl;
    };
    choose_step();
    if (impactor)
      report_contact_oscillation(*impactor, mass, dt);

    // Free dofs move by M a = f_ext - f_int; the supports move as
    // prescribed and react with f_int - f_ext (the inertia of their own
    // nodes is the support's: it stays out of the ledger, as does their
    // kinetic energy).
    const auto split_mass = [&]() {
      bool positive = true;
      for (const auto i : owned)
        if (hanging->is_hanging(i))
          free_inverse_mass(i) = 0;
        else
          {
            positive             = positive && mass(i) > 0;
            free_inverse_mass(i) = 1. / mass(i);
          }
      // Q2's hanging weights include -1/8: a master's condensed mass
      // could in principle vanish.
      if (Utilities::MPI::min(positive ? 1 : 0, comm) == 0)
        throw CollectiveError("a lumped nodal mass is not positive on this "
                              "mesh (hanging nodes of a Q2 mesh?); use "
                              "Finite element degree = 1 with local "
                              "refinement");
      support_mask = 0;
      for (const auto &support : supports)
        for (const auto i : support)
          if (owned.is_element(i))
            free_inverse_mass(i) = 0, support_mask(i) = 1;
      free_inverse_mass.compress(VectorOperation::insert);
      support_mask.compress(VectorOperation::insert);
      free_mass = mass;
      for (const auto i : owned)
        if (free_inverse_mass(i) == 0)
          free_mass(i) = 0;
      free_mass.compress(VectorOperation::insert);
    };
    split_mass();

    std::unique_ptr<BulkForceOperator<dim>>  bulk;
    typename ElasticAssembler<dim>::CellList loaded_cells;
    // Whether any rank has a loaded cell: a scene loaded only by its
    // supports, an initial velocity or an impactor skips the load
    // assembly (its scratch objects and reduction) in every step.
    bool any_loaded = false;
    // After crack insertion (same_mesh) the element matrices stay.
    const auto build_operators = [&](const bool same_mesh = false) {
      TimerOutput::Scope scope(timer, "element matrices");
      if (same_mesh)
        bulk->renumber(dof_layer, assembler);
      else
        bulk = std::make_unique<BulkForceOperator<dim>>(dof_layer,
                                                        assembler,
                                                        interfaces.get());
      loaded_cells = assembler.loaded_cells(loads);
      any_loaded
        = Utilities::MPI::max(loaded_cells.empty() ? 0u : 1u, comm) > 0;
    };
    build_operators();
    pcout << "  bulk force: " << bulk->summary() << std::endl;

    double strain_energy = 0;
    // Rayleigh damping C v = alpha M v + beta K v, from the velocity at
    // hand when the forces are evaluated (the half-step velocity), so that
    // the scheme stays explicit.
    const double alpha          = parameters.time.rayleigh_alpha;
    const double beta           = parameters.time.rayleigh_beta;
    const bool   damped         = alpha > 0 || beta > 0;
    double       damping_work   = 0;
    auto         update_damping = [&]() {
      if (!damped)
        return;
      damping_force = velocity;
      damping_force.scale(mass);
      damping_force *= alpha;
      if (beta > 0)
        {
          bulk->apply(velocity, stiffness_velocity);
          hanging->condense(stiffness_velocity);
          damping_force.add(beta, stiffness_velocity);
        }
    };
    // Forces, reaction and acceleration of the state in `solution` at t.
    auto evaluate = [&](const double t) {
      {
        TimerOutput::Scope scope(timer, "internal forces");
        strain_energy = bulk->apply(solution, force, true);
        hanging->condense(force);
      }
      if (damped)
        force += damping_force;
      // Without loaded cells `load` stays the zero of its layout.
      if (any_loaded)
        {
          TimerOutput::Scope scope(timer, "loads");
          assembler.assemble_load(loads, t, loaded_cells, load);
          hanging->condense(load);
        }
      // The impactor's forces stay out of `load`: their work is the
      // exchange with the sphere, not external work. They join the
      // internal force as damping does (once per step, not per entry).
      if (impactor)
        {
          TimerOutput::Scope scope(timer, "contact");
          impactor->evaluate(solution, contact);
          hanging->condense(contact);
          force -= contact;
        }
      // Contact between the bodies: internal to the laminate, like the
      // cohesive tractions.
      if (body_contact)
        {
          TimerOutput::Scope scope(timer, "body contact");
          body_contact->evaluate(solution, body_force);
          hanging->condense(body_force);
          force -= body_force;
        }
      // One pass over the owned entries (all four vectors share the
      // layout): a = (f_ext - f_int) / m on free dofs, the reaction
      // f_int - f_ext on the supports.
      const double *f_int = force.begin(), *f_ext = load.begin(),
                   *inverse_mass = free_inverse_mass.begin(),
                   *support      = support_mask.begin();
      double *a = acceleration.begin(), *r = reaction.begin();
      for (std::size_t i = 0; i < force.locally_owned_size(); ++i)
        {
          const double residual = f_int[i] - f_ext[i];
          a[i]                  = -residual * inverse_mass[i];
          r[i]                  = residual * support[i];
        }
    };

    // The energy the run starts with (initial velocity, prescribed
    // displacement at t = 0) enters the balance beside the external work.
    double external_work = 0, initial_energy = 0;
    // What the mesh changes did to the stored and kinetic energy (moved
    // fields, new lumped masses): beside the external work in the balance.
    double     remeshing_energy = 0;
    const bool adaptive         = parameters.adaptivity.during_history();
    auto       kinetic_energy   = [&]() {
      momentum = velocity;
      momentum.scale(free_mass);
      return 0.5 * (momentum * velocity);
    };
    // The linear momentum of the free nodes, per component.
    auto linear_momentum = [&]() {
      std::array<double, dim> p{};
      for (const auto i : owned)
        p[dof_layer.component(i)] += free_mass(i) * velocity(i);
      for (auto &value : p)
        value = Utilities::MPI::sum(value, comm);
      return p;
    };
    // The work of the interface and crack tractions (collective).
    auto interface_work = [&]() {
      double work = 0;
      if (interfaces)
        for (const auto &l : interfaces->ledger(comm))
          work += l.work;
      return work;
    };
    // The penalty energy of the contact between the bodies.
    auto body_contact_energy
      = [&]() { return body_contact ? body_contact->contact_energy() : 0.; };
    // A mesh change moves the sphere's contact to the new face's nodes.
    const auto sphere_contact_energy
      = [&]() { return impactor ? impactor->contact_energy() : 0.; };
    // What a crack insertion or a mesh change may change besides the
    // kinetic energy (collective).
    const auto stored_energy = [&]() {
      return strain_energy + interface_work() + body_contact_energy()
             + sphere_contact_energy();
    };
    auto ledger_row = [&](const double t_row) {
      relevant_solution                                   = solution;
      const double                                kinetic = kinetic_energy();
      std::vector<std::pair<std::string, double>> columns
        = {{"external_work", external_work},
           {"kinetic_energy", kinetic},
           {"strain_energy", strain_energy}};
      const double interface_work = add_interface_columns(columns);
      if (damped)
        columns.emplace_back("damping_work", damping_work);
      if (adaptive)
        columns.emplace_back("remeshing_energy", remeshing_energy);
      double impactor_energy = 0;
      if (impactor)
        {
          // The stick springs' energy is in the contact energy.
          impactor_energy = impactor->kinetic_energy()
                            + impactor->contact_energy()
                            + impactor->friction_dissipation();
          columns.emplace_back("impactor_kinetic", impactor->kinetic_energy());
          columns.emplace_back("contact_energy", impactor->contact_energy());
          // Laminate and sphere together along the face normal.
          const unsigned int axis = parameters.impactor.boundary_id / 2;
          columns.emplace_back("momentum",
                               linear_momentum()[axis]
                                 + impactor->momentum()[axis]);
          const auto more = impactor->columns(t_row);
          columns.insert(columns.end(), more.begin(), more.end());
        }
      double contact_and_friction = 0;
      if (body_contact)
        {
          contact_and_friction = body_contact->contact_energy()
                                 + body_contact->friction_dissipation();
          columns.emplace_back("body_contact_energy",
                               body_contact->contact_energy());
          columns.emplace_back("friction_dissipation",
                               body_contact->friction_dissipation());
          const auto more = body_contact->columns();
          columns.insert(columns.end(), more.begin(), more.end());
          // Contact keeps the momentum of the free nodes (supports
          // excepted): it is in the history to show it.
          const auto p = linear_momentum();
          for (unsigned int d = 0; d < dim; ++d)
            columns.emplace_back(std::string("momentum_") + "xyz"[d], p[d]);
        }
      columns.emplace_back("balance_error",
                           initial_energy + external_work + remeshing_energy
                             - kinetic - strain_energy - interface_work
                             - damping_work - impactor_energy
                             - contact_and_friction);
      return columns;
    };

    if (interfaces)
      interfaces->set_time_step(dt);
    double        t = 0;
    ExplicitState state;
    // The crack check's ghosted displacement, every step.
    GhostImport ghost_import;
    state.dt = dt;
    // last_good: the state of the last output step, written if the run
    // diverges.
    state.vectors = {{"last_good", &last_good},
                     {"displacement", &solution},
                     {"velocity", &velocity},
                     {"acceleration", &acceleration},
                     {"load", &load},
                     {"reaction", &reaction},
                     {"damping_force", &damping_force}};
    if (restart)
      {
        restore_explicit(state);
        // A run resumed with the loads taken out of its parameters.
        if (!any_loaded)
          load = 0;
        relevant_solution = solution;
        strain_energy     = state.strain_energy;
        external_work     = state.external_work;
        damping_work      = state.damping_work;
        initial_energy    = state.initial_energy;
        remeshing_energy  = state.remeshing_energy;
        t = state.base_t + (state.steps - state.base_steps) * dt;
        if (impactor)
          impactor->set_state(state.impactor);
        if (impactor && impactor->has_friction())
          impactor->set_friction_state(state.impactor_friction);
        if (body_contact)
          body_contact->set_state(state.body_contact);
      }
    else
      {
        impose_prescribed(t, solution);
        set_initial_velocity(free_inverse_mass, velocity);
        update_damping();
        // A prescribed sphere starts where its path is at t = 0.
        if (impactor && impactor->is_prescribed())
          impactor->move_to(t);
        evaluate(t);
        initial_energy = strain_energy + kinetic_energy();
        if (body_contact)
          initial_energy += body_contact->contact_energy();
        if (impactor)
          {
            // Touching is allowed, as in static runs: a sphere placed on
            // the face may overlap it by the round-off of its centre.
            if (impactor->penetration_depth()
                > 1e-12 * parameters.impactor.radius)
              throw InputError(
                "Impactor/Center",
                "the impactor overlaps the laminate at t = 0 (by "
                  + number_text(impactor->penetration_depth())
                  + " mm); start it clear of the face");
            initial_energy += impactor->kinetic_energy();
          }
        postprocess(0, t, reaction, ledger_row(t));
        last_good = solution;
      }
    unsigned int  last_good_step = state.last_good_step;
    double        last_good_t    = state.last_good_t;
    unsigned long n              = state.steps;
    // The steps of the current size count from the last mesh change.
    unsigned long base_steps = state.base_steps;
    unsigned int  base_row   = state.base_row;
    double        base_t     = state.base_t;
    const auto    save       = [&](CheckpointData &run, CheckpointData &part) {
      state.steps            = n;
      state.dt               = dt;
      state.strain_energy    = strain_energy;
      state.external_work    = external_work;
      state.damping_work     = damping_work;
      state.initial_energy   = initial_energy;
      state.last_good_step   = last_good_step;
      state.last_good_t      = last_good_t;
      state.base_steps       = base_steps;
      state.base_row         = base_row;
      state.base_t           = base_t;
      state.remeshing_energy = remeshing_energy;
      if (impactor)
        state.impactor = impactor->state();
      if (impactor && impactor->has_friction())
        state.impactor_friction = impactor->friction_state();
      if (body_contact)
        state.body_contact = body_contact->state();
      save_explicit(state, run, part);
    };
    const unsigned long n_start = n;
    // A progress line at most every 10 s of wall time, and at the end.
    using Clock                      = std::chrono::steady_clock;
    const Clock::time_point started  = Clock::now();
    Clock::time_point       reported = started;
    const unsigned int      n_out    = parameters.time.n_steps;
    auto report_progress = [&](const unsigned int out, const double t) {
      const Clock::time_point now = Clock::now();
      if (std::chrono::duration<double>(now - reported).count() < 10
          && out < n_out)
        return;
      reported = now;
      const double rate
        = (n - n_start) / std::chrono::duration<double>(now - started).count();
      pcout << "  t = " << t << " s (" << 100. * out / n_out << " %), " << n
            << " steps, " << rate << " steps/s, about "
            << (n_out - out) * substeps / rate << " s to go" << std::endl;
    };
    // Write the fields of the last output step and stop with @p what.
    const auto stop_with_last_good = [&](const std::string &what) {
      relevant_solution = last_good;
      write_fields(last_good_step, last_good_t);
      std::ostringstream message;
      message << what
              << "; the fields of the last output step (t=" << last_good_t
              << " s) are written";
      throw CollectiveError(message.str());
    };
    // What a mesh change did to the state.
    struct MeshChange
    {
      bool                    by_estimate    = false;
      double                  zz_relative    = -1;
      double                  kinetic_before = 0, kinetic_after = 0;
      double                  energy_before = 0, energy_after = 0;
      std::array<double, dim> momentum_before{}, momentum_after{};
      ExplicitTransferReport  report;
      std::vector<typename CohesiveInterfaces<dim>::Ledger> ledger_before,
        ledger_after;
    };
    // A row of adaptivity.csv and a console line per mesh change.
    const auto log_mesh_change
      = [&](const unsigned int row, const double t, const MeshChange &change) {
          if (!cycle_summary)
            cycle_summary = std::make_unique<History>(
              parameters.output.directory + "/adaptivity.csv",
              Utilities::MPI::this_mpi_process(comm) == 0);
          std::vector<std::pair<std::string, double>> columns
            = {{"step", row},
               {"t", t},
               {"cells", triangulation.n_global_active_cells()},
               {"unknowns", dof_layer.n_dofs()},
               {"by_estimate", change.by_estimate ? 1. : 0.},
               {"zz_relative_error", change.zz_relative},
               {"coarsened_cells", change.report.coarsened_cells},
               {"momentum_dofs", change.report.momentum_dofs},
               {"stable_time_step", stable},
               {"time_step", dt},
               {"kinetic_before", change.kinetic_before},
               {"kinetic_after", change.kinetic_after},
               {"energy_change", change.energy_after - change.energy_before}};
          for (unsigned int d = 0; d < dim; ++d)
            {
              const std::string axis(1, "xyz"[d]);
              columns.emplace_back("momentum_" + axis + "_before",
                                   change.momentum_before[d]);
              columns.emplace_back("momentum_" + axis + "_after",
                                   change.momentum_after[d]);
            }
          columns.emplace_back("remeshing_energy", remeshing_energy);
          if (remeshes())
            {
              columns.emplace_back("kinetic_old_field",
                                   change.report.kinetic_old_field);
              for (const auto &column : last_remeshing.columns())
                columns.push_back(column);
            }
          if (interfaces)
            {
              const auto transfer
                = interface_transfer_columns(change.ledger_before,
                                             change.ledger_after,
                                             change.report.interfaces);
              columns.insert(columns.end(), transfer.begin(), transfer.end());
            }
          cycle_summary->add_row(columns);
          pcout << "  adapted after output step " << row << " (t=" << t
                << " s): " << triangulation.n_global_active_cells()
                << " cells, " << dof_layer.n_dofs() << " unknowns, "
                << change.report.momentum_dofs
                << " velocities from the momentum; stored and kinetic "
                   "energy changed by "
                << change.energy_after - change.energy_before << " N mm"
                << std::endl;
        };
    // The output steps left, at the current step size.
    const auto steps_total = [&]() {
      return base_steps
             + static_cast<unsigned long>(substeps) * (n_out - base_row);
    };
    while (n < steps_total())
      {
        const unsigned int out = base_row + (n - base_steps) / substeps + 1;
        {
          TimerOutput::Scope scope(timer, "time steps");
          previous_load     = load;
          previous_reaction = reaction;
          previous_damping  = damping_force;
          velocity.add(0.5 * dt, acceleration);
          hanging->distribute(velocity);
          old_solution = solution;
          solution.add(dt, velocity);
          hanging->distribute(solution);
          const bool free_sphere = impactor && !impactor->is_prescribed();
          if (free_sphere)
            {
              impactor->kick(0.5 * dt);
              impactor->drift(dt);
            }
          ++n;
          t = base_t + (n - base_steps) * dt;
          // A prescribed sphere moves to where it is at t; it does the
          // work of its mean force over the move (as in static runs).
          Tensor<1, dim> sphere_move, sphere_force;
          try
            {
              if (impactor && !free_sphere)
                {
                  sphere_force = impactor->force_on_laminate();
                  sphere_move  = impactor->step_to(t, dt);
                }
              impose_prescribed(t, solution);
              update_damping();
              evaluate(t);
            }
          catch (const NonFiniteValue &e)
            {
              stop_with_last_good(e.what());
            }
          velocity.add(0.5 * dt, acceleration);
          if (free_sphere)
            impactor->kick(0.5 * dt);
          else if (impactor)
            external_work
              += impactor->finish_step(sphere_force, sphere_move, dt);
          displacement_step = solution;
          displacement_step -= old_solution;
          previous_load += load;
          previous_reaction += reaction;
          external_work += 0.5
                           * (previous_load * displacement_step
                              + previous_reaction * displacement_step);
          if (damped)
            {
              previous_damping += damping_force;
              damping_work += 0.5 * (previous_damping * displacement_step);
            }
          // A step above the critical one shows as strain energy
          // growing beyond all the energy the run was given; a NaN in the
          // response as a non-finite energy.
          if (!std::isfinite(strain_energy)
              || strain_energy
                   > 10 * (std::abs(external_work) + initial_energy + 1e-300))
            {
              std::ostringstream what;
              what << "the explicit solution diverged at t=" << t
                   << " s (strain energy " << strain_energy << " N mm against "
                   << external_work << " N mm of external work and "
                   << initial_energy
                   << " N mm at the start): reduce Time/Safety factor or "
                      "Time/Time step";
              stop_with_last_good(what.str());
            }
        }
        if (parameters.cracks.active)
          {
            // Every face that fails in the step cracks in it; the state
            // moves to the new numbering, and the forces and the
            // acceleration are those of the cracked body.
            std::vector<FailingFace> chosen;
            {
              TimerOutput::Scope scope(timer, "crack check");
              ghost_import(solution, relevant_solution);
              chosen = faces_to_crack(std::numeric_limits<unsigned int>::max());
            }
            if (!chosen.empty())
              {
                TimerOutput::Scope scope(timer, "crack insertion");
                const double       before = kinetic_energy() + stored_energy();
                insert_explicit_cracks(chosen,
                                       {&solution, &velocity, &last_good});
                layout(false);
                lump_mass(true);
                split_mass();
                build_operators(true);
                if (body_contact)
                  body_contact->setup(dof_layer,
                                      released_faces(),
                                      paired_faces());
                // A split node's copies share its face area, so each
                // takes its part of the contact spring: the contact
                // energy stays.
                if (impactor)
                  impactor->setup(dof_layer);
                update_damping();
                evaluate(t);
                const double after = kinetic_energy() + stored_energy();
                log_crack_event(
                  {{"time", t},
                   {"step", static_cast<double>(n)},
                   {"faces", chosen.size()},
                   {"crack_faces", interfaces->n_crack_faces()},
                   {"unknowns", dof_layer.n_dofs()},
                   {"hoffman", chosen.front().hoffman},
                   {"energy_before", before},
                   {"energy_after", after},
                   {"energy_jump",
                    (after - before)
                      / std::max(std::abs(initial_energy + external_work),
                                 1e-300)}});
              }
          }
        // A signal stops the run after a time step; the rest of the
        // checkpoints fall on output steps.
        const bool at_row = (n - base_steps) % substeps == 0;
        if (at_row)
          {
            postprocess(out, t, reaction, ledger_row(t));
            report_progress(out, t);
            last_good      = solution;
            last_good_step = out;
            last_good_t    = t;
          }
        // Between rows a signal is looked for every 10 steps: the check
        // is a reduction over the ranks.
        if (at_row && adaptive && out < n_out)
          {
            // The output step is written: a new mesh starts the next.
            adapt_state(
              out,
              t,
              solution,
              [&](const bool by_estimate, const double zz_relative) {
                // prepare() takes a consistent velocity.
                hanging->distribute(velocity);
                MeshChange change;
                change.by_estimate    = by_estimate;
                change.zz_relative    = zz_relative;
                change.kinetic_before = kinetic_energy();
                change.energy_before  = change.kinetic_before + stored_energy();
                change.momentum_before = linear_momentum();
                if (interfaces)
                  change.ledger_before = interfaces->ledger(comm);
                change.report
                  = move_explicit_state({&solution, &last_good}, velocity);
                if (!change.report.changed)
                  return;
                layout(false);
                lump_mass();
                split_mass();
                // The momentum rule gives supported nodes the mean of
                // their neighbours' velocity; a fixed mesh keeps them at
                // rest (their acceleration is zero), and so does this.
                if (remeshes())
                  {
                    for (const auto i : owned)
                      if (support_mask(i) != 0)
                        velocity(i) = 0;
                    velocity.compress(VectorOperation::insert);
                  }
                build_operators();
                // The sphere keeps its centre and velocity; its
                // contact nodes are those of the new face.
                if (impactor)
                  impactor->setup(dof_layer);
                // The surfaces of the new mesh, their stick
                // springs carried by place; before the step,
                // which their penalties bound.
                if (body_contact)
                  body_contact->setup(dof_layer,
                                      released_faces(),
                                      paired_faces(),
                                      true);
                choose_step();
                if (interfaces)
                  interfaces->set_time_step(dt);
                base_steps = n, base_row = out, base_t = t;
                impose_prescribed(t, solution);
                update_damping();
                evaluate(t);
                change.kinetic_after  = kinetic_energy();
                change.energy_after   = change.kinetic_after + stored_energy();
                change.momentum_after = linear_momentum();
                if (interfaces)
                  change.ledger_after = interfaces->ledger(comm);
                remeshing_energy += change.energy_after - change.energy_before;
                log_mesh_change(out, t, change);
              });
          }
        if (at_row || n % 10 == 0)
          checkpoint_after_step(out, n, at_row, n == steps_total(), save);
      }
    if (body_contact && body_contact->n_evaluations > 0)
      pcout << "  body contact: " << body_contact->n_faces()
            << " surface faces, search " << body_contact->search_seconds
            << " s, all contact work " << body_contact->evaluate_seconds
            << " s over " << body_contact->n_evaluations << " evaluations ("
            << body_contact->n_rebuilds << " candidate searches taking "
            << body_contact->rebuild_seconds << " s, "
            << 1e6 * body_contact->search_seconds / body_contact->n_evaluations
            << " us of search per evaluation)" << std::endl;
    timer.print_wall_time_statistics(comm);
  }

  template void
  Simulator<2>::run_explicit();
  template void
  Simulator<3>::run_explicit();
} // namespace amfrac

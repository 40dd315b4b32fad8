#pragma once

#include <amfrac/adaptivity/error_estimator.h>
#include <amfrac/adaptivity/explicit_state_transfer.h>
#include <amfrac/adaptivity/history_transfer.h>
#include <amfrac/adaptivity/mesh_transfer.h>
#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/assembly/face_hoffman_screen.h>
#include <amfrac/assembly/lever.h>
#include <amfrac/assembly/loads.h>
#include <amfrac/assembly/plastic_plies.h>
#include <amfrac/assembly/total_lagrangian.h>
#include <amfrac/checkpoint/checkpoint_store.h>
#include <amfrac/cohesive/interface_assembler.h>
#include <amfrac/contact/body_contact.h>
#include <amfrac/contact/rigid_impactor.h>
#include <amfrac/dofs/hanging_condensation.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/geometry/laminate.h>
#include <amfrac/material/ply_table.h>
#include <amfrac/parameters/parameters.h>
#include <amfrac/postprocess/field_output.h>
#include <amfrac/postprocess/history.h>
#include <amfrac/postprocess/interface_output.h>
#include <amfrac/postprocess/point_probe.h>
#include <amfrac/solvers/buckling_eigensolver.h>
#include <amfrac/solvers/linear_solver.h>
#include <array>
#include <cstdint>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools_common.h>
#include <functional>
#include <map>
#include <memory>
#include <set>

namespace amfrac
{
  /** A displacement prescribed on the nodes of one boundary id. */
  template <int dim>
  struct PrescribedDisplacement
  {
    std::string                    name;
    types::boundary_id             boundary_id;
    std::shared_ptr<Function<dim>> value;
    std::array<bool, dim>          components;
    /** Optional: component c is prescribed only at nodes where component
     * c of this function is nonzero (nullptr: everywhere on the face). */
    std::shared_ptr<Function<dim>> where;
  };

  /**
   * A static (load-stepped) run of a laminate: mesh, tied-copy DoF layer,
   * bulk assembly, linear solve, output. Everything that the scene does not
   * need is not built.
   */
  template <int dim>
  class Simulator
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** Builds the mesh and validates every input that depends on it;
     * throws InputError before anything is written. */
    Simulator(const parameters::Parameters &parameters, const MPI_Comm comm);

    /** Replace the body force (e.g. a manufactured solution). */
    void
    set_body_force(const std::shared_ptr<Function<dim>> &force);

    /** Replace all prescribed displacements. */
    void
    set_prescribed_displacements(
      const std::vector<PrescribedDisplacement<dim>> &conditions);

    /** Solve every load step and write the output. Throws
     * RunInterrupted after writing a checkpoint on SIGTERM or SIGINT (or
     * at Checkpoint/Stop after step). */
    void
    run();

    /** Continue from @p checkpoint (read by CheckpointStore::read()): the
     * mesh is refined as it was now, run() restores the state and
     * continues after the checkpoint's step. The checkpoint must come from
     * a run of the same scene (InputError otherwise). */
    void
    resume(const CheckpointStore::Contents &checkpoint);

    /** Wall time [s] spent writing checkpoints so far. */
    double
    checkpoint_seconds() const
    {
      return seconds_in_checkpoints;
    }

    /** The displacement on the copy layer (locally owned cells). */
    const dealii::Vector<double> &
    copy_solution() const
    {
      return copy_values;
    }

    const TiedCopyDoFs<dim> &
    dofs() const
    {
      return dof_layer;
    }

    const History &
    history() const
    {
      return *summary;
    }

    /** Explicit runs: the estimated stable time step (0 before run()). */
    double
    estimated_stable_time_step() const
    {
      return estimated_stable_step;
    }

    /** Explicit runs with mass scaling: the mass added [t]. */
    double
    mass_added_by_scaling() const
    {
      return added_mass;
    }

    /** The cohesive interfaces (nullptr if the scene has none). */
    const CohesiveInterfaces<dim> *
    cohesive_interfaces() const
    {
      return interfaces.get();
    }

    /** The interface points of this rank at the last converged state
     * (empty without cohesive interfaces). */
    std::vector<InterfacePointRecord<dim>>
    interface_points() const
    {
      return interfaces ? interfaces->output_points(relevant_solution) :
                          std::vector<InterfacePointRecord<dim>>();
    }

    /** Adaptive runs: adaptivity.csv (one row per cycle, or per mesh
     * change during a load history); nullptr before the first. */
    const History *
    adaptivity_history() const
    {
      return cycle_summary.get();
    }

    /** Crack insertion: cracks.csv (one row per insertion event);
     * nullptr before the first. */
    const History *
    crack_history() const
    {
      return crack_events.get();
    }

    /** Buckling analyses: buckling.csv (one row per mode); nullptr
     * before the analysis. */
    const History *
    buckling_history() const
    {
      return buckling_summary.get();
    }

    /** Adaptive runs: the estimate of the last cycle. */
    const typename ErrorEstimator<dim>::Estimate &
    error_estimate() const
    {
      return last_estimate;
    }

    /** The ZZ and the true error in the energy norm of the last step
     * against @p exact (dim components with gradients). */
    std::pair<double, double>
    energy_errors(const Function<dim> &exact) const;

    /** Global norm of (u_h - exact) of the last step. */
    double
    compute_error(const Function<dim>        &exact,
                  const VectorTools::NormType norm) const;

  private:
    const parameters::Parameters         parameters;
    const MPI_Comm                       comm;
    ConditionalOStream                   pcout;
    mutable TimerOutput                  timer;
    parallel::shared::Triangulation<dim> triangulation;
    Laminate                             laminate;
    std::vector<PlyProperties<dim>>      plies;
    TiedCopyDoFs<dim>                    dof_layer;
    ElasticAssembler<dim>                assembler;
    /** Kinematics = total Lagrangian (nullptr: small strain). */
    std::unique_ptr<TotalLagrangianAssembler<dim>> finite_strain;
    /** Plies with Materials/Plasticity = hoffman (nullptr: none). */
    std::unique_ptr<PlasticPlies<dim>> plasticity;
    /** Why the plies' return mapping failed in the last residual (empty
     * if it did not), the same on every rank. */
    std::string plastic_failure;
    /** The residual of a state just moved to a new mesh: the plies'
     * stress C (eps - eps_p) as transferred, without return mapping (the
     * start of the trapezoidal rules of the next step). */
    bool       as_transferred = false;
    Loads<dim> loads;
    double     estimated_stable_step = 0;
    /** Explicit mass scaling: the added mass [t] and the uniform factor
     * of all masses (1: none). */
    double                                   added_mass          = 0;
    double                                   uniform_mass_factor = 1;
    std::vector<PrescribedDisplacement<dim>> prescribed;
    Lever<dim>                               lever;
    std::unique_ptr<PointProbe<dim>>         probe;
    std::unique_ptr<History>                 summary;
    std::unique_ptr<FieldOutput<dim>>        field_output;
    std::unique_ptr<InterfaceOutput<dim>>    interface_output;
    std::unique_ptr<CohesiveInterfaces<dim>> interfaces;
    /** Runs with an Impactor subsection (nullptr otherwise): a free sphere
     * in explicit runs, a prescribed one in static runs. */
    std::unique_ptr<RigidImpactor<dim>> impactor;
    /** Runs with Contact/Enable (nullptr otherwise). */
    std::unique_ptr<BodyContact<dim>> body_contact;
    /** Crack insertion: where faces may crack (nullptr without crack
     * insertion), and the strength factor of every face (face f of active
     * cell c at c * faces_per_cell + f), evaluated once in a fixed order
     * on every rank, so that a random field (rand_seed()) is one fixed
     * field, the same on all ranks. */
    std::shared_ptr<Function<dim>> crack_region;
    std::vector<double>            crack_strength_scale;
    /** The crack check's candidates (crack_candidate()), found once per
     * mesh rather than per check: per active cell a bit per face, and the
     * owned cells with a bit set when they were found. An insertion
     * clears its faces' bits; a mesh change forgets them
     * (forget_crack_candidates()), and the next check finds them again. */
    mutable bool                      candidates_found = false;
    mutable std::vector<std::uint8_t> candidate_faces;
    mutable std::vector<typename DoFHandler<dim>::active_cell_iterator>
      candidate_cells;
    /** The first round of the crack check on candidate_cells, built with
     * them. */
    mutable std::unique_ptr<FaceHoffmanScreen<dim>> crack_screen;
    /** The strength scale of every regular interior face (both sides),
     * by CellId and face. */
    using FaceValues = std::map<std::pair<CellId, unsigned int>, double>;
    FaceValues
    strength_scale_by_face() const;
    /** Evaluate Crack insertion/Strength scale on every regular interior
     * face (InputError unless positive and finite). After a mesh change
     * (@p previous: the values before it) a face keeps its value and the
     * children of a face take their parent's; only new faces (inside a
     * refined cell, of a coarsened cell, or no longer hanging) are
     * evaluated, so that remeshing does not draw a random field again. */
    void
    evaluate_strength_scale(const FaceValues *previous = nullptr);

    AffineConstraints<double> constraints;
    /** Per prescribed condition: the reduced dofs on its face (and Where)
     * of its components, on the whole mesh; then, with a lever, all the
     * lever's dofs (whose reactions do its work). */
    std::vector<std::vector<types::global_dof_index>> supports;
    TrilinosWrappers::SparseMatrix                    system_matrix;
    Vector                                            solution;
    Vector                                            relevant_solution;
    Vector                                            system_rhs;
    dealii::Vector<double>                            copy_values;

    /** The Newton path (scenes with cohesive interfaces). */
    struct NewtonState
    {
      /** The supports and hanging nodes with zero values: the constraints
       * of a Newton increment. */
      AffineConstraints<double> increment_constraints;
      /** Small strain: the bulk stiffness, condensed and unconstrained.
       * Total Lagrangian: only the unconstrained tangent of the last
       * state update_residual() assembled a tangent for. */
      TrilinosWrappers::SparseMatrix bulk_condensed;
      TrilinosWrappers::SparseMatrix bulk_unconstrained;
      /** Total Lagrangian: the strain energy of the last update_residual()
       * state. */
      double strain_energy = 0;
      Vector converged_solution;
      Vector external_load;
      /** K u + F_interfaces(u) - f, with the entries of hanging dofs handed
       * to their masters (C^T of the hanging constraints alone): its
       * entries on supports are the reactions, including what the
       * hanging dofs next to a support hand to it. */
      Vector residual;
      /** The hanging constraints of the mesh (null without hanging
       * dofs). */
      std::unique_ptr<HangingCondensation<dim>> hanging;
      Vector                                    condensed_residual;
      Vector                                    interface_force;
      /** Plastic plies: int B^T (sigma - C eps) (ghost entries writable)
       * and the plastic work of the run so far. */
      Vector plastic_force;
      double plastic_work = 0;
      Vector increment;
      /** Force scale of the convergence test (reactions and loads). */
      double force_scale = 0;
      /** For the trapezoidal external work. */
      Vector previous_residual;
      Vector previous_load;
      double external_work = 0;
      /** What the transfers to new meshes changed in the stored energy
       * (bulk strain energy plus the interfaces' work), and the work of
       * the out-of-balance forces of a transferred state while it
       * settles in the step after: a mesh change does no external work,
       * so the balance counts it separately. */
      double remeshing_energy = 0;
      /** The state was moved to a new mesh and the next converged step
       * has not been booked yet (its out-of-balance work goes to
       * remeshing_energy; other steps keep theirs in the balance error,
       * which then still shows the Newton tolerance). */
      bool settling = false;
      /** Crack insertion: a new crack starts from the mean stress at each
       * of its points, which does not balance the bulk's nodal forces on
       * the split nodes where the stress varies (and the points of an
       * older crack's tip keep their traction). The converged state on
       * the cracked mesh is then out of balance at free dofs; the work of
       * those forces while it settles in the re-solved step is booked
       * here (with insertion_settling), as for a mesh change. */
      double insertion_energy   = 0;
      bool   insertion_settling = false;
      /** Dissipation control: the prescribed displacements at t = 1
       * (hanging nodes interpolated), K_T of it (unconstrained, then
       * condensed), a second Newton direction, and the force conjugate to
       * t of the converged state. */
      Vector load_pattern;
      Vector pattern_response;
      Vector pattern_condensed;
      Vector pattern_increment;
      double converged_force = 0;
      /** Path following with loads (arc-length): the loads at t = 1 (they
       * are proportional to t); zero without loads. */
      Vector load_unit;
      /** Arc-length: the displacement increment of the last converged
       * step (the direction the path continues in), |du/dt| of the first
       * step (q, the load parameter's scale) and the nominal step
       * length (that of a nominal step of t on the first step). */
      Vector arc_previous;
      double arc_scale   = 0;
      double arc_nominal = 0;
      /** A prescribed sphere: its forces on the laminate (owned entries),
       * and its total force and centre at the last converged step (for the
       * trapezoidal work of what drives it, part of external_work). */
      Vector         contact_force;
      Tensor<1, dim> sphere_force, sphere_center;
      /** Contact between the bodies: their forces (owned entries). */
      Vector body_contact_force;
    };
    /** Adaptivity: the current cycle, the estimate of its last step
     * (the marking criterion), its zz estimate (reported), the last
     * history row, the per-cycle summary and the run's clock. */
    unsigned int                                cycle = 0;
    typename ErrorEstimator<dim>::Estimate      last_estimate;
    typename ErrorEstimator<dim>::Estimate      last_zz;
    std::vector<std::pair<std::string, double>> last_row;
    std::unique_ptr<History>                    cycle_summary;
    /** The active cells of the initial mesh (global and region
     * refinements): adaptivity never coarsens below them. */
    std::set<CellId> initial_cells;
    /** cracks.csv: one row per crack insertion event. */
    std::unique_ptr<History> crack_events;
    std::unique_ptr<History> buckling_summary;
    /** The lowest positive load factor of the last buckling analysis (0:
     * none). */
    double lowest_load_factor = 0;
    /** Buckling analyses written so far, and the next of
     * Buckling/Analysis times to do. */
    unsigned int buckling_analyses  = 0;
    std::size_t  next_analysis_time = 0;
    Timer        clock;
    /** Global remeshing (prisms): the last event (reported with the next
     * cycle, or in the row of a remeshing during a load history), whether
     * Adaptivity/Maximum cells stopped the remeshing during a load
     * history, and the solution carried to the new mesh (tau_2), the first
     * guess of the next solve. */
    struct RemeshingEvent
    {
      double zz_relative_before = 0;
      double predicted_cells    = 0;
      double smallest_size      = 0;
      double mesh_seconds       = 0;
      double transfer_seconds   = 0;
      /** |E(tau_2 u) / E(u) - 1| for the energy norms E on the new and
       * the old mesh. */
      double       energy_change = 0;
      unsigned int outside       = 0;
      /** During a load history: the relative ZZ error of the first
       * estimate on the new mesh (what the remeshing reached), NaN until
       * then; -1 before the first remeshing. */
      double zz_relative_reached = -1;

      /** The columns of adaptivity.csv common to a cycle's and a load
       * history's remeshing. */
      std::vector<std::pair<std::string, double>>
      columns() const
      {
        return {{"predicted_cells", predicted_cells},
                {"smallest_size", smallest_size},
                {"remesh_seconds", mesh_seconds},
                {"transfer_seconds", transfer_seconds},
                {"transfer_points_outside", double(outside)}};
      }
    };
    RemeshingEvent last_remeshing;
    bool           cell_budget_spent = false;
    /** The in-plane mesh of the last remeshing (empty before one): what a
     * checkpoint keeps to rebuild the mesh, which no refinement of the
     * first mesh gives. */
    PlaneMesh remeshed_plane;
    /** The process-zone rule on wedges: the size per active cell the next
     * remeshing meshes to (empty: the ZZ estimate's), and the largest
     * in-plane size of the first mesh, which the field never exceeds
     * (as hexahedra are never coarsened below the first mesh). */
    std::vector<double> process_zone_sizes;
    double              first_mesh_size = 0;
    Vector              first_guess;

    /** Checkpoints: the store (nullptr for refinement cycles, which
     * cannot resume), the checkpoint being resumed from (nullptr on a
     * fresh start), the wall clock since the last one. */
    std::unique_ptr<CheckpointStore>           checkpoints;
    std::unique_ptr<CheckpointStore::Contents> restart;
    Timer                                      checkpoint_clock;
    /** Every mesh change of the run: the refine flags (dim bits per active
     * cell) and the coarsen flags, each as its bit count and 64-bit
     * words. A restart replays them on the initial mesh, which rebuilds
     * the mesh cell for cell in the same order, so that the numbering
     * and every sum are those of the run that went through. */
    std::vector<std::int64_t> mesh_changes;
    /** Append the flags set on the mesh to mesh_changes, then execute
     * them. */
    void
           execute_mesh_change();
    double seconds_in_checkpoints = 0;

    std::unique_ptr<NewtonState> newton;
    /** The linear solver of run_newton(), here so that setup_newton() can
     * release it before system_matrix changes (declared after
     * system_matrix: destroyed first). */
    std::unique_ptr<LinearSolver> newton_solver;
    bool                          solver_ready     = false;
    unsigned int                  n_factorizations = 0;

    struct NewtonReport
    {
      bool                converged = false;
      std::vector<double> residuals;
      /** Why the linear solver failed, if it did. */
      std::string failure;
    };

    /** The state of a path for a checkpoint: rank 0's run file and this
     * rank's part. */
    using StateWriter
      = std::function<void(CheckpointData &run, CheckpointData &part)>;
    /** After step @p step (a row of history.csv; @p at_row: false inside
     * an explicit output interval, where only a signal writes), as
     * checkpoint @p number: write one if Every n steps, Every minutes,
     * Stop after step, the last step (@p last, with Every n steps) or a
     * signal asks for it, with the path's state from @p save; then throw
     * RunInterrupted after a signal or at Stop after step. Collective. */
    void
    checkpoint_after_step(const unsigned int  step,
                          const unsigned long number,
                          const bool          at_row,
                          const bool          last,
                          const StateWriter  &save);
    /** Mesh, tables, output series and interface history. */
    void
    save_common(CheckpointData &run, CheckpointData &part) const;
    /** Tables, output series and interface history of the checkpoint
     * being resumed (the mesh was restored by resume()). */
    void
    restore_common();
    /** Replay the mesh changes of the checkpoint on the initial mesh, or
     * rebuild the mesh of its last remeshing. */
    void
    restore_mesh(const CheckpointData &run);
    /** Wedge meshes: the remeshing state (the cell budget, the stall
     * rule's errors) and the in-plane mesh of the last remeshing. */
    void
    save_remeshing(CheckpointData &run) const;
    /** The remeshing state of save_remeshing(); true if the mesh was
     * rebuilt from the checkpoint's in-plane mesh (a remeshed run). */
    bool
    restore_remeshing(const CheckpointData &run);
    /** InputError naming Kinematics if the checkpoint was written with
     * the other kinematics. */
    void
    check_kinematics(const CheckpointData &run) const;
    /** @p v cell by cell (locally owned cells, local dof order), so that
     * a restart reads it whatever the numbering or number of ranks. */
    void
    save_vector(CheckpointData    &part,
                const std::string &name,
                const Vector      &v) const;
    /** The owned entries of @p v (reinitialized to the owned dofs) from
     * the checkpoint being resumed. */
    void
    restore_vector(const std::string &name, Vector &v) const;
    /** The counters of the Newton loop that a checkpoint keeps. */
    struct NewtonProgress
    {
      double                    t = 0, dt = 0, dtau = 0;
      unsigned int              step = 0, total_iterations = 0;
      bool                      by_dissipation = false;
      std::vector<unsigned int> iterations;
      /** Crack insertion: faces still failing when the last step's rounds
       * (Rounds per step) ran out; the next step may then not be cut. */
      bool failures_left = false;
    };
    /** The Newton state (NewtonState's converged quantities) and
     * @p progress. */
    void
    save_newton(const NewtonProgress &progress,
                CheckpointData       &run,
                CheckpointData       &part) const;
    /** Restore what save_newton() wrote, after setup_newton(). */
    void
    restore_newton(NewtonProgress &progress);
    /** The plastic history of the owned cells from the checkpoint being
     * resumed (whatever the number of ranks that wrote it). */
    void
    restore_plastic_history();
    /** The state of an explicit run that a checkpoint keeps: the time
     * steps done, the scalars of the ledger and the vectors, by name. */
    struct ExplicitState
    {
      unsigned long steps = 0;
      double        dt = 0, strain_energy = 0;
      double        external_work = 0, damping_work = 0;
      double        initial_energy = 0;
      /** The output step whose state a divergence writes (the vector
       * "last_good"), and its time. */
      unsigned int last_good_step = 0;
      double       last_good_t    = 0;
      /** The last mesh change (at an output step; none: all zero): the
       * steps done and the output step and time it happened at, from which
       * the steps of the current size count. */
      unsigned long base_steps       = 0;
      unsigned int  base_row         = 0;
      double        base_t           = 0;
      double        remeshing_energy = 0;
      /** RigidImpactor::state() (empty without an impactor), and its
       * friction_state() (empty without friction). */
      std::vector<double> impactor, impactor_friction;
      /** BodyContact::state() (empty without contact). */
      std::vector<double>             body_contact;
      std::map<std::string, Vector *> vectors;
    };
    void
    save_explicit(const ExplicitState &state,
                  CheckpointData      &run,
                  CheckpointData      &part) const;
    /** Restore what save_explicit() wrote; the checkpoint's time step
     * must be @p state.dt (InputError otherwise). */
    void
    restore_explicit(ExplicitState &state);
    /** Checkpoints of a fresh run: the store, emptied; of a resumed run:
     * the store and the restored tables. */
    void
    prepare_checkpoints();

    void
    build_loads_and_supports();
    /** Geometry/Imperfection mode: the linear buckling mode of the
     * small-strain state at End time, scaled, added to the vertices of the
     * initial mesh, and everything that depends on them rebuilt (nothing
     * is written). */
    void
    seed_imperfection_from_mode();
    /** The lowest @p n_modes buckling modes of the small-strain state at
     * @p t (load factors and modes, positive factors only). */
    BucklingEigensolver::Result
    small_strain_buckling(const double t, const unsigned int n_modes);
    /** The lowest positive load factors and modes of (K + lambda K_G) v
     * = 0 with K_G of the stress of @p state (ghosted), K factorized in
     * @p solver, the rows @p fixed constrains left out. */
    BucklingEigensolver::Result
    buckling_eigenpairs(LinearSolver                         &solver,
                        const TrilinosWrappers::SparseMatrix &K,
                        const AffineConstraints<double>      &fixed,
                        const Vector                         &state,
                        const BucklingEigensolver::Settings  &settings);
    /** Move every vertex by @p displacement (all reduced dofs on this
     * rank): the mean of the values of its cells. */
    void
    move_vertices(const Vector &displacement);
    void
    make_probe();
    /** Refinement cycles of a linear scene (Adaptivity subsection). */
    void
    run_adaptive();
    /** The estimators on the current mesh and DoF layer. */
    ErrorEstimator<dim>
    error_estimator() const;
    /** Both estimates of the solution at @p t (ZZ always, Kelly if it
     * is the chosen estimator), into last_zz and last_estimate. */
    void
    estimate_error(const double t);
    /** Mark by the Adaptivity strategy and refine; false if no cell was
     * marked. */
    bool
    refine_mesh();
    /** Prisms: regenerate the mesh with Gmsh from the size field of the
     * ZZ error (RemeshingRule) and carry the solution to it; false if the
     * cell budget is spent. */
    bool
    remesh();
    /** What moves fields to a remeshed mesh: called with the transfer
     * from the old layer to the new one and the fields on the old layer
     * (in the order given to remesh_carrying()). */
    using Carry
      = std::function<void(const NonMatchingTransfer<dim> &,
                           const std::vector<dealii::Vector<double>> &)>;
    /** The mesh change of remesh(), between cycles and during a load
     * history: the new mesh from Gmsh for the last estimate's size field,
     * the DoF layer rebuilt on it, and @p carry called with @p copies (the
     * copy values of every cell of the old layer, TiedCopyDoFs::
     * expand_all()) on a copy of the old layer, to carry them to the new
     * one (tau_2); fills last_remeshing but its energy change. False,
     * with nothing changed, if the cell budget (Adaptivity/Maximum cells)
     * is spent. */
    bool
    remesh_carrying(const std::vector<dealii::Vector<double>> &copies,
                    const Carry                               &carry);
    /** The process-zone rule on wedges (Adaptivity/Process zone
     * elements): true, with process_zone_sizes filled, if a cell within
     * l_cz of a front is coarser than 1.5 l_cz / n; the sizes are
     * l_cz / n within 2 l_cz of the front and grow linearly (by half the
     * distance) to first_mesh_size beyond. */
    bool
    plan_process_zone_remeshing();
    /** Whether the mesh adapts by global remeshing (wedges). */
    bool
    remeshes() const
    {
      return !dof_layer.reference_cell().is_hyper_cube();
    }
    /** Flags by the Adaptivity strategy from last_estimate. */
    void
    mark_by_estimate();
    /** Clear flags beyond Maximum refinement level and below the initial
     * mesh; false if no flag is left. */
    bool
    limit_flags();
    /** Whether coarsening @p cell keeps the mesh at least as fine as the
     * initial one. */
    bool
    coarsenable(
      const typename Triangulation<dim>::active_cell_iterator &cell) const;
    /** Scenes with cohesive interfaces: after converged step @p step
     * (0: before the first) at @p t, refine and coarsen if Refine every,
     * Error threshold or the process-zone rule asks for it, and move the
     * converged state to the new mesh. */
    void
    adapt_during_history(const unsigned int step, const double t);
    /** What adapt_during_history() decides, for any path: whether Refine
     * every, Error threshold (ZZ of @p state, the displacement) or the
     * process-zone rule asks for a change after step @p step at @p t; if
     * so, flags the cells and calls @p change(by_estimate, zz_relative),
     * which must execute the flags and move the state (repeatedly for
     * the process-zone rule, one level per call). A wedge mesh is not
     * flagged: @p change remeshes it (remesh_carrying()). */
    void
    adapt_state(const unsigned int                                   step,
                const double                                         t,
                const Vector                                        &state,
                const std::function<void(const bool, const double)> &change);
    /** What a mesh change of an explicit run did. */
    struct ExplicitTransferReport
    {
      typename CohesiveInterfaces<dim>::TransferReport interfaces;
      unsigned int                                     coarsened_cells = 0;
      types::global_dof_index                          momentum_dofs   = 0;
      /** A remeshing: the kinetic energy of the old velocity field
       * integrated at the new mesh's points, which bounds the new one's
       * (NonMatchingTransfer::momentum()); -1 otherwise. */
      double kinetic_old_field = -1;
      /** False if nothing moved (a remeshing with the cell budget spent). */
      bool changed = true;
    };
    /** Explicit runs: execute the flags and move the displacement-like
     * @p fields (the displacement first) and the @p velocity to the new
     * mesh (ExplicitStateTransfer: nodal interpolation, momentum kept at
     * the nodes of coarsened cells), and the interface history (tau_1) if
     * there are interfaces. */
    ExplicitTransferReport
    move_explicit_state(const std::vector<Vector *> &fields, Vector &velocity);
    /** The cell budget (Adaptivity/Maximum cells) is spent: no more
     * remeshing during this run, and say so. */
    void
    stop_remeshing();
    /** move_explicit_state() on a wedge mesh: remesh_carrying(), the
     * fields by NonMatchingTransfer::nodal(), the velocity by its momentum
     * rule on the new lumped mass, the interface history by
     * CohesiveInterfaces::relocate(). */
    ExplicitTransferReport
    remesh_explicit_state(const std::vector<Vector *> &fields,
                          Vector                      &velocity);
    /** Make every refine flag a cut along the plies and refine coarser
     * cells at the vertices of flagged cells along the plies too, so that
     * deal.II never has to refine through the thickness. */
    void
    keep_refinement_in_plane();
    /** The process-zone rule: refine near the delamination fronts,
     * coarsen far from them (if nothing else marks). */
    void
    mark_process_zone(const bool coarsen);
    /** l_cz = 0.88 E_zz G_Ic / sigma_N^2 per cohesive interface (E_zz of
     * the ply below it). */
    std::vector<double>
    process_zone_lengths() const;
    /** Execute the flags and move the converged Newton state at @p t:
     * displacement by SolutionTransfer on the copy layer (tau_2),
     * interface history by CohesiveInterfaces::transfer() (tau_1). A
     * wedge mesh is remeshed instead (remesh_carrying(): displacement by
     * NonMatchingTransfer, interface history by
     * CohesiveInterfaces::relocate()); nothing changes once the cell
     * budget is spent.
     * adaptivity.csv logs what asked for the change: @p by_estimate
     * (Refine every or Error threshold) and the relative ZZ error of the
     * converged state if it was estimated (-1 otherwise). */
    void
    refine_and_transfer(const unsigned int step,
                        const double       t,
                        const bool         by_estimate,
                        const double       zz_relative);
    /** Plastic plies: tau_1 of the plastic history prepared for the
     * flags set on the mesh (nullptr without plastic plies). */
    std::unique_ptr<QuadratureHistoryTransfer<dim>>
    prepare_plastic_transfer() const;
    /** The transfer rule of each component of the plastic history across
     * a refinement, and with @p remeshing between unrelated meshes
     * (Adaptivity/Plastic history transfer). */
    std::vector<typename QuadratureHistoryTransfer<dim>::Rule>
    plastic_transfer_rules(const bool remeshing) const;
    /** Rebuild everything that depends on the mesh. */
    void
    setup_after_refinement();
    /** The faces the DoF layer leaves untied: cohesive interfaces, cracks
     * and unbonded interfaces (Contact/Unbonded interfaces). */
    typename TiedCopyDoFs<dim>::FaceFilter
    released_faces() const;
    /** Face @p face of @p cell lies on an unbonded interface
     * (Contact/Unbonded interfaces): the plies on its sides are separate
     * bodies. */
    bool
    is_unbonded(const typename Triangulation<dim>::cell_iterator &cell,
                const unsigned int                                face) const;
    /** The released faces with a cohesive partner (interfaces, cracks). */
    typename TiedCopyDoFs<dim>::FaceFilter
    paired_faces() const;
    /** The same without the timer section (inside the constructor's);
     * @p same_mesh: the mesh is that of the last call, and only the cracks
     * not built yet (CohesiveInterfaces::unbuilt_cracks()) were added. */
    void
    rebuild_after_mesh_change(const bool same_mesh = false);
    /** One row of adaptivity.csv and its console line. */
    void
    report_cycle();
    PatchLoad<dim>
    build_patch_load() const;
    void
    set_initial_velocity(const Vector &free_inverse_mass,
                         Vector       &velocity) const;
    /** A face the Hoffman criterion fails on: its lower cell (the smaller
     * CellId) and face, the Hoffman index of the mean stress of its two
     * cells at the face centre, and how well its normal matches the
     * largest principal stress direction. */
    struct FailingFace
    {
      typename Triangulation<dim>::cell_iterator cell;
      unsigned int                               face;
      double                                     hoffman;
      double                                     alignment;
    };
    /** Crack insertion: faces a crack may be inserted in (interior,
     * regular, inside one ply of Crack insertion/Plies, of the candidate
     * kind, in the region, not cracked yet). */
    bool
    crack_candidate(const typename Triangulation<dim>::cell_iterator &cell,
                    const unsigned int face) const;
    /** The faces to insert next, the most critical first, at most Faces
     * per round; the same on every rank (collective). */
    std::vector<FailingFace>
    faces_to_crack(const unsigned int max_faces) const;
    /** Fill candidate_faces and candidate_cells unless they are found. */
    void
    find_crack_candidates() const;
    /** After a mesh change (refinement, moved vertices). */
    void
    forget_crack_candidates();
    /** The interface elements after the DoF layer released new faces:
     * new cracks start from the mean traction of the two cells in
     * @p converged and take their onset from @p onset (both ghosted, on
     * the new numbering). */
    typename CohesiveInterfaces<dim>::CrackReport
    rebuild_crack_elements(const Vector &converged, const Vector &onset);
    /** Static runs, after an insertion round's residual at the converged
     * state: the new points' tractions balanced to it (Crack
     * insertion/Balance inserted tractions), the residual evaluated
     * again; the columns of cracks.csv (residuals over the rows the new
     * points act on, before and after). */
    std::vector<std::pair<std::string, double>>
    balance_inserted_tractions();
    /** Explicit runs: release @p chosen, rebuild the DoF layer and the
     * interface elements, and move the @p carried vectors (the
     * displacement first, owned entries) to the new numbering. */
    void
    insert_explicit_cracks(const std::vector<FailingFace> &chosen,
                           const std::vector<Vector *>    &carried);
    /** omega^2 bound of the interface and crack penalty springs for any
     * crack pattern of the candidate faces, and where (collective). */
    double
    crack_frequency_squared(Point<dim> &where) const;
    /** One row of cracks.csv: an insertion event. */
    void
    log_crack_event(const std::vector<std::pair<std::string, double>> &row);
    /** What insert_cracks() did. */
    struct InsertionReport
    {
      unsigned int inserted = 0;
      /** The most critical face exceeded the onset tolerance: nothing was
       * inserted, the step should be cut. */
      bool   overshoot = false;
      double hoffman   = 0;
    };
    /** The stresses of @p cell (owned, or across a released face) at the
     * quadrature points of @p values (gradients, reinitialized here) from
     * @p state (locally relevant entries). */
    std::vector<PlyStress>
    cell_stresses(const typename DoFHandler<dim>::active_cell_iterator &cell,
                  FEValues<dim>                                        &values,
                  const Vector &state) const;
    /** After the converged Newton state at @p t (from @p t_previous):
     * insert the faces of faces_to_crack(), rebuild the DoF layer, the
     * interface elements and the Newton state, and move both states to
     * the new numbering (collective). With @p check_onset, a most
     * critical face beyond Crack insertion/Onset tolerance inserts
     * nothing and reports the overshoot. */
    InsertionReport
    insert_cracks(const double t_previous,
                  const double t,
                  const bool   check_onset);
    /** Connected components of cells across faces that are not fully
     * debonded (collective). */
    unsigned int
    count_fragments() const;

    void
    collect_supports();
    void
    make_constraints(const double               t,
                     AffineConstraints<double> &target,
                     const bool                 homogeneous) const;
    /** The load steps of a linear scene, and of a scene with cohesive
     * interfaces; run() has checked and collected the supports. */
    void
    run_linear();
    void
    run_newton();
    /** Buckling subsection: the lowest positive load factors of the state
     * of the last step at @p t (relevant_solution), with K factorized in
     * @p solver and the rows @p fixed constrains left out. */
    void
    analyse_buckling(LinearSolver                    &solver,
                     const AffineConstraints<double> &fixed,
                     const double                     t);
    /** The same for the converged Newton state: K is its tangent (bulk
     * and interfaces), which must be symmetric positive definite (no
     * softening point, no frictional contact: CollectiveError). */
    void
    analyse_newton_buckling(LinearSolver &solver, const double t);
    /** analyse_newton_buckling() once the interfaces have been checked. */
    void
    analyse_newton_state(LinearSolver &solver, const double t);
    /** Why the interfaces at relevant_solution refuse a buckling analysis
     * (a point softens or rubs: no symmetric positive definite tangent),
     * empty if they do not. Collective. */
    std::string
    interfaces_refuse_buckling(const double t, const bool report = true);
    /** Buckling/Analysis times: whether the converged step at @p t is the
     * first at or past the next analysis time (the times it passed are
     * consumed with it). */
    bool
    buckling_due(const double t);
    /** analyse_newton_buckling() during the load history: a state that
     * cannot be analysed is reported and skipped, not an error. */
    void
    analyse_during_history(LinearSolver &solver, const double t);
    /** Run @p analysis of the state at @p t; a CollectiveError it throws
     * is reported as a warning instead of ending the run. */
    void
    skip_failed_analysis(const std::function<void()> &analysis, const double t);
    /** CollectiveError if an interface point of relevant_solution (the
     * state at @p t_ahead on the path) softens or rubs. */
    void
    refuse_softening_ahead(const double t_ahead);
    /** Total Lagrangian: linearized pre-buckling of the converged state at
     * @p t. K_T(t + mu) ~ K_T(t) + mu dK_T/dt along the path tangent
     * du/dt, and the lowest positive mu of (K_T + mu dK_T/dt) v = 0. */
    void
    analyse_prebuckled_state(LinearSolver &solver, const double t);
    /** The load patterns of analyse_prebuckled_state() (InputError naming
     * Buckling/Number of modes if the loads are not proportional to t). */
    void
    setup_prebuckling_pattern();
    /** The lowest positive lambda of (K + lambda B) v = 0, K factorized in
     * @p solver, the rows @p fixed constrains left out. */
    BucklingEigensolver::Result
    solve_buckling_problem(LinearSolver                         &solver,
                           const TrilinosWrappers::SparseMatrix &K,
                           const TrilinosWrappers::SparseMatrix &B,
                           const AffineConstraints<double>      &fixed,
                           const BucklingEigensolver::Settings  &settings);
    BucklingEigensolver::Settings
    buckling_settings() const;
    /** The reaction_* and force_* columns of a history row from
     * @p residual (reactions on the supports, forces conjugate to t). */
    std::vector<std::pair<std::string, double>>
    load_columns(const double t, const Vector &residual) const;
    /** buckling.csv and the modes as buckling_modes.pvd, each scaled to a
     * largest displacement of 1. A factor lambda is the critical load
     * parameter over the state's, t_c = lambda t. Without @p rates the
     * loads scale with it (lambda L); with them they follow the path
     * tangent (L + (t_c - t) dL/dt, the rates dL/dt of the load columns
     * in @p rates). */
    void
    write_buckling_modes(
      const std::vector<double>                         &factors,
      std::vector<Vector>                                modes,
      const std::vector<double>                         &residuals,
      const double                                       t,
      const std::vector<std::pair<std::string, double>> *rates = nullptr);
    /** Time integration = explicit: central differences, lumped mass. */
    void
    run_explicit();
    /** Inputs an explicit run cannot take (throws InputError). */
    void
    check_explicit_input() const;
    /** 2 / omega_max from the elements and the interface and contact
     * penalties against the lumped @p mass (logged with where each bound is
     * attained), shortened for Rayleigh stiffness damping. */
    double
    stable_time_step(const Vector                   &mass,
                     const HangingCondensation<dim> &hanging);
    /** The largest element omega^2 (Irons), and where. */
    double
    element_frequency_squared(Point<dim> &where) const;
    /** Logs how many time steps @p dt one oscillation of the stiffest
     * contact spring takes, with a warning below 10. */
    void
    report_contact_oscillation(const RigidImpactor<dim> &impactor,
                               const Vector             &mass,
                               const double              dt) const;
    /** Gershgorin row sums of the interface and contact penalty springs
     * per dof. */
    void
    penalty_row_sums(Vector &row_sums) const;
    /** Mass scaling: add nodal mass so that @p target is Safety factor
     * times the stable step; logs and sets added_mass. */
    void
    scale_mass(Vector &mass, const double target);
    /** The explicit step from the estimate and the Time parameters. */
    double
    choose_time_step(const double stable) const;
    /** The message for a prescribed value (condition @p k, @p dof) that
     * is not finite at @p t. */
    std::string
    prescribed_not_finite(const unsigned int            k,
                          const types::global_dof_index dof,
                          const double                  t) const;
    /** Throw NonFiniteValue on every rank if any rank has a @p not_finite
     * message (collective). */
    void
    check_finite(const std::string &not_finite) const;
    /** The prescribed displacements at @p t into the supported dofs. */
    void
    impose_prescribed(const double t, Vector &u) const;
    /** Dissipation and opening control: a step is regular while it moves
     * t by at most this much (8 nominal steps: a long crack is compliant,
     * a dissipation step of the DCB near its end moves t by 3-4, on a mesh
     * refined through the thickness at the front more); an iterate four
     * times as far is abandoned at once rather than iterated on. */
    double
    path_step_bound() const;
    /** Fracture energy dissipated by all cohesive interfaces in their
     * converged states (the ledger's "dissipated", summed over ranks). */
    double
    interface_dissipation() const;
    /** The per-interface ledger columns; returns the summed work of the
     * interface tractions. */
    double
    add_interface_columns(std::vector<std::pair<std::string, double>> &columns);
    /** 1/2 u.K u of the bulk (small strain), or the strain energy of the
     * last residual evaluation (total Lagrangian, which evaluated u). */
    double
    bulk_strain_energy(const Vector &u) const;
    /** The Newton state on the current mesh; after a @p mesh_change the
     * contact between the bodies carries its stick springs by place. */
    void
    setup_newton(const bool mesh_change = false);
    /** Static contact between the bodies: the surface of the current
     * mesh; after a @p mesh_change the stick springs of the old one move
     * to it by place (BodyContact::setup()). */
    void
    setup_static_contact(const bool mesh_change);
    /** The Newton matrix's pattern (the contact pairs found at @p u) and
     * the condensed bulk; the solver starts afresh. */
    void
    build_newton_matrix(const Vector &u);
    /** The columns of contact between the bodies at the converged state,
     * whose friction history is kept; returns their penalty energy and
     * friction dissipation. */
    double
    add_static_contact_columns(
      std::vector<std::pair<std::string, double>> &columns);
    /** A prescribed sphere at time @p t and the converged state: its force
     * and centre, from which the next step's work is counted. At t = 0 it
     * must not touch the laminate. */
    void
    start_static_impactor(const double t);
    /** The sphere's columns of a converged step (its friction history
     * committed), its driver's work added to the external work; returns
     * the contact energy and the friction's dissipation. */
    double
    add_static_impactor_columns(
      std::vector<std::pair<std::string, double>> &columns);
    NewtonReport
    solve_newton_step(const double t, LinearSolver &solver);
    /** The condensed residual (and its norm) from NewtonState::residual;
     * sets the force scale. */
    double
    condense_residual();
    /** C^T @p full with zero constrained entries into @p condensed;
     * returns the squared norm of the constrained entries of @p full. */
    double
    condense(const Vector &full, Vector &condensed);
    /** sum_i g_i R_i over the supports: the force conjugate to t. */
    double
    load_force(const Vector &residual) const;
    /** K_T(@p state) times the load pattern, into pattern_response and
     * pattern_condensed; returns pattern . K_T pattern. */
    double
    pattern_derivative(const Vector &state);
    /** The path-following patterns: the prescribed displacements at
     * t = 1 (load_pattern) and, if @p with_loads, the loads at t = 1
     * (load_unit); both must be proportional to t (InputError naming
     * @p control and the parameter @p name otherwise), and without
     * @p with_loads there must be no loads. */
    void
    setup_load_pattern(const bool         with_loads,
                       const std::string &control,
                       const std::string &name = "Nonlinear solver/Control");
    /** K_T(relevant_solution) @p direction, unconstrained. */
    void
    tangent_product(const Vector &direction, Vector &product);
    /** One step of dissipation control from the converged state at
     * load parameter @p t0: the new load parameter goes to @p t. */
    NewtonReport
    solve_dissipation_step(const double  t0,
                           const double  increment,
                           double       &t,
                           LinearSolver &solver);
    /** The two Newton directions of a path-following iteration with one
     * factorization: K du_I = -r into increment, K du_II = -dR/dt into
     * pattern_increment (after pattern_derivative()); false, with the
     * reason in @p report, if the linear solver failed. */
    bool
    solve_both_directions(LinearSolver &solver, NewtonReport &report);
    /** The two directions of a path-following iteration at solution
     * (solve_both_directions() after pattern_derivative()): the increment
     * K du_I = -r with its constraints distributed, and into @p direction
     * the change of the solution per unit t, du_II with the prescribed
     * part g(1). False, with the reason in @p report, if the linear solver
     * failed. */
    bool
    path_directions(LinearSolver &solver,
                    NewtonReport &report,
                    Vector       &direction);
    /** One step of Crisfield's arc-length method of length @p radius
     * from the converged state at @p t0 (0: the nominal length, set
     * here); the new load parameter goes to @p t. */
    NewtonReport
    solve_arc_length_step(const double  t0,
                          double       &radius,
                          double       &t,
                          LinearSolver &solver);
    /** One step of opening control: the summed normal opening of the
     * bonded interface points grows by @p increment. */
    NewtonReport
    solve_opening_step(const double  t0,
                       const double  increment,
                       double       &t,
                       LinearSolver &solver);
    /** Factorize system_matrix (analysed once) and solve for @p x. */
    void
    linear_solve(LinearSolver &solver, Vector &x, const Vector &b);
    /** The residual of the linearized step from the converged state to the
     * new prescribed values (in solution); the tangent of the converged
     * state goes to system_matrix. */
    double
    predictor_residual();
    double
    update_residual(const Vector                   &trial,
                    TrilinosWrappers::SparseMatrix *tangent);
    /** Plastic plies: NewtonState::plastic_force (and the tangent's
     * correction) of relevant_solution; false, with plastic_failure set
     * on every rank, if the return mapping failed anywhere (collective). */
    bool
    add_plastic_correction(TrilinosWrappers::SparseMatrix *tangent);
    /** Plastic plies: the converged step's state (solution) becomes the
     * history, its plastic work goes to the run's total. */
    void
    commit_plastic_state();
    std::vector<std::pair<std::string, double>>
    energy_ledger();
    std::vector<std::vector<double>>
    rigid_body_modes() const;
    std::vector<std::vector<double>>
    owned_node_coordinates() const;
    void
    postprocess(const unsigned int                                 step,
                const double                                       t,
                const Vector                                      &residual,
                const std::vector<std::pair<std::string, double>> &columns);
    /** Field output of step @p step (and the interface points) from
     * relevant_solution, expanded to copy_values; with @p update_plastic
     * the plastic fields are evaluated first (postprocess() sets them
     * itself). Collective. */
    void
    write_fields(const unsigned int step,
                 const double       t,
                 const bool         update_plastic = true);
    /** Plastic plies: the cell means of the plastic strain and kappa into
     * the field output. */
    void
    set_plastic_fields(const typename PlasticPlies<dim>::CellMeans &means);
    /** Per prescribed condition, the force conjugate to the load
     * parameter t: sum_i R_i dg_i/dt (the load P for a displacement
     * +-P-conjugate opening, e.g. the DCB's arms opened by +-t/2). */
    std::vector<double>
    conjugate_forces(const double t, const Vector &residual) const;
    void
    prepare_output_directory() const;
  };
} // namespace amfrac

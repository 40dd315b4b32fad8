#pragma once

#include <amfrac/base/ordered_sums.h>
#include <amfrac/cohesive/camanho_davila_law.h>
#include <amfrac/cohesive/deformed_frame.h>
#include <amfrac/cohesive/seed_law.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/parameters/parameters.h>
#include <amfrac/postprocess/interface_output.h>
#include <array>
#include <cstdint>
#include <deal.II/base/partitioner.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace amfrac
{
  /**
   * The cohesive ply interfaces of a laminate (the seed's discrete-element
   * bonding). Interface k lies between ply k and ply k + 1; its faces are
   * released in the tied-copy DoF layer, so each ply is a body of its own,
   * and every pair of faces across it is an interface element that bonds
   * the two copies of its nodes by the seed's law.
   *
   * An interface element integrates the traction of the gap
   * g = u(upper ply) - u(lower ply), expressed in the local frame (normal of
   * the lower ply's face first, then the tangents), with Gauss or
   * Gauss-Lobatto points; every point keeps the law's history of the last
   * converged step and a trial state of the current iterate, and the work
   * done on it, so that the energy ledger can split the interface work into
   * what is stored, dissipated by fracture and dissipated by friction.
   *
   * With total Lagrangian plies the frame follows the deformed mid-surface
   * of the two faces (cohesive::DeformedFrame): the gap is [[u]] in the
   * frame of the mid-surface's convected tangents, so that a delaminated
   * sublaminate can rotate without a spurious opening or sliding, the
   * traction is per reference area, and the tangent includes the
   * derivative of the frame (the geometric terms).
   */
  template <int dim>
  class CohesiveInterfaces
  {
  public:
    using CellIterator = typename TiedCopyDoFs<dim>::CellIterator;
    using Vector       = TrilinosWrappers::MPI::Vector;
    using Matrix       = TrilinosWrappers::SparseMatrix;

    /** @p deformed_frame: the local frame follows the deformed
     * mid-surface (total Lagrangian kinematics; the Newton path only). */
    explicit CohesiveInterfaces(const parameters::CohesiveInterfaces &data,
                                const bool deformed_frame = false);

    /** Crack insertion: inserted faces get an extrinsic bilinear law of
     * penalty stiffness @p penalty (one more entry of ledger()) and, once
     * fully softened, Coulomb @p friction in contact (stick spring:
     * @p penalty). */
    void
    enable_cracks(const double penalty, const double friction = 0);

    bool
    cracks_enabled() const
    {
      return crack_penalty > 0;
    }

    /** True if face @p face of @p cell is an inserted crack. */
    bool
    is_crack(const typename Triangulation<dim>::cell_iterator &cell,
             const unsigned int                                face) const;

    /** Release face @p face of @p cell (a regular interior face, seen from
     * either side) as a crack; the DoF layer and rebuild() take it up. */
    void
    add_crack(const typename Triangulation<dim>::cell_iterator &cell,
              const unsigned int                                face);

    /** The inserted crack faces, from both sides (CellId binary, 4
     * numbers, and the face), the same on every rank: what a checkpoint
     * keeps. */
    std::vector<std::int64_t>
    crack_keys() const;

    /** Release the faces of crack_keys() output (a checkpoint's) on the
     * mesh @p triangulation; throws InputError if one is not a regular
     * interior face there (the checkpoint is of another scene). */
    void
    add_cracks(const Triangulation<dim>        &triangulation,
               const std::vector<std::int64_t> &keys);

    /** After a mesh change: the crack faces of refined cells move to the
     * children on them (children of a cracked face are cracked). Cells
     * with a crack face are never coarsened (match_flags()); throws if a
     * crack face is no longer regular on both sides. */
    void
    follow_mesh_change(const Triangulation<dim> &triangulation);

    /** The cracks added since the elements were last built (each face
     * once, from the side it was added from): the faces the DoF layer
     * releases before rebuild() builds their elements. */
    const std::vector<std::pair<CellId, unsigned int>> &
    unbuilt_cracks() const
    {
      return unbuilt;
    }

    /** Number of inserted crack faces (each once, all ranks: the set is
     * replicated). */
    std::size_t
    n_crack_faces() const
    {
      return cracked.size() / 2;
    }

    /** The global traction (stress times @p normal, the lower cell's
     * outward normal) at @p point of the face between @p lower and
     * @p upper: in the state a new crack starts from if @p at_onset is
     * false (the last converged state), else in the state whose stress
     * failed the face (the onset). */
    using CrackTraction = std::function<Tensor<1, dim>(const CellIterator &,
                                                       const CellIterator &,
                                                       const Point<dim> &,
                                                       const Tensor<1, dim> &,
                                                       const bool at_onset)>;

    /** What a rebuild() did on this rank. */
    struct CrackReport
    {
      unsigned long new_points = 0;
      /** Energy per area held at insertion, summed times JxW. */
      double inserted_energy = 0;
    };

    /**
     * After the DoF layer released the unbuilt cracks (the mesh
     * unchanged): the existing elements move to the new numbering with
     * their converged and trial states, and only the new cracks' elements
     * are built (the cost is that of the new faces). The points
     * of a new crack start at the traction T0 of the converged state
     * (@p traction, the mean stress of the two cells times the normal) on
     * an extrinsic law with the ply's fracture energy @p toughness (of the
     * lower cell): the gap is offset by T0 / penalty, so that the law gives
     * T0 at zero opening and the face carries what the intact material
     * did; its onset traction is the largest effective traction at the
     * onset state (the point's and the face centre's, so that a point
     * where a bending gradient lowers the stress does not start weak).
     * Collective.
     */
    CrackReport
    rebuild(const TiedCopyDoFs<dim>                           &dofs,
            const CrackTraction                               &traction,
            const std::function<double(const CellIterator &)> &toughness);

    /** What balance_new_cracks() did (all ranks). */
    struct BalanceReport
    {
      /** Least-squares iterations, and new points whose corrected
       * traction would have needed a stiffer penalty (kept at T0). */
      unsigned int  iterations = 0;
      unsigned long limited    = 0;
      /** The largest change of a point's traction [MPa]. */
      double largest_correction = 0;
    };

    /**
     * Static crack insertion, after rebuild() and an evaluation at the
     * converged state: the points of the last rebuild() start from the
     * stress of the two cells, which is not in balance with the nodal
     * forces of the split copies (a Q1 stress is constant per cell, the
     * nodal forces are not). Their tractions change by the smallest
     * delta (least squares of sum_q JxW_q |delta_q|^2, by CGLS) for which
     * their forces cancel @p residual (the condensed residual, owned
     * entries) on the rows that @p free_rows marks 1 (free, not hanging)
     * and that the new points touch. The least squares act on those rows
     * only: a force on a hanging row of a new face, which the residual
     * hands to its masters, is not moved there (a crack face whose
     * vertex hangs is balanced approximately). @p touched marks with 1
     * the rows the new points act on after @p condense (the residual's
     * condensation, applied to an owned vector), the masters of hanging
     * rows included, so that what is left there is reported. Offsets,
     * onset tractions and inserted energies follow the new tractions
     * (converged and trial states). @p relevant: the locally relevant
     * dofs. Collective.
     */
    BalanceReport
    balance_new_cracks(const Vector                        &residual,
                       const Vector                        &free_rows,
                       const IndexSet                      &relevant,
                       const std::function<void(Vector &)> &condense,
                       Vector                              &touched);

    /** The elements (lower cell and face) of all ranks whose points are
     * all debonded: the faces that separate fragments (collective). */
    std::vector<std::pair<CellId, unsigned int>>
    separated_faces(const MPI_Comm comm) const;


    /** The faces that the DoF layer must leave untied. */
    typename TiedCopyDoFs<dim>::FaceFilter
    released_faces() const;

    /** Build the interface elements of the locally owned cells and put the
     * pre-crack in their history. Throws InputError if a cohesive interface
     * face is hanging or if the pre-crack region covers every point of every
     * cohesive interface (a single interface may be fully open); returns the
     * number of pre-cracked points (all ranks). */
    unsigned long
    setup(const TiedCopyDoFs<dim> &dofs, const std::string &constants);

    /** Add the couplings across the interfaces to @p pattern. */
    void
    add_couplings(const AffineConstraints<double>   &constraints,
                  TrilinosWrappers::SparsityPattern &pattern) const;

    /**
     * Evaluate the law at the displacement @p solution (locally relevant
     * entries): add the interface forces to @p force (a vector with
     * writable ghosts, compressed by the caller) and, if @p tangent is
     * given, the consistent tangent condensed with @p constraints. The
     * point states become the trial states.
     */
    void
    assemble(const Vector                    &solution,
             Vector                          &force,
             const AffineConstraints<double> &constraints,
             Matrix                          *tangent);

    /** Add K_T(solution) @p direction to @p product (a vector with
     * writable ghosts), with the tangent of the converged history; the
     * point states are not touched. */
    /** Add to @p gradient the derivative at @p solution (locally relevant
     * entries) of the integral of the normal opening over the points that
     * are bonded in the converged state (the controlled quantity of
     * opening control; linear in u unless the frame follows the
     * deformation). */
    void
    add_opening_gradient(const Vector &solution, Vector &gradient) const;

    void
    add_tangent_product(const Vector &solution,
                        const Vector &direction,
                        Vector       &product) const;

    /** The pseudo-time step of the current load step (for the viscous
     * regularization). */
    void
    set_time_step(const double dt)
    {
      time_step = dt;
    }

    /** True if the tangent of the last assemble() equals, point by point,
     * the one of the last mark_factorized() (on this rank): a solver may
     * then reuse its factorization. */
    bool
    tangent_unchanged() const
    {
      return unchanged;
    }

    /** Number of debonded points (all ranks) that opened, closed, started
     * or stopped slipping over
     * the last three assemble() calls with a tangent (two iterations):
     * while the contact set still changes, a slow residual decrease is not
     * a stagnating Newton iteration (semi-smooth Newton moves the edge of
     * the contact zone a few points per iteration until it settles). */
    unsigned long
    contact_changes(const MPI_Comm comm) const;

    /** The tangent of the last assemble() has been factorized. */
    void
    mark_factorized();

    /** Accept the trial states as the converged history. */
    void
    commit();

    /** Explicit dynamics: number the element dofs in the local arrays of
     * @p partitioner (owned, then ghosts) for add_forces(), and plan the
     * partition-independent sums of the element forces (collective). */
    void
    set_local_indices(const Utilities::MPI::Partitioner &partitioner);

    /** Explicit dynamics with crack insertion: a bound of omega^2 of the
     * penalty springs (Gershgorin's, as add_penalty_row_sums()) that holds
     * for any crack pattern among the faces @p may_crack selects: on each
     * locally owned cell, every such face a crack, every cohesive face as
     * it is, and every node of the cell a copy of its own, with the
     * cell's share of the lumped mass (@p element_mass). A copy shared by
     * several cells has its springs over its mass at most the largest
     * ratio of its cells, so that the bound covers any splitting. With
     * @p contact_penalty > 0 (contact between the bodies, BodyContact's
     * rows as a pressure per unit penetration), the faces @p in_contact
     * selects carry it too, on top of their cohesive penalty. Returns the
     * bound on this rank, the dof's support point in @p where. */
    double
    crack_frequency_squared(
      const TiedCopyDoFs<dim> &dofs,
      const std::function<void(const CellIterator &, dealii::Vector<double> &)>
        &element_mass,
      const std::function<bool(const CellIterator &, unsigned int)> &may_crack,
      Point<dim>                                                    &where,
      const double contact_penalty = 0,
      const std::function<bool(const CellIterator &, unsigned int)> &in_contact
      = {}) const;

    /** Explicit dynamics: @p f += the interface forces of the jumps of
     * @p u (local arrays, see set_local_indices()); updates the trial
     * states, and commits them. The same laws and sums as assemble()
     * without a tangent, on local indices and the nonzero shape values
     * only. */
    void
    add_forces(const double *u, double *f);

    /** Energies (per unit width in 2D) and areas of one interface. */
    struct Ledger
    {
      double work        = 0; ///< total work of the tractions on the gaps
      double stored      = 0; ///< recoverable (elastic) part of the work
      double dissipated  = 0; ///< by fracture (the bonded phase)
      double friction    = 0; ///< by friction after debonding
      double viscous     = 0; ///< by the viscous regularization
      double debonded    = 0; ///< fully debonded area (length in 2D)
      double damaged     = 0; ///< area with kappa > 0
      double min_opening = 0; ///< most negative normal gap (contact)
      /** Inserted cracks: the energy their faces held at insertion (the
       * offset law's T0^2 / 2 K per area; stored + dissipated = work +
       * inserted). */
      double inserted = 0;
    };

    /** One ledger per cohesive interface (summed over ranks), in the
     * order of interfaces(). */
    std::vector<Ledger>
    ledger(const MPI_Comm comm) const;

    const std::vector<unsigned int> &
    interfaces() const
    {
      return data.interfaces;
    }

    /** The converged state of every interface point of this rank, with the
     * mean displacement of its two faces from @p solution (locally relevant
     * entries). */
    std::vector<InterfacePointRecord<dim>>
    output_points(const Vector &solution) const;

    /** Explicit dynamics: the row sums sum_j |K_ij| of the penalty
     * springs (the stiffest of the normal, shear, contact and stick
     * penalties) per dof, added into @p row_sums (writable with ghosts;
     * the caller compresses). Against the lumped mass they bound omega^2
     * by Gershgorin's theorem on M^-1 K. */
    void
    add_penalty_row_sums(Vector &row_sums) const;

    /** Number of interface quadrature points on this rank. */
    std::size_t
    n_local_points() const;

    /** Adaptivity (the process-zone rule): the bonded points of all ranks
     * that lie within @p reach[k] of a damaged or debonded point of the
     * same interface (the k-th of interfaces()), i.e. the stretch ahead of
     * every delamination front, each with the reach of its interface. */
    std::vector<std::pair<Point<dim>, double>>
    front_points(const std::vector<double> &reach, const MPI_Comm comm) const;

    /** Adaptivity: make the refine and coarsen flags of @p triangulation
     * agree across every cohesive face, so that both sides stay
     * conforming (a face is refined or coarsened on both sides or on
     * none). Calls prepare_coarsening_and_refinement() until the flags
     * settle; returns false if no flag is left. */
    bool
    match_flags(Triangulation<dim> &triangulation) const;

    /** The converged interface states of all ranks, with the place of
     * each lower face in its coarse cell, taken before the mesh changes. */
    struct Snapshot
    {
      struct Face
      {
        unsigned int                      face;
        unsigned int                      interface;   ///< as Element's
        std::pair<Point<dim>, Point<dim>> box;         ///< as Element::box
        std::vector<Point<dim>>           unit_points; ///< in the lower cell
        std::vector<Point<dim>>           points;      ///< in space
        std::vector<unsigned char>        pre_crack;   ///< as Element's
        std::vector<double>               JxW;
        std::vector<double> states; ///< packed, state_size() per point
      };
      std::vector<Face> faces;
      /** (coarse cell, face) to the positions in faces. */
      std::map<std::pair<types::coarse_cell_id, unsigned int>,
               std::vector<std::size_t>>
        index;
    };

    Snapshot
    snapshot(const MPI_Comm comm) const;

    /** What a transfer did, summed over the ranks. */
    struct TransferReport
    {
      unsigned long injected   = 0; ///< points inside an old face
      unsigned long aggregated = 0; ///< points of a coarsened face
      /** Points whose damage (or debonded status) grew under the gap of
       * the transferred displacement; kept as it was. */
      unsigned long beyond_history = 0;
      /** |sum of the interface forces on all nodes| / sum of their
       * magnitudes at the transferred state: round-off if the two faces of
       * every new interface element match. */
      double force_imbalance = 0;
    };

    /**
     * The seed's tau_1 for interface history, after setup() on the new
     * mesh: a point inside an old face (kept or refined) takes the state of
     * the nearest old point of that face (injection: on two-point rules
     * every old point hands its state to the children that its weight
     * covers, so dissipated energy is kept exactly); a point of a
     * coarsened face takes the largest damage, the debonded status and the
     * JxW-weighted works of the old points nearest to it (damage never
     * decreases, dissipated energy is kept). Gap and traction are then
     * those of @p solution (the transferred displacement, locally relevant
     * entries) under the transferred history.
     */
    TransferReport
    transfer(const Snapshot &old, const Vector &solution, const MPI_Comm comm);

    /**
     * The seed's tau_1 for interface history across a global remeshing
     * (the old and the new mesh unrelated), after setup() on the new mesh
     * @p mesh: every point is located on the interface surface by its
     * position, on its own interface.
     * - A new point takes the state of the nearest old point (the old
     *   history read as constant around each old point). The pre-crack is
     *   input that setup() has seeded by position: a new point outside it
     *   looks only at old points outside it.
     * - An old point that no new point is nearest to (a coarser new mesh)
     *   joins the nearest point outside the pre-crack of the new face it
     *   lies in, and a point with several sources takes the most damaged
     *   one's state: the largest damage and a debonded status survive any
     *   mesh. Old pre-crack points never join.
     * - The densities of dissipated work are the JxW-weighted means of the
     *   sources', scaled per interface so that the dissipated energies
     *   are kept exactly (unless a total is round-off of the law).
     * Gap and traction are then those of @p solution, as in transfer().
     * The report counts as injected the points with one source and as
     * aggregated those with more. The result does not depend on the
     * number of ranks.
     */
    TransferReport
    relocate(const Snapshot           &old,
             const Triangulation<dim> &mesh,
             const Vector             &solution,
             const MPI_Comm            comm);

    /** Checkpoint: per element of this rank, the lower cell (CellId in
     * binary, 4 numbers), its face and its number of points into @p keys;
     * per point the packed converged state and the contact status into
     * @p states; and the two contact-change counters (summed over the
     * ranks, on rank 0 only, so that any number of ranks can read them
     * back). */
    void
    save(std::vector<std::int64_t> &keys,
         std::vector<double>       &states,
         std::vector<std::int64_t> &counters,
         const MPI_Comm             comm) const;

    /** Restore the states of this rank's elements from the saved ones of
     * all ranks (save()'s output, concatenated per rank); throws
     * std::runtime_error if an element or its points are missing. */
    void
    load(const std::vector<const std::vector<std::int64_t> *> &keys,
         const std::vector<const std::vector<double> *>       &states,
         const std::vector<std::int64_t>                      &counters,
         const MPI_Comm                                        comm);

  private:
    /** The state of one interface point. */
    struct PointState
    {
      cohesive::PointHistory<dim> history;
      Tensor<1, dim>              gap;      ///< local frame
      Tensor<1, dim>              traction; ///< local frame
      /** Viscous traction of the regularization (local frame). */
      Tensor<1, dim> viscous;
      double         bond_work     = 0;
      double         friction_work = 0;
      double         viscous_work  = 0;
      /** Inserted cracks (zero elsewhere): the gap offset T0 / K (local
       * frame), the onset traction, the fracture energy and the energy
       * per area held at insertion. */
      Tensor<1, dim> offset;
      double         strength  = 0;
      double         toughness = 0;
      double         inserted  = 0;
    };

    /** Two faces across an interface and what their integration needs. */
    struct Element
    {
      /** The level-0 ancestor of the lower cell. */
      types::coarse_cell_id coarse_cell;
      /** The lower cell itself (checkpoints). */
      CellId       cell;
      unsigned int face; ///< of the lower cell
      /** A triangular face's (a wedge's top or bottom) longest edge; 0
       * for other faces. */
      double triangle_edge = 0;
      /** The lower cell in the reference coordinates of its coarse
       * (level-0) cell: lower and upper corner. */
      std::pair<Point<dim>, Point<dim>> box;
      /** Position in the list of interfaces; its size for a crack. */
      unsigned int interface;
      /** The active cell index of the lower cell (the elements are in
       * the order of the active cells, then faces). */
      unsigned int                         active_cell;
      std::vector<types::global_dof_index> dofs; ///< lower face, upper face
      /** The copies (TiedCopyDoFs::copy_handler()) behind dofs. */
      std::vector<types::global_dof_index> copies;
      std::vector<unsigned char>           component;
      /** shape(q, k): the value of local dof k at point q, negative on the
       * lower face, so that the gap is sum_k shape(q, k) u_k. */
      FullMatrix<double>          shape;
      std::vector<double>         JxW;
      std::vector<Tensor<2, dim>> frame; ///< rows: normal, tangents
      /** Deformed frame only: the derivative of the mid-surface
       * displacement along the reference tangent a (frame row a + 1) at
       * point q per unit value of local dof k: tangent_shape[a](q, k). */
      std::array<FullMatrix<double>, dim - 1> tangent_shape;
      std::vector<Point<dim>>                 points;
      /** The points in the lower cell's reference coordinates. */
      std::vector<Point<dim>> unit_points;
      std::vector<PointState> converged;
      std::vector<PointState> trial;
      /** The point tangents (global frame, times JxW) of the last
       * assemble() with a matrix, and of the last factorized matrix. */
      std::vector<Tensor<2, dim>> assembled;
      std::vector<Tensor<2, dim>> factorized;
      /** Contact status of debonded points at the last assemble() with a
       * tangent: 0 open, 1 sticking, 2 slipping. */
      std::vector<unsigned char> status;
      /** Per point: 1 if setup() seeded it as the Pre-crack region (input,
       * which a law may overwrite in the history, e.g. kappa). */
      std::vector<unsigned char> pre_crack;
      /** Explicit dynamics: local indices of dofs, and per point q the
       * nonzero shape values (local dof k, value) in
       * nonzero[start[q] .. start[q + 1]). */
      std::vector<unsigned int>                    local_dofs;
      std::vector<unsigned int>                    start;
      std::vector<std::pair<unsigned int, double>> nonzero;
    };

    /** Explicit dynamics: element forces go to slots (element after
     * element, its dofs in order: first_slot[e] + k), summed into the
     * owners' entries by the lower cell, face and local dof. */
    OrderedSums               force_sums;
    std::vector<unsigned int> first_slot;

    const parameters::CohesiveInterfaces data;
    const bool                           deformed_frame;
    /** Inserted crack faces, each from both sides; penalty of their law
     * (0: no crack insertion). */
    std::set<std::pair<CellId, unsigned int>>    cracked;
    std::vector<std::pair<CellId, unsigned int>> unbuilt;
    /** Positions in elements of those the last rebuild() built. */
    std::vector<unsigned int>               fresh;
    double                                  crack_penalty  = 0;
    double                                  crack_friction = 0;
    const cohesive::SeedLawProperties       law;
    const cohesive::CamanhoDavilaProperties camanho_davila;
    std::vector<Element>                    elements;
    double                                  time_step = 1;

    /** Evaluate point @p q of @p element at @p global_gap (trial state,
     * local @p tangent); returns its traction in the global frame times
     * JxW. */
    Tensor<1, dim>
                  point_force(Element              &element,
                              const unsigned int    q,
                              const Tensor<1, dim> &global_gap,
                              Tensor<2, dim>       &tangent) const;
    bool          unchanged = false;
    unsigned long changes = 0, previous_changes = 0;

    void
    count_contact_change(Element &element, const unsigned int q);

    /** Coulomb mu and stick penalty of a point's law (a crack's or the
     * ply interfaces'). */
    double
    friction_of(const PointState &state) const;
    double
    stick_penalty_of(const PointState &state) const;

    /** The stiffest penalty of the ply interfaces' law (normal, shear,
     * contact, stick). */
    double
    largest_ply_penalty() const;

    bool
    is_cohesive(const typename Triangulation<dim>::cell_iterator &cell,
                const unsigned int                                face) const;

    /** Energy per area held elastically at a point (the ledger's
     * "stored"). */
    double
    stored_energy(const PointState &state) const;

    /** The 1D rule of the interface points (a face's rule is its tensor
     * product): each point owns the stretch of [0, 1] that its weight
     * covers, [bounds[i], bounds[i + 1]]. */
    std::vector<double> rule_points, rule_bounds;
    void
    set_point_regions(const unsigned int n_points);

    /** The rules of the interface points on the faces of the cell shape
     * (one per face on a wedge): Gauss with @p n_nodes points per
     * direction, or the nodal (Lobatto) rule. */
    hp::QCollection<dim - 1>
    face_rules(const TiedCopyDoFs<dim> &dofs, const unsigned int n_nodes) const;

    /** Damage of a point for output and for the front (1 if debonded). */
    double
    damage(const PointState &state) const;

    static constexpr unsigned int
    state_size()
    {
      return 4 * dim + (dim - 1) + 8;
    }
    static void
    pack(const PointState &state, std::vector<double> &out);
    static PointState
    unpack(const double *in);

    /** The region of the point at @p unit (reference coordinates of a
     * cell whose face @p face it lies on), in the coordinates of the coarse
     * cell in which that cell is @p box. */
    std::array<std::pair<double, double>, dim>
    point_region(const Point<dim>                        &unit,
                 const unsigned int                       face,
                 const std::pair<Point<dim>, Point<dim>> &box) const;

    /** The state of every point of @p element from the old faces. */
    void
    transfer_element(Element        &element,
                     const Snapshot &old,
                     TransferReport &report) const;

    /** Gap and traction of the converged states at @p solution. */
    void
    rebase(Element &element, const Vector &solution, TransferReport &report);

    /** The part of transfer() and relocate() after the history: @p carry
     * sets an element's converged states, then the pre-crack is seeded
     * again, the states are rebased on @p solution and the balance of the
     * interface forces is measured into @p report, whose counters are
     * then summed over the ranks. */
    void
    finish_transfer(const std::function<void(Element &)> &carry,
                    const Vector                         &solution,
                    const MPI_Comm                        comm,
                    TransferReport                       &report);

    /** relocate(): the old points @p sources that no new point is
     * nearest to (@p taken is 0), but not the pre-crack's, added to the
     * sources @p from (per element and point) of the nearest point outside
     * the pre-crack of the new face they lie in (of any rank if they lie
     * in none); then every list sorted, without repeats. */
    template <typename Source>
    void
    place_left_over(const Triangulation<dim>        &mesh,
                    const std::vector<Source>       &sources,
                    const std::vector<unsigned int> &taken,
                    std::vector<std::vector<std::vector<unsigned int>>> &from,
                    const MPI_Comm comm) const;

    /** The point of @p element outside the pre-crack nearest to @p p, if
     * it has one. */
    std::optional<unsigned int>
    nearest_outside(const Element &element, const Point<dim> &p) const;

    /** Densities of what a point dissipated (fracture, friction,
     * viscous), per area; rebase() adds what a new gap stores. */
    std::array<double, 3>
    dissipated_densities(const PointState &state) const;

    void
    check_conforming(const DoFHandler<dim> &handler) const;

    /** Every element from its lower cell: the smaller ply index for a
     * ply interface, the smaller CellId for a crack. */
    void
    make_elements(const TiedCopyDoFs<dim> &dofs);

    /** The elements of the faces @p faces (lower side, locally owned
     * cells, in the order given). */
    std::vector<Element>
    build_elements(
      const TiedCopyDoFs<dim>                                  &dofs,
      const std::vector<std::pair<CellIterator, unsigned int>> &faces) const;

    /** The element of @p face of @p cell (the lower ply's side); @p lower
     * and @p upper evaluate the two faces. */
    Element
    make_element(const TiedCopyDoFs<dim> &dofs,
                 const CellIterator      &cell,
                 const unsigned int       face,
                 FEFaceValues<dim>       &lower,
                 FEFaceValues<dim>       &upper) const;

    /** Static crack insertion (balance_new_cracks()): @p force (writable
     * ghosts) = the forces of the fresh points' global tractions
     * @p tractions times sqrt(JxW), compressed (with |shape| if
     * @p absolute); and the adjoint, @p tractions = sqrt(JxW) times the
     * gap of @p values (ghosted) at the fresh points. */
    void
    spread_fresh(const std::vector<Tensor<1, dim>> &tractions,
                 Vector                            &force,
                 const bool                         absolute = false) const;
    void
    gather_fresh(const Vector                &values,
                 std::vector<Tensor<1, dim>> &tractions) const;

    /** The fresh points' tractions changed by the global z / sqrt(JxW)
     * (balance_new_cracks()), with their offsets, onsets and inserted
     * energies; a point whose new onset the penalty cannot carry keeps
     * its traction (counted in @p report). */
    void
    apply_corrections(const std::vector<Tensor<1, dim>> &z,
                      BalanceReport                     &report);

    /** The extrinsic law of a crack point: Camanho-Davila with one
     * strength and one fracture energy in all modes (those of the point)
     * and the crack penalty. */
    cohesive::CamanhoDavilaProperties
    crack_law(const PointState &state) const;

    /** Deformed frame: the frame of point @p q of @p element at its dof
     * values @p u, the global gap there, and the derivatives
     * B[k] = d (local gap) / d u_k. */
    cohesive::DeformedFrame<dim>
    deformed_kinematics(const Element                &element,
                        const unsigned int            q,
                        const dealii::Vector<double> &u,
                        Tensor<1, dim>               &global_gap,
                        std::vector<Tensor<1, dim>>  &B) const;

    /** Deformed frame: the law at every point of @p element at its dof
     * values @p u from the converged history; the forces into @p r, the
     * consistent tangent (with the frame's derivatives) into @p K if
     * given, the states into @p trial if given. */
    void
    deformed_element(const Element                &element,
                     const dealii::Vector<double> &u,
                     dealii::Vector<double>       &r,
                     FullMatrix<double>           *K,
                     std::vector<PointState>      *trial) const;

    /** The law at one point, with the work increment from the converged
     * state. */
    PointState
    evaluate(const PointState     &converged,
             const Tensor<1, dim> &gap,
             Tensor<2, dim>       &tangent) const;
  };
} // namespace amfrac

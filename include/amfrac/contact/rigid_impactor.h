#pragma once

#include <algorithm>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/parameters/impactor.h>
#include <array>
#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace amfrac
{
  /**
   * A rigid sphere that strikes one face of the laminate (issue 10), or a
   * cylinder of unbounded length along an axis in the face's plane (then
   * read "its closest point on the axis" for "the centre" below):
   * node-to-sphere penalty contact with Coulomb friction. A face node at
   * x inside the sphere (gap g = |x - c| - R < 0) is pushed out along
   * n = (x - c) / |x - c| by the force -k g n with k = Penalty times the
   * node's share of the face area (the integral of its shape function over
   * the face), and the sphere feels the opposite. The contact is the
   * potential E_c = sum_i k_i g_i^2 / 2, so plate, sphere and contact
   * together keep their energy up to the time integration's error.
   *
   * Friction (Friction coefficient mu > 0): a node in contact is held to
   * the sphere's surface by a stick spring k_t = factor k in the tangent
   * plane. Its tangential force grows from the last committed one (turned
   * into the current tangent plane) by -k_t s, where s is the tangential
   * part of the node's displacement increment less the centre's, and is
   * returned to the Coulomb limit mu k |g| when it exceeds it. The sphere
   * translates only (a guided striker: its rotation is held), so the
   * friction torque does no work. The dissipation of a step is the work of
   * the friction force (trapezoidal) less the change of the stick
   * springs' energy, which is part of contact_energy(); a node that leaves
   * contact releases its spring's energy into the dissipation. Explicit
   * runs commit the history at every evaluation; static runs evaluate
   * trial states from the last commit() (the converged step).
   *
   * The history of a node is keyed by its position and by its side (the
   * direction from it to the centres of its face's cells): the numbering
   * depends on the partition, and the copies of a node split by a crack
   * share a position but lie on opposite sides. A mesh change or a crack
   * insertion hands each new node the history of the old node at its
   * position whose side is closest to its own, as the stretch of its
   * stick spring (force / k_t): the heir's force is its own k_t times that
   * stretch. The copies of a split node, whose areas add up to its area,
   * so share its force and stick energy in proportion to their stiffness;
   * an old vertex whose area refinement or coarsening changed keeps its
   * stretch, not its force. A node that refinement adds at the midpoint of
   * an old face's edge or at its centre takes the mean stretch (and
   * displacement) of that face's vertices, on its side. A uniform stick
   * field so keeps the force on the sphere, each node's force and the
   * contact energy through any mesh change (checked). With quadratic
   * elements the nodes refinement adds between an old vertex and an old
   * edge's midpoint start without a spring.
   *
   * A guided sphere (the default) moves along the face's normal only: its
   * acceleration across it is held at zero (a drop-weight striker, and
   * what symmetry planes through its path require).
   *
   * The sphere moves with the laminate's central differences: kick() by
   * half a step with the acceleration of the last evaluate(), drift() by a
   * whole step. Each rank evaluates the nodes it owns; the force on the
   * sphere adds every node's share in the order of the nodes' positions,
   * on any number of ranks (the same sum bit for bit; the numbering of the
   * nodes depends on the partition).
   */
  template <int dim>
  class RigidImpactor
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** @p explicit_run: the history is committed at every evaluate(), as
     * the explicit time integration takes no trial states (a prescribed
     * sphere in a static run keeps it until commit()). */
    RigidImpactor(const parameters::Impactor &parameters,
                  MPI_Comm                    comm,
                  const bool                  explicit_run = false);

    /** The candidate nodes of the current mesh: the owned nodes on the
     * face, with their area. After a mesh change or a crack insertion the
     * friction history moves to the new nodes (see the class
     * description). Collective. */
    void
    setup(const TiedCopyDoFs<dim> &dofs);

    /** The contact forces of the displacement @p u (owned entries) on the
     * laminate into @p contact (owned entries, overwritten), the force on
     * the sphere and its acceleration, and the contact energy. Collective. */
    void
    evaluate(const Vector &u, Vector &contact);

    /** A prescribed sphere: its centre at time @p t, Center + Velocity t
     * or Center + Path(t). */
    void
    move_to(const double t);
    /** A prescribed sphere in an explicit run, before the evaluate() of
     * the step that ends at @p t (of length @p dt): it moves to where it is
     * at @p t, with the mean velocity of the step. Returns the move. */
    Tensor<1, dim>
    step_to(const double t, const double dt);
    /** The same after that evaluate(): the impulse of the mean force of
     * the step on the sphere, for the mean contact force of the output
     * interval. @p force_before is the force on the laminate before the
     * step (force_on_laminate()). Returns the work the sphere did on the
     * laminate and its contact in the step, the mean force on the laminate
     * times the move (the trapezoidal rule, as in static runs). */
    double
    finish_step(const Tensor<1, dim> &force_before,
                const Tensor<1, dim> &move,
                const double          dt);
    /** Whether the centre is prescribed (an indenter) rather than free. */
    bool
    is_prescribed() const
    {
      return prescribed;
    }

    /** Static runs: keep the friction history of the last evaluate() (the
     * converged state) as the reference of the next step's slips. */
    void
    commit();

    /** Static runs: the contact tangent at @p u (owned entries),
     * d(k g n)/du = k (n n^T + g / r (I - n n^T)) per node in contact with
     * r = |x - c|, and with friction the stick spring's or the sliding
     * force's (node_tangent()), into @p tangent through @p constraints
     * (hanging nodes hand it to their parents). Not compressed. */
    void
    add_tangent(const Vector                    &u,
                const AffineConstraints<double> &constraints,
                TrilinosWrappers::SparseMatrix  &tangent) const;

    /** The same tangent times @p direction added to @p product (owned
     * entries, unconstrained). */
    void
    add_tangent_product(const Vector &u,
                        const Vector &direction,
                        Vector       &product) const;

    /** The force of the sphere on the laminate along the face's inward
     * normal at the last evaluate(), all ranks. */
    double
    normal_force() const
    {
      return -inward * force[normal_axis];
    }

    /** The centre's coordinate along the face's normal. */
    double
    normal_position() const
    {
      return center[normal_axis];
    }

    /** The nodes in contact at the last evaluate(), all ranks. */
    unsigned int
    contact_nodes() const
    {
      return n_contact;
    }

    /** The force of the sphere on the laminate at the last evaluate(). */
    Tensor<1, dim>
    force_on_laminate() const
    {
      return -force;
    }

    Tensor<1, dim>
    position() const
    {
      return center;
    }

    void
    kick(const double half_step)
    {
      velocity += half_step * acceleration;
    }

    void
    drift(const double step)
    {
      center += step * velocity;
    }

    /** Zero for a prescribed sphere: its motion is a boundary condition
     * (the work it does is external work), not a body of the system. */
    double
    kinetic_energy() const
    {
      return prescribed ? 0. : 0.5 * mass * velocity.norm_square();
    }

    /** sum_i k_i g_i^2 / 2 at the last evaluate(), all ranks. */
    double
    contact_energy() const
    {
      return energy;
    }

    /** The deepest penetration of a node at the last evaluate(). */
    double
    penetration_depth() const
    {
      return penetration;
    }

    /** The linear momentum of the sphere (zero if prescribed, see
     * kinetic_energy()). */
    Tensor<1, dim>
    momentum() const
    {
      return prescribed ? Tensor<1, dim>() : mass * velocity;
    }

    /** Explicit stability: Gershgorin's row sums of the contact springs,
     * 2 k_i on each component of every candidate node (its own spring and
     * the coupling to the sphere; k_i alone for a prescribed sphere, which
     * is no unknown), added to @p rows (owned entries). */
    void
    add_penalty_rows(Vector &rows) const;

    /** Gershgorin's bound on omega^2 of the sphere's row: 2 sum k_i / M
     * over the candidates of all ranks (zero for a prescribed sphere: it
     * has no row). Collective. */
    double
    frequency_squared() const;

    /** The largest k_i / m_i of the candidate nodes against the lumped
     * @p mass (owned entries): the square of the fastest contact
     * oscillation of a node against the sphere. Collective. */
    double
    node_frequency_squared(const Vector &mass) const;

    /** The history columns of an output step at @p t: centre and
     * velocity along the face normal, the contact force on the laminate
     * along the inward normal (at t, and the mean since the last output
     * step: the sphere's momentum change over the interval, which the
     * chatter of single nodes does not blur), the nodes in contact and
     * the deepest penetration; with friction, the force's components in
     * the face, the sums of the nodes' normal and friction forces, the
     * sliding nodes and the dissipation. */
    std::vector<std::pair<std::string, double>>
    columns(const double t);

    /** With friction: the force on the laminate in the face's plane, the
     * sums of the nodes' normal and friction forces, the sliding nodes and
     * the dissipation so far (none without friction). */
    std::vector<std::pair<std::string, double>>
    friction_columns() const;

    /** Centre, velocity and acceleration, the velocity and time of the
     * last output step, the force and, for a prescribed sphere, the
     * impulse since that step (for a checkpoint). */
    std::vector<double>
    state() const;
    void
    set_state(const std::vector<double> &values);

    /** Friction: the energy dissipated since the start (all ranks). */
    double
    friction_dissipation() const
    {
      return dissipation;
    }

    bool
    has_friction() const
    {
      return friction_coefficient > 0;
    }

    /** The friction history of every node of all ranks, keyed by the
     * nodes' positions, and the committed centre and dissipation (for a
     * checkpoint; the same values on any number of ranks). Collective. */
    std::vector<double>
    friction_state() const;
    /** Restore friction_state() on the current nodes (saved nodes no
     * longer on the face are dropped). Throws on every rank if a node of
     * the face has no entry. Collective. */
    void
    set_friction_state(const std::vector<double> &values);

    /** Take over friction_state() of the impactor of the mesh before a
     * crack insertion: the heirs of its nodes as in the class's
     * description; a node at no old node's position starts afresh (the
     * state does not know the old faces: a mesh change goes through
     * setup() of the same impactor). Collective. */
    void
    inherit_friction_state(const std::vector<double> &values);

  private:
    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               position;
      double                                   stiffness;
      /** Unit direction from the node into its face's cells (the mean of
       * their centres): which copy of a split node it is. */
      Tensor<1, dim> side;
    };

    /** A face of the laminate under the sphere: its vertices, the unit
     * direction from each vertex to its cell's centre (which copy of a
     * split node the vertex is, as a node's side tells) and its diameter.
     * Every rank keeps all faces (the triangulation is shared). */
    struct Face
    {
      std::vector<Point<dim>>     vertices;
      std::vector<Tensor<1, dim>> sides;
      double                      size;
    };

    /** What the friction of a node keeps from the last commit: its
     * tangential force and stick energy, whether it touched, and its
     * displacement then. */
    struct History
    {
      Tensor<1, dim> force;
      double         stick_energy = 0;
      bool           in_contact   = false;
      Tensor<1, dim> displacement;
      /** The displacement is that of an evaluation (false for a node new
       * to the face: its first slip increment is zero). */
      bool referenced = false;
    };

    /** The node's displacement since the commit less the centre's. */
    Tensor<1, dim>
    slip_increment(const unsigned int i, const Vector &u) const;

    /** friction_state() into the history of the current nodes; a node it
     * does not name starts afresh, or, if @p require_all, throws on every
     * rank. A checkpoint (@p require_all) restores each record as it was;
     * otherwise the heirs take the records' stick stretch, and a node at the
     * midpoint of an edge or at the centre of one of @p old_faces the mean
     * of that face's vertices. Collective. */
    void
    restore_history(const std::vector<double> &values,
                    const bool                 require_all,
                    const std::vector<Face>   &old_faces = {});

    /** friction_state() parsed: its records (position, side, then the
     * history: force, stick energy, contact flag, displacement; older
     * checkpoints have no side) by position. */
    struct Records
    {
      const std::vector<double>                                  &values;
      bool                                                        with_sides;
      unsigned int                                                stride, first;
      std::size_t                                                 n_saved;
      std::map<std::array<double, dim>, std::vector<std::size_t>> at_position;

      const double *
      history_of(const long k) const
      {
        return values.data() + k * stride + first;
      }
    };
    Records
    parse_records(const std::vector<double> &values) const;

    /** The record at @p position whose side is closest to @p side, or -1
     * if none is there. */
    long
    closest_record(const Records        &records,
                   const Point<dim>     &position,
                   const Tensor<1, dim> &side) const;

    /** For each node, the record whose history it takes (closest_record()
     * at its position and side), or -1. */
    std::vector<long>
    heirs_of(const Records &records) const;

    /** For each node without a record (@p source -1): the records of the
     * vertices of the face of @p old_faces at whose centre or edge
     * midpoint it lies, on its side (empty if none). */
    std::vector<std::vector<long>>
    places_of(const Records           &records,
              const std::vector<long> &source,
              const std::vector<Face> &old_faces) const;

    /** Node @p i takes the mean stretch, displacement and contact of the
     * records @p members. */
    void
    carry(const Records           &records,
          const std::vector<long> &members,
          const unsigned int       i);

    /** A checkpoint's records node for node (throws on every rank if a
     * node or a record in contact is left over). Collective. */
    void
    restore_exactly(const Records &records, const std::vector<long> &source);

    /** The sum over the nodes of all ranks that take record k of their
     * stiffness, per record (added in a partition-independent order).
     * Collective. */
    std::vector<double>
    heirs_stiffness(const std::vector<long> &source,
                    const std::size_t        n_saved) const;

    /** The stiffest spring of a node over k: the stick spring's factor
     * if friction makes it stiffer than the normal one. */
    double
    stiffest() const
    {
      return friction_coefficient > 0 ? std::max(1., tangential_factor) : 1.;
    }

    /** The response of node @p i at @p u: normal n, pressure force
     * p = -k g (0 out of contact), and with friction the old tangential
     * force, the slip since the commit, the trial force and the returned
     * one, the normal part of the trial before it is projected (for the
     * tangent) and whether it slides. */
    struct Response
    {
      Tensor<1, dim> n, old_force, slip, trial, friction;
      double         gap = 0, distance = 0, pressure = 0;
      double         normal_part = 0;
      bool           slipping    = false;
    };
    Response
    respond(const unsigned int i, const Vector &u) const;

    /** The contact tangent of node @p i at @p u (zero out of contact). */
    Tensor<2, dim>
    node_tangent(const unsigned int i, const Vector &u) const;

    Tensor<1, dim>
    displacement(const Node &node, const Vector &u) const;

    MPI_Comm comm;
    double   radius, mass, penalty;
    double   friction_coefficient, tangential_factor;
    bool     static_mode;
    /** The centre follows move_to() (an indenter), not the forces. */
    bool prescribed;
    /** A free sphere moves along the face's normal only. */
    bool guided;
    /** Center + path(t) for a prescribed sphere (null: Velocity t). */
    std::shared_ptr<Function<dim>> path;
    unsigned int                   boundary_id, normal_axis;
    double                         inward; // -1 on a + face, +1 on a - face
    std::vector<Node>              nodes;
    std::vector<Face>              faces;
    Tensor<1, dim>                 center, velocity, acceleration, force;
    /** A cylinder's unit axis (zero: a sphere, or the circle in 2D). */
    Tensor<1, dim> axis;
    /** The parameter Center: a prescribed sphere is at start + Velocity t
     * or start + Path(t). */
    Tensor<1, dim> start;
    /** A prescribed sphere without a Path moves with this velocity (the
     * parameter; velocity is what it did in the last step, for the
     * output: feeding that back would let round-off grow step by
     * step). */
    Tensor<1, dim> prescribed_velocity;
    Tensor<1, dim> row_velocity;
    double         row_time = 0;
    /** A prescribed sphere in an explicit run: the impulse of the force on
     * it since the last output step (a free sphere's is its momentum
     * change). */
    Tensor<1, dim> row_impulse;
    double         energy = 0, penetration = 0;
    unsigned int   n_contact = 0;
    /** Friction: the committed history per node, the last evaluation's
     * (static runs keep it at commit()), the centre of the commit, the
     * dissipation so far and that of the last evaluation since the
     * commit, and the sums of the last evaluation. */
    std::vector<History> history, trial_history;
    /** setup() ran before (the same on every rank). */
    bool           set_up = false;
    Tensor<1, dim> committed_center;
    double         dissipation = 0, pending_dissipation = 0;
    double         pressure_sum = 0, friction_sum = 0;
    unsigned int   n_sliding = 0;
  };
} // namespace amfrac

#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/parameters/contact.h>
#include <array>
#include <cstdint>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace amfrac
{
  /**
   * Contact between the laminate's own bodies (issue 10): penalty
   * node-to-face contact with Coulomb friction, for explicit runs and on
   * the static Newton path (with its tangent), with Q1 elements.
   *
   * The surface is every outer face and both sides of every released face
   * (cohesive interfaces, cracks, unbonded interfaces). Each surface node
   * (a reduced node) is a slave of every surface face it is not excluded
   * from: the faces the node is a vertex of are excluded, so is every
   * face the node lay behind in the undeformed laminate (inside its body:
   * a node that hangs on the face's own cell lies only half an edge
   * behind it), and so is a face of an outer or a paired surface (an
   * interface or crack whose cohesive element keeps its own contact) if
   * the node lay on it in the undeformed laminate. So a crack face meeting
   * a face it was never paired with, a fragment hitting another or a
   * sublaminate sliding far along its neighbour are in contact, and a
   * cohesive pair is not counted twice.
   *
   * Search: each face's box (its vertices, the points a depth behind
   * them, 2 % of its size and twice a margin) in a uniform grid whose cell
   * sizes are the mean box extents per direction; each node keeps the
   * faces whose box holds it as candidates until some node has moved by a
   * third of the margin (Verlet). O(faces + nodes) per search, and no pair
   * of far faces is ever looked at. Narrow phase: the closest point of the
   * bilinear face (Newton on its two coordinates), the gap g along the face's
   * outward normal there; a node is in contact with the nearest face it
   * penetrates by less than half the depth of the face's cell and half its
   * shortest edge (deeper points belong to another face, e.g. the other
   * side of a thin ply) and that its own faces look at (area_penalty . n
   * below -1e-3 |area_penalty|: a node that hangs at the midpoint of an
   * edge of the face's own cell lies half that edge behind it, on a face at
   * right angles to it).
   *
   * Forces: the node gets -k g n and the face's nodes +k g N_a n
   * (momentum exactly kept). For a fixed k that is the gradient of the
   * potential k g^2 / 2, since the point is the closest one; k follows the
   * normal (below), and the force leaves out its derivative, which
   * vanishes for flat contact that does not turn. Both surfaces are slaves (two
   * passes), each node with k = Penalty x area / 2, where area is its
   * share of the area of its faces projected on the contact normal, so
   * that matching meshes penetrate by pressure / Penalty; a node none of
   * whose faces looks at a face is not in contact with it. With finite
   * strain the area and its direction are the current ones
   * (set_deformed_areas()), so that a body that turns over or folds during
   * the run touches what its faces now look at.
   * Friction: the tangential force grows with the tangential slip
   * increment relative to the face, k_t = factor x k, and is returned to
   * the Coulomb cone mu k |g|; the dissipation is the work of the
   * friction force (trapezoidal over the step) less the change of the
   * stick springs' energy, so it is zero while sticking; a stick spring
   * whose node leaves contact (or is split by a crack) releases its energy
   * into the dissipation, and a node that leaves the face it touched
   * dissipates, as a pair whose force falls to zero, the mean of its old
   * force and none along the step's slip on that face (leaving_work()).
   *
   * Static runs: evaluate() takes the friction history from the last
   * converged state (commit()). The tangent of a pair is -c_I df/du_J with
   * c = (1, -N_1, ..., -N_m) over the node and its face's nodes: the
   * normal part -k n (x) dg/du (dg from the closest point, with the
   * turning of a face whose edge the node has passed), the stick spring
   * -k_t c_J (I - n n^T) or the slip's return (the cone's radius follows
   * the normal force, the direction the trial force); the turning of the
   * normal times the gap is left out. Its matrix entries couple each node to
   * the nodes of its candidate faces; when a later search finds a
   * candidate outside them, couplings_outdated() says so and the
   * simulator builds the pattern again.
   *
   * MPI: every rank gathers the displacements of all surface nodes (one
   * Allgatherv of the owned ones) and evaluates the whole surface in an
   * order independent of the partition (nodes sorted by their undeformed
   * position, faces by cell), then keeps the forces on its owned dofs. The
   * forces, energies and histories are the same on any number of ranks bit
   * for bit, and no reduction is needed; the cost per rank is that of the
   * surface, not of the volume.
   */
  template <int dim>
  class BodyContact
  {
  public:
    using Vector     = TrilinosWrappers::MPI::Vector;
    using FaceFilter = typename TiedCopyDoFs<dim>::FaceFilter;

    BodyContact(const parameters::Contact &parameters, MPI_Comm comm);

    /** The surface of the current mesh and numbering. @p released: the
     * faces the DoF layer left untied; @p paired: those of them with a
     * cohesive partner (interfaces and cracks). The friction history of a
     * node moves with its key (its first cell and vertex), so it survives
     * a crack insertion that renumbers the dofs. After a @p mesh_change
     * (refinement or coarsening: the keys, active cell indices, mean
     * nothing on the new mesh) it moves by place instead: see
     * carry_by_place(). Collective. */
    void
    setup(const TiedCopyDoFs<dim> &dofs,
          const FaceFilter        &released,
          const FaceFilter        &paired,
          const bool               mesh_change = false);

    /** The contact forces on the laminate at the displacement @p u
     * (owned entries) into @p contact (owned entries, overwritten), and
     * the update of the friction history from the last call. Collective. */
    void
    evaluate(const Vector &u, Vector &contact);

    /** Static runs: the entries coupling every surface node to the nodes
     * of its candidate faces at the displacement @p u, from the rows this
     * rank owns, through @p constraints (a hanging node's row and column
     * go to its parents); they are remembered for couplings_outdated().
     * Collective. */
    void
    add_couplings(const Vector                      &u,
                  const AffineConstraints<double>   &constraints,
                  TrilinosWrappers::SparsityPattern &pattern);

    /** A search since add_couplings() found a candidate face of a node
     * whose entries are not in the pattern. */
    bool
    couplings_outdated() const
    {
      return outdated;
    }

    /** The tangent of the pairs of the last evaluate(), from the rows
     * this rank owns, into @p tangent through the constraints that the
     * last add_couplings() was given (a hanging node's rows and columns go
     * to its parents, a supported row keeps the bulk's diagonal; static
     * runs; call compress(add) after it). */
    void
    add_tangent(TrilinosWrappers::SparseMatrix &tangent) const;

    /** @p product += that tangent times @p direction (owned entries).
     * Collective. */
    void
    add_tangent_product(const Vector &direction, Vector &product);

    /** Static runs: evaluate() computes trial states from the last
     * converged one, which commit() replaces by the last evaluation's. */
    void
    set_static()
    {
      static_mode = true;
    }
    void
    commit();

    /** Finite strain (total Lagrangian runs): a node's area vector, which
     * gives its penalty k = -area . n and says which faces it looks at,
     * follows its faces as they turn and stretch (evaluated at every
     * displacement) instead of staying the undeformed one. A body that
     * folds or turns over then touches itself and others as it would
     * unturned; with the undeformed vector a node turned by 90 degrees
     * would look at no face. The vector's change is left out of the
     * tangent, as the penalty's change with the face's normal is. */
    void
    set_deformed_areas()
    {
      deformed_areas = true;
    }

    /** No pair now and none when the tangent was last factorized. */
    bool
    tangent_unchanged() const
    {
      return pairs.empty() && !pairs_factorized;
    }
    void
    mark_factorized()
    {
      pairs_factorized = !pairs.empty();
    }

    /** Penalty energy of the normal and stick springs at the last
     * evaluate(). */
    double
    contact_energy() const
    {
      return energy;
    }

    /** Energy dissipated by friction since the start. */
    double
    friction_dissipation() const
    {
      return dissipation;
    }

    /** Explicit stability: each surface node's springs, as a slave and as
     * a face node of the slaves on its faces, 4 (k + k_t) on each of its
     * rows (owned entries of @p rows). */
    void
    add_penalty_rows(Vector &rows) const;

    /** The history columns: nodes in contact, the sum of their normal and
     * friction forces, the deepest penetration. */
    std::vector<std::pair<std::string, double>>
    columns() const;

    /** Friction history, last positions and dissipation (for a
     * checkpoint); the same on every rank. */
    std::vector<double>
    state() const;
    void
    set_state(const std::vector<double> &values);

    /** Surface faces and nodes of the last setup(). */
    std::size_t
    n_faces() const
    {
      return faces.size();
    }
    std::size_t
    n_nodes() const
    {
      return nodes.size();
    }

    /** Wall time of the search (grid and closest points) and of the
     * whole evaluation, summed over the calls, and the number of calls. */
    double        search_seconds = 0, evaluate_seconds = 0, rebuild_seconds = 0;
    unsigned long n_evaluations = 0, n_rebuilds = 0;

  private:
    static constexpr unsigned int n_face_vertices = 1u << (dim - 1);

    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               reference;
      /** Half the penalty times the node's share of each of its faces'
       * area, as a vector along the faces' outward normals, and the sum
       * of the magnitudes. A node in contact with a face of normal n
       * takes -area_penalty . n: the share of its faces that look at the
       * face (a node on the edge of a block does not add the side face's
       * area to the contact of its top face). */
      Tensor<1, dim> area_penalty;
      /** The same in the current configuration (set_deformed_areas()). */
      Tensor<1, dim> current_area;
      double         stiffness = 0;
      /** (active cell index, vertex) of its first copy: partition- and
       * numbering-independent. */
      std::pair<unsigned int, unsigned int> key;
      /** Every (active cell index, vertex) at the node: after a crack
       * insertion splits it, the next setup() finds the copies' parent by
       * their own keys among these. */
      std::vector<std::pair<unsigned int, unsigned int>> corners;
    };

    /** setup(): the friction history of the old nodes (@p old, by key)
     * to the new ones: a node that kept its key takes its own; the copies
     * of a split node (found through @p parent_of, the old node of each
     * corner) share their parent's by their stiffness. The old nodes
     * taken are removed from @p old. */
    template <typename Carried, typename Parent>
    void
    inherit_history(
      std::map<std::pair<unsigned int, unsigned int>, Carried>      &old,
      const std::map<std::pair<unsigned int, unsigned int>, Parent> &parent_of);

    struct Face
    {
      std::array<unsigned int, n_face_vertices> nodes;
      /** +1 or -1: turns the vertices' orientation into the outward
       * normal of the face's cell. */
      double sign;
      /** Half the depth of the face's cell along its normal, at most half
       * its shortest edge: deeper penetrations are not this face's. */
      double depth;
      /** Outer and paired faces exclude the nodes that lay on them. */
      bool exclude_coincident;
    };

    struct History
    {
      /** The stick spring's force; if @p carried, its stretch
       * (force / k_t) instead. */
      Tensor<1, dim> friction;
      /** |friction|^2 / (2 k_t) when it was stored. */
      double stick_energy = 0;
      bool   in_contact   = false;
      /** Set by a mesh change: the next evaluate() turns the stretch into
       * the force of the node's new stiffness. */
      bool carried = false;
      /** The face and the point on it that the node touched, for the
       * friction work of the step in which it leaves the face. */
      unsigned int   face = numbers::invalid_unsigned_int;
      Point<dim - 1> xi;
    };

    /** setup() after a mesh change: each new node takes the stick
     * stretch of the old surface at its place, on its side (@p old, the
     * old nodes and faces): an old node's own, or the mean of the old
     * face's vertices at the midpoint of one of its edges or at its
     * centre (the new vertices refinement makes on flat faces; a vertex a
     * curved manifold moves off them starts without a spring); the place
     * whose side (an old node's outward normal, a mean's the normalized
     * sum of its members') is closest to the node's wins (an old node on
     * a tie), and only on the node's side. The stretch times the new
     * stiffness keeps the friction force and the stick energy of a
     * uniform stick field; what changes (also where the new cone is
     * narrower) is a mesh-change effect, booked by the simulator with the
     * remeshing energy, not dissipation. */
    void
    carry_by_place(const std::vector<Node>    &old_nodes,
                   const std::vector<Face>    &old_faces,
                   const std::vector<History> &old_history);
    /** The stick stretch of a history record (zero if not sticking). */
    static Tensor<1, dim>
    stretch_of(const History &h);

    /** Closest point of @p x on the face with vertex positions
     * @p vertices: whether it lies within @p inside (in face coordinates)
     * of the face, its coordinates (clamped to the face) and the point;
     * @p clamped (if given) is set when the coordinates were clamped. */
    bool
    project(const std::array<Point<dim>, n_face_vertices> &vertices,
            const Point<dim>                              &x,
            Point<dim - 1>                                &xi,
            Point<dim>                                    &on_face,
            const double                                   inside,
            bool *clamped = nullptr) const;
    /** The unit normal of the face (before its sign) at @p xi. */
    Tensor<1, dim>
    normal(const std::array<Point<dim>, n_face_vertices> &vertices,
           const Point<dim - 1>                          &xi) const;
    static std::array<double, n_face_vertices>
    shape_values(const Point<dim - 1> &xi);
    /** Node @p s is never in contact with @p face: in the undeformed
     * laminate it lay behind it (inside the face's body: a node of the
     * face's own cell or one that hangs on it), or on it if the face
     * excludes coincident nodes. */
    bool
    excluded(const unsigned int s, const Face &face) const;
    void
    gather_positions(const Vector &u);
    /** Each node's current_area from the current positions. */
    void
    update_current_areas();
    /** The area vector that node @p s presses with: the undeformed one,
     * or the current one with set_deformed_areas(). */
    const Tensor<1, dim> &
    facing_area(const unsigned int s) const
    {
      return deformed_areas ? nodes[s].current_area : nodes[s].area_penalty;
    }
    /** The owned entries of @p u at every surface node, gathered. */
    void
    gather(const Vector &u, std::vector<Tensor<1, dim>> &values);
    /** Every candidate of the last search is in the matrix. */
    bool
    candidates_coupled() const;
    /** The friction work of node @p s in the step in which it left the
     * face it touched: what a pair whose force falls to zero over the
     * step dissipates (the trapezoidal rule of the external work). */
    double
    leaving_work(const unsigned int s) const;
    /** x_s - x(xi): node @p s from the point @p xi of @p face, from the
     * reference positions and the displacements separately. */
    Tensor<1, dim>
    offset(const unsigned int    s,
           const Face           &face,
           const Point<dim - 1> &xi) const;
    /** The dofs of a node and a face: the node's, then its face nodes'. */
    std::vector<types::global_dof_index>
    pair_dofs(const unsigned int slave, const unsigned int face) const;
    /** @p f into the owned entries @p entries of node @p node's dofs (if
     * this rank owns it). */
    void
    add_to_owned(double               *entries,
                 const unsigned int    node,
                 const Tensor<1, dim> &f) const;
    /** The local coordinates of a face's centre. */
    static Point<dim - 1>
    face_middle();
    /** last_slaves from the history's contact flags. */
    void
    collect_slaves();
    /** Find the candidate faces of every node again (grid and boxes) if
     * a node has moved too far since the last time. */
    void
    update_candidates();

    MPI_Comm comm;
    double   penalty, friction_coefficient, tangential_factor;

    std::vector<Node>    nodes;
    std::vector<Face>    faces;
    std::vector<History> history;
    /** Current positions and displacements of all nodes, and the
     * displacements the slip increments start from (the last evaluation's
     * in explicit runs, the last converged state's in static ones). */
    std::vector<Point<dim>>     positions;
    std::vector<Tensor<1, dim>> displacements, previous;
    /** Nodes without a last position yet (new, or split by a crack). */
    std::vector<bool> fresh;
    /** The nodes this rank sends, and the gathered order of all ranks. */
    std::vector<unsigned int> owned_nodes, gathered_nodes;
    /** The owned nodes' entries in the owned part of a vector. */
    std::vector<std::array<unsigned int, dim>> owned_local;
    std::vector<int>                           gather_sizes, gather_offsets;
    std::vector<double>                        send_buffer, receive_buffer;

    /** A node in contact with a face: its closest point's coordinates,
     * the normal there and the gap. */
    struct Pair
    {
      unsigned int   slave, face;
      Point<dim - 1> xi;
      Tensor<1, dim> n;
      double         gap;
      /** Friction: the trial force before the return, the stick
       * stiffness, and whether the node slips. */
      Tensor<1, dim> trial;
      double         kt       = 0;
      bool           slipping = false;
    };
    /** A pair's members: its node, then its face's nodes. */
    static constexpr unsigned int n_members = n_face_vertices + 1;
    /** A pair's share of the tangent at the last evaluation: block
     * [I][J] is d(-F_I)/du_J, with F_I the contact force on member I. */
    using PairTangent
      = std::array<std::array<Tensor<2, dim>, n_members>, n_members>;
    PairTangent
    pair_tangent(const Pair &pair) const;
    /** A pair's members, and whether this rank owns one of them. */
    std::array<unsigned int, n_members>
    members_of(const Pair &pair) const;
    bool
    owns_a_member(const Pair &pair) const;
    /** What pair_tangent() differentiates the friction with: the shape
     * values at the closest point and their gradients in xi, and the
     * gradients of xi, the normal, the penalty k and the gap with respect
     * to each member's displacement. */
    struct PairGradients
    {
      std::array<double, n_face_vertices>                        N;
      std::array<Tensor<1, dim - 1>, n_face_vertices>            dN;
      std::array<std::array<Tensor<1, dim>, dim - 1>, n_members> dxi{};
      std::array<Tensor<2, dim>, n_members>                      dn;
      std::array<Tensor<1, dim>, n_members>                      dk, dg;
    };
    /** The friction's part of pair_tangent(): adds d f_t/du_J to @p B
     * and returns f_t. */
    Tensor<1, dim>
    add_friction_gradient(const Pair                            &pair,
                          const PairGradients                   &gradients,
                          std::array<Tensor<2, dim>, n_members> &B) const;
    /** Scratch of evaluate(), kept to reuse its memory: the faces' boxes,
     * the grid (cell key, face) sorted, the pairs found. */
    std::vector<std::pair<Point<dim>, Point<dim>>>      boxes;
    std::vector<std::pair<std::uint64_t, unsigned int>> grid;
    std::vector<Pair>                                   pairs;
    /** Per node: its index among the owned nodes (-1: another rank's),
     * and a mark used inside evaluate() (all false between calls); the
     * nodes in contact at the last evaluate(). */
    std::vector<int>          local_of_node;
    std::vector<bool>         touching;
    std::vector<unsigned int> last_slaves;
    /** The candidate faces of each node (CSR), the positions they were
     * found at and the margin the boxes were grown by. */
    std::vector<unsigned int> candidate_start, candidates;
    std::vector<Point<dim>>   built_positions;
    double                    margin           = 0;
    bool                      candidates_built = false;
    /** Static runs: the parents (and weights) of every surface dof that
     * hangs (none for a supported one), gathered from the ranks that own
     * them by add_couplings() (a rank's constraints hold its relevant dofs
     * only, and a face in contact may lie anywhere). */
    std::map<types::global_dof_index,
             std::vector<std::pair<types::global_dof_index, double>>>
      constrained_dofs;
    /** A surface dof's targets in the matrix: its parents if it is
     * constrained (none if supported), else itself. */
    void
    matrix_targets(
      const types::global_dof_index                            dof,
      std::vector<std::pair<types::global_dof_index, double>> &into) const;
    /** Static runs: the candidates whose entries are in the matrix (CSR,
     * each node's faces sorted), and whether a search found others. */
    std::vector<unsigned int> coupled_start, coupled;
    bool                      outdated = false, pairs_factorized = false;
    /** Static runs: the friction history and dissipation of the last
     * evaluation, kept by commit(). */
    bool                 static_mode = false, deformed_areas = false;
    std::vector<History> trial_history;
    double               pending_dissipation = 0;
    /** Scratch of add_tangent_product(). */
    std::vector<Tensor<1, dim>> gathered;

    double energy = 0, dissipation = 0, normal_force = 0, friction_force = 0,
           penetration     = 0;
    unsigned int n_contact = 0;
  };
} // namespace amfrac

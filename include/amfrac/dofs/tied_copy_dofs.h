#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <memory>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /**
   * The tied-copy DoF layer (doc/design.md). Every cell owns its own copy
   * of each of its nodes (a discontinuous FE_DGQ layout on an intact
   * triangulation); a tie map decides which copies are one unknown. Copies
   * across an intact face are tied; copies across a released face (a
   * cohesive interface or a crack) are not, so releasing a face duplicates
   * exactly the nodes that the released faces separate.
   *
   * All linear algebra lives on the *reduced* numbering, one index per
   * group of tied copies, so matrices and solvers cost what a continuous
   * FE_Q code costs. Reduced indices are numbered node by node (the dim
   * components of a node are consecutive, as algebraic multigrid wants),
   * and each MPI rank owns a contiguous block: a group belongs to the
   * lowest rank owning one of its copies.
   */
  template <int dim>
  class TiedCopyDoFs
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    /** Says whether the face @p face of @p cell is released (untied). */
    using FaceFilter
      = std::function<bool(const CellIterator &cell, const unsigned int face)>;

    /** Copies of the element of @p degree for cells of @p shape: the
     * hypercube (Q elements on quadrilaterals and hexahedra) or, in 3D, the
     * wedge (P elements on prisms). Every cell of the mesh has that shape. */
    TiedCopyDoFs(const Triangulation<dim> &triangulation,
                 const unsigned int        degree,
                 const ReferenceCell      &shape
                 = ReferenceCells::get_hypercube<dim>());

    /** Build the copies and the tie map; faces for which @p released
     * returns true stay untied. On a hanging face, a fine copy that sits on
     * a coarse node is tied to it and the others are constrained to
     * interpolate the coarse face (hanging_node_constraints()). */
    void
    distribute(const FaceFilter &released = FaceFilter());

    /** A face of a cell of copy_handler(). */
    using Face = std::pair<CellIterator, unsigned int>;

    /** Release @p faces (regular interior faces, from either side) on the
     * mesh of the last distribute(), which has not changed since: crack
     * insertion. @p released says which faces are released now (those of
     * the last call and @p faces). Only the groups of the copies on
     * @p faces are formed again; the rest is a few linear passes over
     * integer arrays (no geometry, no face matching as in distribute()).
     * The result is the one distribute(@p released) gives. */
    void
    release(const std::vector<Face> &faces, const FaceFilter &released);

    /** The DoFHandler of the copy space (for FEValues and DataOut). */
    const DoFHandler<dim> &
    copy_handler() const
    {
      return dof_handler;
    }

    /** The mapping every integral and output on the copy space uses:
     * where the mesh has curved manifolds (an open hole: a Q2 solution on
     * a polygonal hole would converge to the polygon's answer) MappingQ of
     * the element's degree on hexahedra and MappingFE of FE_WedgeP of the
     * degree on wedges (HoleEdgeManifold), the linear map otherwise.
     * Chosen at the first distribute(). */
    const Mapping<dim> &
    get_mapping() const
    {
      return *mapping;
    }

    const FiniteElement<dim> &
    get_fe() const
    {
      return *fe;
    }

    /** The shape of every cell (hypercube or wedge). */
    const ReferenceCell &
    reference_cell() const
    {
      return shape;
    }

    /** The straight-sided mapping of the cell shape (MappingQ1, or the
     * linear wedge map): where the copies are, whatever the manifolds. */
    const Mapping<dim> &
    get_linear_mapping() const
    {
      return shape.template get_default_linear_mapping<dim>();
    }

    /** The Gauss rule exact to degree 2 n - 1 (@p n_points_1d = n) on the
     * cell shape: QGauss, or on a wedge the Witherden-Vincent triangle rule
     * times QGauss<1> (n at most 7; deal.II's QGaussWedge stops at 4). */
    Quadrature<dim>
    cell_quadrature(const unsigned int n_points_1d) const;

    /** The same with @p n_points_through points along the last axis (the
     * laminate's thickness in 3D): the triangle (or QGauss<dim-1>) rule of
     * @p n_points_1d times QGauss<1>(@p n_points_through). */
    Quadrature<dim>
    cell_quadrature(const unsigned int n_points_1d,
                    const unsigned int n_points_through) const;

    /** The same rules on the faces, for FEFaceValues: one rule for the
     * faces of a hypercube, one per face in face order on a wedge (it has
     * triangles and quadrilaterals). */
    hp::QCollection<dim - 1>
    face_quadrature(const unsigned int n_points_1d) const;

    /** Number of reduced unknowns. */
    types::global_dof_index
    n_dofs() const
    {
      return support_points.size();
    }

    types::global_dof_index
    n_copies() const
    {
      return copy_to_reduced.size();
    }

    const IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    /** Hanging-node constraints on the reduced numbering (all lines, on
     * every rank). */
    const AffineConstraints<double> &
    hanging_node_constraints() const
    {
      return hanging_constraints;
    }

    /** Reduced indices on locally owned cells and on their neighbours
     * across released faces, the owned ones, and those that hanging
     * constraints of these refer to. */
    const IndexSet &
    locally_relevant_dofs() const
    {
      return relevant_dofs;
    }

    /** Make @p dofs locally relevant on this rank (e.g. the few dofs of a
     * constraint that couples distant nodes, such as a loading lever). */
    void
    add_relevant_dofs(const std::vector<types::global_dof_index> &dofs)
    {
      relevant_dofs.add_indices(dofs.begin(), dofs.end());
      relevant_dofs.compress();
    }

    /** The reduced dofs on the boundary faces with id @p boundary_id for
     * which @p select(dof) is true, sorted, each once. Scans all cells of
     * the replicated mesh, so every rank gets the same list. */
    std::vector<types::global_dof_index>
    boundary_dofs(
      const types::boundary_id                                  boundary_id,
      const std::function<bool(const types::global_dof_index)> &select) const;

    /** The cells, owned or not, with at least one locally owned dof, in
     * the order of the active cells (the same on every rank). A sum of
     * cell contributions over these cells into the owned entries alone
     * adds, for every owned entry, the same terms in the same order as a
     * single rank does: the result does not depend on the partition
     * (ElasticAssembler::lumped_mass(), BulkForceOperator). */
    std::vector<CellIterator>
    cells_with_owned_dofs() const;

    /** The reduced index of copy @p copy (a dof of copy_handler()). */
    types::global_dof_index
    reduced_index(const types::global_dof_index copy) const
    {
      return copy_to_reduced[copy];
    }

    /** Reduced indices of the dofs of @p cell, in the cell's local order. */
    void
    get_dof_indices(const CellIterator                   &cell,
                    std::vector<types::global_dof_index> &indices) const;

    const Point<dim> &
    support_point(const types::global_dof_index i) const
    {
      return support_points[i];
    }

    unsigned int
    component(const types::global_dof_index i) const
    {
      return components[i];
    }

    /** Local dofs of a cell whose support points lie on face @p face. */
    const std::vector<unsigned int> &
    dofs_on_face(const unsigned int face) const
    {
      return face_dofs[face];
    }

    /** Write the copy values of locally owned cells from a reduced vector
     * that holds the locally relevant entries. */
    template <typename VectorType>
    void
    expand(const VectorType &reduced, Vector<double> &copies) const;

    /** Every reduced entry on every rank, from the owned entries of
     * @p owned (a sum over the ranks). */
    Vector<double>
    replicate(const TrilinosWrappers::MPI::Vector &owned) const;

    /** The copy values of all cells, owned or not, from a replicated
     * reduced vector (for SolutionTransfer on copy_handler(), which visits
     * every cell of the shared mesh). */
    void
    expand_all(const Vector<double> &replicated, Vector<double> &copies) const;

    /** The owned entries of @p reduced from copy values on all cells, the
     * copies of a group averaged: the inverse of expand_all() for a field
     * of the space (on a coarsened cell the copies of a group may differ
     * by the projection's round-off). Hanging entries are left to the
     * constraints. */
    void
    gather(const Vector<double>          &copies,
           TrilinosWrappers::MPI::Vector &reduced) const;

    /** Per reduced unknown (all of them, on every rank), the sum of
     * @p copies over its copies, added in the order of the cells: the
     * same on every rank and for any number of ranks (the copies are
     * numbered rank by rank), so that results do not depend on the
     * partition by round-off, which explicit runs amplify. */
    Vector<double>
    sums_over_copies(const Vector<double> &copies) const;

    /** Bytes held by the layer (copies, tie map, support points). */
    std::size_t
    memory_consumption() const;

  private:
    const Triangulation<dim>              &triangulation;
    const ReferenceCell                    shape;
    std::unique_ptr<FESystem<dim>>         fe;
    std::unique_ptr<Mapping<dim>>          mapping;
    DoFHandler<dim>                        dof_handler;
    std::vector<std::vector<unsigned int>> face_dofs;
    std::vector<types::global_dof_index>   copy_to_reduced;
    std::vector<Point<dim>>                support_points;
    /** Real positions of all copies (from the last distribute()). */
    std::vector<Point<dim>>    copy_position;
    std::vector<unsigned char> components;
    IndexSet                   owned_dofs;
    AffineConstraints<double>  hanging_constraints;
    IndexSet                   relevant_dofs;

    /** The tie map as a union-find forest over the copies (flat after
     * every numbering: each copy points at its group's root). */
    std::vector<types::global_dof_index> parent;
    /** The copies in the order the numbering visits them (rank by rank,
     * cell by cell, node by node), with the offset of each rank's part. */
    std::vector<types::global_dof_index> visit_order;
    std::vector<std::size_t>             rank_visits;
    /** The active cell (index, iterator) of each copy. */
    std::vector<unsigned int> copy_cell;
    std::vector<CellIterator> active_cells;
    /** Copies whose reduced index is locally relevant: those of owned
     * cells and of their neighbours across released faces. */
    std::vector<types::global_dof_index> relevant_copies;

    /** (coarse copy, shape value) pairs that a hanging copy interpolates. */
    using HangingWeights
      = std::vector<std::pair<types::global_dof_index, double>>;
    /** Fine copies on hanging faces that sit on a coarse node (tied to
     * it), and those that interpolate the coarse face. */
    std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
      hanging_ties;
    std::vector<std::pair<types::global_dof_index, HangingWeights>>
      hanging_copies;

    /** Tie the copies of face @p f of @p cell to its neighbour's that
     * share a support point and a component (a conforming face). */
    void
    tie_face(const CellIterator                   &cell,
             const unsigned int                    f,
             std::vector<types::global_dof_index> &mine,
             std::vector<types::global_dof_index> &theirs);

    /** tie_face() on every conforming face that is not released. */
    void
    tie_faces(const FaceFilter &released);

    /** Call @p callback(copy, weights) for every fine copy on a hanging
     * face that is not released: weights are (coarse copy, shape value)
     * pairs, a single pair when the copy sits on a coarse node. */
    template <typename Callback>
    void
    for_each_hanging_copy(const FaceFilter &released,
                          const Callback   &callback) const;

    /** visit_order, copy_cell, active_cells and relevant_copies of the
     * mesh. */
    void
    index_copies(const FaceFilter &released);

    /** Number the groups of the tie map: reduced indices, support points,
     * owned and relevant sets, hanging-node constraints. */
    void
    number_groups();
  };



  template <int dim>
  template <typename VectorType>
  void
  TiedCopyDoFs<dim>::expand(const VectorType &reduced,
                            Vector<double>   &copies) const
  {
    copies.reinit(n_copies());
    std::vector<types::global_dof_index> local(fe->n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(local);
          for (const auto c : local)
            copies[c] = reduced[copy_to_reduced[c]];
        }
  }
} // namespace amfrac

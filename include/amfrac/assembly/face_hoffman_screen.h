#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/orthotropic.h>
#include <amfrac/material/ply_table.h>
#include <cstdint>
#include <deal.II/base/quadrature.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <vector>

class Epetra_BlockMap;

namespace amfrac
{
  /** The centres of the faces of the reference hypercube, face f at
   * point f: where the crack check evaluates the stress. */
  template <int dim>
  Quadrature<dim>
  face_centre_points();

  /**
   * The first round of the crack check: the Hoffman index of each
   * candidate face at its centre, in the stress of one of its cells. An
   * explicit run checks every face in every step, which through FEValues
   * cost more than the step itself (the impact beam: 46 % of the run).
   * Here the material-axes stress at the face centres of a cell is one
   * small matrix times the cell's nodal values, and cells of the same ply
   * and shape (shape_key(), a translated copy) share that matrix, as
   * BulkForceOperator's cells share their stiffness. A shape's matrix is
   * that of the first cell of the mesh with it, whichever rank evaluates
   * it, so that the indices do not depend on the partition.
   *
   * The crack check decides on the mean of the two cells' stresses, among
   * the faces one side of which fails on its own (the Hoffman index is
   * not convex for every set of strengths: with Zt != Yt the mean may
   * fail where neither side does). A face whose two cells are both
   * screened here (same ply; on one rank, every interior face) is
   * evaluated once and reported with the smaller of its larger side's
   * index (of the sides with their bit) and its mean's, so that the
   * caller's second round sees the faces that fail; a face with its other
   * cell on another rank, with its own side's index (as before the
   * screen).
   *
   * Plies homogenized from layers (2D in-plane models) take the largest
   * index of their layers: covers() is false for them, and the caller
   * evaluates their cells itself.
   */
  template <int dim>
  class FaceHoffmanScreen
  {
  public:
    using Cell   = typename DoFHandler<dim>::active_cell_iterator;
    using Vector = TrilinosWrappers::MPI::Vector;
    static constexpr unsigned int n_faces = GeometryInfo<dim>::faces_per_cell;

    /** The screen of @p cells (locally owned cells of
     * dofs.copy_handler()) whose ply covers(); the plies are indexed by
     * material id. */
    FaceHoffmanScreen(const TiedCopyDoFs<dim>               &dofs,
                      const std::vector<PlyProperties<dim>> &plies,
                      const std::vector<Cell>               &cells);
    ~FaceHoffmanScreen();

    /** Whether the screen evaluates cells of ply @p ply. */
    static bool
    covers(const PlyProperties<dim> &ply);

    /** A face of a screened cell and its index. */
    struct Index
    {
      Cell         cell;
      unsigned int face;
      double       hoffman;
    };

    /**
     * The faces whose index reaches @p limit (or is not a number), in the
     * order of the cells and faces: face f of cell c is evaluated if bit f
     * of @p face_bits[c's active cell index] is set, with the strengths
     * scaled by @p strength_scale[c's active cell index * n_faces + f]. A
     * face evaluated from its two cells is reported once, from the cell of
     * the smaller active index whose bit is set.
     * @p state holds the locally relevant entries of the current DoF
     * numbering; a new numbering (a new map of @p state) is picked up
     * here.
     */
    std::vector<Index>
    failing(const Vector                    &state,
            const std::vector<std::uint8_t> &face_bits,
            const std::vector<double>       &strength_scale,
            const double                     limit) const;

    /** Number of screened cells and of their shapes' matrices. */
    std::size_t
    n_cells() const
    {
      return cells.size();
    }
    std::size_t
    n_shapes() const
    {
      return hoffman.size();
    }

  private:
    /** The positions of the cells' dofs in the local array of @p state. */
    void
    locate_dofs(const Vector &state) const;

    /** Pair the faces whose two cells are both screened (partner). */
    void
    find_partners();

    /** The material-axes stress at the centre of face @p f of screened
     * cell @p c, from the cell's dof values in @p all, times @p scale:
     * the components (11, 22, 33, 23, 13, 12) in @p stress[0..5] (it
     * holds column_length entries). */
    void
    face_stress(const unsigned int c,
                const unsigned int f,
                const double      *all,
                const double       scale,
                double            *stress) const;

    const TiedCopyDoFs<dim>  &dofs;
    const unsigned int        dofs_per_cell;
    std::vector<Cell>         cells;
    std::vector<unsigned int> shape_of_cell;
    /** Per shape, per face and per dof of the cell, a column: the 6
     * material-axes stress components (11, 22, 33, 23, 13, 12) of the
     * dof's shape function, padded to gathered_columns_product()'s
     * column length with zeros. */
    std::vector<double>       matrices;
    std::vector<HoffmanIndex> hoffman;
    /** Per screened cell and face: the screened cell on its other side
     * (same ply, regular face) and that cell's face number; -1 if none. */
    std::vector<int>          partner;
    std::vector<unsigned int> partner_face;
    /** The map the local positions refer to, kept alive so that a new
     * map cannot take its address. */
    mutable std::unique_ptr<Epetra_BlockMap> located_map;
    mutable std::vector<int>                 local_dofs;
  };
} // namespace amfrac

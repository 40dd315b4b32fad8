#pragma once

#include <amfrac/adaptivity/mesh_transfer.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/ply_table.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>
#include <vector>

namespace amfrac
{
  /** Displacement and stress (model axes) at fixed points. The cell around
   * each point is found once; its owner evaluates and the values are
   * summed over ranks, so every rank gets them. With finite strain (total
   * Lagrangian) the stress is the second Piola-Kirchhoff stress of the
   * Green-Lagrange strain. */
  template <int dim>
  class PointProbe
  {
  public:
    /** Throws std::invalid_argument naming a point outside the mesh. */
    PointProbe(const TiedCopyDoFs<dim>               &dofs,
               const std::vector<PlyProperties<dim>> &plies,
               const std::vector<Point<dim>>         &points,
               const bool                             finite_strain = false);

    struct Value
    {
      Tensor<1, dim>        displacement;
      SymmetricTensor<2, 3> stress;
    };

    /** @p plastic_strain: the plastic strain of every active cell (3D,
     * laminate axes), taken off the strain for the stress; empty: none. */
    std::vector<Value>
    evaluate(const dealii::Vector<double>             &copy_values,
             const std::vector<SymmetricTensor<2, 3>> &plastic_strain
             = {}) const;

  private:
    /** The cell around @p p and the point's (projected) reference
     * coordinates in it; an end iterator if no cell contains @p p.
     * @p wedges searches a wedge mesh (null on hypercubes). */
    std::pair<typename TiedCopyDoFs<dim>::CellIterator, Point<dim>>
    locate(const Point<dim> &p, const CellLocator<dim> *wedges) const;

    const TiedCopyDoFs<dim>                              &dofs;
    const std::vector<PlyProperties<dim>>                &plies;
    const bool                                            finite_strain;
    std::vector<typename TiedCopyDoFs<dim>::CellIterator> cells;
    std::vector<Point<dim>>                               unit_points;
  };
} // namespace amfrac

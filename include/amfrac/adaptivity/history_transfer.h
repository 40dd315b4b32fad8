#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/solution_transfer.h>
#include <map>
#include <memory>
#include <vector>

namespace amfrac
{
  /**
   * The seed's tau_1 for bulk quadrature-point history (plastic strain and
   * other internal variables of the plies), across one refinement and
   * coarsening of the mesh. Each history component follows one of two
   * rules:
   *
   * - smooth: the seed's three steps. The point values are projected to
   *   nodes (an L2 projection, the ZZ smoothing, in a space that is
   *   continuous inside each ply and free across plies, so that a ply's
   *   history never leaks into its neighbour), the nodal field moves to
   *   the new mesh (deal.II's SolutionTransfer on the copy layer: exact
   *   for refinement, a projection for coarsening), and it is evaluated at
   *   the new points. A field of the recovery space (e.g. constant or, for
   *   degree 1 and up, linear per ply) survives exactly.
   * - non_decreasing (damage-like variables that must never decrease):
   *   injection where a cell is refined (each new point takes the value of
   *   the parent's point nearest to it, in the parent's reference
   *   coordinates: the old value there), the largest value of all the
   *   children's points where cells are coarsened, and the old values
   *   where a cell is kept.
   *
   * Usage: prepare() with the old field before
   * Triangulation::execute_coarsening_and_refinement(), interpolate()
   * after it. Every rank passes the field on every active cell (the shared
   * mesh is the same on all ranks) and gets it back the same way.
   */
  template <int dim>
  class QuadratureHistoryTransfer
  {
  public:
    /** smooth: projected and interpolated. non_decreasing: injected
     * into refined cells from the parent's nearest point, the largest of
     * the children where cells are coarsened. injected: the same across
     * a refinement; between unrelated meshes (NonMatchingTransfer) the
     * nearest old point's value, or the largest old value inside the new
     * cell if larger (a hardening variable such as kappa, which must
     * stay with the plastic strain it measures), where non_decreasing
     * takes the largest value of the whole old cell (damage). nearest:
     * between unrelated meshes only, the value of the old point nearest
     * (in reference coordinates) among those of the old cell that holds
     * the new point: the value of one old point, never a mean. */
    enum class Rule
    {
      smooth,
      non_decreasing,
      injected,
      nearest
    };
    /** values[active cell index][q * n_components + c] at the points of
     * the quadrature given to the constructor. */
    using Field = std::vector<std::vector<double>>;

    /** @p degree is that of the recovery space (that of the displacement
     * is the natural choice); one rule per history component. With
     * @p keep_unchanged_cells, a cell the mesh change keeps keeps its
     * values exactly in every component (the projection is used only
     * where cells are refined or coarsened). */
    QuadratureHistoryTransfer(const Triangulation<dim> &triangulation,
                              const unsigned int        degree,
                              const Quadrature<dim>    &quadrature,
                              const std::vector<Rule>  &rules,
                              const bool keep_unchanged_cells = false);

    /** Project the smooth components to nodes and remember the others;
     * the refine and coarsen flags must be set (and final). */
    void
    prepare(const Field &old_field);

    /** The field at the points of the new mesh. */
    Field
    interpolate();

  private:
    /** The L2 projection of the smooth components to the recovery space:
     * one copy-layer vector per dim components. */
    std::vector<dealii::Vector<double>>
    project(const Field &field) const;

    void
    transfer_non_decreasing(Field &field) const;

    const Triangulation<dim>           &triangulation;
    const Quadrature<dim>               quadrature;
    const std::vector<Rule>             rules;
    const bool                          keep_unchanged_cells;
    std::vector<unsigned int>           smooth;
    TiedCopyDoFs<dim>                   recovery;
    std::vector<dealii::Vector<double>> old_copies;
    std::unique_ptr<SolutionTransfer<dim, dealii::Vector<double>>> transfer;
    std::map<CellId, std::vector<double>>                          old_values;
  };
} // namespace amfrac

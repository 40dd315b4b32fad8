#pragma once

#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/tria.h>

namespace amfrac
{
  using namespace dealii;

  /**
   * Keep the refinement of a 3D laminate mesh in the plane of the plies:
   * every refine flag becomes @p cut (cut_x, cut_y or cut_xy), and every
   * coarser cell at a vertex of a flagged cell is flagged with @p cut too.
   *
   * Why: deal.II keeps at most one hanging level across faces and edges,
   * and when a refinement would break that it refines the coarse
   * neighbour as it sees fit, in 3D often isotropically; a cell refined
   * through the thickness next to one refined along the plies leaves
   * faces that neither side's face contains (no side is "the coarse one"
   * there, and the tied-copy layer cannot tie them). Refining the coarser
   * vertex neighbours along the plies first leaves deal.II nothing to do.
   * In 2D deal.II's anisotropic refinement has no such faces: nothing is
   * changed.
   */
  template <int dim>
  void
  keep_refinement_in_plane(Triangulation<dim>       &triangulation,
                           const RefinementCase<dim> cut);

  /** Whether any active cell of @p triangulation is flagged for a
   * refinement through the thickness (the last axis; 3D only). */
  template <int dim>
  bool
  flagged_through_thickness(const Triangulation<dim> &triangulation);
} // namespace amfrac

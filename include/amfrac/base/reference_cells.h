#pragma once

#include <algorithm>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

namespace amfrac
{
  using namespace dealii;

  /** Whether @p unit lies in the reference cell @p shape (a hypercube or
   * the wedge, triangle times [0, 1]) up to @p tolerance. deal.II 9.4's
   * ReferenceCell::contains_point() has no wedge, and its cell search
   * (GridTools::find_active_cell_around_point) tests the unit cube, which
   * accepts points outside a wedge. */
  template <int dim>
  bool
  inside_reference_cell(const ReferenceCell &shape,
                        const Point<dim>    &unit,
                        const double         tolerance)
  {
    if (shape.is_hyper_cube())
      return GeometryInfo<dim>::is_inside_unit_cell(unit, tolerance);
    // The wedge: x, y in the triangle, z in [0, 1].
    return dim == 3 && unit[0] >= -tolerance && unit[1] >= -tolerance
           && unit[0] + unit[1] <= 1 + tolerance && unit[dim - 1] >= -tolerance
           && unit[dim - 1] <= 1 + tolerance;
  }

  /** The point of the reference cell @p shape nearest to @p unit: clamped
   * on a hypercube; on the wedge clamped through the thickness and
   * projected on the triangle in its plane. */
  template <int dim>
  Point<dim>
  project_to_reference_cell(const ReferenceCell &shape, const Point<dim> &unit)
  {
    if (shape.is_hyper_cube())
      return GeometryInfo<dim>::project_to_unit_cell(unit);
    Point<dim> q        = unit;
    q[0]                = std::max(0., q[0]);
    q[1]                = std::max(0., q[1]);
    q[dim - 1]          = std::clamp(q[dim - 1], 0., 1.);
    const double excess = q[0] + q[1] - 1;
    if (excess > 0)
      {
        // Onto the hypotenuse x + y = 1 (then clamped to its ends).
        q[0] = std::clamp(q[0] - 0.5 * excess, 0., 1.);
        q[1] = 1 - q[0];
      }
    return q;
  }

  /** The reference coordinates of @p p in @p cell under @p mapping. On a
   * wedge by Newton's method on the *linear* wedge map, whatever @p mapping
   * is (P2 wedges on a curved hole differ from it by O(h^2 / R) near the
   * hole; the callers locate points, they do not integrate): deal.II 9.4's
   * MappingFE::transform_real_to_unit_cell() needs second derivatives that
   * its wedge polynomials do not implement. Throws
   * Mapping::ExcTransformationFailed when Newton does not converge (a
   * degenerate cell, or a point far outside). */
  template <int dim>
  Point<dim>
  real_to_unit(const Mapping<dim>                               &mapping,
               const typename Triangulation<dim>::cell_iterator &cell,
               const Point<dim>                                 &p);
} // namespace amfrac

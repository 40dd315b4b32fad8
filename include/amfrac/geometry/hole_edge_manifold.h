#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/manifold.h>
#include <memory>

namespace amfrac
{
  using namespace dealii;

  /**
   * The geometry of the prism cells around a cylindrical hole (axis along
   * z): a new point between points that all lie on the hole's surface is
   * put on that surface (the flat average pushed radially out to the
   * radius); any other new point is the flat average.
   *
   * Why not CylindricalManifold on the hole's faces, as on hexahedra:
   * deal.II 9.4's MappingFE (the only curved mapping of wedges) asks the
   * manifold of the *cell* for every support point. A cylindrical manifold
   * on the cell would also curve the cell's edges to its neighbours, which
   * stay straight in the neighbours' flat mapping, and open gaps. With this
   * manifold, the edge midpoints and face centres of P2 wedges on the hole
   * move onto the circle, every other edge stays straight, so the curved
   * mesh stays conforming (an isoparametric hole). It is set on every
   * cell, face and edge of the plate (make_laminate_mesh()): MappingFE
   * asserts in debug builds that the manifold ids of a cell agree.
   */
  class HoleEdgeManifold : public Manifold<3>
  {
  public:
    HoleEdgeManifold(const Point<3> &axis_point, const double radius);

    std::unique_ptr<Manifold<3>>
    clone() const override;

    Point<3>
    get_new_point(const ArrayView<const Point<3>> &surrounding_points,
                  const ArrayView<const double>   &weights) const override;

    /** Whether @p p lies on the hole's surface (relative tolerance). */
    bool
    on_surface(const Point<3> &p) const;

  private:
    const Point<3> axis_point;
    const double   radius;

    double
    distance_from_axis(const Point<3> &p) const;
  };
} // namespace amfrac

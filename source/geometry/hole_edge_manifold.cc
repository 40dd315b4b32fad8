#include <amfrac/geometry/hole_edge_manifold.h>
#include <cmath>

namespace amfrac
{
  HoleEdgeManifold::HoleEdgeManifold(const Point<3> &axis_point,
                                     const double    radius)
    : axis_point(axis_point)
    , radius(radius)
  {}



  std::unique_ptr<Manifold<3>>
  HoleEdgeManifold::clone() const
  {
    return std::make_unique<HoleEdgeManifold>(axis_point, radius);
  }



  double
  HoleEdgeManifold::distance_from_axis(const Point<3> &p) const
  {
    return std::hypot(p[0] - axis_point[0], p[1] - axis_point[1]);
  }



  bool
  HoleEdgeManifold::on_surface(const Point<3> &p) const
  {
    // Gmsh puts the hole's nodes on the circle to round-off.
    return std::abs(distance_from_axis(p) - radius) < 1e-8 * radius;
  }



  Point<3>
  HoleEdgeManifold::get_new_point(
    const ArrayView<const Point<3>> &surrounding_points,
    const ArrayView<const double>   &weights) const
  {
    Point<3> average;
    bool     all_on_surface = true;
    for (unsigned int i = 0; i < surrounding_points.size(); ++i)
      if (weights[i] != 0.)
        {
          average += weights[i] * surrounding_points[i];
          all_on_surface = all_on_surface && on_surface(surrounding_points[i]);
        }
    const double r = distance_from_axis(average);
    if (!all_on_surface || r == 0.)
      return average;
    Point<3> projected = average;
    for (unsigned int d = 0; d < 2; ++d)
      projected[d]
        = axis_point[d] + (average[d] - axis_point[d]) * (radius / r);
    return projected;
  }
} // namespace amfrac

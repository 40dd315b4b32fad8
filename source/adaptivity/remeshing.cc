#include <algorithm>
#include <amfrac/adaptivity/remeshing.h>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace amfrac
{
  namespace bgi = boost::geometry::index;

  double
  in_plane_size(const Triangulation<3>::cell_iterator &cell)
  {
    double       sum = 0;
    unsigned int n   = 0;
    for (const unsigned int l : cell->line_indices())
      {
        const Point<3> &a      = cell->line(l)->vertex(0);
        const Point<3> &b      = cell->line(l)->vertex(1);
        const double    length = std::hypot(a[0] - b[0], a[1] - b[1]);
        // The edges through the thickness have no in-plane length.
        if (length > 1e-9 * cell->diameter())
          {
            sum += length;
            ++n;
          }
      }
    if (n == 0)
      throw std::logic_error("in_plane_size: a cell has no in-plane edge");
    return sum / n;
  }



  std::vector<double>
  RemeshingRule::new_sizes(const Triangulation<3>      &mesh,
                           const dealii::Vector<float> &cell_errors,
                           const double                 eta_target) const
  {
    std::vector<double> sizes(mesh.n_active_cells());
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const double eta = cell_errors[cell->active_cell_index()];
        // An error-free cell grows as much as allowed.
        const double factor
          = eta > 0 ? std::clamp(std::pow(eta_target / eta, 1. / degree),
                                 smallest_factor,
                                 largest_factor) :
                      largest_factor;
        // On a grid of steps of 2^(1/32): the mesh Gmsh makes of the sizes
        // does not depend on the round-off of the errors (one rank and two
        // solve to round-off apart, and must remesh alike).
        const double step = std::exp2(std::round(32 * std::log2(factor)) / 32);
        sizes[cell->active_cell_index()]
          = std::max(min_size, step * in_plane_size(cell));
      }
    return sizes;
  }



  namespace
  {
    /** The barycentric coordinates of @p p in the triangle @p x. */
    std::array<double, 3>
    barycentric(const std::array<Point<2>, 3> &x, const Point<2> &p)
    {
      const Tensor<1, 2> a = x[1] - x[0], b = x[2] - x[0], c = p - x[0];
      const double       det = a[0] * b[1] - a[1] * b[0];
      const double       l1  = (c[0] * b[1] - c[1] * b[0]) / det;
      const double       l2  = (a[0] * c[1] - a[1] * c[0]) / det;
      return {{1 - l1 - l2, l1, l2}};
    }
  } // namespace



  InPlaneSizeField::InPlaneSizeField(const Triangulation<3>    &mesh,
                                     const std::vector<double> &cell_sizes)
  {
    // Column vertices: the vertices of the plies above each other share
    // their (x, y) exactly (the mesh is extruded).
    std::map<std::pair<double, double>, unsigned int> column;
    std::set<std::array<unsigned int, 3>>             seen;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        std::vector<unsigned int> footprint;
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<3> &x = cell->vertex(v);
            const auto [entry, added]
              = column.emplace(std::make_pair(x[0], x[1]), points.size());
            if (added)
              {
                points.emplace_back(x[0], x[1]);
                sizes.push_back(std::numeric_limits<double>::max());
              }
            if (std::find(footprint.begin(), footprint.end(), entry->second)
                == footprint.end())
              footprint.push_back(entry->second);
          }
        if (footprint.size() != 3 && footprint.size() != 4)
          throw std::logic_error("InPlaneSizeField: the mesh is not extruded "
                                 "along z");
        for (const unsigned int node : footprint)
          sizes[node]
            = std::min(sizes[node], cell_sizes[cell->active_cell_index()]);
        // A quadrilateral's vertices are in lexicographic order.
        std::vector<std::array<unsigned int, 3>> parts;
        if (footprint.size() == 3)
          parts.push_back({{footprint[0], footprint[1], footprint[2]}});
        else
          {
            parts.push_back({{footprint[0], footprint[1], footprint[3]}});
            parts.push_back({{footprint[0], footprint[3], footprint[2]}});
          }
        for (const auto &triangle : parts)
          {
            auto key = triangle;
            std::sort(key.begin(), key.end());
            if (seen.insert(key).second)
              triangles.push_back(triangle);
          }
      }
    std::vector<std::pair<BoundingBox<2>, unsigned int>> boxes;
    for (unsigned int t = 0; t < triangles.size(); ++t)
      {
        std::vector<Point<2>> corners;
        for (const unsigned int node : triangles[t])
          corners.push_back(points[node]);
        BoundingBox<2> box(corners);
        box.extend(1e-9 * box.side_length(0) + 1e-9 * box.side_length(1));
        boxes.emplace_back(box, t);
      }
    tree = pack_rtree(boxes);
  }



  double
  InPlaneSizeField::operator()(const Point<2> &p) const
  {
    std::vector<std::pair<BoundingBox<2>, unsigned int>> candidates;
    tree.query(bgi::intersects(p), std::back_inserter(candidates));
    if (candidates.empty())
      tree.query(bgi::nearest(p, 4), std::back_inserter(candidates));
    // The candidate whose smallest coordinate is largest contains p, or
    // is the nearest (its coordinates then clamped onto the triangle).
    std::array<double, 3> best{};
    unsigned int          best_triangle = candidates.front().second;
    double                best_smallest = -std::numeric_limits<double>::max();
    for (const auto &[box, t] : candidates)
      {
        const auto &nodes = triangles[t];
        const auto  l     = barycentric(
          {{points[nodes[0]], points[nodes[1]], points[nodes[2]]}}, p);
        const double smallest = *std::min_element(l.begin(), l.end());
        if (smallest > best_smallest)
          {
            best_smallest = smallest;
            best          = l;
            best_triangle = t;
          }
      }
    double sum = 0;
    for (double &l : best)
      {
        l = std::max(0., l);
        sum += l;
      }
    double value = 0;
    for (unsigned int i = 0; i < 3; ++i)
      value += best[i] / sum * sizes[triangles[best_triangle][i]];
    return value;
  }



  double
  InPlaneSizeField::predicted_triangles() const
  {
    double n = 0;
    for (const auto &nodes : triangles)
      {
        const Tensor<1, 2> a    = points[nodes[1]] - points[nodes[0]];
        const Tensor<1, 2> b    = points[nodes[2]] - points[nodes[0]];
        const double       area = 0.5 * std::abs(a[0] * b[1] - a[1] * b[0]);
        const double       h
          = (sizes[nodes[0]] + sizes[nodes[1]] + sizes[nodes[2]]) / 3;
        n += area / (std::sqrt(3.) / 4 * h * h);
      }
    return n;
  }



  void
  InPlaneSizeField::scale(const double factor)
  {
    for (double &h : sizes)
      h *= factor;
  }



  std::pair<double, double>
  InPlaneSizeField::range() const
  {
    const auto [low, high] = std::minmax_element(sizes.begin(), sizes.end());
    return {*low, *high};
  }



  InPlaneSize
  InPlaneSizeField::function() const
  {
    return [this](const Point<2> &p) { return (*this)(p); };
  }
} // namespace amfrac

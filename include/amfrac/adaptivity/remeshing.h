#pragma once

#include <amfrac/geometry/laminate.h>
#include <array>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>
#include <utility>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /** The mean length of the in-plane edges of @p cell of a mesh extruded
   * along z (the edges whose ends differ in x or y): its element size as
   * Gmsh's in-plane size field means it. */
  double
  in_plane_size(const Triangulation<3>::cell_iterator &cell);

  /** The seed's remeshing rule (Zienkiewicz and Zhu): the new size of a
   * cell is h (eta_target / eta_K)^(1/p), bounded, the factor rounded to
   * a power of 2^(1/32) (so that round-off in the errors does not change
   * the new mesh). */
  struct RemeshingRule
  {
    /** The element degree p. */
    unsigned int degree = 1;
    /** A cell shrinks to no less than this fraction of its size ... */
    double smallest_factor = 0.25;
    /** ... and grows to no more than this multiple of it. */
    double largest_factor = 2;
    /** No size below this [mm] (0: no bound). */
    double min_size = 0;

    /** The new in-plane size of every active cell of @p mesh (by
     * active_cell_index) from its error @p cell_errors and the error
     * @p eta_target every cell should hold. */
    std::vector<double>
    new_sizes(const Triangulation<3>      &mesh,
              const dealii::Vector<float> &cell_errors,
              const double                 eta_target) const;
  };



  /**
   * A continuous in-plane element size field from sizes per cell of an
   * extruded mesh, for Gmsh: each column vertex (a point of the plane
   * where cells of any ply meet) takes the smallest size of the cells
   * around it, and the field interpolates those linearly on the in-plane
   * footprint of the cells (a wedge's triangle; a hexahedron's
   * quadrilateral split in two). A point outside the footprint (on a
   * curved boundary the new mesh resolves better than the old) takes the
   * value of the nearest footprint point.
   */
  class InPlaneSizeField
  {
  public:
    InPlaneSizeField(const Triangulation<3>    &mesh,
                     const std::vector<double> &cell_sizes);

    double
    operator()(const Point<2> &p) const;

    /** The number of triangles a mesh of this field will have about: the
     * area of each footprint triangle over that of the equilateral
     * triangle of its mean size. */
    double
    predicted_triangles() const;

    /** The triangles of the footprint. */
    unsigned int
    n_triangles() const
    {
      return triangles.size();
    }

    /** Multiply every size by @p factor (a cell budget). */
    void
    scale(const double factor);

    /** The smallest and largest size. */
    std::pair<double, double>
    range() const;

    /** The field as the std::function of make_laminate_mesh() (refers to
     * this object). */
    InPlaneSize
    function() const;

  private:
    std::vector<Point<2>>                          points;
    std::vector<double>                            sizes;
    std::vector<std::array<unsigned int, 3>>       triangles;
    RTree<std::pair<BoundingBox<2>, unsigned int>> tree;
  };
} // namespace amfrac

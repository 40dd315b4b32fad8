#pragma once

#include <amfrac/parameters/parameters.h>
#include <array>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <functional>
#include <string>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /**
   * The in-plane (x, y) mesh of a laminate, made by Gmsh: triangles or
   * quadrilaterals (counterclockwise seen from +z) and the boundary id of
   * every boundary edge. Extruded ply by ply by extrude_plane_mesh(), the
   * triangles become wedges and the quadrilaterals hexahedra.
   */
  struct PlaneMesh
  {
    std::vector<Point<2>>                    points;
    std::vector<std::array<unsigned int, 3>> triangles;
    std::vector<std::array<unsigned int, 4>> quadrilaterals;
    /** Boundary edges (two point indices) with their boundary id. */
    std::vector<std::array<unsigned int, 2>> edges;
    std::vector<types::boundary_id>          edge_ids;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &points &triangles &quadrilaterals &edges &edge_ids;
    }
  };

  /** The boundary id of a physical curve called @p name: x-, x+, y-, y+
   * are 0..3 as on the box (so that the Boundary conditions subsections
   * of those names apply to them); every other curve is traction free
   * and gets id 6, like the structured plate's hole. */
  types::boundary_id
  boundary_id_of_curve(const std::string &name);

  /**
   * Read a 2D Gmsh file (.geo: meshed here with its own sizes times
   * @p size_factor; .msh: taken as it is and split @p refinements times,
   * each split cutting every element into four). Throws an InputError
   * naming Geometry/Mesh file for a file Gmsh cannot read, a mesh that is
   * not planar or has elements other than 3-node triangles and 4-node
   * quadrilaterals.
   */
  PlaneMesh
  read_plane_mesh(const std::string &file,
                  const double       size_factor,
                  const unsigned int refinements);

  /** A .geo @p file meshed with the element size @p size (mm at a point of
   * the plane) instead of its own: the remeshing of a prism laminate. */
  PlaneMesh
  read_plane_mesh(const std::string                             &file,
                  const std::function<double(const Point<2> &)> &size);

  /**
   * The in-plane mesh of an open-hole plate [0, L] x [0, W] with a hole
   * of radius R at its centre, made by Gmsh with the element size
   * @p size (mm at a point of the plane). The straight sides are x-, x+,
   * y-, y+; the hole is id 6. With @p radius = 0, the rectangle.
   */
  PlaneMesh
  mesh_open_hole_plane(const double                                   length,
                       const double                                   width,
                       const double                                   radius,
                       const std::function<double(const Point<2> &)> &size);

  /** The element size of Geometry/Hole radius on prisms: Width /
   * Elements along width far from the hole, the circumference over
   * Elements around hole at it, growing linearly in between (a quarter
   * of the distance), all halved per Global refinement. */
  std::function<double(const Point<2> &)>
  open_hole_element_size(const parameters::Geometry &geometry);

  /**
   * Run @p make on rank 0 of @p comm and give its mesh (a PlaneMesh or a
   * VolumeMesh) to every rank (a shared triangulation needs the same
   * coarse mesh everywhere, and Gmsh is a global state): an InputError on
   * rank 0 is thrown on every rank.
   */
  template <class Mesh>
  Mesh
  make_mesh_on_root(const std::function<Mesh()> &make, const MPI_Comm comm);

  /**
   * Extrude @p plane through the thickness coordinates @p z (bottom to
   * top, the element layers of the plies): a wedge per triangle and a
   * hexahedron per quadrilateral and layer. Lateral faces take the id of
   * their edge, the bottom is z- (4) and the top z+ (5). A mesh with both
   * triangles and quadrilaterals is refused (mixed meshes are not
   * supported yet).
   */
  void
  extrude_plane_mesh(const PlaneMesh           &plane,
                     const std::vector<double> &z,
                     Triangulation<3>          &triangulation);
} // namespace amfrac

#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <string>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /**
   * A laminate's 3D mesh read from a Gmsh .msh file: hexahedra or wedges
   * (their vertices in deal.II's order, positively oriented, a
   * hexahedron's third axis the one closest to the thickness axis z), the
   * ply of every cell, and the boundary faces of the physical surfaces
   * with their ids.
   */
  struct VolumeMesh
  {
    std::vector<Point<3>>                  points;
    std::vector<std::vector<unsigned int>> cells;
    std::vector<unsigned int>              ply_of_cell;
    /** Boundary faces (their point indices, sorted) with their id. */
    std::vector<std::vector<unsigned int>> faces;
    std::vector<types::boundary_id>        face_ids;

    bool
    empty() const
    {
      return cells.empty();
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &points &cells &ply_of_cell &faces &face_ids;
    }
  };

  /** The boundary id of a physical surface called @p name: x-, x+, y-,
   * y+, z-, z+ are 0..5 as on the box; every other surface is traction
   * free and gets id 6. */
  types::boundary_id
  boundary_id_of_surface(const std::string &name);

  /**
   * Read the 3D mesh of a Gmsh @p file of @p n_plies plies (a .msh as it
   * is, a .geo of volumes meshed with its own sizes), split
   * @p refinements times (each split cutting every element into eight).
   * The ply of an element is its physical volume named "ply k", k = 1 ..
   * @p n_plies from the bottom of the Stacking sequence. Returns an empty
   * mesh if the file is 2D (an in-plane outline, for read_plane_mesh()). Throws
   * an InputError naming Geometry/Mesh file for a file Gmsh cannot read,
   * elements other than 8-node hexahedra and 6-node wedges, both kinds in one
   * file, a missing ply volume, and an element in no or in two ply volumes.
   */
  VolumeMesh
  read_volume_mesh(const std::string &file,
                   const unsigned int n_plies,
                   const unsigned int refinements);

  /** @p mesh as @p triangulation: the material id of a cell is its ply,
   * boundary faces take the id of their physical surface (6 if they have
   * none). Throws an InputError naming Geometry/Mesh file for a face in
   * two named surfaces, a named surface off the boundary, plies meshed
   * apart (boundary faces on one another) and plies numbered from the
   * top. */
  void
  create_volume_mesh(const VolumeMesh &mesh, Triangulation<3> &triangulation);

  /** Throws an InputError naming @p parameter if two plies that are not
   * neighbours in the stacking touch (a ply drop of a 3D mesh file) and
   * one of the ply interfaces between them is in @p interfaces (sorted):
   * it would stay bonded. */
  void
  refuse_interfaces_between_distant_plies(
    const Triangulation<3>          &triangulation,
    const std::vector<unsigned int> &interfaces,
    const std::string               &parameter);
} // namespace amfrac

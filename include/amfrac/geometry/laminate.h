#pragma once

#include <amfrac/geometry/plane_mesh.h>
#include <amfrac/geometry/stacking_sequence.h>
#include <amfrac/material/orthotropic.h>
#include <amfrac/parameters/parameters.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <functional>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /** The stacking of a laminate: its plies bottom-up and where they are. */
  struct Laminate
  {
    std::vector<Ply>          plies;
    std::vector<unsigned int> material_of_ply;
    /** Thickness coordinates of the ply boundaries, bottom to top
     * (n_plies + 1 values, the first is 0). */
    std::vector<double> ply_boundaries;
    /** A 2D in-plane model (Geometry/2D model): the plies are homogenized
     * through the thickness, the mesh has one material. */
    bool in_plane;

    Laminate(const parameters::Geometry  &geometry,
             const parameters::Materials &materials);

    unsigned int
    n_plies() const
    {
      return plies.size();
    }

    double
    thickness() const
    {
      return ply_boundaries.back();
    }
  };

  /**
   * Mesh the laminate box [0,L] x [0,W] x [0,t] (3D) or [0,L] x [0,t]
   * (2D plane strain, y is the thickness axis) with structured hexahedra
   * (quadrilaterals): ply boundaries are mesh planes, the material id of
   * every cell is its ply index, boundary ids 0..2*dim-1 are the faces
   * x-, x+, y-, y+, (z-, z+).
   */
  /** The same for Geometry/Hole radius > 0 (3D, or 2D in-plane): the
   * plate with a hole, extruded ply by ply in 3D; boundary id 6 is the
   * hole. The refinement of make_laminate_mesh follows the hole's
   * cylindrical (circular) manifold. A 2D in-plane mesh is the plate's
   * (x, y) plane with material id 0 everywhere. */
  template <int dim>
  void
  make_open_hole_mesh(const parameters::Geometry &geometry,
                      const Laminate             &laminate,
                      Triangulation<dim>         &triangulation);

  /** The in-plane element size [mm] at a point of the (x, y) plane. */
  using InPlaneSize = std::function<double(const Point<2> &)>;

  /** The in-plane mesh of a prism laminate's remeshing: its outline (the
   * box, the open-hole plate or the .geo of Geometry/Mesh file) meshed
   * by Gmsh on rank 0 of @p comm with the element size @p size, given to
   * every rank. Throws an InputError (on every rank) if Gmsh fails; the
   * caller's mesh is untouched. */
  PlaneMesh
  mesh_laminate_plane(const parameters::Geometry &geometry,
                      const InPlaneSize          &size,
                      const MPI_Comm              comm);

  /** With @p region_along_plies (3D), the Refinement region is refined
   * in the plane of the plies only (keep_refinement_in_plane()), as runs
   * that adapt during their load history refine. A prism laminate given
   * @p plane (mesh_laminate_plane(), or a checkpoint's) is that in-plane
   * mesh extruded ply by ply: the global remeshing of an adaptive run.
   * Returns whether the plies came from a 3D Geometry/Mesh file's
   * physical volumes (such a mesh cannot be remeshed). */
  template <int dim>
  bool
  make_laminate_mesh(const parameters::Geometry &geometry,
                     const Laminate             &laminate,
                     Triangulation<dim>         &triangulation,
                     const bool                  region_along_plies = false,
                     const PlaneMesh            *plane              = nullptr);

} // namespace amfrac

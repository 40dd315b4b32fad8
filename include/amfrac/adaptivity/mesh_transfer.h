#pragma once

#include <amfrac/adaptivity/history_transfer.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>
#include <map>
#include <memory>
#include <vector>

namespace amfrac
{
  /**
   * Finds the cell of a mesh around a point, ply by ply: the cells of each
   * material id in an R-tree of their bounding boxes, the candidates
   * tested by inverting their mapping. A point outside every cell of its
   * ply (a curved boundary meshed twice differently, round-off on a ply
   * face) takes the nearest point of the nearest candidate: the field is
   * extrapolated from the closest cell, never left undefined.
   */
  template <int dim>
  class CellLocator
  {
  public:
    using CellIterator = typename TiedCopyDoFs<dim>::CellIterator;

    explicit CellLocator(const TiedCopyDoFs<dim> &dofs);

    struct Location
    {
      CellIterator cell;
      /** Reference coordinates, projected into the reference cell. */
      Point<dim> unit;
      /** False if the point lay outside every cell of its ply. */
      bool inside;
    };

    /** The cell of ply @p ply around @p p (throws if the ply has no
     * cell). */
    Location
    locate(const Point<dim> &p, const types::material_id ply) const;

    /** The first cell of any ply (in the order of the material ids) that
     * contains @p p; Location::inside is false if none does. */
    Location
    locate(const Point<dim> &p) const;

  private:
    using Box = BoundingBox<dim>;
    const TiedCopyDoFs<dim>                                          &dofs;
    std::map<types::material_id, RTree<std::pair<Box, CellIterator>>> trees;
  };



  /**
   * The seed's transfer between two unrelated meshes, for global
   * remeshing (eqs. 14-17): every new node or Gauss point is located in a
   * cell of the old mesh of its own ply (CellLocator: the old mapping
   * inverted, eq. 14) and the old field is interpolated there.
   *
   * - nodal() is tau_2: the copy values of the old layer at every copy of
   *   the new one (eqs. 15, 17). Each copy is located in its own cell's
   *   ply, so a field that jumps across a released ply interface keeps
   *   both of its sides. A field of the old space is transferred exactly
   *   where the new copies lie in it: a linear field to round-off.
   * - quadrature() is tau_1 (eqs. 15-16) for Gauss-point variables, per
   *   component one of these rules:
   *   - smooth: the point values are projected to the vertices of the old
   *     mesh (the lumped L2 projection with the linear element, ply by
   *     ply: a ply's history never leaks into its neighbour; positive
   *     weights on any shape and degree), and that field is interpolated
   *     at the new points. A value constant in a ply stays that constant.
   *   - non_decreasing (damage, debonded status): a new point takes the
   *     largest old value of the old cell it lies in and of the old points
   *     that lie in its new cell, so no point loses damage and the largest
   *     damage of the laminate survives a coarser mesh.
   *   - injected (a hardening variable such as kappa, which has to stay
   *     with the smoothed plastic strain it measures): the value of the
   *     old point nearest to the new point in the old cell it lies in, or
   *     the largest of the old points that lie in its new cell if that is
   *     larger (a coarser mesh keeps the largest value).
   *   - nearest (the plastic strain, Adaptivity/Plastic history transfer
   *     = nearest point): the value of the old point nearest to the new
   *     point (in reference coordinates) in the old cell it lies in.
   *     Unlike smooth, it keeps the peaks of a plastic zone; a smoothed
   *     peak leaves the carried stress (of the new total strain) outside
   *     the yield surface, and the next step yields it again.
   *
   * Both meshes are the replicated meshes of parallel::shared, so every
   * rank computes the same values on every cell (no communication).
   */
  template <int dim>
  class NonMatchingTransfer
  {
  public:
    /** The rules and field layout of QuadratureHistoryTransfer (the
     * transfer across a refinement), so a history moves either way. */
    using Rule  = typename QuadratureHistoryTransfer<dim>::Rule;
    using Field = typename QuadratureHistoryTransfer<dim>::Field;

    NonMatchingTransfer(const TiedCopyDoFs<dim> &old_dofs,
                        const TiedCopyDoFs<dim> &new_dofs);

    /** tau_2: @p old_copies (copy values on every old cell, e.g. from
     * TiedCopyDoFs::expand_all()) at every copy of the new layer (for
     * TiedCopyDoFs::gather()). */
    Vector<double>
    nodal(const Vector<double> &old_copies) const;

    /** tau_1: @p old_field at the points @p old_points of every old cell,
     * @p rules.size() components, moved to the points @p new_points of
     * every new cell. */
    Field
    quadrature(const Field             &old_field,
               const Quadrature<dim>   &old_points,
               const std::vector<Rule> &rules,
               const Quadrature<dim>   &new_points) const;

    /** What the momentum rule of a velocity needs on the new layer, per
     * copy i: int rho phi_i v_old,c(i) and int rho phi_i over its cell. */
    struct Momentum
    {
      Vector<double> momentum;
      Vector<double> mass;
      /** 1/2 int rho |v_old|^2 at the same points: the bound of the new
       * kinetic energy. */
      double kinetic_energy = 0;
    };

    /** The momentum rule for a velocity (remeshing of explicit runs):
     * @p old_copies evaluated at the points @p new_points of every new
     * cell (each located in the old mesh of its ply) and integrated
     * against the new shape functions, with @p density per material id.
     * Summed over the copies of a reduced unknown, momentum / mass is a
     * weighted mean of the old velocity with the non-negative weights
     * rho phi_i JxW (degree 1, Gauss points inside the cell): the kinetic
     * energy of the new lumped mass never exceeds the old field's at
     * those points, and the new lumped momentum is the old field's
     * integral. (The lumped mass of a linear wedge, its vertices with
     * equal weights, equals this mass on affine wedges: those of the
     * extruded meshes, which remeshing keeps flat, without Mesh
     * distortion or Imperfection.) Nodal interpolation instead hands a node of
     * a coarser mesh the mass of the nodes it replaces at its own velocity,
     * which can create kinetic energy. */
    Momentum
    momentum(const Vector<double>      &old_copies,
             const std::vector<double> &density,
             const Quadrature<dim>     &new_points) const;

    /** How many new nodes (a vertex once per ply) and points lay outside the
     * old mesh of their ply at the last call (extrapolated from the nearest
     * cell). */
    unsigned int
    n_outside() const
    {
      return outside;
    }

  private:
    /** The smooth components projected to the old vertices, ply by ply:
     * [component][(vertex, ply) slot]. */
    std::vector<std::vector<double>>
    project_to_vertices(const Field             &old_field,
                        const Quadrature<dim>   &old_points,
                        const std::vector<Rule> &rules) const;

    /** The largest old value of each non-decreasing component that lies
     * in each new cell: [new cell][component]. */
    std::vector<std::vector<double>>
    largest_inside_new_cells(const Field             &old_field,
                             const Quadrature<dim>   &old_points,
                             const std::vector<Rule> &rules) const;

    const TiedCopyDoFs<dim> &old_dofs;
    const TiedCopyDoFs<dim> &new_dofs;
    CellLocator<dim>         old_cells;
    CellLocator<dim>         new_cells;
    /** The slot of (vertex index, ply) of the old mesh. */
    std::map<std::pair<unsigned int, types::material_id>, unsigned int> slots;
    mutable unsigned int outside = 0;
  };
} // namespace amfrac

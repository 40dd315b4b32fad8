#pragma once

#include <cmath>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <limits>
#include <map>
#include <vector>

namespace amfrac
{
  /**
   * What makes two elements' matrices equal: the ply and the vertex
   * positions relative to the first vertex (the mapping is linear, so a
   * translated copy has the same matrices), rounded to 1e-9 of the
   * element's size. With a mapping of higher degree (@p curved_mapping:
   * TiedCopyDoFs maps elements of degree 2 with the manifolds) a cell with
   * a curved manifold on itself, a face or an edge (the open hole's) is a
   * shape of its own. BulkForceOperator shares element stiffness matrices
   * by it, FaceHoffmanScreen its face-stress matrices.
   */
  template <int dim, typename CellIterator>
  std::vector<long long>
  shape_key(const CellIterator &cell, const bool curved_mapping)
  {
    const double quantum = 1e-9 * cell->diameter();
    // The offsets in units of the size leave the size out: a refined
    // cell's child has its parent's key but not its matrices (element
    // stiffness in 3D and every strain operator scale with 1 / size).
    std::vector<long long> key{static_cast<long long>(cell->material_id()),
                               std::llround(1e9 * std::log(cell->diameter()))};
    for (const unsigned int v : cell->vertex_indices())
      for (unsigned int d = 0; d < dim; ++d)
        key.push_back(
          std::llround((cell->vertex(v)[d] - cell->vertex(0)[d]) / quantum));
    if (!curved_mapping)
      return key;
    constexpr auto flat   = dealii::numbers::flat_manifold_id;
    bool           curved = cell->manifold_id() != flat;
    for (const unsigned int f : cell->face_indices())
      curved |= cell->face(f)->manifold_id() != flat;
    if constexpr (dim == 3)
      for (const unsigned int l : cell->line_indices())
        curved |= cell->line(l)->manifold_id() != flat;
    if (curved)
      key.push_back(-1 - static_cast<long long>(cell->active_cell_index()));
    return key;
  }



  /** Every active cell of a mesh sorted into shapes (by shape_key). */
  template <int dim>
  struct CellShapes
  {
    using Cell = typename dealii::DoFHandler<dim>::active_cell_iterator;
    /** The shape of each active cell, by active cell index. */
    std::vector<unsigned int> shape_of_cell;
    /** The first cell (in active cell order) of each shape. */
    std::vector<Cell> first_cell;
  };



  /**
   * Sort all active cells of @p handler into shapes. Every rank of a shared
   * mesh sorts all cells, so that the shapes' numbers and first cells are
   * the same on every rank (their matrices are then computed from the same
   * cell everywhere, and results do not depend on the partition). With
   * @p max_shapes given, a mesh of more shapes gives no sorting at all
   * (both vectors empty), and the sorting's memory stays bounded.
   */
  template <int dim>
  CellShapes<dim>
  sort_into_shapes(const dealii::DoFHandler<dim> &handler,
                   const bool                     curved_mapping,
                   const std::size_t              max_shapes
                   = std::numeric_limits<std::size_t>::max())
  {
    CellShapes<dim>                                shapes;
    std::map<std::vector<long long>, unsigned int> index;
    shapes.shape_of_cell.resize(handler.get_triangulation().n_active_cells());
    for (const auto &cell : handler.active_cell_iterators())
      {
        const auto [entry, added]
          = index.emplace(shape_key<dim>(cell, curved_mapping),
                          shapes.first_cell.size());
        if (added)
          shapes.first_cell.push_back(cell);
        if (shapes.first_cell.size() > max_shapes)
          return CellShapes<dim>();
        shapes.shape_of_cell[cell->active_cell_index()] = entry->second;
      }
    return shapes;
  }
} // namespace amfrac

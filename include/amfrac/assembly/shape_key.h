#pragma once

#include <cmath>
#include <deal.II/base/types.h>
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
} // namespace amfrac

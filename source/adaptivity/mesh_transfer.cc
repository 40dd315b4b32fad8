#include <algorithm>
#include <amfrac/adaptivity/mesh_transfer.h>
#include <amfrac/base/reference_cells.h>
#include <boost/geometry/index/rtree.hpp>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_wedge_p.h>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>

namespace amfrac
{
  namespace bgi = boost::geometry::index;

  template <int dim>
  CellLocator<dim>::CellLocator(const TiedCopyDoFs<dim> &dofs)
    : dofs(dofs)
  {
    // Boxes of the vertices, grown by a little of the cell's size so that
    // a point on a face (round-off either way) finds both cells.
    std::map<types::material_id, std::vector<std::pair<Box, CellIterator>>>
      boxes;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        Box box = dofs.get_mapping().get_bounding_box(cell);
        box.extend(1e-8 * cell->diameter());
        boxes[cell->material_id()].emplace_back(box, cell);
      }
    for (auto &[ply, list] : boxes)
      trees.emplace(ply, pack_rtree(list));
  }



  template <int dim>
  typename CellLocator<dim>::Location
  CellLocator<dim>::locate(const Point<dim>        &p,
                           const types::material_id ply) const
  {
    const auto tree = trees.find(ply);
    if (tree == trees.end())
      throw std::invalid_argument("CellLocator: the mesh has no cell of ply "
                                  + std::to_string(ply));
    std::vector<std::pair<Box, CellIterator>> candidates;
    tree->second.query(bgi::intersects(p), std::back_inserter(candidates));
    if (candidates.empty())
      tree->second.query(bgi::nearest(p, 8), std::back_inserter(candidates));

    const auto &mapping = dofs.get_mapping();
    const auto &shape   = dofs.reference_cell();
    Location    nearest{candidates.front().second, Point<dim>(), false};
    double      distance = std::numeric_limits<double>::infinity();
    for (const auto &[box, cell] : candidates)
      {
        Point<dim> unit;
        try
          {
            unit = real_to_unit<dim>(mapping, cell, p);
          }
        catch (const typename Mapping<dim>::ExcTransformationFailed &)
          {
            continue;
          }
        if (inside_reference_cell(shape, unit, 1e-10))
          return {cell, project_to_reference_cell(shape, unit), true};
        const Point<dim> projected = project_to_reference_cell(shape, unit);
        const double     d
          = p.distance(mapping.transform_unit_to_real_cell(cell, projected));
        if (d < distance)
          {
            distance = d;
            nearest  = {cell, projected, false};
          }
      }
    if (!std::isfinite(distance))
      throw std::runtime_error("CellLocator: no cell maps to the point");
    return nearest;
  }



  template <int dim>
  typename CellLocator<dim>::Location
  CellLocator<dim>::locate(const Point<dim> &p) const
  {
    std::optional<Location> first;
    for (const auto &[ply, tree] : trees)
      {
        const Location found = locate(p, ply);
        if (found.inside)
          return found;
        if (!first)
          first = found;
      }
    return *first;
  }



  namespace
  {
    /** The linear scalar element of @p shape: its shape function k
     * belongs to vertex k of the cell. */
    template <int dim>
    std::unique_ptr<FiniteElement<dim>>
    linear_element(const ReferenceCell &shape)
    {
      if constexpr (dim == 3)
        if (shape == ReferenceCells::Wedge)
          return std::make_unique<FE_WedgeP<dim>>(1);
      AssertThrow(shape.is_hyper_cube(), ExcNotImplemented());
      return std::make_unique<FE_Q<dim>>(1);
    }
  } // namespace



  template <int dim>
  NonMatchingTransfer<dim>::NonMatchingTransfer(
    const TiedCopyDoFs<dim> &old_dofs,
    const TiedCopyDoFs<dim> &new_dofs)
    : old_dofs(old_dofs)
    , new_dofs(new_dofs)
    , old_cells(old_dofs)
    , new_cells(new_dofs)
  {
    for (const auto &cell : old_dofs.copy_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        slots.emplace(std::make_pair(cell->vertex_index(v),
                                     cell->material_id()),
                      slots.size());
  }



  template <int dim>
  Vector<double>
  NonMatchingTransfer<dim>::nodal(const Vector<double> &old_copies) const
  {
    const auto &old_fe = old_dofs.get_fe(), &new_fe = new_dofs.get_fe();
    const auto &old_base = old_fe.base_element(0);
    const auto &new_base = new_fe.base_element(0);
    std::vector<types::global_dof_index> old_indices(old_fe.n_dofs_per_cell()),
      new_indices(new_fe.n_dofs_per_cell());
    Vector<double> copies(new_dofs.n_copies());
    outside = 0;
    // A node is located once for all its components, and a vertex once for
    // all the cells of its ply around it (a vertex of an extruded mesh has
    // a dozen).
    using Location = typename CellLocator<dim>::Location;
    std::map<std::pair<unsigned int, types::material_id>, Location> at_vertex;
    const auto locate = [&](const auto &cell, const Point<dim> &p) {
      for (const unsigned int v : cell->vertex_indices())
        if (p.distance(cell->vertex(v)) < 1e-12 * cell->diameter())
          {
            const auto key
              = std::make_pair(cell->vertex_index(v), cell->material_id());
            const auto known = at_vertex.find(key);
            if (known != at_vertex.end())
              return known->second;
            const Location found = old_cells.locate(p, cell->material_id());
            outside += found.inside ? 0 : 1;
            return at_vertex.emplace(key, found).first->second;
          }
      const Location found = old_cells.locate(p, cell->material_id());
      outside += found.inside ? 0 : 1;
      return found;
    };
    std::vector<double> phi(old_base.n_dofs_per_cell());
    for (const auto &cell : new_dofs.copy_handler().active_cell_iterators())
      {
        cell->get_dof_indices(new_indices);
        for (unsigned int k = 0; k < new_base.n_dofs_per_cell(); ++k)
          {
            const Point<dim> p
              = new_dofs.get_linear_mapping().transform_unit_to_real_cell(
                cell, new_base.unit_support_point(k));
            const Location found = locate(cell, p);
            found.cell->get_dof_indices(old_indices);
            for (unsigned int m = 0; m < phi.size(); ++m)
              phi[m] = old_base.shape_value(m, found.unit);
            for (unsigned int c = 0; c < dim; ++c)
              {
                double value = 0;
                for (unsigned int m = 0; m < phi.size(); ++m)
                  value
                    += phi[m]
                       * old_copies
                         [old_indices[old_fe.component_to_system_index(c, m)]];
                copies[new_indices[new_fe.component_to_system_index(c, k)]]
                  = value;
              }
          }
      }
    return copies;
  }



  template <int dim>
  std::vector<std::vector<double>>
  NonMatchingTransfer<dim>::project_to_vertices(
    const Field             &old_field,
    const Quadrature<dim>   &old_points,
    const std::vector<Rule> &rules) const
  {
    const auto         linear = linear_element<dim>(old_dofs.reference_cell());
    FEValues<dim>      values(old_dofs.get_mapping(),
                         *linear,
                         old_points,
                         update_values | update_JxW_values);
    const unsigned int n_components = rules.size();
    std::vector<std::vector<double>> sums(n_components,
                                          std::vector<double>(slots.size()));
    std::vector<double>              weights(slots.size());
    for (const auto &cell : old_dofs.copy_handler().active_cell_iterators())
      {
        // The linear element is not the copy layer's: a mesh cell, not a DoF
        // cell, for its shape values.
        values.reinit(typename Triangulation<dim>::cell_iterator(cell));
        const auto &field = old_field[cell->active_cell_index()];
        for (const unsigned int k : cell->vertex_indices())
          {
            const unsigned int slot
              = slots.at({cell->vertex_index(k), cell->material_id()});
            for (const unsigned int q : values.quadrature_point_indices())
              {
                const double w = values.shape_value(k, q) * values.JxW(q);
                weights[slot] += w;
                for (unsigned int c = 0; c < n_components; ++c)
                  if (rules[c] == Rule::smooth)
                    sums[c][slot] += w * field[q * n_components + c];
              }
          }
      }
    for (auto &component : sums)
      for (unsigned int s = 0; s < slots.size(); ++s)
        component[s] /= weights[s];
    return sums;
  }



  namespace
  {
    /** The index of the point of @p points nearest to @p unit (reference
     * coordinates). */
    template <int dim>
    unsigned int
    nearest_point(const Quadrature<dim> &points, const Point<dim> &unit)
    {
      unsigned int nearest = 0;
      for (unsigned int p = 1; p < points.size(); ++p)
        if (points.point(p).distance_square(unit)
            < points.point(nearest).distance_square(unit))
          nearest = p;
      return nearest;
    }
  } // namespace



  template <int dim>
  std::vector<std::vector<double>>
  NonMatchingTransfer<dim>::largest_inside_new_cells(
    const Field             &old_field,
    const Quadrature<dim>   &old_points,
    const std::vector<Rule> &rules) const
  {
    const unsigned int               n_components = rules.size();
    std::vector<std::vector<double>> largest(
      new_dofs.copy_handler().get_triangulation().n_active_cells(),
      std::vector<double>(n_components,
                          -std::numeric_limits<double>::infinity()));
    FEValues<dim> values(old_dofs.get_mapping(),
                         old_dofs.get_fe(),
                         old_points,
                         update_quadrature_points);
    for (const auto &cell : old_dofs.copy_handler().active_cell_iterators())
      {
        values.reinit(cell);
        const auto &field = old_field[cell->active_cell_index()];
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const auto found = new_cells.locate(values.quadrature_point(q),
                                                cell->material_id());
            auto      &into  = largest[found.cell->active_cell_index()];
            for (unsigned int c = 0; c < n_components; ++c)
              if (rules[c] != Rule::smooth)
                into[c] = std::max(into[c], field[q * n_components + c]);
          }
      }
    return largest;
  }



  template <int dim>
  typename NonMatchingTransfer<dim>::Field
  NonMatchingTransfer<dim>::quadrature(const Field             &old_field,
                                       const Quadrature<dim>   &old_points,
                                       const std::vector<Rule> &rules,
                                       const Quadrature<dim> &new_points) const
  {
    const unsigned int n_components = rules.size();
    const auto         vertex_values
      = project_to_vertices(old_field, old_points, rules);
    const auto largest = largest_inside_new_cells(old_field, old_points, rules);
    const auto linear  = linear_element<dim>(old_dofs.reference_cell());

    FEValues<dim> values(new_dofs.get_mapping(),
                         new_dofs.get_fe(),
                         new_points,
                         update_quadrature_points);
    Field field(new_dofs.copy_handler().get_triangulation().n_active_cells(),
                std::vector<double>(new_points.size() * n_components));
    outside = 0;
    for (const auto &cell : new_dofs.copy_handler().active_cell_iterators())
      {
        values.reinit(cell);
        auto &into = field[cell->active_cell_index()];
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const auto found = old_cells.locate(values.quadrature_point(q),
                                                cell->material_id());
            outside += found.inside ? 0 : 1;
            const auto &old_values = old_field[found.cell->active_cell_index()];
            // The nearest old point, once per new point (every injected
            // and nearest component takes its value).
            const unsigned int nearest = nearest_point(old_points, found.unit);
            for (unsigned int c = 0; c < n_components; ++c)
              {
                double &value = into[q * n_components + c];
                if (rules[c] == Rule::smooth)
                  {
                    value = 0;
                    for (const unsigned int k : found.cell->vertex_indices())
                      value += linear->shape_value(k, found.unit)
                               * vertex_values[c][slots.at(
                                 {found.cell->vertex_index(k),
                                  cell->material_id()})];
                  }
                else if (rules[c] == Rule::non_decreasing)
                  {
                    value = largest[cell->active_cell_index()][c];
                    for (unsigned int p = 0; p < old_points.size(); ++p)
                      value = std::max(value, old_values[p * n_components + c]);
                  }
                else if (rules[c] == Rule::nearest)
                  value = old_values[nearest * n_components + c];
                else
                  value = std::max(largest[cell->active_cell_index()][c],
                                   old_values[nearest * n_components + c]);
              }
          }
      }
    return field;
  }



  template <int dim>
  typename NonMatchingTransfer<dim>::Momentum
  NonMatchingTransfer<dim>::momentum(const Vector<double>      &old_copies,
                                     const std::vector<double> &density,
                                     const Quadrature<dim> &new_points) const
  {
    const auto &old_fe = old_dofs.get_fe(), &new_fe = new_dofs.get_fe();
    const auto &old_base = old_fe.base_element(0);
    std::vector<types::global_dof_index> old_indices(old_fe.n_dofs_per_cell()),
      new_indices(new_fe.n_dofs_per_cell());
    FEValues<dim> values(new_dofs.get_mapping(),
                         new_fe,
                         new_points,
                         update_values | update_quadrature_points
                           | update_JxW_values);
    Momentum      result{Vector<double>(new_dofs.n_copies()),
                    Vector<double>(new_dofs.n_copies())};
    outside = 0;
    for (const auto &cell : new_dofs.copy_handler().active_cell_iterators())
      {
        values.reinit(cell);
        cell->get_dof_indices(new_indices);
        const double rho = density.at(cell->material_id());
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const auto found = old_cells.locate(values.quadrature_point(q),
                                                cell->material_id());
            outside += found.inside ? 0 : 1;
            found.cell->get_dof_indices(old_indices);
            Tensor<1, dim> v;
            for (unsigned int m = 0; m < old_base.n_dofs_per_cell(); ++m)
              for (unsigned int c = 0; c < dim; ++c)
                v[c] += old_base.shape_value(m, found.unit)
                        * old_copies
                          [old_indices[old_fe.component_to_system_index(c, m)]];
            result.kinetic_energy += 0.5 * rho * (v * v) * values.JxW(q);
            for (const unsigned int i : values.dof_indices())
              {
                const double w = rho * values.shape_value(i, q) * values.JxW(q);
                result.mass[new_indices[i]] += w;
                result.momentum[new_indices[i]]
                  += w * v[new_fe.system_to_component_index(i).first];
              }
          }
      }
    return result;
  }



  template class CellLocator<2>;
  template class CellLocator<3>;
  template class NonMatchingTransfer<2>;
  template class NonMatchingTransfer<3>;
} // namespace amfrac

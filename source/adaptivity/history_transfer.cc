#include <algorithm>
#include <amfrac/adaptivity/history_transfer.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <limits>

namespace amfrac
{
  namespace
  {
    /** The recovery space is free across faces between plies. */
    template <int dim>
    bool
    between_plies(const typename TiedCopyDoFs<dim>::CellIterator &cell,
                  const unsigned int                              face)
    {
      return !cell->at_boundary(face)
             && cell->neighbor(face)->material_id() != cell->material_id();
    }
  } // namespace



  template <int dim>
  QuadratureHistoryTransfer<dim>::QuadratureHistoryTransfer(
    const Triangulation<dim> &triangulation,
    const unsigned int        degree,
    const Quadrature<dim>    &quadrature,
    const std::vector<Rule>  &rules,
    const bool                keep_unchanged_cells)
    : triangulation(triangulation)
    , quadrature(quadrature)
    , rules(rules)
    , keep_unchanged_cells(keep_unchanged_cells)
    , recovery(triangulation, degree)
  {
    for (unsigned int c = 0; c < rules.size(); ++c)
      {
        // A refinement keeps the cells it does not touch; the rule is for
        // meshes that share nothing.
        AssertThrow(rules[c] != Rule::nearest,
                    ExcMessage("Rule::nearest is for NonMatchingTransfer"));
        if (rules[c] == Rule::smooth)
          smooth.push_back(c);
      }
  }



  template <int dim>
  std::vector<dealii::Vector<double>>
  QuadratureHistoryTransfer<dim>::project(const Field &field) const
  {
    const auto        &fe        = recovery.get_fe();
    const auto        &hanging   = recovery.hanging_node_constraints();
    const unsigned int n_local   = fe.n_dofs_per_cell();
    const unsigned int n_history = rules.size();
    std::vector<types::global_dof_index> indices(n_local);

    DynamicSparsityPattern dsp(recovery.n_dofs());
    for (const auto &cell : recovery.copy_handler().active_cell_iterators())
      {
        recovery.get_dof_indices(cell, indices);
        hanging.add_entries_local_to_global(indices, dsp, false);
      }
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> mass(pattern);

    // dim history components per pass, one per vector component.
    const unsigned int n_passes = (smooth.size() + dim - 1) / dim;
    std::vector<dealii::Vector<double>> rhs(
      n_passes, dealii::Vector<double>(recovery.n_dofs()));
    FEValues<dim>          values(recovery.get_mapping(),
                         fe,
                         quadrature,
                         update_values | update_JxW_values);
    FullMatrix<double>     cell_mass(n_local, n_local);
    dealii::Vector<double> cell_rhs(n_local);
    for (const auto &cell : recovery.copy_handler().active_cell_iterators())
      {
        values.reinit(cell);
        recovery.get_dof_indices(cell, indices);
        const auto &at = field[cell->active_cell_index()];
        cell_mass      = 0;
        for (unsigned int i = 0; i < n_local; ++i)
          for (unsigned int j = 0; j < n_local; ++j)
            if (fe.system_to_component_index(i).first
                == fe.system_to_component_index(j).first)
              for (const unsigned int q : values.quadrature_point_indices())
                cell_mass(i, j) += values.shape_value(i, q)
                                   * values.shape_value(j, q) * values.JxW(q);
        for (unsigned int pass = 0; pass < n_passes; ++pass)
          {
            cell_rhs = 0;
            for (unsigned int i = 0; i < n_local; ++i)
              {
                const unsigned int d = fe.system_to_component_index(i).first;
                if (pass * dim + d >= smooth.size())
                  continue;
                const unsigned int c = smooth[pass * dim + d];
                for (const unsigned int q : values.quadrature_point_indices())
                  cell_rhs(i) += values.shape_value(i, q)
                                 * at[q * n_history + c] * values.JxW(q);
              }
            if (pass == 0)
              hanging.distribute_local_to_global(
                cell_mass, cell_rhs, indices, mass, rhs[0]);
            else
              hanging.distribute_local_to_global(cell_rhs, indices, rhs[pass]);
          }
      }

    SparseDirectUMFPACK solver;
    solver.initialize(mass);
    std::vector<dealii::Vector<double>> copies(n_passes);
    for (unsigned int pass = 0; pass < n_passes; ++pass)
      {
        dealii::Vector<double> nodal(recovery.n_dofs());
        solver.vmult(nodal, rhs[pass]);
        hanging.distribute(nodal);
        recovery.expand_all(nodal, copies[pass]);
      }
    return copies;
  }



  template <int dim>
  void
  QuadratureHistoryTransfer<dim>::prepare(const Field &old_field)
  {
    AssertThrow(old_field.size() == triangulation.n_active_cells(),
                ExcMessage("the history field needs one entry per active "
                           "cell"));
    recovery.distribute(&between_plies<dim>);
    old_copies = smooth.empty() ? std::vector<dealii::Vector<double>>() :
                                  project(old_field);
    transfer = std::make_unique<SolutionTransfer<dim, dealii::Vector<double>>>(
      recovery.copy_handler());
    if (!old_copies.empty())
      transfer->prepare_for_coarsening_and_refinement(old_copies);
    old_values.clear();
    for (const auto &cell : triangulation.active_cell_iterators())
      old_values[cell->id()] = old_field[cell->active_cell_index()];
  }



  template <int dim>
  typename QuadratureHistoryTransfer<dim>::Field
  QuadratureHistoryTransfer<dim>::interpolate()
  {
    const unsigned int n_history = rules.size();
    const unsigned int n_q       = quadrature.size();
    Field              field(triangulation.n_active_cells(),
                std::vector<double>(n_q * n_history, 0.));
    recovery.distribute(&between_plies<dim>);
    if (!old_copies.empty())
      {
        std::vector<dealii::Vector<double>> copies(
          old_copies.size(), dealii::Vector<double>(recovery.n_copies()));
        transfer->interpolate(old_copies, copies);
        FEValues<dim>                       values(recovery.get_mapping(),
                             recovery.get_fe(),
                             quadrature,
                             update_values);
        std::vector<dealii::Vector<double>> at(n_q,
                                               dealii::Vector<double>(dim));
        for (const auto &cell : recovery.copy_handler().active_cell_iterators())
          {
            values.reinit(cell);
            auto &mine = field[cell->active_cell_index()];
            for (unsigned int pass = 0; pass < copies.size(); ++pass)
              {
                values.get_function_values(copies[pass], at);
                for (unsigned int d = 0;
                     d < dim && pass * dim + d < smooth.size();
                     ++d)
                  for (unsigned int q = 0; q < n_q; ++q)
                    mine[q * n_history + smooth[pass * dim + d]] = at[q][d];
              }
          }
      }
    transfer_non_decreasing(field);
    transfer.reset();
    old_copies.clear();
    return field;
  }



  template <int dim>
  void
  QuadratureHistoryTransfer<dim>::transfer_non_decreasing(Field &field) const
  {
    const unsigned int n_history = rules.size();
    const unsigned int n_q       = quadrature.size();
    const auto         copy      = [&](std::vector<double>       &to,
                          const unsigned int         q_to,
                          const std::vector<double> &from,
                          const unsigned int         q_from,
                          const bool                 all = false) {
      for (unsigned int c = 0; c < n_history; ++c)
        if (all || rules[c] != Rule::smooth)
          to[q_to * n_history + c] = from[q_from * n_history + c];
    };
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        auto &mine = field[cell->active_cell_index()];
        if (const auto kept = old_values.find(cell->id());
            kept != old_values.end())
          {
            for (unsigned int q = 0; q < n_q; ++q)
              copy(mine, q, kept->second, q, keep_unchanged_cells);
            continue;
          }
        if (cell->level() > 0)
          if (const auto parent = old_values.find(cell->parent()->id());
              parent != old_values.end())
            {
              // Refined: injection from the parent's nearest point.
              unsigned int child = 0;
              while (cell->parent()->child(child) != cell)
                ++child;
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  const Point<dim> in_parent
                    = GeometryInfo<dim>::child_to_cell_coordinates(
                      quadrature.point(q),
                      child,
                      cell->parent()->refinement_case());
                  unsigned int nearest = 0;
                  for (unsigned int k = 1; k < n_q; ++k)
                    if (in_parent.distance(quadrature.point(k))
                        < in_parent.distance(quadrature.point(nearest)))
                      nearest = k;
                  copy(mine, q, parent->second, nearest);
                }
              continue;
            }
        // Coarsened: the largest value of the children's points.
        std::vector<double> largest(n_history,
                                    -std::numeric_limits<double>::max());
        bool                found = false;
        const auto          path  = cell->id().get_child_indices();
        for (unsigned int i = 0; i < GeometryInfo<dim>::max_children_per_cell;
             ++i)
          {
            std::vector<std::uint8_t> indices(path.begin(), path.end());
            indices.push_back(i);
            const auto child = old_values.find(
              CellId(cell->id().get_coarse_cell_id(), indices));
            if (child == old_values.end())
              continue;
            found = true;
            for (unsigned int q = 0; q < n_q; ++q)
              for (unsigned int c = 0; c < n_history; ++c)
                largest[c]
                  = std::max(largest[c], child->second[q * n_history + c]);
          }
        AssertThrow(found,
                    ExcMessage("a cell of the new mesh is neither an old "
                               "cell, nor a child, nor the parent of old "
                               "cells: more than one refinement step"));
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int c = 0; c < n_history; ++c)
            if (rules[c] != Rule::smooth)
              mine[q * n_history + c] = largest[c];
      }
  }



  template class QuadratureHistoryTransfer<2>;
  template class QuadratureHistoryTransfer<3>;
} // namespace amfrac

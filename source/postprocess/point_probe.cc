#include <algorithm>
#include <amfrac/adaptivity/mesh_transfer.h>
#include <amfrac/assembly/displacement_gradients.h>
#include <amfrac/base/reference_cells.h>
#include <amfrac/postprocess/point_probe.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <sstream>
#include <stdexcept>

namespace amfrac
{
  template <int dim>
  PointProbe<dim>::PointProbe(const TiedCopyDoFs<dim>               &dofs,
                              const std::vector<PlyProperties<dim>> &plies,
                              const std::vector<Point<dim>>         &points,
                              const bool finite_strain)
    : dofs(dofs)
    , plies(plies)
    , finite_strain(finite_strain)
  {
    // deal.II 9.4's search tests the unit cube, which is wrong for a wedge
    // (inside_reference_cell()): on wedges the transfer's locator searches.
    std::unique_ptr<CellLocator<dim>> wedges;
    if (!dofs.reference_cell().is_hyper_cube())
      wedges = std::make_unique<CellLocator<dim>>(dofs);
    for (const Point<dim> &p : points)
      {
        const auto found = locate(p, wedges.get());
        if (found.first.state() != IteratorState::valid)
          {
            std::ostringstream text;
            text << "point (" << p << ") lies outside the laminate";
            throw std::invalid_argument(text.str());
          }
        cells.push_back(found.first);
        unit_points.push_back(found.second);
      }
  }



  template <int dim>
  std::pair<typename TiedCopyDoFs<dim>::CellIterator, Point<dim>>
  PointProbe<dim>::locate(const Point<dim>       &p,
                          const CellLocator<dim> *wedges) const
  {
    const Mapping<dim> &mapping = dofs.get_mapping();
    const auto         &shape   = dofs.reference_cell();
    if (shape.is_hyper_cube())
      {
        try
          {
            const auto found
              = GridTools::find_active_cell_around_point(mapping,
                                                         dofs.copy_handler(),
                                                         p);
            if (found.first.state() == IteratorState::valid)
              return {found.first,
                      project_to_reference_cell(shape, found.second)};
          }
        catch (...)
          {}
        return {dofs.copy_handler().end(), Point<dim>()};
      }
    const auto found = wedges->locate(p);
    if (found.inside)
      return {found.cell, found.unit};
    return {dofs.copy_handler().end(), Point<dim>()};
  }



  template <int dim>
  std::vector<typename PointProbe<dim>::Value>
  PointProbe<dim>::evaluate(
    const dealii::Vector<double>             &copy_values,
    const std::vector<SymmetricTensor<2, 3>> &plastic_strain) const
  {
    std::vector<Value>  values(cells.size());
    std::vector<double> flat;
    for (unsigned int k = 0; k < cells.size(); ++k)
      {
        if (cells[k]->is_locally_owned())
          {
            FEValues<dim> fe_values(dofs.get_mapping(),
                                    dofs.get_fe(),
                                    Quadrature<dim>(unit_points[k]),
                                    update_values | update_gradients);
            fe_values.reinit(cells[k]);
            std::vector<Tensor<1, dim>>      u(1);
            std::vector<Tensor<2, dim>>      grad(1);
            const FEValuesExtractors::Vector displacement(0);
            fe_values[displacement].get_function_values(copy_values, u);
            fe_values[displacement].get_function_gradients(copy_values, grad);
            values[k].displacement = u[0];
            values[k].stress
              = evaluate_ply_stress(
                  plies[cells[k]->material_id()],
                  strain_measure(grad[0], finite_strain),
                  plastic_strain.empty() ?
                    nullptr :
                    &plastic_strain[cells[k]->active_cell_index()])
                  .model;
          }
        for (unsigned int d = 0; d < dim; ++d)
          flat.push_back(values[k].displacement[d]);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            flat.push_back(values[k].stress[i][j]);
      }
    const MPI_Comm comm
      = dofs.copy_handler().get_triangulation().get_communicator();
    Utilities::MPI::sum(flat, comm, flat);
    unsigned int n = 0;
    for (auto &value : values)
      {
        for (unsigned int d = 0; d < dim; ++d)
          value.displacement[d] = flat[n++];
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            value.stress[i][j] = flat[n++];
      }
    return values;
  }

  template class PointProbe<2>;
  template class PointProbe<3>;
} // namespace amfrac

#include <amfrac/base/reference_cells.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_wedge_p.h>

namespace amfrac
{
  template <int dim>
  Point<dim>
  real_to_unit(const Mapping<dim>                               &mapping,
               const typename Triangulation<dim>::cell_iterator &cell,
               const Point<dim>                                 &p)
  {
    if (cell->reference_cell().is_hyper_cube())
      return mapping.transform_real_to_unit_cell(cell, p);
    // Only a wedge comes here (amfrac's other shape is the hypercube).
    if constexpr (dim == 3)
      {
        static const FE_WedgeP<3> linear(1);
        Point<3>                  unit(1. / 3, 1. / 3, 0.5);
        const double              tolerance = 1e-13 * cell->diameter();
        for (unsigned int iteration = 0; iteration < 30; ++iteration)
          {
            Point<3>     x;
            Tensor<2, 3> jacobian;
            for (const unsigned int k : cell->vertex_indices())
              {
                x += linear.shape_value(k, unit) * cell->vertex(k);
                jacobian
                  += outer_product(cell->vertex(k), linear.shape_grad(k, unit));
              }
            const Tensor<1, 3> residual = x - p;
            if (residual.norm() < tolerance)
              return unit;
            if (!(std::abs(determinant(jacobian)) > 0))
              break;
            unit -= invert(jacobian) * residual;
          }
      }
    AssertThrow(false, typename Mapping<dim>::ExcTransformationFailed());
    return Point<dim>();
  }

  template Point<2>
  real_to_unit(const Mapping<2> &,
               const Triangulation<2>::cell_iterator &,
               const Point<2> &);
  template Point<3>
  real_to_unit(const Mapping<3> &,
               const Triangulation<3>::cell_iterator &,
               const Point<3> &);
} // namespace amfrac

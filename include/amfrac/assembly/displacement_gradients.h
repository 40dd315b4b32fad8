#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /** The gradient of the displacement at every quadrature point of the
   * cell @p fe_values was reinitialized on, from its nodal values @p u
   * (a primitive vector element: shape i moves component c_i only). */
  template <int dim>
  void
  displacement_gradients(const FEValues<dim>          &fe_values,
                         const dealii::Vector<double> &u,
                         std::vector<Tensor<2, dim>>  &gradients)
  {
    const auto &fe = fe_values.get_fe();
    gradients.resize(fe_values.n_quadrature_points);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        gradients[q] = 0;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            gradients[q][c] += u(i) * fe_values.shape_grad(i, q);
          }
      }
  }

  /** The Green-Lagrange strain E = (F^T F - I) / 2 of F = I + @p grad_u,
   * as (H + H^T + H^T H) / 2 without forming F^T F - I, which would lose
   * the small strains of a stiff ply to cancellation. */
  template <int dim>
  SymmetricTensor<2, dim>
  green_lagrange_strain(const Tensor<2, dim> &grad_u)
  {
    return symmetrize(grad_u) + 0.5 * symmetrize(transpose(grad_u) * grad_u);
  }

  /** The strain of the kinematics: sym(@p grad_u) for small strains, the
   * Green-Lagrange strain with @p finite_strain (total Lagrangian). */
  template <int dim>
  SymmetricTensor<2, dim>
  strain_measure(const Tensor<2, dim> &grad_u, const bool finite_strain)
  {
    return finite_strain ? green_lagrange_strain(grad_u) : symmetrize(grad_u);
  }
} // namespace amfrac

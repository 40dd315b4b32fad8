#include <amfrac/assembly/displacement_gradients.h>
#include <amfrac/assembly/total_lagrangian.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace amfrac
{
  template <int dim>
  FiniteStrainPoint<dim>::FiniteStrainPoint(const Tensor<2, dim> &grad_u,
                                            const SymmetricTensor<4, dim> &C)
  {
    F              = unit_symmetric_tensor<dim>() + grad_u;
    E              = green_lagrange_strain(grad_u);
    S              = C * E;
    P              = F * Tensor<2, dim>(S);
    energy_density = 0.5 * (E * S);
  }



  template <int dim>
  TotalLagrangianAssembler<dim>::TotalLagrangianAssembler(
    const TiedCopyDoFs<dim>               &dofs,
    const std::vector<PlyProperties<dim>> &plies)
    : dofs(dofs)
    , plies(plies)
  {}



  template <int dim>
  double
  TotalLagrangianAssembler<dim>::assemble(
    const Vector                    &relevant_solution,
    const AffineConstraints<double> &constraints,
    Vector                          &force,
    Matrix                          *condensed,
    Matrix                          *unconstrained) const
  {
    const auto            &fe = dofs.get_fe();
    const unsigned int     n  = fe.n_dofs_per_cell();
    FEValues<dim>          fe_values(dofs.get_mapping(),
                            fe,
                            dofs.cell_quadrature(fe.degree + 1),
                            update_gradients | update_JxW_values);
    const bool             with_tangent = condensed || unconstrained;
    FullMatrix<double>     K(n, n);
    dealii::Vector<double> u(n), f(n);
    std::vector<types::global_dof_index> indices(n);
    std::vector<Tensor<2, dim>> gradients(fe_values.n_quadrature_points);
    // Per shape function: delta E_i = sym(F^T grad phi_i) and C : delta E_i.
    std::vector<SymmetricTensor<2, dim>> variation(n), stress_variation(n);
    AffineConstraints<double>            none;
    none.close();

    // Cells of this rank have dofs that other ranks own: add into a
    // vector that can take them, then hand them over.
    const MPI_Comm comm
      = dofs.copy_handler().get_triangulation().get_communicator();
    Vector writable;
    writable.reinit(dofs.locally_owned_dofs(),
                    dofs.locally_relevant_dofs(),
                    comm,
                    true);
    if (condensed)
      *condensed = 0;
    if (unconstrained)
      *unconstrained = 0;
    double energy = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          dofs.get_dof_indices(cell, indices);
          for (unsigned int i = 0; i < n; ++i)
            u(i) = relevant_solution(indices[i]);
          displacement_gradients(fe_values, u, gradients);
          const auto &C = plies[cell->material_id()].stiffness;
          f             = 0;
          K             = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const FiniteStrainPoint<dim> point(gradients[q], C);
              const double                 JxW = fe_values.JxW(q);
              energy += point.energy_density * JxW;
              for (unsigned int i = 0; i < n; ++i)
                {
                  // Shape i has the single component c: grad phi_i =
                  // e_c (x) g, so delta E_i = sym(F^T e_c (x) g).
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const Tensor<1, dim> &g = fe_values.shape_grad(i, q);
                  f(i) += point.P[c] * g * JxW;
                  if (!with_tangent)
                    continue;
                  variation[i] = symmetrize(outer_product(point.F[c], g));
                  stress_variation[i] = C * variation[i] * JxW;
                }
              if (!with_tangent)
                continue;
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c_i
                    = fe.system_to_component_index(i).first;
                  const Tensor<1, dim> S_g = Tensor<2, dim>(point.S)
                                             * fe_values.shape_grad(i, q) * JxW;
                  for (unsigned int j = 0; j <= i; ++j)
                    {
                      K(i, j) += stress_variation[i] * variation[j];
                      if (fe.system_to_component_index(j).first == c_i)
                        K(i, j) += S_g * fe_values.shape_grad(j, q);
                    }
                }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = i + 1; j < n; ++j)
              K(i, j) = K(j, i);
          writable.add(indices, f);
          if (condensed)
            constraints.distribute_local_to_global(K, indices, *condensed);
          if (unconstrained)
            none.distribute_local_to_global(K, indices, *unconstrained);
        }
    writable.compress(VectorOperation::add);
    force = writable;
    if (condensed)
      condensed->compress(VectorOperation::add);
    if (unconstrained)
      unconstrained->compress(VectorOperation::add);
    return Utilities::MPI::sum(energy, comm);
  }



  template struct FiniteStrainPoint<2>;
  template struct FiniteStrainPoint<3>;
  template class TotalLagrangianAssembler<2>;
  template class TotalLagrangianAssembler<3>;
} // namespace amfrac

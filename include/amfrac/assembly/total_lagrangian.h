#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/ply_table.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace amfrac
{
  /**
   * The plies' St Venant-Kirchhoff response at one point: Green-Lagrange
   * strain E = (F^T F - I) / 2 of F = I + grad u, second Piola-Kirchhoff
   * stress S = C : E with the ply's (orthotropic) small-strain stiffness,
   * first Piola-Kirchhoff stress P = F S and the strain energy density
   * E : C : E / 2. A rigid rotation F = R gives E = 0: no stress.
   */
  template <int dim>
  struct FiniteStrainPoint
  {
    Tensor<2, dim>          F;
    SymmetricTensor<2, dim> E;
    SymmetricTensor<2, dim> S;
    Tensor<2, dim>          P;
    double                  energy_density;

    FiniteStrainPoint(const Tensor<2, dim>          &grad_u,
                      const SymmetricTensor<4, dim> &C);
  };

  /**
   * Bulk (ply) total Lagrangian kinematics on the tied-copy layer: the
   * internal force F_int(u)_i = int P : grad(phi_i) dX and its consistent
   * tangent, the material part delta E_i : C : delta E_j plus the geometric
   * part grad(phi_i) . S grad(phi_j) (equal components), in the reduced
   * numbering. Used by the Newton path when Kinematics = total Lagrangian;
   * a small-strain scene never builds it.
   */
  template <int dim>
  class TotalLagrangianAssembler
  {
  public:
    using Matrix = TrilinosWrappers::SparseMatrix;
    using Vector = TrilinosWrappers::MPI::Vector;

    TotalLagrangianAssembler(const TiedCopyDoFs<dim>               &dofs,
                             const std::vector<PlyProperties<dim>> &plies);

    /** F_int(@p relevant_solution) without constraints into @p force (its
     * entries on supported dofs are reactions). If @p condensed is given,
     * the tangent condensed by @p constraints goes there, and if
     * @p unconstrained is given, the tangent without constraints (for
     * products with prescribed displacement jumps). Returns the strain
     * energy (summed over the ranks). Collective. */
    double
    assemble(const Vector                    &relevant_solution,
             const AffineConstraints<double> &constraints,
             Vector                          &force,
             Matrix                          *condensed,
             Matrix                          *unconstrained) const;

  private:
    const TiedCopyDoFs<dim>               &dofs;
    const std::vector<PlyProperties<dim>> &plies;
  };
} // namespace amfrac

#pragma once

#include <amfrac/assembly/loads.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/ply_table.h>
#include <deal.II/base/function.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <set>

namespace amfrac
{
  /**
   * A posteriori error estimators for the ply elasticity on the tied-copy
   * layer. Both give one indicator per active cell in the energy norm
   * (sqrt of N mm) and know the plies:
   *
   * - Zienkiewicz-Zhu: the stress recovered by superconvergent patch
   *   recovery (SPR, Zienkiewicz and Zhu 1992) in a space that is
   *   continuous inside each ply and discontinuous across ply interfaces
   *   and released faces (a second tied-copy layer that releases every
   *   face between different plies; patches never cross plies), so
   *   material jumps are not taken for error;
   *   eta_K^2 = int_K (s* - s_h) : C^-1 : (s* - s_h).
   * - Kelly: eta_K^2 = h_K / (24 E) sum over the faces of K of
   *   int_F |[s_h n]|^2, with the jump of the traction (not of the
   *   gradient), so that a ply interface with continuous traction counts
   *   nothing; released (cohesive) faces and supported boundary faces
   *   count nothing, other boundary faces count s_h n minus the applied
   *   traction. E is the largest stiffness entry of the plies (it only
   *   gives the indicator the units of the ZZ one).
   *
   * The displacement is passed as a reduced vector with every entry on
   * every rank (replicate()); the indicators come back summed over the
   * ranks, so that every rank marks the same cells of the shared mesh.
   */
  template <int dim>
  class ErrorEstimator
  {
  public:
    using FaceFilter = typename TiedCopyDoFs<dim>::FaceFilter;

    struct Estimate
    {
      /** eta_K per active cell (all cells, on every rank). */
      dealii::Vector<float> cell_errors;
      /** sqrt(sum eta_K^2). */
      double error = 0;
      /** Energy norm of u_h, sqrt(int s_h : e_h). */
      double solution_norm = 0;

      /** eta = ||e*|| / sqrt(||u_h||^2 + ||e*||^2) (the seed's measure). */
      double
      relative() const
      {
        const double total
          = std::sqrt(solution_norm * solution_norm + error * error);
        return total > 0 ? error / total : 0.;
      }
    };

    /** What Kelly needs of the boundary: the supported boundary ids (no
     * residual there) and the loads (the residual is s_h n - t). */
    struct Boundary
    {
      std::set<types::boundary_id> supported;
      const Loads<dim>            *loads = nullptr;
      double                       time  = 0;
    };

    /** With @p finite_strain (total Lagrangian), the stress is the
     * second Piola-Kirchhoff stress of the Green-Lagrange strain, so that
     * a rigid rotation carries no error. */
    ErrorEstimator(const TiedCopyDoFs<dim>               &dofs,
                   const std::vector<PlyProperties<dim>> &plies,
                   const FaceFilter                      &released,
                   const bool finite_strain = false);

    /** All entries of a distributed reduced vector, on every rank. */
    dealii::Vector<double>
    replicate(const TrilinosWrappers::MPI::Vector &owned) const;

    Estimate
    zienkiewicz_zhu(const dealii::Vector<double> &displacement) const;

    Estimate
    kelly(const dealii::Vector<double> &displacement,
          const Boundary               &boundary) const;

    /** The true error in the energy norm against @p exact (dim
     * components with gradients), summed over the ranks. */
    double
    energy_error(const dealii::Vector<double> &displacement,
                 const Function<dim>          &exact) const;

  private:
    const TiedCopyDoFs<dim>               &dofs;
    const std::vector<PlyProperties<dim>> &plies;
    const FaceFilter                       released;
    const bool                             finite_strain;
    std::vector<SymmetricTensor<4, dim>>   compliance;
    MPI_Comm                               comm;

    /** s_h in model axes at the points of @p values (already reinit). */
    void
    cell_stresses(const typename TiedCopyDoFs<dim>::CellIterator &cell,
                  const dealii::Vector<double>                   &u,
                  const FEValuesBase<dim, dim>                   &values,
                  std::vector<SymmetricTensor<2, dim>>           &stress) const;

    /** Sum @p local over the ranks into an Estimate with norms. */
    Estimate
    finish(dealii::Vector<float> &local, double norm_squared) const;

    /** The recovered stress s* (components in the unrolled order of
     * SymmetricTensor) at the nodes of @p recovery, a layer continuous
     * inside each ply, by superconvergent patch recovery: per vertex and
     * ply, a least-squares polynomial of the element degree through the
     * stresses at the Gauss points of degree p of the patch cells; every
     * node takes the mean of the full-rank fits of the patches its cells
     * belong to (rank-deficient fits, at corners or in plies one element
     * thick, only where no full-rank fit reaches). */
    std::vector<dealii::Vector<double>>
    recover_stress(const TiedCopyDoFs<dim>      &recovery,
                   const dealii::Vector<double> &u) const;
  };
} // namespace amfrac

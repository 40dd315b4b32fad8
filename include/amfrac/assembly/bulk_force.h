#pragma once

#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/assembly/element_kernel.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <string>

namespace amfrac
{
  /**
   * The bulk force K u of explicit dynamics without a global matrix: the
   * element matrices of the locally owned cells, shared among cells of the
   * same ply and shape (ElementMatrixKernel), applied to a ghosted copy of
   * u; contributions to ghost dofs are sent to their owners.
   */
  template <int dim>
  class BulkForceOperator
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    BulkForceOperator(const TiedCopyDoFs<dim>     &dofs,
                      const ElasticAssembler<dim> &assembler);

    /** @p force = K @p solution (both without ghosts); returns the strain
     * energy summed over all ranks. */
    double
    apply(const Vector &solution, Vector &force) const;

    /** Element and matrix counts and the memory they take (all ranks). */
    std::string
    summary() const;

  private:
    MPI_Comm                                           comm;
    ElementMatrixKernel                                kernel;
    mutable LinearAlgebra::distributed::Vector<double> u;
    mutable LinearAlgebra::distributed::Vector<double> f;
  };
} // namespace amfrac

#pragma once

#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/assembly/element_kernel.h>
#include <amfrac/cohesive/interface_assembler.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <string>

namespace amfrac
{
  /**
   * The internal force of explicit dynamics without a global matrix: K u
   * from the element matrices of the locally owned cells, shared among
   * cells of the same ply and shape (ElementMatrixKernel), plus, if given,
   * the cohesive interface forces (CohesiveInterfaces::add_forces), all on
   * one ghosted copy of u. Every rank evaluates all cells with a dof it
   * owns (its own and a layer of its neighbours'), so that each entry of
   * the force is the same sum in the same order on any number of ranks:
   * runs on 1 and on N ranks do not drift apart by round-off.
   */
  template <int dim>
  class BulkForceOperator
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** @p interfaces (may be null) get their local indices here. */
    BulkForceOperator(const TiedCopyDoFs<dim>     &dofs,
                      const ElasticAssembler<dim> &assembler,
                      CohesiveInterfaces<dim>     *interfaces = nullptr);

    /** @p force = K @p solution (both without ghosts), plus the interface
     * forces if @p with_interfaces (which updates and commits their
     * history); returns the strain energy of the plies summed over all
     * ranks. */
    double
    apply(const Vector &solution,
          Vector       &force,
          const bool    with_interfaces = false) const;

    /** Element and matrix counts and the memory they take (all ranks). */
    std::string
    summary() const;

  private:
    /** The kernel's elements: the cells flagged in @p evaluated (by
     * active cell index), in the order of the active cells. */
    void
    add_elements(const TiedCopyDoFs<dim>           &dofs,
                 const ElasticAssembler<dim>       &assembler,
                 const std::vector<bool>           &evaluated,
                 const Utilities::MPI::Partitioner &partitioner);

    MPI_Comm                                           comm;
    ElementMatrixKernel                                kernel;
    std::size_t                                        owned_elements = 0;
    CohesiveInterfaces<dim>                           *interfaces;
    mutable LinearAlgebra::distributed::Vector<double> u;
    mutable LinearAlgebra::distributed::Vector<double> f;
  };
} // namespace amfrac

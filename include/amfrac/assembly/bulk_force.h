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

    /** After crack insertion (the mesh unchanged, the numbering new): the
     * elements move to the new numbering and keep their shapes' matrices
     * (a shape is not looked up again; only a shape no cell of this rank
     * evaluated before gets its matrix now, and matrices no longer used
     * stay in the table, so summary() may count more than a fresh
     * operator). */
    void
    renumber(const TiedCopyDoFs<dim>     &dofs,
             const ElasticAssembler<dim> &assembler);

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
    using Cell = typename TiedCopyDoFs<dim>::CellIterator;

    /** Sort the cells into shapes (shape_of_cell, shapes). */
    void
    find_shapes(const TiedCopyDoFs<dim> &dofs);

    /** The ghosted vectors and the kernel's elements on the current
     * numbering. */
    void
    lay_out(const TiedCopyDoFs<dim>     &dofs,
            const ElasticAssembler<dim> &assembler);

    /** The kernel's elements: the cells flagged in @p evaluated (by
     * active cell index), in the order of the active cells. */
    void
    add_elements(const TiedCopyDoFs<dim>           &dofs,
                 const ElasticAssembler<dim>       &assembler,
                 const std::vector<bool>           &evaluated,
                 const Utilities::MPI::Partitioner &partitioner);

    /** Per active cell its shape; per shape the first cell of the mesh
     * with it and its matrix in the kernel (-1: none yet). */
    std::vector<unsigned int>         shape_of_cell;
    std::vector<std::pair<Cell, int>> shapes;

    MPI_Comm                                           comm;
    ElementMatrixKernel                                kernel;
    std::size_t                                        owned_elements = 0;
    CohesiveInterfaces<dim>                           *interfaces;
    mutable LinearAlgebra::distributed::Vector<double> u;
    mutable LinearAlgebra::distributed::Vector<double> f;
  };
} // namespace amfrac

#include <algorithm>
#include <amfrac/assembly/bulk_force.h>
#include <amfrac/assembly/shape_key.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <sstream>

namespace amfrac
{
  template <int dim>
  BulkForceOperator<dim>::BulkForceOperator(
    const TiedCopyDoFs<dim>     &dofs,
    const ElasticAssembler<dim> &assembler,
    CohesiveInterfaces<dim>     *interfaces)
    : comm(dofs.copy_handler().get_triangulation().get_communicator())
    , kernel(dofs.get_fe().n_dofs_per_cell())
    , interfaces(interfaces)
  {
    find_shapes(dofs);
    lay_out(dofs, assembler);
  }



  template <int dim>
  void
  BulkForceOperator<dim>::renumber(const TiedCopyDoFs<dim>     &dofs,
                                   const ElasticAssembler<dim> &assembler)
  {
    AssertThrow(shape_of_cell.size()
                  == dofs.copy_handler().get_triangulation().n_active_cells(),
                ExcMessage("BulkForceOperator::renumber() needs the mesh of "
                           "the operator's construction"));
    kernel.clear_elements();
    owned_elements = 0;
    lay_out(dofs, assembler);
  }



  template <int dim>
  void
  BulkForceOperator<dim>::find_shapes(const TiedCopyDoFs<dim> &dofs)
  {
    CellShapes<dim> sorted
      = sort_into_shapes(dofs.copy_handler(), dofs.get_fe().degree > 1);
    shape_of_cell = std::move(sorted.shape_of_cell);
    for (const Cell &cell : sorted.first_cell)
      shapes.emplace_back(cell, -1);
  }



  template <int dim>
  void
  BulkForceOperator<dim>::lay_out(const TiedCopyDoFs<dim>     &dofs,
                                  const ElasticAssembler<dim> &assembler)
  {
    // Every cell with an owned dof is evaluated here, owned or not, so
    // that each owned entry of K u is summed on one rank, term by term as
    // on a single rank (no partial sums of other ranks).
    const auto                           cells = dofs.cells_with_owned_dofs();
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(n);
    IndexSet                             ghosts = dofs.locally_relevant_dofs();
    std::vector<bool>                    evaluated(shape_of_cell.size());
    // An owned cell all of whose dofs belong to other ranks is evaluated
    // too, for its strain energy (its forces are not used here).
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        evaluated[cell->active_cell_index()] = true;
    std::vector<bool> needed(dofs.n_dofs(), false);
    for (const auto &cell : cells)
      {
        evaluated[cell->active_cell_index()] = true;
        dofs.get_dof_indices(cell, indices);
        for (const auto i : indices)
          needed[i] = true;
      }
    std::vector<types::global_dof_index> sorted;
    for (types::global_dof_index i = 0; i < needed.size(); ++i)
      if (needed[i])
        sorted.push_back(i);
    ghosts.add_indices(sorted.begin(), sorted.end());
    ghosts.compress();
    const auto partitioner
      = std::make_shared<Utilities::MPI::Partitioner>(dofs.locally_owned_dofs(),
                                                      ghosts,
                                                      comm);
    u.reinit(partitioner);
    f.reinit(partitioner);
    if (interfaces)
      interfaces->set_local_indices(*partitioner);
    add_elements(dofs, assembler, evaluated, *partitioner);
  }



  template <int dim>
  void
  BulkForceOperator<dim>::add_elements(
    const TiedCopyDoFs<dim>           &dofs,
    const ElasticAssembler<dim>       &assembler,
    const std::vector<bool>           &evaluated,
    const Utilities::MPI::Partitioner &partitioner)
  {
    // A shape's matrix is that of the first cell of the mesh with the
    // shape, whichever rank evaluates it: matrices of translated copies
    // differ in round-off, which must not depend on the partition.
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(n);
    std::vector<unsigned int>            local(n);
    FullMatrix<double>                   K(n, n);
    std::vector<double>                  row_major(n * n);
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        if (!evaluated[cell->active_cell_index()])
          continue;
        auto &[first, matrix]
          = shapes[shape_of_cell[cell->active_cell_index()]];
        if (matrix < 0)
          {
            assembler.element_stiffness(first, K);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                row_major[i * n + j] = K(i, j);
            matrix = kernel.add_matrix(row_major);
          }
        dofs.get_dof_indices(cell, indices);
        for (unsigned int i = 0; i < n; ++i)
          local[i] = partitioner.global_to_local(indices[i]);
        kernel.add_element(matrix, local.data(), cell->is_locally_owned());
        owned_elements += cell->is_locally_owned();
      }
  }



  template <int dim>
  double
  BulkForceOperator<dim>::apply(const Vector &solution,
                                Vector       &force,
                                const bool    with_interfaces) const
  {
    // Owned entries are stored in the same (ascending) order in both
    // vector types.
    const unsigned int n_owned = u.locally_owned_size();
    Assert(solution.locally_owned_size() == n_owned, ExcInternalError());
    std::copy(solution.begin(), solution.end(), u.begin());
    u.update_ghost_values();
    // The ghost entries of f collect partial sums that are not used: each
    // owned entry is complete here (see the constructor), so there is no
    // compress().
    f = 0;
    f.zero_out_ghost_values();
    const double energy = kernel.apply(u.get_values(), f.get_values());
    if (with_interfaces && interfaces)
      interfaces->add_forces(u.get_values(), f.get_values());
    std::copy(f.begin(), f.begin() + n_owned, force.begin());
    return Utilities::MPI::sum(energy, comm);
  }



  template <int dim>
  std::string
  BulkForceOperator<dim>::summary() const
  {
    const double elements = Utilities::MPI::sum(1. * owned_elements, comm);
    const double evaluated
      = Utilities::MPI::sum(1. * kernel.n_elements(), comm);
    const double matrices = Utilities::MPI::sum(1. * kernel.n_matrices(), comm);
    const double bytes
      = Utilities::MPI::sum(1. * kernel.memory_consumption(), comm);
    std::ostringstream s;
    s << matrices << " element matrices for " << elements << " elements ("
      << bytes / 1048576. << " MB)";
    if (evaluated > elements)
      s << ", " << evaluated - elements
        << " evaluations of neighbours' cells for partition-independent sums";
    return s.str();
  }



  template class BulkForceOperator<2>;
  template class BulkForceOperator<3>;
} // namespace amfrac

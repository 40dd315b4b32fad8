#include <amfrac/assembly/bulk_force.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <map>
#include <sstream>

namespace amfrac
{
  namespace
  {
    /** What makes two elements' matrices equal: the ply and the vertex
     * positions relative to the first vertex (the mapping is linear, so
     * a translated copy has the same matrix), rounded to 1e-9 of the
     * element's size. */
    template <int dim>
    std::vector<long long>
    shape_key(const typename TiedCopyDoFs<dim>::CellIterator &cell)
    {
      const double           quantum = 1e-9 * cell->diameter();
      std::vector<long long> key{static_cast<long long>(cell->material_id())};
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          key.push_back(
            std::llround((cell->vertex(v)[d] - cell->vertex(0)[d]) / quantum));
      return key;
    }
  } // namespace



  template <int dim>
  BulkForceOperator<dim>::BulkForceOperator(
    const TiedCopyDoFs<dim>     &dofs,
    const ElasticAssembler<dim> &assembler,
    CohesiveInterfaces<dim>     *interfaces)
    : comm(dofs.copy_handler().get_triangulation().get_communicator())
    , kernel(dofs.get_fe().n_dofs_per_cell())
    , interfaces(interfaces)
  {
    const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
      dofs.locally_owned_dofs(), dofs.locally_relevant_dofs(), comm);
    u.reinit(partitioner);
    f.reinit(partitioner);
    if (interfaces)
      interfaces->set_local_indices(*partitioner);
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(n);
    std::vector<unsigned int>            local(n);
    std::map<std::vector<long long>, unsigned int> matrix_of_shape;
    FullMatrix<double>                             K(n, n);
    std::vector<double>                            row_major(n * n);
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto key   = shape_key<dim>(cell);
          auto       found = matrix_of_shape.find(key);
          if (found == matrix_of_shape.end())
            {
              assembler.element_stiffness(cell, K);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  row_major[i * n + j] = K(i, j);
              found = matrix_of_shape.emplace(key, kernel.add_matrix(row_major))
                        .first;
            }
          dofs.get_dof_indices(cell, indices);
          for (unsigned int i = 0; i < n; ++i)
            local[i] = partitioner->global_to_local(indices[i]);
          kernel.add_element(found->second, local.data());
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
    f                   = 0;
    const double energy = kernel.apply(u.get_values(), f.get_values());
    if (with_interfaces && interfaces)
      interfaces->add_forces(u.get_values(), f.get_values());
    f.compress(VectorOperation::add);
    std::copy(f.begin(), f.begin() + n_owned, force.begin());
    return Utilities::MPI::sum(energy, comm);
  }



  template <int dim>
  std::string
  BulkForceOperator<dim>::summary() const
  {
    const double elements = Utilities::MPI::sum(1. * kernel.n_elements(), comm);
    const double matrices = Utilities::MPI::sum(1. * kernel.n_matrices(), comm);
    const double bytes
      = Utilities::MPI::sum(1. * kernel.memory_consumption(), comm);
    std::ostringstream s;
    s << matrices << " element matrices for " << elements << " elements ("
      << bytes / 1048576. << " MB)";
    return s.str();
  }



  template class BulkForceOperator<2>;
  template class BulkForceOperator<3>;
} // namespace amfrac

#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /** The largest @p value over all ranks; @p where becomes the position
   * reported with it by the (lowest) rank that holds it. Collective. */
  template <int dim>
  double
  max_and_where(const double value, Point<dim> &where, const MPI_Comm comm)
  {
    const double       global = Utilities::MPI::max(value, comm);
    const unsigned int owner
      = Utilities::MPI::min(value == global ?
                              Utilities::MPI::this_mpi_process(comm) :
                              Utilities::MPI::n_mpi_processes(comm),
                            comm);
    std::vector<double> point(dim);
    for (unsigned int d = 0; d < dim; ++d)
      point[d] = where[d];
    point = Utilities::MPI::broadcast(comm, point, owner);
    for (unsigned int d = 0; d < dim; ++d)
      where[d] = point[d];
    return global;
  }
} // namespace amfrac

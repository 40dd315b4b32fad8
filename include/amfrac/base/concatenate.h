#pragma once

#include <deal.II/base/mpi.h>
#include <numeric>
#include <type_traits>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /** Every rank's @p local values, concatenated in the order of the ranks
   * (one MPI_Allgatherv, after an all_gather of the sizes), on every rank.
   * For double and unsigned int. Collective. */
  template <typename T>
  std::vector<T>
  concatenate_over_ranks(const std::vector<T> &local, const MPI_Comm comm)
  {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, unsigned int>,
                  "concatenate_over_ranks: double or unsigned int");
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return local;
    const int        mine  = local.size();
    const auto       sizes = Utilities::MPI::all_gather(comm, mine);
    std::vector<int> offsets(sizes.size(), 0);
    std::partial_sum(sizes.begin(), sizes.end() - 1, offsets.begin() + 1);
    std::vector<T>     all(offsets.back() + sizes.back());
    const MPI_Datatype type
      = std::is_same_v<T, double> ? MPI_DOUBLE : MPI_UNSIGNED;
    MPI_Allgatherv(local.data(),
                   mine,
                   type,
                   all.data(),
                   sizes.data(),
                   offsets.data(),
                   type,
                   comm);
    return all;
  }
} // namespace amfrac

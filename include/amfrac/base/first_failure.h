#pragma once

#include <deal.II/base/mpi.h>
#include <string>

namespace amfrac
{
  /**
   * Collective: if any rank has a non-empty @p failure, every rank throws
   * @p Error with the failure of the lowest such rank (prefixed by
   * "(rank r) " with @p name_rank on more than one rank), so that all ranks
   * unwind together and none waits in a later collective call. Costs one
   * integer reduction when no rank failed.
   */
  template <typename Error>
  void
  throw_first_failure(const MPI_Comm     comm,
                      const std::string &failure,
                      const bool         name_rank = false)
  {
    using namespace dealii;
    if (Utilities::MPI::max(failure.empty() ? 0 : 1, comm) == 0)
      return;
    const auto failures = Utilities::MPI::all_gather(comm, failure);
    for (unsigned int r = 0; r < failures.size(); ++r)
      if (!failures[r].empty())
        throw Error(name_rank && failures.size() > 1 ?
                      "(rank " + std::to_string(r) + ") " + failures[r] :
                      failures[r]);
  }
} // namespace amfrac

// OrderedSums: contributions scattered over the ranks in a way that
// depends on the number of ranks sum to the same bits on any number of
// ranks: each owned entry equals the serial sum of its terms in key order.
#include "../check.h"

#include <amfrac/base/ordered_sums.h>
#include <cmath>
#include <deal.II/base/mpi.h>

using namespace amfrac;

namespace
{
  const unsigned int n_entries = 40, n_terms = 2000;

  /** Term j: its entry and a value whose magnitude spans 16 decades, so
   * that the order of the additions shows in the last bits. */
  types::global_dof_index
  target(const unsigned int j)
  {
    return (j * 7919u) % n_entries;
  }

  double
  value(const unsigned int j)
  {
    return std::pow(10., int(j % 17) - 8) * (1 + 1e-3 * j)
           * (j % 3 == 0 ? -1 : 1);
  }

  /** Keys that order term j differently from j itself. */
  OrderedSums::Key
  key(const unsigned int j)
  {
    return OrderedSums::Key{{(j * 37u) % 101u, j, 0, 0, 0, 0}};
  }

  /** The sum of the terms of @p entry in key order, or in the reverse. */
  double
  serial_sum(const types::global_dof_index entry, const bool reverse)
  {
    std::vector<std::pair<OrderedSums::Key, double>> terms;
    for (unsigned int j = 0; j < n_terms; ++j)
      if (target(j) == entry)
        terms.emplace_back(key(j), value(j));
    std::sort(terms.begin(), terms.end());
    if (reverse)
      std::reverse(terms.begin(), terms.end());
    double sum = 0;
    for (const auto &term : terms)
      sum += term.second;
    return sum;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);

  // Entries in contiguous blocks in rank order, rank 1 owning none on
  // three ranks or more (its block is empty: deal.II then reports a local
  // range of (0, 0)); the terms dealt out by another rule.
  const auto block_begin = [&](const unsigned int r) {
    return (n_ranks >= 3 && r == 2 ? 1 : r) * n_entries / n_ranks;
  };
  IndexSet owned(n_entries), ghosts(n_entries);
  owned.add_range(block_begin(rank),
                  rank + 1 == n_ranks ? n_entries : block_begin(rank + 1));
  std::vector<types::global_dof_index> targets;
  std::vector<OrderedSums::Key>        keys;
  std::vector<double>                  values;
  for (unsigned int j = 0; j < n_terms; ++j)
    if ((j * 31u) % n_ranks == rank)
      {
        targets.push_back(target(j));
        keys.push_back(key(j));
        values.push_back(value(j));
        if (!owned.is_element(target(j)))
          ghosts.add_index(target(j));
      }
  const Utilities::MPI::Partitioner entries(owned, ghosts, comm);

  OrderedSums sums;
  sums.reinit(targets, keys, entries);
  std::copy(values.begin(), values.end(), sums.slots());
  std::vector<double> f(entries.locally_owned_size()
                          + entries.n_ghost_indices(),
                        0.);
  sums.add_to(f.data());

  // Bit for bit the serial sum in key order; the reverse order differs in
  // some entries (else this test could not tell orders apart).
  unsigned int order_matters = 0;
  for (const auto i : owned)
    {
      const double expected = serial_sum(i, false);
      CHECK(f[entries.global_to_local(i)] == expected);
      order_matters += serial_sum(i, true) != expected;
    }
  CHECK(Utilities::MPI::sum(order_matters, comm) > 0);

  // Again after a second round of values (the plan is reused).
  std::fill(f.begin(), f.end(), 0.);
  for (std::size_t s = 0; s < values.size(); ++s)
    sums.slots()[s] = 2 * values[s];
  sums.add_to(f.data());
  for (const auto i : owned)
    CHECK(f[entries.global_to_local(i)] == 2 * serial_sum(i, false));
  return amfrac_test::summary();
}

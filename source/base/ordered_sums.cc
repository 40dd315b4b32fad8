#include <algorithm>
#include <amfrac/base/ordered_sums.h>
#include <deal.II/base/mpi.h>
#include <map>
#include <numeric>
#include <tuple>

namespace amfrac
{
  namespace
  {
    /** One contribution: the entry it adds to, its key, and its slot
     * (global numbering: this rank's slots follow those of lower ranks). */
    struct Term
    {
      types::global_dof_index target;
      OrderedSums::Key        key;
      types::global_dof_index slot;

      /** For Utilities::MPI::some_to_some() (which copies the bytes of a
       * trivially copyable type but needs this to compile). */
      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &target &key &slot;
      }

      bool
      operator<(const Term &other) const
      {
        return std::tie(target, key, slot)
               < std::tie(other.target, other.key, other.slot);
      }
    };

    /** The rank owning global entry @p i, from the end of every rank's
     * contiguous block (ranks in order; a rank owning nothing has an
     * empty block, whatever its local_range() says, and is skipped). */
    unsigned int
    owner(const std::vector<types::global_dof_index> &ends,
          const types::global_dof_index               i)
    {
      return std::upper_bound(ends.begin(), ends.end(), i) - ends.begin();
    }

    /** @p terms (all to owned entries of @p entries) in the order of
     * Term::operator<: bucketed by target (a counting sort, linear in
     * the number of terms), then each target's few terms sorted. A full
     * sort of every term was most of a crack insertion event in an
     * explicit fragmentation run. */
    std::vector<Term>
    sorted_by_target(const std::vector<Term>           &terms,
                     const Utilities::MPI::Partitioner &entries)
    {
      const types::global_dof_index base = entries.local_range().first;
      std::vector<std::size_t>      begin(entries.locally_owned_size() + 1, 0);
      for (const Term &term : terms)
        ++begin[term.target - base + 1];
      std::partial_sum(begin.begin(), begin.end(), begin.begin());
      std::vector<Term>        sorted(terms.size());
      std::vector<std::size_t> next(begin.begin(), begin.end() - 1);
      for (const Term &term : terms)
        sorted[next[term.target - base]++] = term;
      for (std::size_t b = 0; b + 1 < begin.size(); ++b)
        if (begin[b + 1] - begin[b] > 1)
          std::sort(sorted.begin() + begin[b], sorted.begin() + begin[b + 1]);
      return sorted;
    }
  } // namespace



  void
  OrderedSums::reinit(const std::vector<types::global_dof_index> &targets,
                      const std::vector<Key>                     &keys,
                      const Utilities::MPI::Partitioner          &entries)
  {
    AssertDimension(targets.size(), keys.size());
    const MPI_Comm     comm    = entries.get_mpi_communicator();
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const types::global_dof_index n_mine = targets.size();
    // This rank's slots follow those of the lower ranks.
    unsigned long long mine = n_mine, before = 0;
    MPI_Exscan(&mine, &before, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    const types::global_dof_index first   = my_rank == 0 ? 0 : before;
    const types::global_dof_index n_slots = Utilities::MPI::sum(mine, comm);
    entry.clear();
    slot.clear();
    start = {0};
    // No contributions on any rank (deal.II's partitioner cannot number
    // an empty set on several ranks).
    if (n_slots == 0)
      {
        values.reinit(0);
        return;
      }
    // The blocks follow each other in rank order: each ends at the sum of
    // the owned sizes up to its rank.
    const auto sizes = Utilities::MPI::all_gather(
      comm, types::global_dof_index(entries.locally_owned_size()));
    std::vector<types::global_dof_index> ends(sizes.size());
    std::partial_sum(sizes.begin(), sizes.end(), ends.begin());
    AssertThrow(sizes[my_rank] == 0
                  || entries.local_range().first
                       == ends[my_rank] - sizes[my_rank],
                ExcMessage("OrderedSums: the owned entries must be blocks "
                           "in rank order"));

    std::vector<Term>                         terms;
    std::map<unsigned int, std::vector<Term>> outgoing;
    for (types::global_dof_index s = 0; s < n_mine; ++s)
      {
        const Term         term{targets[s], keys[s], first + s};
        const unsigned int rank = owner(ends, term.target);
        (rank == my_rank ? terms : outgoing[rank]).push_back(term);
      }
    IndexSet ghosts(n_slots);
    for (const auto &[rank, received] :
         Utilities::MPI::some_to_some(comm, outgoing))
      for (const Term &term : received)
        {
          terms.push_back(term);
          ghosts.add_index(term.slot);
        }
    IndexSet owned(n_slots);
    owned.add_range(first, first + n_mine);
    const auto partitioner
      = std::make_shared<Utilities::MPI::Partitioner>(owned, ghosts, comm);
    values.reinit(partitioner);

    terms = sorted_by_target(terms, entries);
    for (std::size_t t = 0; t < terms.size(); ++t)
      {
        if (t == 0 || terms[t].target != terms[t - 1].target)
          {
            if (t > 0)
              start.push_back(slot.size());
            entry.push_back(entries.global_to_local(terms[t].target));
          }
        slot.push_back(partitioner->global_to_local(terms[t].slot));
      }
    if (!terms.empty())
      start.push_back(slot.size());
  }



  void
  OrderedSums::add_to(double *f)
  {
    // Collective unless no rank has contributions (the same on all).
    if (values.size() == 0)
      return;
    values.update_ghost_values();
    const double *v = values.get_values();
    for (std::size_t r = 0; r < entry.size(); ++r)
      for (unsigned int k = start[r]; k < start[r + 1]; ++k)
        f[entry[r]] += v[slot[k]];
  }
} // namespace amfrac

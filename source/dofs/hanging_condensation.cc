#include <algorithm>
#include <amfrac/dofs/hanging_condensation.h>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deal.II/base/mpi.h>

namespace amfrac
{
  template <int dim>
  HangingCondensation<dim>::HangingCondensation(const TiedCopyDoFs<dim> &dofs,
                                                const MPI_Comm           comm)
    : comm(comm)
    , owned(dofs.locally_owned_dofs())
  {
    AssertThrow(owned.is_contiguous(),
                ExcMessage("the owned reduced dofs of a rank are a block"));
    const types::global_dof_index first
      = owned.n_elements() > 0 ? owned.nth_index_in_set(0) : 0;
    // Lines in ascending order of the hanging entry, for is_hanging().
    const auto &constraints = dofs.hanging_node_constraints();
    std::vector<const AffineConstraints<double>::ConstraintLine *> lines;
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        lines.push_back(&line);
    std::sort(lines.begin(), lines.end(), [](const auto *a, const auto *b) {
      return a->index < b->index;
    });
    IndexSet ghosts(owned.size());
    for (const auto *line : lines)
      for (const auto &entry : line->entries)
        if (!owned.is_element(entry.first))
          ghosts.add_index(entry.first);
    ghosts.compress();
    exchange.reinit(owned, ghosts, comm);
    // A key of a dof that is the same on any partition: the bits of its
    // support point (the numbering is not).
    const auto key = [&](const types::global_dof_index i) {
      OrderedSums::Key k{};
      for (unsigned int d = 0; d < dim; ++d)
        {
          std::uint64_t bits;
          std::memcpy(&bits, &dofs.support_point(i)[d], sizeof(bits));
          k[2 * d]     = static_cast<unsigned int>(bits >> 32);
          k[2 * d + 1] = static_cast<unsigned int>(bits);
        }
      return k;
    };
    std::vector<types::global_dof_index> targets;
    std::vector<OrderedSums::Key>        keys;
    offsets.push_back(0);
    for (const auto *line : lines)
      {
        AssertThrow(line->inhomogeneity == 0, ExcInternalError());
        hanging.push_back(line->index);
        hanging_local.push_back(line->index - first);
        // The masters in the order of their keys: an interpolation of
        // four values rounds by the order of the terms.
        auto entries = line->entries;
        std::sort(entries.begin(),
                  entries.end(),
                  [&](const auto &a, const auto &b) {
                    return key(a.first) < key(b.first);
                  });
        double sum = 0;
        for (const auto &[master, weight] : entries)
          {
            targets.push_back(master);
            keys.push_back(key(line->index));
            const bool mine = owned.is_element(master);
            masters.push_back(
              {mine,
               mine ? master - first :
                      exchange.get_partitioner()->global_to_local(master),
               weight});
            sum += std::abs(weight);
          }
        offsets.push_back(masters.size());
        weight_sum = std::max(weight_sum, sum);
      }
    sums.reinit(targets, keys, *exchange.get_partitioner());
    n_global_hanging = Utilities::MPI::sum(hanging.size(), comm);
    weight_sum       = Utilities::MPI::max(weight_sum, comm);
    any_remote = Utilities::MPI::max(ghosts.n_elements() > 0 ? 1 : 0, comm) > 0;
    for (const auto &[begin, end] :
         exchange.get_partitioner()->import_indices())
      for (auto i = begin; i < end; ++i)
        shared.push_back(i);
  }



  template <int dim>
  void
  HangingCondensation<dim>::condense(Vector &v, const bool absolute) const
  {
    if (empty())
      return;
    double *x     = v.begin();
    double *slots = sums.slots();
    for (std::size_t k = 0; k < hanging.size(); ++k)
      {
        const double value  = x[hanging_local[k]];
        x[hanging_local[k]] = 0;
        for (std::size_t e = offsets[k]; e < offsets[k + 1]; ++e)
          *slots++
            = (absolute ? std::abs(masters[e].weight) : masters[e].weight)
              * value;
      }
    // A master may itself be hanging only in chains, which deal.II's
    // closed constraints do not have: the hanging entries are zero now,
    // and adding to the masters does not touch them.
    sums.add_to(x);
  }



  template <int dim>
  void
  HangingCondensation<dim>::distribute(Vector &v) const
  {
    if (empty())
      return;
    double *x = v.begin();
    if (any_remote)
      {
        for (const auto i : shared)
          exchange.local_element(i) = x[i];
        exchange.update_ghost_values();
      }
    for (std::size_t k = 0; k < hanging.size(); ++k)
      {
        double value = 0;
        for (std::size_t e = offsets[k]; e < offsets[k + 1]; ++e)
          {
            const Master &m = masters[e];
            value += m.weight
                     * (m.owned ? x[m.index] : exchange.local_element(m.index));
          }
        x[hanging_local[k]] = value;
      }
    if (any_remote)
      {
        for (const auto i : shared)
          exchange.local_element(i) = 0;
        exchange.zero_out_ghost_values();
      }
  }



  template <int dim>
  bool
  HangingCondensation<dim>::is_hanging(const types::global_dof_index i) const
  {
    return std::binary_search(hanging.begin(), hanging.end(), i);
  }



  template class HangingCondensation<2>;
  template class HangingCondensation<3>;
} // namespace amfrac

#include <algorithm>
#include <amfrac/dofs/hanging_condensation.h>
#include <cmath>
#include <deal.II/base/mpi.h>

namespace amfrac
{
  template <int dim>
  HangingCondensation<dim>::HangingCondensation(const TiedCopyDoFs<dim> &dofs,
                                                const MPI_Comm           comm)
    : comm(comm)
    , owned(dofs.locally_owned_dofs())
  {
    // Lines in ascending order of the hanging entry, for is_hanging().
    const auto &constraints = dofs.hanging_node_constraints();
    std::vector<const AffineConstraints<double>::ConstraintLine *> lines;
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        lines.push_back(&line);
    std::sort(lines.begin(), lines.end(), [](const auto *a, const auto *b) {
      return a->index < b->index;
    });
    IndexSet needed = owned;
    offsets.push_back(0);
    for (const auto *line : lines)
      {
        AssertThrow(line->inhomogeneity == 0, ExcInternalError());
        hanging.push_back(line->index);
        double sum = 0;
        for (const auto &[master, weight] : line->entries)
          {
            masters.push_back(master);
            weights.push_back(weight);
            needed.add_index(master);
            sum += std::abs(weight);
          }
        offsets.push_back(masters.size());
        weight_sum = std::max(weight_sum, sum);
      }
    needed.compress();
    n_global_hanging = Utilities::MPI::sum(hanging.size(), comm);
    weight_sum       = Utilities::MPI::max(weight_sum, comm);
    if (n_global_hanging == 0)
      return;
    ghosted.reinit(owned, needed, comm);
    sums.reinit(owned, needed, comm, true);
  }



  template <int dim>
  void
  HangingCondensation<dim>::condense(Vector &v, const bool absolute) const
  {
    if (empty())
      return;
    sums = 0;
    for (std::size_t k = 0; k < hanging.size(); ++k)
      {
        const double value = v(hanging[k]);
        for (std::size_t e = offsets[k]; e < offsets[k + 1]; ++e)
          sums(masters[e])
            += (absolute ? std::abs(weights[e]) : weights[e]) * value;
      }
    // A master may itself be hanging only in chains, which deal.II's
    // closed constraints do not have: zeroing after the loop is safe.
    for (const auto s : hanging)
      sums(s) -= v(s);
    sums.compress(VectorOperation::add);
    // Owned entries are stored alike in both vectors.
    double       *target = v.begin();
    const double *added  = sums.begin();
    for (std::size_t i = 0; i < v.locally_owned_size(); ++i)
      target[i] += added[i];
  }



  template <int dim>
  void
  HangingCondensation<dim>::distribute(Vector &v) const
  {
    if (empty())
      return;
    ghosted = v;
    for (std::size_t k = 0; k < hanging.size(); ++k)
      {
        double value = 0;
        for (std::size_t e = offsets[k]; e < offsets[k + 1]; ++e)
          value += weights[e] * ghosted(masters[e]);
        v(hanging[k]) = value;
      }
    v.compress(VectorOperation::insert);
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

#pragma once

#include <array>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <memory>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /**
   * Sums of contributions to the owned entries of a distributed vector,
   * in an order that does not depend on the partition. Each rank
   * computes the contributions of the objects it owns (say interface
   * elements) into slots of its own; the owner of an entry fetches the
   * slots of other ranks that add to it and adds all of them in the order
   * of their keys. On one rank and on N ranks every entry is then the
   * same sum of the same terms in the same order, bit for bit, whereas a
   * compress() adds other ranks' partial sums in an order that depends on
   * the partition (explicit runs amplify that round-off).
   */
  class OrderedSums
  {
  public:
    /** Any key that orders the contributions the same way on every rank,
     * e.g. a cell's CellId binary, a face and a local dof. */
    using Key = std::array<unsigned int, 6>;

    /** Collective. Slot s of this rank (s < targets.size()) adds to the
     * global entry targets[s], in the order of keys[s] among the
     * contributions to that entry (equal keys: an order of the slots that
     * may depend on the partition; keys are meant to be unique).
     * @p entries numbers the entries of the vector add_to() adds to: each
     * rank owns one contiguous block, the blocks in rank order (as the
     * TiedCopyDoFs numbering has them); targets must be owned or ghost
     * entries. */
    void
    reinit(const std::vector<types::global_dof_index> &targets,
           const std::vector<Key>                     &keys,
           const Utilities::MPI::Partitioner          &entries);

    /** This rank's slots, to be written before add_to(). */
    double *
    slots()
    {
      return values.begin();
    }

    /** Collective: f[i] += the contributions to owned entry i (local index
     * of the partitioner given to reinit()), in the order of their keys. */
    void
    add_to(double *f);

  private:
    LinearAlgebra::distributed::Vector<double> values;
    /** Per owned entry with contributions: its local index, and its slots
     * (local indices in `values`) in slot[start[r] .. start[r + 1]). */
    std::vector<unsigned int> entry, start, slot;
  };
} // namespace amfrac

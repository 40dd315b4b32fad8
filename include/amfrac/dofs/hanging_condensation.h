#pragma once

#include <amfrac/base/ordered_sums.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <vector>

namespace amfrac
{
  /**
   * The hanging-node constraints u_s = sum_m c_sm u_m of a TiedCopyDoFs
   * layer in the form explicit dynamics needs them: no matrix, only
   * vectors without ghosts on the reduced numbering.
   *
   * - condense(): the transpose C^T of the constraints on a vector of nodal
   *   forces (or lumped masses): each hanging entry is handed to its
   *   masters with its weights and becomes zero. A lumped mass condensed
   *   this way is the row sum of C^T M C, the lumped mass of the
   *   constrained space.
   * - distribute(): the hanging entries of a displacement or velocity
   *   interpolated from their masters.
   *
   * Each rank keeps the constraint lines of the hanging entries it owns;
   * their masters may belong to other ranks.
   */
  template <int dim>
  class HangingCondensation
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    HangingCondensation(const TiedCopyDoFs<dim> &dofs, const MPI_Comm comm);

    /** True if the mesh has no hanging entries (on any rank). */
    bool
    empty() const
    {
      return n_global_hanging == 0;
    }

    /** v <- C^T v, with |c| instead of c if @p absolute (for bounds such as
     * Gershgorin's on condensed rows). */
    void
    condense(Vector &v, const bool absolute = false) const;

    /** The hanging entries of @p v from their masters. */
    void
    distribute(Vector &v) const;

    /** Whether the reduced dof @p i is a hanging entry (owned ones only). */
    bool
    is_hanging(const types::global_dof_index i) const;

    /** The largest sum of |c| over one constraint line (1 for Q1; larger
     * for Q2, whose hanging weights include -1/8). */
    double
    largest_weight_sum() const
    {
      return weight_sum;
    }

  private:
    /** A master of a hanging entry: its weight, and where its value is:
     * an owned entry (local index of the reduced vector) or a ghost of
     * the exchange vector (local index there). */
    struct Master
    {
      bool                    owned;
      types::global_dof_index index;
      double                  weight;
    };

    MPI_Comm comm;
    IndexSet owned;
    /** Owned hanging entries, global (sorted) and local indices. */
    std::vector<types::global_dof_index> hanging;
    std::vector<types::global_dof_index> hanging_local;
    /** Masters of hanging[k] in [offsets[k], offsets[k+1]). */
    std::vector<std::size_t> offsets;
    std::vector<Master>      masters;
    double                   weight_sum       = 1;
    unsigned long            n_global_hanging = 0;
    /** The contributions of condense(), one slot per (hanging entry,
     * master), added to each master in the order of the hanging entries'
     * positions: the same sums on any number of ranks (explicit runs
     * amplify round-off that depends on the partition). */
    mutable OrderedSums sums;
    /** Whether any rank has a master owned by another rank: only then
     * does distribute() communicate. */
    bool any_remote = false;
    /** Owned entries plus the other ranks' masters as ghosts: the
     * masters' values come to distribute() through update_ghost_values();
     * only the entries involved are touched. */
    mutable LinearAlgebra::distributed::Vector<double> exchange;
    /** Local indices of the owned entries other ranks read (the
     * partitioner's import indices). */
    std::vector<types::global_dof_index> shared;
  };
} // namespace amfrac

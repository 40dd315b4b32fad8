#pragma once

#include <amfrac/dofs/hanging_condensation.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/solution_transfer.h>
#include <map>
#include <memory>
#include <vector>

namespace amfrac
{
  /**
   * The seed's tau_2 for the state of an explicit run (displacement-like
   * fields and the velocity on the reduced numbering of a TiedCopyDoFs
   * layer) across one refinement and coarsening of the mesh.
   *
   * Displacement-like fields are interpolated at the nodes of the new
   * mesh: a refined cell's children carry the parent's polynomial (deal.II's
   * SolutionTransfer on the copy space), a kept cell keeps its values, and
   * a cell made by coarsening takes the old values at its nodes, all of
   * which were nodes of its children (nodal interpolation: an L2 projection
   * would change the field at nodes that stay).
   *
   * The velocity is interpolated the same way, except at the nodes of
   * coarsened cells: there it is the momentum of the old velocity field
   * over the node's cells divided by the node's new lumped mass,
   *   v_I = (sum_K int_K rho phi_I v_old) / M_I,
   * where cells not made by coarsening contribute their lumped m_IK v_I.
   * So the mesh change keeps the lumped momentum sum_I M_I v_I exactly,
   * and (for degree 1, whose shape functions and hanging weights are
   * non-negative) it never creates kinetic energy: nodal interpolation
   * alone hands a surviving node the mass of the dropped ones at its own
   * velocity, and a short wave coarsened that way gains energy each time.
   * The acceleration is not transferred: the caller evaluates the forces
   * on the new mesh.
   *
   * Usage: construct and prepare() with the final flags, before
   * Triangulation::execute_coarsening_and_refinement(); call interpolate()
   * once the layer has been distributed on the new mesh. Collective; the
   * mesh is replicated (parallel::shared), so every rank prepares every
   * coarsened cell.
   */
  template <int dim>
  class ExplicitStateTransfer
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** @p density: the density of each material id. */
    ExplicitStateTransfer(const TiedCopyDoFs<dim>   &dofs,
                          const std::vector<double> &density,
                          const MPI_Comm             comm);

    /** Remember @p fields (displacement-like) and @p velocity (owned
     * entries, hanging entries consistent) on the current mesh. */
    void
    prepare(const std::vector<const Vector *> &fields, const Vector &velocity);

    /** The fields and the velocity on the new mesh (reinitialized to the
     * new layout, hanging entries interpolated). */
    void
    interpolate(const std::vector<Vector *> &fields, Vector &velocity);

    /** Cells of the new mesh made by coarsening. */
    unsigned int
    n_coarsened_cells() const
    {
      return coarsened.size();
    }

    /** Reduced unknowns whose velocity came from the momentum rule (all
     * ranks). */
    types::global_dof_index
    n_momentum_dofs() const
    {
      return n_momentum;
    }

  private:
    /** What a coarsened cell needs from its children: its nodal values
     * of each field (velocity last), and the momentum int rho phi_i v. */
    struct Parent
    {
      std::vector<dealii::Vector<double>> values;
      dealii::Vector<double>              momentum;
    };

    const TiedCopyDoFs<dim>                                       &dofs;
    std::vector<double>                                            density;
    MPI_Comm                                                       comm;
    std::vector<dealii::Vector<double>>                            copies;
    std::unique_ptr<SolutionTransfer<dim, dealii::Vector<double>>> transfer;
    std::map<CellId, Parent>                                       coarsened;
    types::global_dof_index n_momentum = 0;

    /** Values and momentum of the parent of the flagged @p cell. */
    Parent
    restrict_to_parent(
      const typename DoFHandler<dim>::cell_iterator &parent) const;

    /** The copy values of the new mesh: transferred, and nodal values on
     * coarsened cells. */
    std::vector<dealii::Vector<double>>
    new_copies() const;

    /** The velocity at the nodes of coarsened cells from the momentum. */
    void
    conserve_momentum(const dealii::Vector<double>   &velocity_copies,
                      const HangingCondensation<dim> &hanging,
                      Vector                         &velocity);
  };
} // namespace amfrac

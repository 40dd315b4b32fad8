#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/parameters/parameters.h>
#include <deal.II/base/function.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <vector>

namespace amfrac
{
  /**
   * The rigid, weightless loading lever of a mixed-mode bending (MMB) test
   * (Reeder & Crews 1990) as a linear constraint on the displacement w
   * along the thickness axis. The lever is pinned to the hinge nodes, rests
   * on the saddle nodes and its load point, a distance c beyond the saddle,
   * follows the prescribed w_P(t). With x_A, x_B, x_P the hinge, saddle and
   * load-point positions along the laminate and r = (x_B - x_A)/(x_P -
   * x_A), the lever line gives
   *
   *   w_i = w_m                          for every hinge node i,
   *   w_j = (1 - r) w_m + r w_P(t)       for every saddle node j,
   *
   * with w_m the first hinge dof (free). The forces on hinge and saddle
   * then keep the lever's ratio whatever the crack length, as in the test
   * machine, and the work of the load point is P dw_P with P the force
   * conjugate to t. Both sides may be lines of nodes (3D, across the
   * width): each moves as a rigid tab.
   */
  template <int dim>
  class Lever
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    Lever(const parameters::BoundaryConditions &conditions);

    bool
    active() const
    {
      return !hinge.empty();
    }

    /** Find the hinge and saddle dofs (every rank scans the replicated
     * mesh, so all agree) and check the geometry; throws InputError naming
     * the parameter. */
    void
    collect(const TiedCopyDoFs<dim> &dofs);

    /** Hinge dofs then saddle dofs: every dof the lever constrains or
     * pins. They must be locally relevant on every rank. */
    std::vector<types::global_dof_index>
    all_dofs() const;

    /** Add the lever's lines (those of locally relevant dofs) to
     * @p constraints; without the w_P(t) inhomogeneity if @p homogeneous. */
    void
    add_constraints(const double               t,
                    const bool                 homogeneous,
                    const IndexSet            &relevant,
                    AffineConstraints<double> &constraints) const;

    /** The force conjugate to t, r w_P'(t) sum_j R_j over the saddle dofs
     * (@p residual holds the internal-minus-external forces). */
    double
    force(const double t, const Vector &residual, const MPI_Comm comm) const;

    /** w at the hinge and the mean w of the saddle nodes (@p solution must
     * hold the lever dofs). */
    std::pair<double, double>
    displacements(const Vector &solution) const;

    /** r = (x_B - x_A) / (x_P - x_A). */
    double
    ratio() const
    {
      return r;
    }

  private:
    /** A copy: the simulator may be built from a temporary. */
    const parameters::Lever              prm;
    std::shared_ptr<Function<dim>>       load_point;
    std::shared_ptr<Function<dim>>       hinge_where;
    std::shared_ptr<Function<dim>>       saddle_where;
    std::vector<types::global_dof_index> hinge;
    std::vector<types::global_dof_index> saddle;
    double                               r = 1;

    double
    load_point_displacement(const double t) const;
  };
} // namespace amfrac

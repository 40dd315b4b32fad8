#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/parameters/impactor.h>
#include <array>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <string>
#include <utility>
#include <vector>

namespace amfrac
{
  /**
   * A rigid sphere that strikes one face of the laminate (issue 10, first
   * step): node-to-sphere penalty contact without friction. A face node at
   * x inside the sphere (gap g = |x - c| - R < 0) is pushed out along
   * n = (x - c) / |x - c| by the force -k g n with k = Penalty times the
   * node's share of the face area (the integral of its shape function over
   * the face), and the sphere feels the opposite. The contact is the
   * potential E_c = sum_i k_i g_i^2 / 2, so plate, sphere and contact
   * together keep their energy up to the time integration's error.
   *
   * The sphere moves with the laminate's central differences: kick() by
   * half a step with the acceleration of the last evaluate(), drift() by a
   * whole step. Each rank evaluates the nodes it owns; the force on the
   * sphere adds every node's share in the order of the nodes' positions,
   * on any number of ranks (the same sum bit for bit; the numbering of the
   * nodes depends on the partition).
   */
  template <int dim>
  class RigidImpactor
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    RigidImpactor(const parameters::Impactor &parameters, MPI_Comm comm);

    /** The candidate nodes of the current mesh: the owned nodes on the
     * face, with their area. */
    void
    setup(const TiedCopyDoFs<dim> &dofs);

    /** The contact forces of the displacement @p u (owned entries) on the
     * laminate into @p contact (owned entries, overwritten), the force on
     * the sphere and its acceleration, and the contact energy. Collective. */
    void
    evaluate(const Vector &u, Vector &contact);

    /** A prescribed sphere: its centre at time @p t, Center + Velocity t. */
    void
    move_to(const double t)
    {
      center = start + t * velocity;
    }

    /** Static runs: the contact tangent at @p u (owned entries),
     * d(k g n)/du = k (n n^T + g / r (I - n n^T)) per node in contact with
     * r = |x - c|, into @p tangent through @p constraints (hanging nodes
     * hand it to their parents). Not compressed. */
    void
    add_tangent(const Vector                    &u,
                const AffineConstraints<double> &constraints,
                TrilinosWrappers::SparseMatrix  &tangent) const;

    /** The same tangent times @p direction added to @p product (owned
     * entries, unconstrained). */
    void
    add_tangent_product(const Vector &u,
                        const Vector &direction,
                        Vector       &product) const;

    /** The force of the sphere on the laminate along the face's inward
     * normal at the last evaluate(), all ranks. */
    double
    normal_force() const
    {
      return -inward * force[normal_axis];
    }

    /** The centre's coordinate along the face's normal. */
    double
    normal_position() const
    {
      return center[normal_axis];
    }

    /** The nodes in contact at the last evaluate(), all ranks. */
    unsigned int
    contact_nodes() const
    {
      return n_contact;
    }

    /** The force of the sphere on the laminate at the last evaluate(). */
    Tensor<1, dim>
    force_on_laminate() const
    {
      return -force;
    }

    Tensor<1, dim>
    position() const
    {
      return center;
    }

    void
    kick(const double half_step)
    {
      velocity += half_step * acceleration;
    }

    void
    drift(const double step)
    {
      center += step * velocity;
    }

    double
    kinetic_energy() const
    {
      return 0.5 * mass * velocity.norm_square();
    }

    /** sum_i k_i g_i^2 / 2 at the last evaluate(), all ranks. */
    double
    contact_energy() const
    {
      return energy;
    }

    /** The deepest penetration of a node at the last evaluate(). */
    double
    penetration_depth() const
    {
      return penetration;
    }

    /** The linear momentum of the sphere. */
    Tensor<1, dim>
    momentum() const
    {
      return mass * velocity;
    }

    /** Explicit stability: Gershgorin's row sums of the contact springs,
     * 2 k_i on each component of every candidate node (its own spring and
     * the coupling to the sphere), added to @p rows (owned entries). */
    void
    add_penalty_rows(Vector &rows) const;

    /** Gershgorin's bound on omega^2 of the sphere's row: 2 sum k_i / M
     * over the candidates of all ranks. Collective. */
    double
    frequency_squared() const;

    /** The largest k_i / m_i of the candidate nodes against the lumped
     * @p mass (owned entries): the square of the fastest contact
     * oscillation of a node against the sphere. Collective. */
    double
    node_frequency_squared(const Vector &mass) const;

    /** The history columns of an output step at @p t: centre and
     * velocity along the face normal, the contact force on the laminate
     * along the inward normal (at t, and the mean since the last output
     * step: the sphere's momentum change over the interval, which the
     * chatter of single nodes does not blur), the nodes in contact and
     * the deepest penetration. */
    std::vector<std::pair<std::string, double>>
    columns(const double t);

    /** Centre, velocity and acceleration, and the velocity and time of
     * the last output step (for a checkpoint). */
    std::vector<double>
    state() const;
    void
    set_state(const std::vector<double> &values);

  private:
    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               position;
      double                                   stiffness;
    };

    /** The contact tangent of @p node at @p u (zero out of contact). */
    Tensor<2, dim>
    node_tangent(const Node &node, const Vector &u) const;

    MPI_Comm          comm;
    double            radius, mass, penalty;
    unsigned int      boundary_id, normal_axis;
    double            inward; // -1 on a + face, +1 on a - face
    std::vector<Node> nodes;
    Tensor<1, dim>    center, velocity, acceleration, force;
    /** Center at t = 0 (a prescribed sphere moves from it). */
    Tensor<1, dim> start;
    Tensor<1, dim> row_velocity;
    double         row_time = 0;
    double         energy = 0, penetration = 0;
    unsigned int   n_contact = 0;
  };
} // namespace amfrac

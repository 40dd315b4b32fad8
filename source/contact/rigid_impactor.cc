#include <algorithm>
#include <amfrac/base/concatenate.h>
#include <amfrac/contact/rigid_impactor.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <map>
#include <numeric>
#include <tuple>

namespace amfrac
{
  namespace
  {
    /** A node's position at @p u less the centre, its length and the gap
     * to the sphere (negative inside). */
    template <int dim, typename Node, typename Vector>
    std::tuple<Tensor<1, dim>, double, double>
    offset(const Node           &node,
           const Vector         &u,
           const Tensor<1, dim> &center,
           const double          radius)
    {
      Tensor<1, dim> d;
      for (unsigned int c = 0; c < dim; ++c)
        d[c] = node.position[c] + u(node.dofs[c]) - center[c];
      const double distance = d.norm();
      return {d, distance, distance - radius};
    }
  } // namespace



  template <int dim>
  RigidImpactor<dim>::RigidImpactor(const parameters::Impactor &p,
                                    MPI_Comm                    comm)
    : comm(comm)
    , radius(p.radius)
    , mass(p.mass)
    , penalty(p.penalty)
    , boundary_id(p.boundary_id)
    , normal_axis(p.boundary_id / 2)
    , inward(p.boundary_id % 2 == 1 ? -1. : 1.)
  {
    // 2D: the first two of the three components (x and the thickness y).
    AssertThrow(p.center.size() >= dim && p.velocity.size() >= dim,
                ExcInternalError());
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = p.center[d], velocity[d] = p.velocity[d];
    row_velocity = velocity;
    start        = center;
  }



  template <int dim>
  void
  RigidImpactor<dim>::setup(const TiedCopyDoFs<dim> &dofs)
  {
    const auto                          &fe = dofs.get_fe();
    const QGauss<dim - 1>                quadrature(fe.degree + 1);
    FEFaceValues<dim>                    face_values(dofs.get_mapping(),
                                  fe,
                                  quadrature,
                                  update_values | update_JxW_values);
    const IndexSet                      &owned = dofs.locally_owned_dofs();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    // Keyed by the node's first reduced dof: the same node seen from
    // several faces gathers its area once per face.
    std::map<types::global_dof_index, Node> found;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && cell->face(f)->boundary_id() == boundary_id)
          {
            dofs.get_dof_indices(cell, indices);
            face_values.reinit(cell, f);
            for (const unsigned int i : dofs.dofs_on_face(f))
              {
                const auto [component, base] = fe.system_to_component_index(i);
                if (component != 0 || !owned.is_element(indices[i]))
                  continue;
                double area = 0;
                for (const unsigned int q :
                     face_values.quadrature_point_indices())
                  area += face_values.shape_value_component(i, q, 0)
                          * face_values.JxW(q);
                // operator[] value-initializes: stiffness 0 on the first
                // visit.
                Node &node = found[indices[i]];
                if (node.stiffness == 0)
                  {
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        node.dofs[d]
                          = indices[fe.component_to_system_index(d, base)];
                        AssertThrow(owned.is_element(node.dofs[d]),
                                    ExcMessage("a node's components are "
                                               "owned by one rank"));
                      }
                    node.position = dofs.support_point(indices[i]);
                  }
                node.stiffness += penalty * area;
              }
          }
    nodes.clear();
    for (auto &[dof, node] : found)
      nodes.push_back(node);
  }



  template <int dim>
  void
  RigidImpactor<dim>::evaluate(const Vector &u, Vector &contact)
  {
    contact = 0;
    // This rank's contributions per node in contact: its position (the
    // key of the sum), the force on the sphere and the energy.
    constexpr unsigned int stride = 2 * dim + 1;
    std::vector<double>    shares;
    double                 deepest = 0;
    for (const Node &node : nodes)
      {
        const auto [d, distance, gap] = offset(node, u, center, radius);
        if (gap >= 0 || distance == 0)
          continue;
        const Tensor<1, dim> on_node = (-node.stiffness * gap / distance) * d;
        for (unsigned int c = 0; c < dim; ++c)
          shares.push_back(node.position[c]);
        for (unsigned int c = 0; c < dim; ++c)
          {
            contact(node.dofs[c]) = on_node[c];
            shares.push_back(-on_node[c]);
          }
        shares.push_back(0.5 * node.stiffness * gap * gap);
        deepest = std::max(deepest, -gap);
      }
    contact.compress(VectorOperation::insert);
    // Every rank gathers all shares and adds them in the order of the
    // nodes' positions: the numbering of the nodes depends on the
    // partition, their positions do not.
    shares  = concatenate_over_ranks(shares, comm);
    deepest = Utilities::MPI::max(deepest, comm);
    std::vector<std::size_t> order(shares.size() / stride);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](const auto a, const auto b) {
      return std::lexicographical_compare(shares.begin() + a * stride,
                                          shares.begin() + a * stride + dim,
                                          shares.begin() + b * stride,
                                          shares.begin() + b * stride + dim);
    });
    force  = Tensor<1, dim>();
    energy = 0;
    for (const std::size_t k : order)
      {
        const double *share = shares.data() + k * stride + dim;
        for (unsigned int c = 0; c < dim; ++c)
          force[c] += share[c];
        energy += share[dim];
      }
    n_contact    = order.size();
    penetration  = deepest;
    acceleration = force / mass;
  }



  template <int dim>
  Tensor<2, dim>
  RigidImpactor<dim>::node_tangent(const Node &node, const Vector &u) const
  {
    const auto [d, distance, gap] = offset(node, u, center, radius);
    if (gap >= 0 || distance == 0)
      return Tensor<2, dim>();
    const Tensor<1, dim> n       = d / distance;
    const Tensor<2, dim> normal  = outer_product(n, n);
    const Tensor<2, dim> in_face = unit_symmetric_tensor<dim>() - normal;
    // The gap's curvature term softens the tangential directions: a node
    // pressed in by |g| slides around the sphere of radius r.
    return node.stiffness * (normal + (gap / distance) * in_face);
  }



  template <int dim>
  void
  RigidImpactor<dim>::add_tangent(const Vector                    &u,
                                  const AffineConstraints<double> &constraints,
                                  TrilinosWrappers::SparseMatrix &tangent) const
  {
    FullMatrix<double>                   block(dim, dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (const Node &node : nodes)
      {
        const Tensor<2, dim> k = node_tangent(node, u);
        if (k.norm() == 0)
          continue;
        for (unsigned int a = 0; a < dim; ++a)
          {
            dofs[a] = node.dofs[a];
            for (unsigned int b = 0; b < dim; ++b)
              block(a, b) = k[a][b];
          }
        constraints.distribute_local_to_global(block, dofs, tangent);
      }
  }



  template <int dim>
  void
  RigidImpactor<dim>::add_tangent_product(const Vector &u,
                                          const Vector &direction,
                                          Vector       &product) const
  {
    for (const Node &node : nodes)
      {
        const Tensor<2, dim> k = node_tangent(node, u);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            product(node.dofs[a]) += k[a][b] * direction(node.dofs[b]);
      }
    product.compress(VectorOperation::add);
  }



  template <int dim>
  void
  RigidImpactor<dim>::add_penalty_rows(Vector &rows) const
  {
    for (const Node &node : nodes)
      for (unsigned int c = 0; c < dim; ++c)
        rows(node.dofs[c]) += 2 * node.stiffness;
    rows.compress(VectorOperation::add);
  }



  template <int dim>
  double
  RigidImpactor<dim>::frequency_squared() const
  {
    double sum = 0;
    for (const Node &node : nodes)
      sum += node.stiffness;
    return 2 * Utilities::MPI::sum(sum, comm) / mass;
  }



  template <int dim>
  double
  RigidImpactor<dim>::node_frequency_squared(const Vector &mass) const
  {
    double largest = 0;
    for (const Node &node : nodes)
      if (mass(node.dofs[0]) > 0)
        largest = std::max(largest, node.stiffness / mass(node.dofs[0]));
    return Utilities::MPI::max(largest, comm);
  }



  template <int dim>
  std::vector<std::pair<std::string, double>>
  RigidImpactor<dim>::columns(const double t)
  {
    const unsigned int a = normal_axis;
    const double       mean
      = t > row_time ?
          -inward * mass * (velocity[a] - row_velocity[a]) / (t - row_time) :
          0.;
    row_velocity = velocity;
    row_time     = t;
    return {{"impactor_position", center[a]},
            {"impactor_velocity", velocity[a]},
            {"contact_force", -inward * force[a]},
            {"mean_contact_force", mean},
            {"contact_nodes", n_contact},
            {"penetration", penetration}};
  }



  template <int dim>
  std::vector<double>
  RigidImpactor<dim>::state() const
  {
    std::vector<double> values;
    for (const auto *t : {&center, &velocity, &acceleration, &row_velocity})
      for (unsigned int d = 0; d < dim; ++d)
        values.push_back((*t)[d]);
    values.push_back(row_time);
    return values;
  }



  template <int dim>
  void
  RigidImpactor<dim>::set_state(const std::vector<double> &values)
  {
    AssertThrow(values.size() == 4 * dim + 1,
                ExcMessage("the checkpoint's impactor state has "
                           + std::to_string(values.size()) + " values, not "
                           + std::to_string(4 * dim + 1)));
    std::size_t k = 0;
    for (auto *t : {&center, &velocity, &acceleration, &row_velocity})
      for (unsigned int d = 0; d < dim; ++d)
        (*t)[d] = values[k++];
    row_time = values[k];
  }



  template class RigidImpactor<2>;
  template class RigidImpactor<3>;
} // namespace amfrac

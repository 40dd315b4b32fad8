#include <algorithm>
#include <amfrac/base/concatenate.h>
#include <amfrac/contact/rigid_impactor.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

namespace amfrac
{
  namespace
  {
    /** A node's position at @p u less its closest point on the axis (the
     * centre of a sphere: @p axis zero), its length and the gap to the
     * surface (negative inside). */
    template <int dim, typename Node, typename Vector>
    std::tuple<Tensor<1, dim>, double, double>
    offset(const Node           &node,
           const Vector         &u,
           const Tensor<1, dim> &center,
           const Tensor<1, dim> &axis,
           const double          radius)
    {
      Tensor<1, dim> d;
      for (unsigned int c = 0; c < dim; ++c)
        d[c] = node.position[c] + u(node.dofs[c]) - center[c];
      d -= (d * axis) * axis;
      const double distance = d.norm();
      return {d, distance, distance - radius};
    }

    /** @p v less its part along the unit vector @p n. */
    template <int dim>
    Tensor<1, dim>
    tangential(const Tensor<1, dim> &v, const Tensor<1, dim> &n)
    {
      return v - (v * n) * n;
    }

    /** The order of the records of @p stride values in @p values, each led
     * by a node's position, by position: the same on any number of ranks
     * (the numbering of the nodes depends on the partition). The copies of
     * a node split by a crack share a position: the rest of the record
     * orders them. */
    template <int dim>
    std::vector<std::size_t>
    order_by_position(const std::vector<double> &values,
                      const unsigned int         stride)
    {
      std::vector<std::size_t> order(values.size() / stride);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](const auto a, const auto b) {
        return std::lexicographical_compare(values.begin() + a * stride,
                                            values.begin() + (a + 1) * stride,
                                            values.begin() + b * stride,
                                            values.begin() + (b + 1) * stride);
      });
      return order;
    }

    /** friction_state() ends with this tag after the committed centre and
     * the dissipation since its records carry the nodes' sides; the
     * state of older checkpoints ends with the dissipation, which is never
     * negative. */
    constexpr double sides_tag = -2;

    template <int dim>
    std::array<double, dim>
    key_of(const Point<dim> &p)
    {
      std::array<double, dim> key;
      for (unsigned int d = 0; d < dim; ++d)
        key[d] = p[d];
      return key;
    }

    /** A prescribed centre that is not finite at @p t (a time in
     * explicit runs, the load parameter in static ones) stops the run,
     * naming the Path. */
    template <int dim>
    void
    require_finite_centre(const Tensor<1, dim> &center,
                          const double          t,
                          const bool            static_mode)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (!std::isfinite(center[d]))
          throw NonFiniteValue("parameter <Impactor/Path>: the striker's "
                               "centre is not finite at t = "
                               + number_text(t) + (static_mode ? "" : " s")
                               + " (a division by zero or the root of "
                                 "a negative number in the expression?)");
    }
  } // namespace



  template <int dim>
  RigidImpactor<dim>::RigidImpactor(const parameters::Impactor &p,
                                    MPI_Comm                    comm,
                                    const bool                  explicit_run)
    : comm(comm)
    , radius(p.radius)
    , mass(p.mass)
    , penalty(p.penalty)
    , friction_coefficient(p.friction)
    , tangential_factor(p.tangential_factor)
    , static_mode(p.prescribed && !explicit_run)
    , prescribed(p.prescribed)
    , guided(p.guided && !p.prescribed)
    , boundary_id(p.boundary_id)
    , normal_axis(p.boundary_id / 2)
    , inward(p.boundary_id % 2 == 1 ? -1. : 1.)
  {
    // 2D: the first two of the three components (x and the thickness y).
    AssertThrow(p.center.size() >= dim && p.velocity.size() >= dim,
                ExcInternalError());
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = p.center[d], velocity[d] = p.velocity[d];
    if (p.cylinder && dim == 3)
      for (unsigned int d = 0; d < dim; ++d)
        axis[d] = p.axis[d];
    row_velocity        = velocity;
    prescribed_velocity = velocity;
    start               = center;
    committed_center    = center;
    if (!p.path.empty())
      {
        // The centre at t = 0 is Center + Path(0), and in explicit runs
        // the velocity of the first row is the path's slope over a
        // nanosecond (Velocity is not used; later rows have the last
        // step's mean). The difference of the path's values, not of the
        // centres: Center's round-off would be divided by the nanosecond.
        path = make_expression_function<dim>(p.path, 3, "", "Impactor/Path");
        move_to(0);
        require_finite_centre(center, 0., static_mode);
        committed_center = center;
        if (!static_mode)
          {
            const double h = 1e-9;
            for (unsigned int d = 0; d < dim; ++d)
              {
                path->set_time(h);
                const double later = path->value(Point<dim>(), d);
                path->set_time(0);
                velocity[d] = (later - path->value(Point<dim>(), d)) / h;
              }
            require_finite_centre(velocity, h, false);
            row_velocity = velocity;
          }
      }
  }



  template <int dim>
  void
  RigidImpactor<dim>::move_to(const double t)
  {
    if (!path)
      {
        center = start + t * prescribed_velocity;
        return;
      }
    path->set_time(t);
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = start[d] + path->value(Point<dim>(), d);
  }



  template <int dim>
  Tensor<1, dim>
  RigidImpactor<dim>::step_to(const double t, const double dt)
  {
    Assert(prescribed && !static_mode, ExcInternalError());
    const Tensor<1, dim> before = center;
    move_to(t);
    require_finite_centre(center, t, false);
    const Tensor<1, dim> move = center - before;
    velocity                  = move / dt;
    return move;
  }



  template <int dim>
  double
  RigidImpactor<dim>::finish_step(const Tensor<1, dim> &force_before,
                                  const Tensor<1, dim> &move,
                                  const double          dt)
  {
    const Tensor<1, dim> mean = 0.5 * (force_before + force_on_laminate());
    row_impulse -= dt * mean;
    return mean * move;
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
    const std::vector<Face>                 old_faces = std::move(faces);
    faces.clear();
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && cell->face(f)->boundary_id() == boundary_id)
          {
            const auto face = cell->face(f);
            Face       kept_face{{}, {}, face->diameter()};
            for (const unsigned int v : face->vertex_indices())
              {
                kept_face.vertices.push_back(face->vertex(v));
                const Tensor<1, dim> inward = cell->center() - face->vertex(v);
                kept_face.sides.push_back(inward / inward.norm());
              }
            faces.push_back(std::move(kept_face));
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
                node.side += cell->center() - node.position;
              }
          }
    // A mesh change keeps the friction history of the nodes that stay
    // (refinement keeps every vertex where it was), gathered from all
    // ranks: the new partition may give a node to another rank.
    const std::vector<double> kept = friction_coefficient > 0 && set_up ?
                                       friction_state() :
                                       std::vector<double>();
    nodes.clear();
    for (auto &[dof, node] : found)
      {
        node.side /= node.side.norm();
        nodes.push_back(node);
      }
    set_up = true;
    if (friction_coefficient == 0)
      return;
    history.assign(nodes.size(), History());
    trial_history = history;
    if (!kept.empty())
      restore_history(kept, false, old_faces);
  }



  template <int dim>
  Tensor<1, dim>
  RigidImpactor<dim>::displacement(const Node &node, const Vector &u) const
  {
    Tensor<1, dim> v;
    for (unsigned int c = 0; c < dim; ++c)
      v[c] = u(node.dofs[c]);
    return v;
  }



  template <int dim>
  Tensor<1, dim>
  RigidImpactor<dim>::slip_increment(const unsigned int i,
                                     const Vector      &u) const
  {
    const History &h = history[i];
    // A node new to the face (after a mesh change) starts from where it is.
    if (!h.referenced)
      return Tensor<1, dim>();
    return displacement(nodes[i], u) - h.displacement
           - (center - committed_center);
  }



  template <int dim>
  typename RigidImpactor<dim>::Response
  RigidImpactor<dim>::respond(const unsigned int i, const Vector &u) const
  {
    const Node &node = nodes[i];
    Response    r;
    const auto [d, distance, gap] = offset(node, u, center, axis, radius);
    if (gap >= 0 || distance == 0)
      return r;
    r.n        = d / distance;
    r.gap      = gap;
    r.distance = distance;
    r.pressure = -node.stiffness * gap;
    if (friction_coefficient == 0)
      return r;
    // The slip of the node against the sphere's surface since the commit,
    // from displacement increments (a stiff spring times the round-off of
    // positions would be a residual floor).
    const History       &h         = history[i];
    const Tensor<1, dim> increment = slip_increment(i, u);
    const Tensor<1, dim> stored    = h.in_contact ? h.force : Tensor<1, dim>();
    const double         kt        = tangential_factor * node.stiffness;
    r.slip                         = tangential(increment, r.n);
    r.old_force                    = tangential(stored, r.n);
    r.normal_part                  = (stored - kt * increment) * r.n;
    r.trial                        = r.old_force - kt * r.slip;
    r.friction                     = r.trial;
    const double limit             = friction_coefficient * r.pressure;
    // On the cone within round-off counts as sticking, so that the
    // decision does not depend on the order of sums (as in BodyContact).
    r.slipping = r.trial.norm() > limit * (1 + 1e-10);
    if (r.slipping)
      r.friction *= limit / r.trial.norm();
    return r;
  }



  template <int dim>
  void
  RigidImpactor<dim>::evaluate(const Vector &u, Vector &contact)
  {
    contact = 0;
    // This rank's contributions per node in contact or releasing its stick
    // spring: its position (the key of the sum), the force on the sphere,
    // the energy, the dissipation, the normal and friction forces and
    // whether it slides.
    constexpr unsigned int stride = 2 * dim + 5;
    std::vector<double>    shares;
    double                 deepest       = 0;
    const bool             with_friction = friction_coefficient > 0;
    std::vector<History>  &updated = static_mode ? trial_history : history;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const Node    &node = nodes[i];
        const Response r    = respond(i, u);
        Tensor<1, dim> on_node;
        double         stick = 0, dissipated = 0;
        if (with_friction)
          {
            // A copy: in explicit runs the update overwrites it.
            const History        h         = history[i];
            const Tensor<1, dim> increment = slip_increment(i, u);
            History             &next      = updated[i];
            next                           = History();
            next.displacement              = displacement(node, u);
            next.referenced                = true;
            if (r.pressure == 0 && !h.in_contact)
              continue;
            if (r.pressure > 0)
              {
                const double kt   = tangential_factor * node.stiffness;
                stick             = r.friction.norm_square() / (2 * kt);
                next.force        = r.friction;
                next.stick_energy = stick;
                next.in_contact   = true;
              }
            // The friction force's work less the change of the stick
            // spring's energy: zero while the node sticks. A node that
            // left contact did the work of its old force over the step
            // and releases its spring.
            dissipated = r.pressure > 0 ?
                           -0.5 * (r.old_force + r.friction) * r.slip :
                           -0.5 * h.force * increment;
            dissipated -= stick - (h.in_contact ? h.stick_energy : 0.);
          }
        else if (r.pressure == 0)
          continue;
        on_node = r.pressure * r.n + r.friction;
        for (unsigned int c = 0; c < dim; ++c)
          shares.push_back(node.position[c]);
        for (unsigned int c = 0; c < dim; ++c)
          {
            contact(node.dofs[c]) = on_node[c];
            shares.push_back(-on_node[c]);
          }
        shares.push_back(0.5 * node.stiffness * r.gap * r.gap + stick);
        shares.push_back(dissipated);
        shares.push_back(r.pressure);
        shares.push_back(r.friction.norm());
        shares.push_back(r.slipping ? 1 : 0);
        deepest = std::max(deepest, -r.gap);
      }
    contact.compress(VectorOperation::insert);
    // Every rank gathers all shares and adds them in the order of the
    // nodes' positions: the numbering of the nodes depends on the
    // partition, their positions do not.
    shares  = concatenate_over_ranks(shares, comm);
    deepest = Utilities::MPI::max(deepest, comm);
    const std::vector<std::size_t> order
      = order_by_position<dim>(shares, stride);
    force  = Tensor<1, dim>();
    energy = pressure_sum = friction_sum = 0;
    n_contact = n_sliding = 0;
    double dissipated     = 0;
    for (const std::size_t k : order)
      {
        const double *share = shares.data() + k * stride + dim;
        for (unsigned int c = 0; c < dim; ++c)
          force[c] += share[c];
        energy += share[dim];
        dissipated += share[dim + 1];
        pressure_sum += share[dim + 2];
        friction_sum += share[dim + 3];
        n_sliding += share[dim + 4] > 0 ? 1 : 0;
        n_contact += share[dim + 2] > 0 ? 1 : 0;
      }
    penetration  = deepest;
    acceleration = force / mass;
    if (guided)
      for (unsigned int c = 0; c < dim; ++c)
        if (c != normal_axis)
          acceleration[c] = 0;
    if (!with_friction)
      return;
    if (static_mode)
      pending_dissipation = dissipated;
    else
      {
        dissipation += dissipated;
        committed_center = center;
      }
  }



  template <int dim>
  void
  RigidImpactor<dim>::commit()
  {
    if (friction_coefficient == 0)
      return;
    history = trial_history;
    dissipation += pending_dissipation;
    pending_dissipation = 0;
    committed_center    = center;
  }



  template <int dim>
  Tensor<2, dim>
  RigidImpactor<dim>::node_tangent(const unsigned int i, const Vector &u) const
  {
    const Response r = respond(i, u);
    if (r.pressure == 0)
      return Tensor<2, dim>();
    const double         k       = nodes[i].stiffness;
    const Tensor<2, dim> normal  = outer_product(r.n, r.n);
    const Tensor<2, dim> in_face = unit_symmetric_tensor<dim>() - normal;
    // The normal turns with the node across the axis only, dn/du = Q / r
    // with Q = P less the axis' direction (P for a sphere).
    const Tensor<2, dim> curved = in_face - outer_product(axis, axis);
    // The gap's curvature term softens the curved directions: a node
    // pressed in by |g| slides around the sphere or cylinder of radius r.
    Tensor<2, dim> tangent = k * (normal + (r.gap / r.distance) * curved);
    if (friction_coefficient == 0)
      return tangent;
    // The trial force T = P(n) v, v = f_old - k_t (du - dc), turns with
    // the normal: dT/du = -k_t P - (n (x) Q T + (n . v) Q) / r.
    const double         kt = tangential_factor * k;
    const Tensor<2, dim> trial_gradient
      = -kt * in_face
        - (outer_product(r.n, curved * r.trial) + r.normal_part * curved)
            / r.distance;
    if (!r.slipping)
      return tangent - trial_gradient;
    // Sliding: the force mu p t with t = T / |T|; p grows with the
    // penetration (mu k t (x) n), t turns with T.
    const Tensor<1, dim> t     = r.friction / r.friction.norm();
    const double         limit = friction_coefficient * r.pressure;
    const Tensor<2, dim> turn
      = Tensor<2, dim>(unit_symmetric_tensor<dim>()) - outer_product(t, t);
    return tangent + friction_coefficient * k * outer_product(t, r.n)
           - (limit / r.trial.norm()) * (turn * trial_gradient);
  }



  template <int dim>
  void
  RigidImpactor<dim>::add_tangent(const Vector                    &u,
                                  const AffineConstraints<double> &constraints,
                                  TrilinosWrappers::SparseMatrix &tangent) const
  {
    FullMatrix<double>                   block(dim, dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const Tensor<2, dim> k = node_tangent(i, u);
        if (k.norm() == 0)
          continue;
        for (unsigned int a = 0; a < dim; ++a)
          {
            dofs[a] = nodes[i].dofs[a];
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
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const Tensor<2, dim> k = node_tangent(i, u);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            product(nodes[i].dofs[a]) += k[a][b] * direction(nodes[i].dofs[b]);
      }
    product.compress(VectorOperation::add);
  }



  template <int dim>
  void
  RigidImpactor<dim>::add_penalty_rows(Vector &rows) const
  {
    for (const Node &node : nodes)
      for (unsigned int c = 0; c < dim; ++c)
        rows(node.dofs[c])
          += (prescribed ? 1 : 2) * stiffest() * node.stiffness;
    rows.compress(VectorOperation::add);
  }



  template <int dim>
  double
  RigidImpactor<dim>::frequency_squared() const
  {
    double sum = 0;
    for (const Node &node : nodes)
      sum += node.stiffness;
    // Collective on every rank alike: prescribed is the same everywhere.
    if (prescribed)
      return 0;
    return 2 * stiffest() * Utilities::MPI::sum(sum, comm) / mass;
  }



  template <int dim>
  double
  RigidImpactor<dim>::node_frequency_squared(const Vector &mass) const
  {
    double largest = 0;
    for (const Node &node : nodes)
      if (mass(node.dofs[0]) > 0)
        largest
          = std::max(largest, stiffest() * node.stiffness / mass(node.dofs[0]));
    return Utilities::MPI::max(largest, comm);
  }



  template <int dim>
  std::vector<std::pair<std::string, double>>
  RigidImpactor<dim>::columns(const double t)
  {
    const unsigned int a = normal_axis;
    // The impulse on the sphere over the interval: its momentum change, or
    // for a prescribed sphere the sum of its steps' impulses.
    const double impulse
      = prescribed ? row_impulse[a] : mass * (velocity[a] - row_velocity[a]);
    const double mean = t > row_time ? -inward * impulse / (t - row_time) : 0.;
    row_velocity      = velocity;
    row_time          = t;
    row_impulse       = Tensor<1, dim>();
    std::vector<std::pair<std::string, double>> columns
      = {{"impactor_position", center[a]},
         {"impactor_velocity", velocity[a]},
         {"contact_force", -inward * force[a]},
         {"mean_contact_force", mean},
         {"contact_nodes", n_contact},
         {"penetration", penetration}};
    if (!guided)
      for (unsigned int c = 0; c < dim; ++c)
        if (c != a)
          columns.emplace_back(std::string("impactor_velocity_") + "xyz"[c],
                               velocity[c]);
    const auto more = friction_columns();
    columns.insert(columns.end(), more.begin(), more.end());
    return columns;
  }



  template <int dim>
  std::vector<std::pair<std::string, double>>
  RigidImpactor<dim>::friction_columns() const
  {
    if (friction_coefficient == 0)
      return {};
    std::vector<std::pair<std::string, double>> columns;
    for (unsigned int c = 0; c < dim; ++c)
      if (c != normal_axis)
        columns.emplace_back(std::string("contact_force_") + "xyz"[c],
                             -force[c]);
    columns.emplace_back("pressure_force_sum", pressure_sum);
    columns.emplace_back("friction_force_sum", friction_sum);
    columns.emplace_back("sliding_nodes", n_sliding);
    columns.emplace_back("impactor_friction_dissipation", dissipation);
    return columns;
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
    for (const auto *t : {&force, &row_impulse})
      for (unsigned int d = 0; d < dim; ++d)
        values.push_back((*t)[d]);
    return values;
  }



  template <int dim>
  void
  RigidImpactor<dim>::set_state(const std::vector<double> &values)
  {
    // Checkpoints before stop 54 end with row_time (a free sphere's force
    // is its mass times its acceleration).
    AssertThrow(values.size() == 6 * dim + 1 || values.size() == 4 * dim + 1,
                ExcMessage("the checkpoint's impactor state has "
                           + std::to_string(values.size()) + " values, not "
                           + std::to_string(6 * dim + 1) + " (or "
                           + std::to_string(4 * dim + 1) + " before stop 54)"));
    std::size_t k = 0;
    for (auto *t : {&center, &velocity, &acceleration, &row_velocity})
      for (unsigned int d = 0; d < dim; ++d)
        (*t)[d] = values[k++];
    row_time = values[k++];
    force    = mass * acceleration;
    if (k < values.size())
      for (auto *t : {&force, &row_impulse})
        for (unsigned int d = 0; d < dim; ++d)
          (*t)[d] = values[k++];
    for (unsigned int d = 0; d < dim; ++d)
      if (guided && d != normal_axis && velocity[d] != 0)
        throw InputError("Impactor/Guided",
                         "the checkpoint's sphere moves across the face's "
                         "normal (a run without the guide): resume it with "
                         "Guided = false");
  }



  template <int dim>
  std::vector<double>
  RigidImpactor<dim>::friction_state() const
  {
    // Per node: position, side, force, stick energy, contact flag,
    // displacement.
    constexpr unsigned int stride = 4 * dim + 2;
    std::vector<double>    values;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const History &h = history[i];
        for (unsigned int c = 0; c < dim; ++c)
          values.push_back(nodes[i].position[c]);
        for (unsigned int c = 0; c < dim; ++c)
          values.push_back(nodes[i].side[c]);
        for (unsigned int c = 0; c < dim; ++c)
          values.push_back(h.force[c]);
        values.push_back(h.stick_energy);
        values.push_back(h.in_contact ? 1 : 0);
        for (unsigned int c = 0; c < dim; ++c)
          values.push_back(h.displacement[c]);
      }
    values = concatenate_over_ranks(values, comm);
    std::vector<double> sorted;
    sorted.reserve(values.size() + dim + 2);
    for (const std::size_t k : order_by_position<dim>(values, stride))
      sorted.insert(sorted.end(),
                    values.begin() + k * stride,
                    values.begin() + (k + 1) * stride);
    for (unsigned int c = 0; c < dim; ++c)
      sorted.push_back(committed_center[c]);
    sorted.push_back(dissipation);
    sorted.push_back(sides_tag);
    return sorted;
  }



  template <int dim>
  void
  RigidImpactor<dim>::set_friction_state(const std::vector<double> &values)
  {
    restore_history(values, true);
  }



  template <int dim>
  void
  RigidImpactor<dim>::inherit_friction_state(const std::vector<double> &values)
  {
    restore_history(values, false);
  }



  template <int dim>
  long
  RigidImpactor<dim>::closest_record(const Records        &records,
                                     const Point<dim>     &position,
                                     const Tensor<1, dim> &side) const
  {
    const auto there = records.at_position.find(key_of(position));
    if (there == records.at_position.end())
      return -1;
    long   source  = -1;
    double closest = -std::numeric_limits<double>::max();
    for (const std::size_t k : there->second)
      {
        double alignment = 0;
        for (unsigned int c = 0; records.with_sides && c < dim; ++c)
          alignment += side[c] * records.values[k * records.stride + dim + c];
        if (alignment > closest)
          closest = alignment, source = k;
      }
    return source;
  }



  template <int dim>
  std::vector<long>
  RigidImpactor<dim>::heirs_of(const Records &records) const
  {
    std::vector<long> source(nodes.size(), -1);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      source[i] = closest_record(records, nodes[i].position, nodes[i].side);
    return source;
  }



  template <int dim>
  std::vector<std::vector<long>>
  RigidImpactor<dim>::places_of(const Records           &records,
                                const std::vector<long> &source,
                                const std::vector<Face> &old_faces) const
  {
    // The places one refinement adds vertices at: the centre of each old
    // face and (3D) the midpoints of its edges (vertices 0-1, 2-3, 0-2 and
    // 1-3 of a quadrilateral in deal.II's numbering).
    struct Place
    {
      Point<dim>                x;
      Tensor<1, dim>            side;
      const Face               *face;
      std::vector<unsigned int> members;
    };
    std::vector<Place> places;
    for (const Face &face : old_faces)
      {
        std::vector<std::vector<unsigned int>> groups;
        groups.emplace_back();
        for (unsigned int v = 0; v < face.vertices.size(); ++v)
          groups.back().push_back(v);
        if (face.vertices.size() == 4)
          groups.insert(groups.end(), {{0, 1}, {2, 3}, {0, 2}, {1, 3}});
        for (const auto &members : groups)
          {
            // The side of a place on a crack's edge (the two faces there
            // share it) is that of its vertices' copies.
            Point<dim>     x;
            Tensor<1, dim> side;
            for (const unsigned int v : members)
              {
                x += face.vertices[v] / double(members.size());
                side += face.sides[v];
              }
            places.push_back({x, side / side.norm(), &face, members});
          }
      }
    std::sort(places.begin(), places.end(), [](const Place &a, const Place &b) {
      return a.x[0] < b.x[0];
    });
    double size = 0;
    for (const Face &face : old_faces)
      size = std::max(size, face.size);
    const double                   tolerance = 1e-9 * size;
    std::vector<std::vector<long>> members(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        if (source[i] >= 0)
          continue;
        const Point<dim> &x  = nodes[i].position;
        auto              it = std::lower_bound(places.begin(),
                                   places.end(),
                                   x[0] - tolerance,
                                   [](const Place &p, const double v) {
                                     return p.x[0] < v;
                                   });
        // The place on the node's side, and at each of its vertices the
        // copy on the place's face's side.
        const Tensor<1, dim> &side = nodes[i].side;
        const Place          *best = nullptr;
        for (; it != places.end() && it->x[0] <= x[0] + tolerance; ++it)
          if (it->x.distance(x) <= tolerance && it->side * side > 0
              && (best == nullptr || it->side * side > best->side * side))
            best = &*it;
        if (best == nullptr)
          continue;
        for (const unsigned int v : best->members)
          members[i].push_back(closest_record(records,
                                              best->face->vertices[v],
                                              best->face->sides[v]));
        if (std::find(members[i].begin(), members[i].end(), -1)
            != members[i].end())
          members[i].clear();
      }
    return members;
  }



  template <int dim>
  std::vector<double>
  RigidImpactor<dim>::heirs_stiffness(const std::vector<long> &source,
                                      const std::size_t        n_saved) const
  {
    std::vector<double> pairs;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (source[i] >= 0)
        {
          pairs.push_back(source[i]);
          pairs.push_back(nodes[i].stiffness);
        }
    pairs = concatenate_over_ranks(pairs, comm);
    std::vector<std::pair<double, double>> sorted;
    for (std::size_t k = 0; k + 1 < pairs.size(); k += 2)
      sorted.emplace_back(pairs[k], pairs[k + 1]);
    std::sort(sorted.begin(), sorted.end());
    std::vector<double> total(n_saved, 0.);
    for (const auto &[k, stiffness] : sorted)
      total[static_cast<std::size_t>(k)] += stiffness;
    return total;
  }



  template <int dim>
  void
  RigidImpactor<dim>::carry(const Records           &records,
                            const std::vector<long> &members,
                            const unsigned int       i)
  {
    History     &h  = history[i];
    const double kt = tangential_factor * nodes[i].stiffness;
    const double n  = members.size();
    for (const long k : members)
      {
        const double  *v = records.history_of(k);
        Tensor<1, dim> force, stretch;
        for (unsigned int c = 0; c < dim; ++c)
          force[c] = v[c];
        // stick_energy = |F|^2 / (2 k_t), so the spring's stretch is
        // F / k_t = 2 stick_energy F / |F|^2.
        const double squared = force.norm_square();
        if (v[dim + 1] > 0 && squared > 0)
          stretch = (2 * v[dim] / squared) * force;
        h.force += (kt / n) * stretch;
        for (unsigned int c = 0; c < dim; ++c)
          h.displacement[c] += v[dim + 2 + c] / n;
        h.in_contact = h.in_contact || v[dim + 1] > 0;
      }
    h.stick_energy = kt > 0 ? h.force.norm_square() / (2 * kt) : 0.;
    h.referenced   = true;
  }



  template <int dim>
  typename RigidImpactor<dim>::Records
  RigidImpactor<dim>::parse_records(const std::vector<double> &values) const
  {
    const bool with_sides     = !values.empty() && values.back() == sides_tag;
    const unsigned int stride = with_sides ? 4 * dim + 2 : 3 * dim + 2;
    const unsigned int tail   = with_sides ? dim + 2 : dim + 1;
    AssertThrow(values.size() >= tail && (values.size() - tail) % stride == 0,
                ExcMessage("the checkpoint's impactor friction state has "
                           + std::to_string(values.size()) + " values"));
    Records records{values,
                    with_sides,
                    stride,
                    with_sides ? 2u * dim : 1u * dim,
                    (values.size() - tail) / stride,
                    {}};
    for (std::size_t k = 0; k < records.n_saved; ++k)
      {
        std::array<double, dim> key;
        std::copy_n(values.data() + k * stride, dim, key.begin());
        records.at_position[key].push_back(k);
      }
    return records;
  }



  template <int dim>
  void
  RigidImpactor<dim>::restore_history(const std::vector<double> &values,
                                      const bool                 require_all,
                                      const std::vector<Face>   &old_faces)
  {
    const Records           records = parse_records(values);
    const std::vector<long> source  = heirs_of(records);
    history.assign(nodes.size(), History());
    if (require_all)
      restore_exactly(records, source);
    else
      {
        // The history follows the position (and the side), as the stick
        // springs' stretch; new nodes take the old face's where they lie.
        const auto members = places_of(records, source, old_faces);
        for (unsigned int i = 0; i < nodes.size(); ++i)
          if (source[i] >= 0)
            carry(records, {source[i]}, i);
          else if (!members[i].empty())
            carry(records, members[i], i);
      }
    trial_history      = history;
    const double *rest = values.data() + records.n_saved * records.stride;
    for (unsigned int c = 0; c < dim; ++c)
      committed_center[c] = rest[c];
    dissipation         = rest[dim];
    pending_dissipation = 0;
  }



  template <int dim>
  void
  RigidImpactor<dim>::restore_exactly(const Records           &records,
                                      const std::vector<long> &source)
  {
    const std::vector<double> shared = heirs_stiffness(source, records.n_saved);
    bool                      missing = false;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        if (source[i] < 0)
          {
            missing = true;
            continue;
          }
        const double *v = records.history_of(source[i]);
        History      &h = history[i];
        // Node for node the share is 1 exactly; the copies of a split
        // node in a checkpoint written before the sides were saved (they
        // cannot be told apart) share their record by stiffness, and a
        // node without area takes no force.
        const double share
          = shared[source[i]] > 0 ? nodes[i].stiffness / shared[source[i]] : 0.;
        for (unsigned int c = 0; c < dim; ++c)
          {
            h.force[c]        = share * v[c];
            h.displacement[c] = v[dim + 2 + c];
          }
        h.stick_energy = share * v[dim];
        h.in_contact   = v[dim + 1] > 0;
        h.referenced   = true;
      }
    // A record in contact that no node took (two copies closer to one
    // record than to the other at their point) would lose its force.
    for (std::size_t k = 0; k < records.n_saved; ++k)
      if (shared[k] == 0 && records.history_of(k)[dim + 1] > 0)
        missing = true;
    // On every rank alike, so that no rank goes on alone.
    if (Utilities::MPI::max(missing ? 1 : 0, comm) > 0)
      throw InputError("Impactor/Friction coefficient",
                       "the checkpoint's friction history of the impactor "
                       "does not match this mesh's face node for node");
  }



  template class RigidImpactor<2>;
  template class RigidImpactor<3>;
} // namespace amfrac

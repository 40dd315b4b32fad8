#include <amfrac/adaptivity/explicit_state_transfer.h>
#include <amfrac/dofs/hanging_condensation.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace amfrac
{
  namespace
  {
    /** The value of component @p c of the field with copy values @p u on a
     * cell (copy indices @p local) at the unit point @p xi. */
    template <int dim>
    double
    value_at(const FiniteElement<dim>                   &fe,
             const std::vector<types::global_dof_index> &local,
             const dealii::Vector<double>               &u,
             const Point<dim>                           &xi,
             const unsigned int                          c)
    {
      double value = 0;
      for (unsigned int j = 0; j < local.size(); ++j)
        if (fe.system_to_component_index(j).first == c)
          value += fe.shape_value(j, xi) * u[local[j]];
      return value;
    }
  } // namespace



  template <int dim>
  ExplicitStateTransfer<dim>::ExplicitStateTransfer(
    const TiedCopyDoFs<dim>   &dofs,
    const std::vector<double> &density,
    const MPI_Comm             comm)
    : dofs(dofs)
    , density(density)
    , comm(comm)
  {}



  template <int dim>
  void
  ExplicitStateTransfer<dim>::prepare(const std::vector<const Vector *> &fields,
                                      const Vector &velocity)
  {
    copies.resize(fields.size() + 1);
    for (std::size_t k = 0; k <= fields.size(); ++k)
      dofs.expand_all(dofs.replicate(k < fields.size() ? *fields[k] : velocity),
                      copies[k]);
    transfer = std::make_unique<SolutionTransfer<dim, dealii::Vector<double>>>(
      dofs.copy_handler());
    transfer->prepare_for_coarsening_and_refinement(copies);
    coarsened.clear();
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->coarsen_flag_set()
          && coarsened.count(cell->parent()->id()) == 0)
        coarsened.emplace(cell->parent()->id(),
                          restrict_to_parent(cell->parent()));
  }



  template <int dim>
  typename ExplicitStateTransfer<dim>::Parent
  ExplicitStateTransfer<dim>::restrict_to_parent(
    const typename DoFHandler<dim>::cell_iterator &parent) const
  {
    const auto        &fe      = dofs.get_fe();
    const auto        &mapping = dofs.get_mapping();
    const unsigned int n       = fe.n_dofs_per_cell();
    Parent             result;
    result.values.assign(copies.size(), dealii::Vector<double>(n));
    result.momentum.reinit(n);
    std::vector<types::global_dof_index> local(n);

    // Every node of the parent is a node of one of its children, where
    // the child's polynomial takes the old nodal value.
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<dim> x
          = mapping.transform_unit_to_real_cell(parent,
                                                fe.unit_support_point(i));
        const unsigned int c     = fe.system_to_component_index(i).first;
        bool               found = false;
        for (unsigned int k = 0; k < parent->n_children() && !found; ++k)
          {
            Point<dim> xi;
            try
              {
                xi = mapping.transform_real_to_unit_cell(parent->child(k), x);
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {
                continue;
              }
            if (!GeometryInfo<dim>::is_inside_unit_cell(xi, 1e-8))
              continue;
            found = true;
            parent->child(k)->get_dof_indices(local);
            for (std::size_t f = 0; f < copies.size(); ++f)
              result.values[f][i] = value_at(fe, local, copies[f], xi, c);
          }
        AssertThrow(found,
                    ExcMessage("a node of a coarsened cell lies in none of "
                               "its children"));
      }

    // The momentum int_parent rho phi_i v over the children, from the
    // children's velocity (exact for affine cells).
    FEValues<dim>       child_values(mapping,
                               fe,
                               QGauss<dim>(fe.degree + 1),
                               update_values | update_quadrature_points
                                 | update_JxW_values);
    const auto         &velocity = copies.back();
    std::vector<double> v(dim);
    for (unsigned int k = 0; k < parent->n_children(); ++k)
      {
        const auto child = parent->child(k);
        child_values.reinit(child);
        child->get_dof_indices(local);
        const double rho = density[child->material_id()];
        for (const unsigned int q : child_values.quadrature_point_indices())
          {
            std::fill(v.begin(), v.end(), 0.);
            for (unsigned int j = 0; j < n; ++j)
              v[fe.system_to_component_index(j).first]
                += child_values.shape_value(j, q) * velocity[local[j]];
            const Point<dim> xi = mapping.transform_real_to_unit_cell(
              parent, child_values.quadrature_point(q));
            for (unsigned int i = 0; i < n; ++i)
              result.momentum[i] += rho * fe.shape_value(i, xi)
                                    * v[fe.system_to_component_index(i).first]
                                    * child_values.JxW(q);
          }
      }
    return result;
  }



  template <int dim>
  std::vector<dealii::Vector<double>>
  ExplicitStateTransfer<dim>::new_copies() const
  {
    std::vector<dealii::Vector<double>> result(
      copies.size(), dealii::Vector<double>(dofs.n_copies()));
    transfer->interpolate(copies, result);
    std::vector<types::global_dof_index> local(dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        const auto parent = coarsened.find(cell->id());
        if (parent == coarsened.end())
          continue;
        cell->get_dof_indices(local);
        for (std::size_t f = 0; f < copies.size(); ++f)
          for (unsigned int i = 0; i < local.size(); ++i)
            result[f][local[i]] = parent->second.values[f][i];
      }
    return result;
  }



  template <int dim>
  void
  ExplicitStateTransfer<dim>::interpolate(const std::vector<Vector *> &fields,
                                          Vector                      &velocity)
  {
    AssertThrow(transfer && fields.size() + 1 == copies.size(),
                ExcMessage("interpolate() needs the fields of prepare()"));
    const auto                     moved = new_copies();
    const HangingCondensation<dim> hanging(dofs, comm);
    for (std::size_t f = 0; f <= fields.size(); ++f)
      {
        Vector &v = f < fields.size() ? *fields[f] : velocity;
        v.reinit(dofs.locally_owned_dofs(), comm);
        dofs.gather(moved[f], v);
        hanging.distribute(v);
      }
    conserve_momentum(moved.back(), hanging, velocity);
    hanging.distribute(velocity);
    transfer.reset();
    copies.clear();
  }



  template <int dim>
  void
  ExplicitStateTransfer<dim>::conserve_momentum(
    const dealii::Vector<double>   &velocity_copies,
    const HangingCondensation<dim> &hanging,
    Vector                         &velocity)
  {
    const auto &fe          = dofs.get_fe();
    const auto &constraints = dofs.hanging_node_constraints();
    const auto &owned       = dofs.locally_owned_dofs();
    const auto  n           = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(n);

    // The nodes of coarsened cells, and every master of a hanging node
    // that one of them constrains or is constrained by: otherwise the
    // condensed momentum of such a hanging node would be split between
    // nodes that keep their velocity and nodes that do not.
    std::vector<bool> touched(dofs.n_dofs(), false);
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (coarsened.count(cell->id()) > 0)
        {
          dofs.get_dof_indices(cell, indices);
          for (const auto i : indices)
            touched[i] = true;
        }
    for (bool changed = true; changed;)
      {
        changed = false;
        for (const auto &line : constraints.get_lines())
          {
            bool any = touched[line.index];
            for (const auto &entry : line.entries)
              any = any || touched[entry.first];
            if (!any)
              continue;
            for (const auto &entry : line.entries)
              if (!touched[entry.first])
                touched[entry.first] = changed = true;
            touched[line.index] = true;
          }
      }

    // Condensed momentum and lumped mass: coarsened cells contribute
    // their children's momentum, the others m_i v_i of their own moved
    // copies, the old velocity field there (at a node that a coarsening
    // made hanging, the old value, not the interpolated one). Cells in
    // mesh order, owned entries only: the sums do not depend on the
    // partition.
    std::vector<types::global_dof_index> local(n);
    dealii::Vector<double>               p(dofs.n_dofs()), m(dofs.n_dofs());
    FEValues<dim>                        lobatto(dofs.get_mapping(),
                          fe,
                          QGaussLobatto<dim>(fe.degree + 1),
                          update_values | update_JxW_values);
    for (const auto &cell : dofs.cells_with_owned_dofs())
      {
        lobatto.reinit(cell);
        dofs.get_dof_indices(cell, indices);
        cell->get_dof_indices(local);
        const double rho    = density[cell->material_id()];
        const auto   parent = coarsened.find(cell->id());
        for (unsigned int i = 0; i < n; ++i)
          if (owned.is_element(indices[i]))
            {
              double mi = 0;
              for (const unsigned int q : lobatto.quadrature_point_indices())
                mi += rho * lobatto.shape_value(i, q) * lobatto.JxW(q);
              m[indices[i]] += mi;
              p[indices[i]] += parent != coarsened.end() ?
                                 parent->second.momentum[i] :
                                 mi * velocity_copies[local[i]];
            }
      }
    Vector momentum(owned, comm), mass(owned, comm);
    for (const auto i : owned)
      momentum(i) = p[i], mass(i) = m[i];
    momentum.compress(VectorOperation::insert);
    mass.compress(VectorOperation::insert);
    hanging.condense(momentum);
    hanging.condense(mass);

    types::global_dof_index count = 0;
    for (const auto i : owned)
      if (touched[i] && !hanging.is_hanging(i) && mass(i) > 0)
        {
          velocity(i) = momentum(i) / mass(i);
          ++count;
        }
    velocity.compress(VectorOperation::insert);
    n_momentum = Utilities::MPI::sum(count, comm);
  }



  template class ExplicitStateTransfer<2>;
  template class ExplicitStateTransfer<3>;
} // namespace amfrac

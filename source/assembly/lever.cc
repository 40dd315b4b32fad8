#include <algorithm>
#include <amfrac/assembly/lever.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/mpi.h>

namespace amfrac
{
  namespace
  {
    types::boundary_id
    boundary_id_of(const std::string &face)
    {
      const auto &names = parameters::BoundaryConditions::face_names;
      return std::find(names.begin(), names.end(), face) - names.begin();
    }



    template <int dim>
    double
    mean_x(const TiedCopyDoFs<dim>                    &dofs,
           const std::vector<types::global_dof_index> &nodes)
    {
      double sum = 0;
      for (const auto i : nodes)
        sum += dofs.support_point(i)[0];
      return sum / nodes.size();
    }
  } // namespace



  template <int dim>
  Lever<dim>::Lever(const parameters::BoundaryConditions &conditions)
    : prm(conditions.lever)
  {
    if (!prm.active())
      return;
    const std::string path = "Boundary conditions/Lever/";
    load_point             = make_expression_function<dim>({prm.displacement},
                                               1,
                                               conditions.constants,
                                               path + "Displacement");
    if (!prm.hinge_where.empty())
      hinge_where = make_expression_function<dim>({prm.hinge_where},
                                                  1,
                                                  conditions.constants,
                                                  path + "Hinge where");
    if (!prm.saddle_where.empty())
      saddle_where = make_expression_function<dim>({prm.saddle_where},
                                                   1,
                                                   conditions.constants,
                                                   path + "Saddle where");
  }



  template <int dim>
  void
  Lever<dim>::collect(const TiedCopyDoFs<dim> &dofs)
  {
    if (!prm.active())
      return;
    const std::string path = "Boundary conditions/Lever/";
    // A hanging dof follows its coarse face, not the lever.
    std::vector<bool> excluded(dofs.n_dofs(), false);
    for (const auto &line : dofs.hanging_node_constraints().get_lines())
      excluded[line.index] = true;
    // The thickness-axis dofs of a face where its condition is nonzero.
    const auto select
      = [&](const std::string &face, const Function<dim> *where) {
          return dofs.boundary_dofs(boundary_id_of(face), [&](const auto dof) {
            return dofs.component(dof) == dim - 1 && !excluded[dof]
                   && (!where || where->value(dofs.support_point(dof)) != 0);
          });
        };
    hinge = select(prm.hinge_face, hinge_where.get());
    require(!hinge.empty(),
            path + "Hinge where",
            "selects no node of face " + prm.hinge_face);
    for (const auto i : hinge)
      excluded[i] = true;
    saddle = select(prm.saddle_face, saddle_where.get());
    require(!saddle.empty(),
            path + "Saddle where",
            "selects no node of face " + prm.saddle_face
              + " that is not a hinge node");

    const double x_A = mean_x(dofs, hinge), x_B = mean_x(dofs, saddle);
    require(std::abs(x_B - x_A) > 0,
            path + "Saddle where",
            "the saddle is at the hinge (mean x = " + std::to_string(x_A)
              + "): the lever has no arm");
    // The load point lies beyond the saddle, away from the hinge.
    const double x_P = x_B + (x_B > x_A ? 1 : -1) * prm.length;
    r                = (x_B - x_A) / (x_P - x_A);
  }



  template <int dim>
  std::vector<types::global_dof_index>
  Lever<dim>::all_dofs() const
  {
    std::vector<types::global_dof_index> all = hinge;
    all.insert(all.end(), saddle.begin(), saddle.end());
    return all;
  }



  template <int dim>
  double
  Lever<dim>::load_point_displacement(const double t) const
  {
    load_point->set_time(t);
    return load_point->value(Point<dim>());
  }



  template <int dim>
  void
  Lever<dim>::add_constraints(const double               t,
                              const bool                 homogeneous,
                              const IndexSet            &relevant,
                              AffineConstraints<double> &constraints) const
  {
    if (!active())
      return;
    const types::global_dof_index master = hinge.front();
    for (std::size_t k = 1; k < hinge.size(); ++k)
      if (relevant.is_element(hinge[k]))
        {
          constraints.add_line(hinge[k]);
          constraints.add_entry(hinge[k], master, 1.);
        }
    const double inhomogeneity
      = homogeneous ? 0. : r * load_point_displacement(t);
    for (const auto j : saddle)
      if (relevant.is_element(j))
        {
          constraints.add_line(j);
          if (r < 1)
            constraints.add_entry(j, master, 1 - r);
          constraints.set_inhomogeneity(j, inhomogeneity);
        }
  }



  template <int dim>
  double
  Lever<dim>::force(const double   t,
                    const Vector  &residual,
                    const MPI_Comm comm) const
  {
    if (!active())
      return 0;
    // dw_P/dt by a one-sided difference: exact for linear ramps.
    const double dt = 1e-6 * std::max(1., std::abs(t));
    const double slope
      = (load_point_displacement(t) - load_point_displacement(t - dt)) / dt;
    double sum = 0;
    for (const auto j : saddle)
      if (residual.locally_owned_elements().is_element(j))
        sum += residual(j);
    return r * slope * Utilities::MPI::sum(sum, comm);
  }



  template <int dim>
  std::pair<double, double>
  Lever<dim>::displacements(const Vector &solution) const
  {
    double sum = 0;
    for (const auto j : saddle)
      sum += solution(j);
    return {solution(hinge.front()), sum / saddle.size()};
  }



  template class Lever<2>;
  template class Lever<3>;
} // namespace amfrac

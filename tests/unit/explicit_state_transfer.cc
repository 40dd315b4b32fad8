// tau_2 for the state of an explicit run (ExplicitStateTransfer, issue 4),
// on a Q1 mesh of two plies whose interface is released (the field jumps
// across it), through a sequence of refinements and coarsenings with
// hanging nodes, in 2D (isotropic cells) and 3D (cells cut along the
// plies only, as runs that adapt during their history cut them):
// - a displacement linear in each ply survives every change exactly (nodal
//   interpolation on coarsened cells, SolutionTransfer elsewhere);
// - the lumped momentum sum_I M_I v_I of a random velocity is kept to
//   round-off, per component, and the lumped kinetic energy never grows;
// - a constant velocity stays constant;
// - nodes away from coarsened cells keep their velocity;
// - the same on two ranks (the test runs under mpirun -np 2 too).
#include "../check.h"

#include <amfrac/adaptivity/explicit_state_transfer.h>
#include <amfrac/dofs/hanging_condensation.h>
#include <amfrac/geometry/in_plane_refinement.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <random>

using namespace amfrac;

namespace
{
  using Vector = TrilinosWrappers::MPI::Vector;
  const std::vector<double> density{2.0, 0.5};

  /** A field linear in each ply, discontinuous across the interface. */
  template <int dim>
  double
  ply_field(const unsigned int ply, const Point<dim> &p, const unsigned int c)
  {
    const double shift = ply == 0 ? 0.3 : -1.1;
    return shift + (c + 1) * p[0] - 0.5 * p[1]
           + (dim == 3 ? 0.2 * p[dim - 1] : 0) + 0.1 * ply * p[0];
  }

  /** The owned entries of the field at every reduced dof (copies of a
   * reduced dof lie in one ply). */
  template <int dim>
  Vector
  sample(const TiedCopyDoFs<dim> &dofs, const bool random, const int seed)
  {
    const auto                            &fe = dofs.get_fe();
    dealii::Vector<double>                 all(dofs.n_dofs());
    std::mt19937                           engine(seed);
    std::uniform_real_distribution<double> uniform(-1, 1);
    std::vector<double>                    noise(dofs.n_dofs());
    for (auto &value : noise)
      value = uniform(engine);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        dofs.get_dof_indices(cell, indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          all[indices[i]]
            = random ? noise[indices[i]] :
                       ply_field<dim>(cell->material_id(),
                                      dofs.support_point(indices[i]),
                                      fe.system_to_component_index(i).first);
      }
    dofs.hanging_node_constraints().distribute(all);
    Vector v(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    for (const auto i : dofs.locally_owned_dofs())
      v(i) = all[i];
    v.compress(VectorOperation::insert);
    return v;
  }

  /** The condensed lumped mass of the current mesh. */
  template <int dim>
  Vector
  lumped_mass(const TiedCopyDoFs<dim> &dofs)
  {
    const auto                          &fe = dofs.get_fe();
    FEValues<dim>                        lobatto(dofs.get_mapping(),
                          fe,
                          QGaussLobatto<dim>(2),
                          update_values | update_JxW_values);
    dealii::Vector<double>               m(dofs.n_dofs());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.cells_with_owned_dofs())
      {
        lobatto.reinit(cell);
        dofs.get_dof_indices(cell, indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          for (const unsigned int q : lobatto.quadrature_point_indices())
            m[indices[i]] += density[cell->material_id()]
                             * lobatto.shape_value(i, q) * lobatto.JxW(q);
      }
    Vector mass(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    for (const auto i : dofs.locally_owned_dofs())
      mass(i) = m[i];
    mass.compress(VectorOperation::insert);
    HangingCondensation<dim>(dofs, MPI_COMM_WORLD).condense(mass);
    return mass;
  }

  /** Momentum per component, kinetic energy and sum M |v| of @p v. */
  template <int dim>
  std::array<double, dim + 2>
  momentum_and_energy(const TiedCopyDoFs<dim> &dofs, const Vector &v)
  {
    const Vector                mass = lumped_mass(dofs);
    std::array<double, dim + 2> result{};
    for (const auto i : dofs.locally_owned_dofs())
      {
        result[dofs.component(i)] += mass(i) * v(i);
        result[dim] += 0.5 * mass(i) * v(i) * v(i);
        result[dim + 1] += mass(i) * std::abs(v(i));
      }
    for (auto &value : result)
      value = Utilities::MPI::sum(value, MPI_COMM_WORLD);
    return result;
  }

  double
  max_difference(const Vector &a, const Vector &b)
  {
    double d = 0;
    for (const auto i : a.locally_owned_elements())
      d = std::max(d, std::abs(a(i) - b(i)));
    return Utilities::MPI::max(d, MPI_COMM_WORLD);
  }

  /** Flags of mesh change @p change: refine some cells, coarsen others. */
  template <int dim>
  void
  flag(Triangulation<dim> &tria, const unsigned int change)
  {
    const RefinementCase<dim> cut
      = dim == 2 ? RefinementCase<dim>::isotropic_refinement :
                   RefinementCase<dim>(RefinementCase<3>::cut_xy);
    for (const auto &cell : tria.active_cell_iterators())
      {
        const double x    = cell->center()[0];
        const bool   left = x < 1;
        // First refine the left half twice, then move the refinement to
        // the right: coarsen on the left, refine on the right.
        if (change < 2 ? left && cell->level() == static_cast<int>(change) :
                         !left && cell->level() < 2 && x < 1.5 + change)
          cell->set_refine_flag(cut);
        else if (change >= 2 && left && cell->level() > 0 && x < 0.5 * change)
          cell->set_coarsen_flag();
      }
    // As runs that adapt during their history do: in the plane of the
    // plies in 3D, both plies alike.
    keep_refinement_in_plane(tria, cut);
    tria.prepare_coarsening_and_refinement();
    AssertThrow(!flagged_through_thickness(tria), ExcInternalError());
  }

  template <int dim>
  void
  run()
  {
    parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    if (dim == 2)
      GridGenerator::subdivided_hyper_rectangle(tria,
                                                {4, 2},
                                                Point<dim>(),
                                                Point<dim>(2, 1));
    else
      GridGenerator::subdivided_hyper_rectangle(tria,
                                                {4, 2, 2},
                                                Point<dim>(),
                                                Point<dim>(2, 1, 1));
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->center()[dim - 1] > 0.5 ? 1 : 0);
    const typename TiedCopyDoFs<dim>::FaceFilter released
      = [](const auto &cell, const unsigned int f) {
          return !cell->at_boundary(f)
                 && cell->neighbor(f)->material_id() != cell->material_id();
        };
    TiedCopyDoFs<dim> dofs(tria, 1);
    dofs.distribute(released);

    Vector displacement = sample(dofs, false, 0);
    Vector velocity     = sample(dofs, true, 1);
    Vector constant(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    constant                 = 0.75;
    double       worst_field = 0, worst_momentum = 0, worst_constant = 0;
    unsigned int coarsened = 0, energy_increases = 0, outside_rule = 0;
    for (unsigned int change = 0; change < 5; ++change)
      {
        const auto before = momentum_and_energy(dofs, velocity);
        flag(tria, change);
        // The random velocity, and a copy of it moved as a nodal field
        // (without the momentum rule), to see where the rule acts; a
        // constant velocity in a second transfer.
        Vector                     nodal = velocity;
        ExplicitStateTransfer<dim> moving(dofs, density, MPI_COMM_WORLD);
        ExplicitStateTransfer<dim> moving_constant(dofs,
                                                   density,
                                                   MPI_COMM_WORLD);
        moving.prepare({&displacement, &nodal}, velocity);
        moving_constant.prepare({}, constant);
        tria.execute_coarsening_and_refinement();
        dofs.distribute(released);
        moving.interpolate({&displacement, &nodal}, velocity);
        moving_constant.interpolate({}, constant);
        coarsened += moving.n_coarsened_cells();
        // Hanging entries follow their masters.
        const HangingCondensation<dim> hanging(dofs, MPI_COMM_WORLD);
        unsigned long                  changed = 0;
        for (const auto i : dofs.locally_owned_dofs())
          changed += !hanging.is_hanging(i) && velocity(i) != nodal(i);
        changed = Utilities::MPI::sum(changed, MPI_COMM_WORLD);
        if (changed > moving.n_momentum_dofs())
          ++outside_rule;

        worst_field
          = std::max(worst_field,
                     max_difference(displacement, sample(dofs, false, 0)));
        Vector expected_constant(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
        expected_constant = 0.75;
        worst_constant    = std::max(worst_constant,
                                  max_difference(constant, expected_constant));
        const auto after  = momentum_and_energy(dofs, velocity);
        for (unsigned int d = 0; d < dim; ++d)
          worst_momentum
            = std::max(worst_momentum,
                       std::abs(after[d] - before[d]) / before[dim + 1]);
        if (after[dim] > before[dim] * (1 + 1e-14))
          ++energy_increases;
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << dim << "D change " << change << ": "
                    << tria.n_active_cells() << " cells, "
                    << moving.n_coarsened_cells() << " coarsened, "
                    << moving.n_momentum_dofs()
                    << " velocities from the momentum; kinetic energy "
                    << before[dim] << " -> " << after[dim] << std::endl;
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << dim << "D: linear field " << worst_field
                << ", constant velocity " << worst_constant
                << ", momentum change / sum M|v| " << worst_momentum
                << std::endl;
    CHECK(coarsened > 0);
    CHECK(worst_field < 1e-13);
    CHECK(worst_constant < 1e-13);
    CHECK(worst_momentum < 1e-13);
    CHECK(energy_increases == 0);
    CHECK(outside_rule == 0);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2>();
  run<3>();
  return amfrac_test::summary();
}

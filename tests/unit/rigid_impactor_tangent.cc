// The rigid sphere's contact tangent (static runs) against central
// differences of its forces, at a deep penetration where the curvature
// term k (g / r) (I - n n^T) is a third of the normal one: a 2 x 2 x 1 block
// whose nine top nodes all lie inside a sphere of radius 1.2 (gaps -0.05 to
// -0.3), displaced at random. add_tangent_product() and add_tangent() (into
// a matrix, without constraints) agree with the differences to 1e-6 of the
// product's size, and with each other to round-off; without the curvature
// term the difference is 0.43 of it (checked).
// With friction, the history committed in the undeformed state: committed
// again after a quarter of the random field and moved by a millionth of it
// more, all nodes stick with a tangential force; moved by the field and
// 0.1 mm along x (mu = 0.1) all slide. The tangents agree with the
// differences to 1e-6 (measured 6.4e-10 and 1.3e-9); without the turning
// of the tangent plane with the normal they are off by 0.22 % and 4.5 %
// (checked).
// The same for a cylinder of radius 1.2 along (1, 1, 0) at 45 degrees in the
// face's plane through the sphere's centre: the nine nodes lie 0.9 to 1.14
// from its axis. Its normal does not turn along the axis, which the
// sphere's curvature term would (off by 0.01 to 0.1 of |K d|, checked).
// A crack through the contact (issue 10 with crack insertion): the face
// x = 0.5 released splits the three top nodes on it. After setup() on the
// cracked layer, with every copy displaced as its node was, 12 nodes touch
// instead of 9, and the contact energy and the force on the sphere are
// those of the intact layer to 1e-14 (the copies share the node's area).
// With friction (mu = 0.3), the history committed with the nodes sticking
// at a quarter of the field on the intact layer and handed to the cracked
// one (inherit_friction_state(), as after a crack insertion): at the same
// displacement the copies share their node's tangential force and stick
// energy by area, so the force on the sphere, its friction sum and the
// contact energy are the intact ones to 1e-12. Each copy taking the whole
// force instead (the history keyed by position alone) is off by 39 % of
// the friction sum (checked). Then each copy moved on its own (at random)
// and committed: a checkpoint's state restored on the cracked layer gives
// every copy its own history back (the copies at one point told apart by
// their side), so that the forces at a further random displacement are
// the same entry by entry.
// check_mesh_change(): a cylinder along x pressed into the 2 x 2 x 1 block
// (explicit mode, mu = 1), the block sheared along x under it (u_x =
// 1e-3 y): every node sticks with a stretch linear in y. Refined (setup()
// of the same impactor), then coarsened back: at the same displacement
// each node's force, the force on the cylinder, the contact energy and the
// friction dissipation are those of an impactor set up on that mesh from
// the start and moved the same way, to 1e-12. Refinement adds nodes at the
// old faces' edge midpoints and centres (they take the mean stretch of the
// right vertices: the linear field's value there); coarsening changes the
// areas of the nodes that stay. The same on the block cracked along x =
// 0.5 with the two sides moved apart by 4e-4 along x. Forces carried
// instead of stretches (a kept node its own, a new one the mean of its
// face's) fail (checked). A sticking history is the same whichever old
// record a node takes (its stretch and displacement come together), so
// check_mesh_change_after_slip() slides the cracked block first under a
// flat cylinder (mu = 0.01, the sides 4e-4 apart), refines, then moves it
// back into sticking: the friction forces are those of the fine mesh slid
// the same way from the start within 1e-2 (measured 2.0e-3, the mean of
// the vertices' cones at the new nodes); new nodes on the crack's line
// that take the other side's copies are off by 0.13 (checked).
#include "../check.h"

#include <amfrac/contact/rigid_impactor.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <random>

using namespace amfrac;
using TrilinosVector = TrilinosWrappers::MPI::Vector;

namespace
{
  parameters::Impactor
  deep_impactor(const bool cylinder)
  {
    parameters::Impactor p;
    p.cylinder = cylinder;
    p.axis
      = {cylinder ? std::sqrt(0.5) : 0., cylinder ? std::sqrt(0.5) : 0., 0.};
    p.active      = true;
    p.face        = "z+";
    p.boundary_id = 5;
    p.radius      = 1.2;
    p.mass        = 1;
    p.center      = {0.5, 0.5, 1.9};
    p.velocity    = {0, 0, 0};
    p.penalty     = 1e3;
    p.prescribed  = true;
    return p;
  }

  /** The residual's share of the sphere at @p u: minus its forces. */
  TrilinosVector
  residual(RigidImpactor<3> &sphere, const TrilinosVector &u)
  {
    TrilinosVector force(u);
    sphere.evaluate(u, force);
    force *= -1;
    return force;
  }
  /** |K d - FD| / |K d| of the tangent at @p u along @p d; add_tangent()
   * into a full matrix and add_tangent_product() agree to round-off. */
  double
  tangent_error(const TiedCopyDoFs<3> &dofs,
                RigidImpactor<3>      &sphere,
                const TrilinosVector  &u,
                const TrilinosVector  &d,
                const std::string     &label)
  {
    const IndexSet &owned = dofs.locally_owned_dofs();
    const double    eps   = 1e-7;
    TrilinosVector  plus(u), minus(u);
    plus.add(eps, d);
    minus.add(-eps, d);
    TrilinosVector difference = residual(sphere, plus);
    difference -= residual(sphere, minus);
    difference /= 2 * eps;

    TrilinosVector product(owned, MPI_COMM_WORLD);
    sphere.add_tangent_product(u, d, product);

    // add_tangent() into a full matrix (27 nodes, 81 unknowns).
    TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      for (const auto j : owned)
        pattern.add(i, j);
    pattern.compress();
    TrilinosWrappers::SparseMatrix matrix(pattern);
    AffineConstraints<double>      none;
    none.close();
    sphere.add_tangent(u, none, matrix);
    matrix.compress(VectorOperation::add);
    TrilinosVector assembled(owned, MPI_COMM_WORLD);
    matrix.vmult(assembled, d);

    TrilinosVector error = product;
    error -= difference;
    TrilinosVector mismatch = assembled;
    mismatch -= product;
    std::cout << label << ": |K d| " << product.l2_norm() << ", |K d - FD| "
              << error.l2_norm() << ", |assembled - product| "
              << mismatch.l2_norm() << std::endl;
    CHECK(product.l2_norm() > 0);
    CHECK(mismatch.l2_norm() < 1e-12 * product.l2_norm());
    return error.l2_norm() / product.l2_norm();
  }

  /** The displacement field u(x) = (0.01 x y, -0.02 x, -0.03 - 0.02 y^2)
   * on the layer @p dofs (every copy takes its node's value). */
  TrilinosVector
  smooth_field(const TiedCopyDoFs<3> &dofs)
  {
    TrilinosVector u(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    for (const auto i : dofs.locally_owned_dofs())
      {
        const Point<3> &x = dofs.support_point(i);
        const double    value[3]
          = {0.01 * x[0] * x[1], -0.02 * x[0], -0.03 - 0.02 * x[1] * x[1]};
        u(i) = value[dofs.component(i)];
      }
    u.compress(VectorOperation::insert);
    return u;
  }

  /** The friction column @p column of the last evaluate() (-1 if none). */
  double
  friction_column(const RigidImpactor<3> &sphere, const std::string &column)
  {
    for (const auto &[name, value] : sphere.friction_columns())
      if (name == column)
        return value;
    return -1;
  }

  /** The sum of the nodes' friction forces of the last evaluate(). */
  double
  friction_sum(const RigidImpactor<3> &sphere)
  {
    return friction_column(sphere, "friction_force_sum");
  }

  /** The friction history of the intact layer handed to the cracked one. */
  void
  check_split_friction(const TiedCopyDoFs<3> &intact,
                       const TiedCopyDoFs<3> &cracked)
  {
    parameters::Impactor with_friction = deep_impactor(false);
    with_friction.friction             = 0.3;
    RigidImpactor<3> before(with_friction, MPI_COMM_WORLD);
    before.setup(intact);
    TrilinosVector u = smooth_field(intact), force(u), zero(u);
    zero             = 0;
    before.evaluate(zero, force);
    before.commit();
    u *= 0.25;
    before.evaluate(u, force);
    before.commit();

    RigidImpactor<3> after(with_friction, MPI_COMM_WORLD);
    after.setup(cracked);
    after.inherit_friction_state(before.friction_state());
    TrilinosVector v = smooth_field(cracked), split_force(v);
    v *= 0.25;
    after.evaluate(v, split_force);
    const double sum = friction_sum(before);
    std::cout << "split with friction: " << before.contact_nodes() << " and "
              << after.contact_nodes() << " nodes touch, friction sums " << sum
              << " and " << friction_sum(after) << ", energy "
              << before.contact_energy() << " and " << after.contact_energy()
              << std::endl;
    CHECK(after.contact_nodes() == 12);
    CHECK(sum > 0);
    CHECK_CLOSE(friction_sum(after), sum, 1e-12 * sum);
    CHECK_CLOSE(after.contact_energy(),
                before.contact_energy(),
                1e-12 * before.contact_energy());
    CHECK((after.force_on_laminate() - before.force_on_laminate()).norm()
          < 1e-12 * before.force_on_laminate().norm());

    std::mt19937                           random(11);
    std::uniform_real_distribution<double> small(-0.01, 0.01);
    for (const auto i : cracked.locally_owned_dofs())
      v(i) += small(random);
    v.compress(VectorOperation::add);
    after.evaluate(v, split_force);
    after.commit();
    RigidImpactor<3> resumed(with_friction, MPI_COMM_WORLD);
    resumed.setup(cracked);
    resumed.set_friction_state(after.friction_state());
    for (const auto i : cracked.locally_owned_dofs())
      v(i) += small(random);
    v.compress(VectorOperation::add);
    TrilinosVector resumed_force(v);
    after.evaluate(v, split_force);
    resumed.evaluate(v, resumed_force);
    resumed_force -= split_force;
    std::cout << "resumed on the cracked layer: |force - original| "
              << resumed_force.linfty_norm() << " of "
              << split_force.linfty_norm() << std::endl;
    CHECK(split_force.linfty_norm() > 0);
    CHECK(resumed_force.linfty_norm() == 0);
  }

  /** The sphere on the intact block and on the block cracked along
   * x = 0.5 through its top face. */
  void
  check_split_nodes(const Triangulation<3> &tria)
  {
    TiedCopyDoFs<3> intact(tria, 1), cracked(tria, 1);
    intact.distribute();
    cracked.distribute([](const auto &cell, const unsigned int f) {
      return std::abs(cell->face(f)->center()[0] - 0.5) < 1e-12;
    });
    CHECK(cracked.n_dofs() > intact.n_dofs());
    std::array<double, 2>                        energy;
    std::array<Tensor<1, 3>, 2>                  force;
    std::array<unsigned int, 2>                  nodes;
    const std::array<const TiedCopyDoFs<3> *, 2> layers = {{&intact, &cracked}};
    for (unsigned int k = 0; k < 2; ++k)
      {
        RigidImpactor<3> sphere(deep_impactor(false), MPI_COMM_WORLD);
        sphere.setup(*layers[k]);
        const TrilinosVector u = smooth_field(*layers[k]);
        TrilinosVector       contact(u);
        sphere.evaluate(u, contact);
        energy[k] = sphere.contact_energy();
        force[k]  = sphere.force_on_laminate();
        nodes[k]  = sphere.contact_nodes();
      }
    std::cout << "split: " << nodes[0] << " and " << nodes[1]
              << " nodes touch, energy " << energy[0] << " and " << energy[1]
              << ", force " << force[0] << " and " << force[1] << std::endl;
    CHECK(nodes[0] == 9 && nodes[1] == 12);
    CHECK(energy[0] > 0);
    CHECK_CLOSE(energy[1], energy[0], 1e-14 * energy[0]);
    CHECK((force[1] - force[0]).norm() < 1e-14 * force[0].norm());
    check_split_friction(intact, cracked);
  }

  /** The frictionless, sticking and sliding tangents of a sphere or of
   * the cylinder against central differences. */
  void
  check_impactor(const TiedCopyDoFs<3> &dofs,
                 const TrilinosVector  &u,
                 const TrilinosVector  &d,
                 const bool             cylinder)
  {
    const std::string shape = cylinder ? "cylinder " : "sphere ";
    const IndexSet   &owned = dofs.locally_owned_dofs();
    {
      RigidImpactor<3> sphere(deep_impactor(cylinder), MPI_COMM_WORLD);
      sphere.setup(dofs);
      TrilinosVector force(u);
      sphere.evaluate(u, force);
      CHECK(sphere.contact_nodes() == 9);
      CHECK(tangent_error(dofs, sphere, u, d, shape + "frictionless") < 1e-6);
    }
    // Friction: the history committed in the undeformed state (every node
    // in contact without a tangential force). Sticking (mu = 0.3): committed
    // again after a quarter of the random field (every node sticks with a
    // tangential force), then moved by a millionth more. Sliding (mu = 0.1):
    // moved by the random field and 0.1 mm along x.
    for (const double shift : {0., 0.1})
      {
        parameters::Impactor with_friction = deep_impactor(cylinder);
        with_friction.friction             = shift == 0 ? 0.3 : 0.1;
        RigidImpactor<3> sphere(with_friction, MPI_COMM_WORLD);
        sphere.setup(dofs);
        TrilinosVector force(u), moved(u);
        moved = 0;
        sphere.evaluate(moved, force);
        sphere.commit();
        moved = u;
        if (shift == 0)
          {
            moved *= 0.25;
            sphere.evaluate(moved, force);
            sphere.commit();
            moved.add(1e-6, u);
          }
        for (const auto i : owned)
          if (dofs.component(i) == 0)
            moved(i) += shift;
        moved.compress(VectorOperation::add);
        sphere.evaluate(moved, force);
        CHECK(sphere.contact_nodes() == 9);
        const auto columns = sphere.friction_columns();
        double     sliding = -1;
        for (const auto &[name, value] : columns)
          if (name == "sliding_nodes")
            sliding = value;
        std::cout << sliding << " of 9 nodes slide" << std::endl;
        CHECK(sliding == (shift == 0 ? 0 : 9));
        CHECK(tangent_error(dofs,
                            sphere,
                            moved,
                            d,
                            shape + (shift == 0 ? "sticking" : "sliding"))
              < 1e-6);
      }
  }
  /** The block @p dofs sheared along x, u_x = shift + a y, plus b beyond
   * the plane x = 0.5 and -b before it (a crack there: each copy of a
   * split node takes its own cell's side). */
  TrilinosVector
  sheared(const TiedCopyDoFs<3> &dofs,
          const double           a,
          const double           b,
          const double           shift = 0)
  {
    const IndexSet                      &owned = dofs.locally_owned_dofs();
    TrilinosVector                       u(owned, MPI_COMM_WORLD);
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        dofs.get_dof_indices(cell, indices);
        const double offset = cell->center()[0] > 0.5 ? b : -b;
        for (const auto i : indices)
          if (owned.is_element(i) && dofs.component(i) == 0)
            u(i) = shift + a * dofs.support_point(i)[1] + offset;
      }
    u.compress(VectorOperation::insert);
    return u;
  }

  /** A cylinder along x with friction (mu = 1, explicit mode: every
   * evaluation commits). */
  parameters::Impactor
  sticking_cylinder()
  {
    parameters::Impactor p = deep_impactor(true);
    p.axis                 = {1, 0, 0};
    p.prescribed           = false;
    p.friction             = 1;
    return p;
  }

  double
  friction_dissipation(const RigidImpactor<3> &sphere)
  {
    return friction_column(sphere, "impactor_friction_dissipation");
  }

  /** @p carried (its history moved through mesh changes) against an
   * impactor set up on @p dofs and moved the same way, to @p u. */
  void
  compare_with_fresh(RigidImpactor<3>      &carried,
                     const TiedCopyDoFs<3> &dofs,
                     const TrilinosVector  &u,
                     const std::string     &label)
  {
    TrilinosVector force(u), fresh_force(u), zero(u);
    zero = 0;
    carried.evaluate(u, force);
    RigidImpactor<3> fresh(sticking_cylinder(), MPI_COMM_WORLD);
    fresh.setup(dofs);
    fresh.evaluate(zero, fresh_force);
    fresh.evaluate(u, fresh_force);
    TrilinosVector difference = force;
    difference -= fresh_force;
    std::cout << label << ": " << carried.contact_nodes() << " nodes touch ("
              << fresh.contact_nodes() << "), friction sum "
              << friction_sum(carried) << " (" << friction_sum(fresh)
              << "), contact energy " << carried.contact_energy() << " ("
              << fresh.contact_energy() << "), |force - fresh| "
              << difference.linfty_norm() << " of " << force.linfty_norm()
              << ", dissipation " << friction_dissipation(carried) << std::endl;
    CHECK(carried.contact_nodes() == fresh.contact_nodes());
    CHECK(friction_sum(fresh) > 0);
    CHECK(difference.linfty_norm() < 1e-12 * force.linfty_norm());
    CHECK_CLOSE(friction_sum(carried),
                friction_sum(fresh),
                1e-12 * friction_sum(fresh));
    CHECK_CLOSE(carried.contact_energy(),
                fresh.contact_energy(),
                1e-12 * fresh.contact_energy());
    CHECK(std::abs(friction_dissipation(carried))
          < 1e-12 * fresh.contact_energy());
    CHECK(std::abs(friction_dissipation(fresh))
          < 1e-12 * fresh.contact_energy());
  }

  /** A flat cylinder along x (radius 100, 0.2 into the block's middle)
   * with mu = 0.01, on the block cracked along x = 0.5 (see the file
   * header). */
  void
  check_mesh_change_after_slip()
  {
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_rectangle(
      tria, {2, 2, 1}, Point<3>(), Point<3>(1, 1, 1), true);
    TiedCopyDoFs<3> dofs(tria, 1);
    const auto      distribute = [&]() {
      dofs.distribute([](const auto &cell, const unsigned int f) {
        return std::abs(cell->face(f)->center()[0] - 0.5) < 1e-12;
      });
    };
    distribute();
    parameters::Impactor p = sticking_cylinder();
    p.radius               = 100;
    p.center               = {0.5, 0.5, 100.8};
    p.friction             = 0.01;
    // Slid by 0.01 (every node slides: its stick stretch is at most
    // mu |g| = 0.002), the two sides of the crack 4e-4 apart; then back by
    // 5e-4 and sheared by 1e-4 y, sticking.
    const auto slide = [&]() { return sheared(dofs, 0, 2e-4, 0.01); };
    const auto stick = [&]() { return sheared(dofs, 1e-4, 2e-4, 0.0095); };
    const auto moved = [&](RigidImpactor<3> &sphere, const TrilinosVector &u) {
      TrilinosVector force(u);
      sphere.evaluate(u, force);
      return force;
    };
    RigidImpactor<3> carried(p, MPI_COMM_WORLD);
    carried.setup(dofs);
    moved(carried, sheared(dofs, 0, 0));
    moved(carried, slide());
    const double slid = friction_sum(carried);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    distribute();
    carried.setup(dofs);
    RigidImpactor<3> fine(p, MPI_COMM_WORLD);
    fine.setup(dofs);
    moved(fine, sheared(dofs, 0, 0));
    moved(fine, slide());
    // The friction forces (along x; the normal ones are the same).
    const TrilinosVector on_carried = moved(carried, stick());
    const TrilinosVector on_fine    = moved(fine, stick());
    double               difference = 0, largest = 0;
    for (const auto i : dofs.locally_owned_dofs())
      if (dofs.component(i) == 0)
        {
          difference
            = std::max(difference, std::abs(on_carried(i) - on_fine(i)));
          largest = std::max(largest, std::abs(on_fine(i)));
        }
    std::cout << "cracked, slid then refined: friction sum " << slid
              << " sliding, then " << friction_sum(carried) << " ("
              << friction_sum(fine) << " on the fine mesh from the start), "
              << "|friction force - fine| " << difference << " of " << largest
              << std::endl;
    CHECK(slid > 0);
    CHECK(difference < 1e-2 * largest);
    CHECK_CLOSE(friction_sum(carried),
                friction_sum(fine),
                1e-2 * friction_sum(fine));
  }

  /** The stick springs through refinement and coarsening (see the file
   * header), on the intact block or on the block cracked along x = 0.5. */
  void
  check_mesh_change(const bool cracked)
  {
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_rectangle(
      tria, {2, 2, 1}, Point<3>(), Point<3>(1, 1, 1), true);
    TiedCopyDoFs<3> dofs(tria, 1);
    const auto      distribute = [&]() {
      if (cracked)
        dofs.distribute([](const auto &cell, const unsigned int f) {
          return std::abs(cell->face(f)->center()[0] - 0.5) < 1e-12;
        });
      else
        dofs.distribute();
    };
    distribute();
    const double      a = 1e-3, b = cracked ? 2e-4 : 0.;
    const std::string name = cracked ? "cracked, " : "";
    RigidImpactor<3>  carried(sticking_cylinder(), MPI_COMM_WORLD);
    carried.setup(dofs);
    TrilinosVector force(sheared(dofs, 0, 0));
    carried.evaluate(sheared(dofs, 0, 0), force);
    compare_with_fresh(carried, dofs, sheared(dofs, a, b), name + "before");
    for (const bool refine : {true, false})
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (refine)
            cell->set_refine_flag();
          else
            cell->set_coarsen_flag();
        tria.execute_coarsening_and_refinement();
        distribute();
        carried.setup(dofs);
        compare_with_fresh(carried,
                           dofs,
                           sheared(dofs, a, b),
                           name + (refine ? "refined" : "coarsened"));
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Triangulation<3>                 tria;
  GridGenerator::subdivided_hyper_rectangle(
    tria, {2, 2, 1}, Point<3>(), Point<3>(1, 1, 1), true);
  TiedCopyDoFs<3> dofs(tria, 1);
  dofs.distribute();

  const IndexSet &owned = dofs.locally_owned_dofs();
  TrilinosVector  u(owned, MPI_COMM_WORLD), d(owned, MPI_COMM_WORLD);
  std::mt19937    random(7);
  std::uniform_real_distribution<double> small(-0.02, 0.02), unit(-1, 1);
  for (const auto i : owned)
    u(i) = small(random), d(i) = unit(random);
  u.compress(VectorOperation::insert);
  d.compress(VectorOperation::insert);

  for (const bool cylinder : {false, true})
    check_impactor(dofs, u, d, cylinder);
  check_split_nodes(tria);
  check_mesh_change(false);
  check_mesh_change(true);
  check_mesh_change_after_slip();
  return amfrac_test::summary();
}

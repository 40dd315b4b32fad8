// Hoffman plasticity with total Lagrangian kinematics: PlasticPlies with
// finite strain on top of the St Venant-Kirchhoff bulk, on the two plies
// of two_plies.h (3D and plane strain, Q1 and Q2), the lower +30 degree
// ply plastic with hardening, the upper -30 degree ply elastic:
//   - below yield, the plastic correction adds nothing at all to the
//     total Lagrangian residual and tangent (the tangent compared by its
//     product with a random direction);
//   - a yielded state turned rigidly by 60 degrees keeps its stored
//     energy and yields no further (no plastic work), and a little more
//     stretch in the turned frame yields again;
//   - loading further in the rotated frame (every point of the plastic
//     ply yielding) and unloading elastically from there (every point
//     yielded before, none now: the geometric term of the plastic stress
//     alone), the tangent is the derivative of the residual (central
//     differences along a random direction), and the tangent product
//     equals the assembled correction times the direction;
//   - unloading, the residual is the derivative of the stored energy
//     int (E - E_p) : C : (E - E_p) / 2.
#include "../check.h"
#include "two_plies.h"

#include <amfrac/assembly/plastic_plies.h>
#include <amfrac/assembly/total_lagrangian.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <random>

using namespace amfrac;

namespace
{
  using Vector = TrilinosWrappers::MPI::Vector;
  using Matrix = TrilinosWrappers::SparseMatrix;
  using amfrac_test::ghosted;
  using amfrac_test::plastic_ply;
  using amfrac_test::rotation;
  using amfrac_test::writable_ghosts;

  template <int dim>
  struct Setup
  {
    amfrac_test::TwoPlies<dim>    mesh;
    TotalLagrangianAssembler<dim> bulk;
    PlasticPlies<dim>             plastic;
    AffineConstraints<double>     none;
    Matrix                        tangent;

    explicit Setup(const unsigned int degree)
      : mesh(degree, {plastic_ply<dim>(30, true), plastic_ply<dim>(-30, false)})
      , bulk(*mesh.dofs, mesh.plies)
      , plastic(*mesh.dofs, mesh.plies, true)
    {
      plastic.setup();
      none.close();
      const auto                       &dofs = *mesh.dofs;
      TrilinosWrappers::SparsityPattern pattern(dofs.locally_owned_dofs(),
                                                dofs.locally_owned_dofs(),
                                                dofs.locally_relevant_dofs(),
                                                MPI_COMM_WORLD);
      ElasticAssembler<dim>(dofs, mesh.plies).add_couplings(none, pattern);
      pattern.compress();
      tangent.reinit(pattern);
    }

    /** R(u) = F_int(u) + the plastic correction; with @p with_tangent
     * K_T into tangent. Returns the stored energy. */
    double
    residual(const Vector &u, Vector &R, const bool with_tangent = false)
    {
      const auto  &dofs     = *mesh.dofs;
      const Vector relevant = ghosted(dofs, u);
      Vector       force    = writable_ghosts(dofs);
      const double elastic  = bulk.assemble(
        relevant, none, R, nullptr, with_tangent ? &tangent : nullptr);
      CHECK(plastic.add_correction(
        relevant, none, force, with_tangent ? &tangent : nullptr));
      force.compress(VectorOperation::add);
      R += force;
      return elastic + plastic.stored_energy_correction(relevant);
    }
  };

  /** u = R x - X for x = X + a uniaxial stretch along x of @p strain and
   * a smooth field of amplitude @p noise (so that every point has a
   * general strain): the stretched state turned by the rotation @p R; and
   * a random direction @p d (the same for every call). */
  template <int dim>
  void
  deform(const TiedCopyDoFs<dim> &dofs,
         const double             strain,
         const double             noise,
         const Tensor<2, dim>    &R,
         Vector                  &u,
         Vector                  &d)
  {
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (const auto i : dofs.locally_owned_dofs())
      {
        const Point<dim>  &X = dofs.support_point(i);
        const unsigned int c = dofs.component(i);
        Point<dim>         x = X;
        x[0] += strain * X[0];
        for (unsigned int k = 0; k < dim; ++k)
          x[k] += noise * std::sin(7 * X[0] + 3 * k + 5 * X[dim - 1]);
        u(i) = (R * x)[c] - X[c];
        d(i) = uniform(random);
      }
    u.compress(VectorOperation::insert);
    d.compress(VectorOperation::insert);
  }

  /** At @p u along @p d: K_T d against central differences of the
   * residual, and the plastic tangent product plus the bulk's against
   * K_T d. */
  template <int dim>
  void
  check_tangent(Setup<dim> &setup, const Vector &u, const Vector &d)
  {
    const TiedCopyDoFs<dim> &dofs = *setup.mesh.dofs;
    Vector                   R(u), KTd(u), Rp(u), Rm(u), up(u), um(u), F(u);
    setup.residual(u, R, true);
    setup.tangent.vmult(KTd, d);
    const double h = 1e-7;
    up.add(h, d);
    um.add(-h, d);
    setup.residual(up, Rp);
    setup.residual(um, Rm);
    Vector difference(Rp);
    difference -= Rm;
    difference /= 2 * h;
    difference -= KTd;
    std::cout << "  |K_T d| = " << KTd.l2_norm()
              << ", |FD - K_T d| = " << difference.l2_norm() << std::endl;
    CHECK(difference.l2_norm() < 1e-6 * KTd.l2_norm());
    // The tangent product is the correction's part of the same operator.
    Vector product = writable_ghosts(dofs);
    setup.plastic.add_tangent_product(ghosted(dofs, u),
                                      ghosted(dofs, d),
                                      product);
    product.compress(VectorOperation::add);
    Vector bulk_d(u);
    setup.bulk.assemble(
      ghosted(dofs, u), setup.none, F, nullptr, &setup.tangent);
    setup.tangent.vmult(bulk_d, d);
    product += bulk_d;
    product -= KTd;
    CHECK(product.l2_norm() < 1e-12 * KTd.l2_norm());
  }

  template <int dim>
  void
  check(const unsigned int degree)
  {
    Setup<dim>               setup(degree);
    const TiedCopyDoFs<dim> &dofs    = *setup.mesh.dofs;
    auto                    &plastic = setup.plastic;
    const Tensor<2, dim>     I       = unit_symmetric_tensor<dim>();
    const Tensor<2, dim>     turn    = rotation<dim>(std::acos(0.5));
    Vector u(dofs.locally_owned_dofs(), MPI_COMM_WORLD), d(u), R(u), F(u);

    // Below yield: exactly the total Lagrangian bulk, residual and tangent.
    deform(dofs, 1e-4, 1e-6, turn, u, d);
    const double energy = setup.residual(u, R, true);
    Vector       KTd(u), Kd(u);
    setup.tangent.vmult(KTd, d);
    setup.bulk.assemble(
      ghosted(dofs, u), setup.none, F, nullptr, &setup.tangent);
    setup.tangent.vmult(Kd, d);
    KTd -= Kd;
    CHECK(KTd.linfty_norm() == 0);
    F -= R;
    CHECK(F.linfty_norm() == 0);
    CHECK(energy > 0);
    CHECK(plastic.commit(ghosted(dofs, u), ghosted(dofs, u)) == 0);
    CHECK(plastic.yielding_points() == 0);

    // A plastic step, unrotated, then the same state turned by 60
    // degrees: no further yield, the same stored energy.
    Vector zero(u), stretched(u), turned(u);
    zero = 0;
    deform(dofs, 0.02, 1e-4, I, stretched, d);
    const double work
      = plastic.commit(ghosted(dofs, stretched), ghosted(dofs, zero));
    CHECK(plastic.yielding_points() == 2 * plastic.n_points());
    CHECK(work > 0);
    const double kappa = plastic.max_kappa();
    deform(dofs, 0.02, 1e-4, turn, turned, d);
    const double before = setup.residual(stretched, R);
    const double after  = setup.residual(turned, R);
    std::cout << "  dim " << dim << ", Q" << degree << ": stored energy "
              << before << " stretched, " << after << " turned by 60 degrees"
              << std::endl;
    CHECK_CLOSE(after / before, 1., 1e-10);
    CHECK(plastic.commit(ghosted(dofs, turned), ghosted(dofs, stretched)) == 0);
    CHECK(plastic.yielding_points() == 0);
    CHECK(plastic.max_kappa() == kappa);
    // A little more stretch in the turned frame yields everywhere again.
    Vector further(u);
    deform(dofs, 0.021, 1e-4, turn, further, d);
    CHECK(plastic.commit(ghosted(dofs, further), ghosted(dofs, turned)) > 0);
    CHECK(plastic.yielding_points() == 2 * plastic.n_points());

    // Loading further, turned (every point of the plastic ply yields):
    // the tangent.
    deform(dofs, 0.025, 1e-4, turn, u, d);
    check_tangent(setup, u, d);

    // Unloading (elastic), turned: R = dW/du, and the tangent of points
    // that have yielded but respond elastically (the geometric term of
    // their plastic stress only).
    deform(dofs, 0.018, 1e-4, turn, u, d);
    check_tangent(setup, u, d);
    setup.residual(u, R);
    Vector up(u), um(u), Rp(u), Rm(u);
    up.add(1e-7, d);
    um.add(-1e-7, d);
    const double slope
      = (setup.residual(up, Rp) - setup.residual(um, Rm)) / 2e-7;
    std::cout << "  dW/du d = " << slope << ", R . d = " << R * d << std::endl;
    CHECK_CLOSE(slope / (R * d), 1., 1e-6);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {1u, 2u})
    {
      check<2>(degree);
      check<3>(degree);
    }
  return amfrac_test::summary();
}

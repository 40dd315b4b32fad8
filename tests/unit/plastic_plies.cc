// Hoffman plasticity of the plies on the Newton path (PlasticPlies), on
// two plies at +30 / -30 degrees (3D and plane strain, Q1 and Q2) whose
// interface nodes are duplicated, the lower ply plastic with hardening,
// the upper elastic:
//   - a state below yield adds nothing at all to the residual or the
//     tangent (the elastic result bit for bit);
//   - after a plastic step is committed, the tangent K + K_p is the
//     derivative of the residual K u + f_p (central differences along a
//     random direction, loading further: every point plastic), and the
//     tangent product equals the assembled tangent times the direction;
//   - unloading elastically from there, the residual is the derivative of
//     the stored energy u.K u / 2 + the plastic correction;
//   - the plastic work of a step is positive and the history field
//     survives gather_field() / set_field() and owned_values() /
//     set_cell_values() unchanged.
#include "../check.h"
#include "two_plies.h"

#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/assembly/plastic_plies.h>
#include <amfrac/material/orthotropic.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <random>

using namespace amfrac;

namespace
{
  using Vector = TrilinosWrappers::MPI::Vector;
  using Matrix = TrilinosWrappers::SparseMatrix;
  using amfrac_test::ghosted;
  using amfrac_test::writable_ghosts;

  /** The two plies of the tests, the lower one plastic. */
  template <int dim>
  struct TwoPlies : amfrac_test::TwoPlies<dim>
  {
    explicit TwoPlies(const unsigned int degree)
      : amfrac_test::TwoPlies<dim>(degree,
                                   {amfrac_test::plastic_ply<dim>(30, true),
                                    amfrac_test::plastic_ply<dim>(-30, false)})
    {}
  };

  /** The elastic bulk K and a matrix of its pattern. */
  template <int dim>
  void
  bulk_matrices(const TwoPlies<dim> &mesh, Matrix &K, Matrix &tangent)
  {
    AffineConstraints<double> none;
    none.close();
    ElasticAssembler<dim> assembler(*mesh.dofs, mesh.plies);
    assembler.reinit_matrix(none, K);
    assembler.assemble_matrix(none, K);
    assembler.reinit_matrix(none, tangent);
  }

  /** R(u) = K u + f_p(u), and with @p tangent K + K_p. */
  template <int dim>
  void
  residual(const TiedCopyDoFs<dim> &dofs,
           PlasticPlies<dim>       &plastic,
           const Matrix            &K,
           const Vector            &u,
           Vector                  &R,
           Matrix                  *tangent = nullptr)
  {
    AffineConstraints<double> none;
    none.close();
    const Vector relevant = ghosted(dofs, u);
    Vector       force    = writable_ghosts(dofs);
    if (tangent)
      tangent->copy_from(K);
    CHECK(plastic.add_correction(relevant, none, force, tangent));
    force.compress(VectorOperation::add);
    K.vmult(R, u);
    R += force;
  }

  /** A uniaxial stretch along x of @p strain, plus a random part of
   * @p noise, and a random direction. */
  template <int dim>
  void
  stretch(const TiedCopyDoFs<dim> &dofs,
          const double             strain,
          const double             noise,
          Vector                  &u,
          Vector                  &d)
  {
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (const auto i : dofs.locally_owned_dofs())
      {
        const Point<dim> &X = dofs.support_point(i);
        u(i)                = (dofs.component(i) == 0 ? strain * X[0] : 0.)
               + noise * uniform(random);
        d(i) = uniform(random);
      }
    u.compress(VectorOperation::insert);
    d.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  check(const unsigned int degree)
  {
    TwoPlies<dim>            mesh(degree);
    const TiedCopyDoFs<dim> &dofs = *mesh.dofs;
    PlasticPlies<dim>        plastic(dofs, mesh.plies);
    plastic.setup();
    Matrix K, KT;
    bulk_matrices(mesh, K, KT);
    Vector u(dofs.locally_owned_dofs(), MPI_COMM_WORLD), d(u), R(u), Ku(u);

    // Below yield: exactly K u and K.
    stretch(dofs, 1e-4, 1e-6, u, d);
    residual(dofs, plastic, K, u, R, &KT);
    K.vmult(Ku, u);
    Ku -= R;
    CHECK(Ku.linfty_norm() == 0);
    CHECK(plastic.tangent_unchanged());
    KT.add(-1., K);
    CHECK(KT.frobenius_norm() == 0);
    CHECK(plastic.commit(ghosted(dofs, u), ghosted(dofs, u)) == 0);
    CHECK(plastic.yielding_points() == 0);

    // A plastic step: yields everywhere in the lower ply.
    Vector zero(u);
    zero = 0;
    stretch(dofs, 0.02, 1e-4, u, d);
    const double work = plastic.commit(ghosted(dofs, u), ghosted(dofs, zero));
    CHECK(plastic.yielding_points() == 2 * plastic.n_points());
    CHECK(work > 0);
    CHECK(plastic.max_kappa() > 0);

    // Loading further: FD of the residual against the tangent.
    stretch(dofs, 0.025, 1e-4, u, d);
    residual(dofs, plastic, K, u, R, &KT);
    CHECK(!plastic.tangent_unchanged());
    plastic.mark_factorized();
    Vector KTd(u), Rp(u), Rm(u), up(u), um(u);
    KT.vmult(KTd, d);
    const double h = 1e-8;
    up.add(h, d);
    um.add(-h, d);
    residual(dofs, plastic, K, up, Rp);
    residual(dofs, plastic, K, um, Rm);
    Vector difference(Rp);
    difference -= Rm;
    difference /= 2 * h;
    difference -= KTd;
    std::cout << "  dim " << dim << ", Q" << degree
              << ": |K_T d| = " << KTd.l2_norm()
              << ", |FD - K_T d| = " << difference.l2_norm() << std::endl;
    CHECK(difference.l2_norm() < 1e-6 * KTd.l2_norm());
    // The tangent product is the same operator.
    Vector product = writable_ghosts(dofs);
    plastic.add_tangent_product(ghosted(dofs, u), ghosted(dofs, d), product);
    product.compress(VectorOperation::add);
    Vector Kd(u);
    K.vmult(Kd, d);
    product += Kd;
    product -= KTd;
    CHECK(product.l2_norm() < 1e-12 * KTd.l2_norm());

    // Unloading (elastic): R = dE/du.
    stretch(dofs, 0.018, 1e-4, u, d);
    residual(dofs, plastic, K, u, R, &KT);
    // Elastic now, but the factorized tangent was plastic.
    CHECK(!plastic.tangent_unchanged());
    plastic.mark_factorized();
    CHECK(plastic.tangent_unchanged());
    const auto energy = [&](const Vector &v) {
      Vector Kv(v);
      K.vmult(Kv, v);
      return 0.5 * (Kv * v)
             + plastic.stored_energy_correction(ghosted(dofs, v));
    };
    up = u, um = u;
    up.add(1e-7, d);
    um.add(-1e-7, d);
    const double slope = (energy(up) - energy(um)) / 2e-7;
    std::cout << "  dE/du d = " << slope << ", R . d = " << R * d << std::endl;
    CHECK_CLOSE(slope / (R * d), 1., 1e-6);
    CHECK(energy(u) > 0);

    // The history through its two serializations.
    const auto        field = plastic.gather_field();
    const auto        owned = plastic.owned_values();
    PlasticPlies<dim> copy(dofs, mesh.plies), copy2(dofs, mesh.plies);
    copy.setup();
    copy.set_field(field);
    CHECK(copy.gather_field() == field);
    copy2.setup();
    unsigned int c     = 0;
    const auto   width = plastic.n_points() * PlasticPlies<dim>::n_components;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        copy2.set_cell_values(cell, owned.data() + width * c++);
    CHECK(copy2.owned_values() == owned);

    // Loading again beyond the last plastic state: every point of the
    // plastic ply yields, none of the elastic one is visited.
    Vector previous(u);
    stretch(dofs, 0.03, 1e-4, u, d);
    plastic.commit(ghosted(dofs, u), ghosted(dofs, previous));
    CHECK(plastic.yielding_points() == 2 * plastic.n_points());
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(1);
  check<2>(2);
  check<3>(1);
  check<3>(2);
  return amfrac_test::summary();
}

// Total Lagrangian kinematics of the plies (St Venant-Kirchhoff):
//   - at a point, a rigid rotation gives no strain and no stress, and a
//     rotation superposed on a stretch leaves E and S unchanged and
//     rotates P;
//   - the internal force is the derivative of the strain energy and the
//     tangent the derivative of the internal force (central differences
//     along a random direction, at a state with a 60 degree rotation, on
//     Q1 and Q2 meshes of two orthotropic plies at +-30 degrees whose
//     interface nodes are duplicated), and the tangent is symmetric;
//   - for small displacements the internal force is K u of small-strain
//     elasticity;
//   - the Zienkiewicz-Zhu estimate of a total Lagrangian run (stress S of
//     the Green-Lagrange strain) is objective: a non-uniform state turned
//     by 60 degrees has the same cell errors and norm to round-off, where
//     the small-strain estimate of the turned state changes.
#include "../check.h"
#include "two_plies.h"

#include <amfrac/adaptivity/error_estimator.h>
#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/assembly/total_lagrangian.h>
#include <amfrac/material/orthotropic.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <random>

using namespace amfrac;

namespace
{
  using amfrac_test::ply_stiffness;
  using amfrac_test::restrict;
  using amfrac_test::rotation;
  using amfrac_test::TwoPlies;

  template <int dim>
  void
  check_point()
  {
    const SymmetricTensor<4, dim> C = restrict<dim>(ply_stiffness(30));
    const Tensor<2, dim>          R = rotation<dim>(1.2);
    const FiniteStrainPoint<dim>  rigid(R - unit_symmetric_tensor<dim>(), C);
    CHECK(rigid.S.norm() < 1e-10);
    CHECK(rigid.P.norm() < 1e-10);
    CHECK(std::abs(rigid.energy_density) < 1e-20);

    Tensor<2, dim> U = unit_symmetric_tensor<dim>();
    U[0][0] += 0.02, U[0][dim - 1] += 0.01, U[dim - 1][0] += 0.01;
    const FiniteStrainPoint<dim> stretch(U - unit_symmetric_tensor<dim>(), C);
    const FiniteStrainPoint<dim> rotated(R * U - unit_symmetric_tensor<dim>(),
                                         C);
    CHECK((rotated.E - stretch.E).norm() < 1e-14);
    CHECK((rotated.S - stretch.S).norm() < 1e-9 * stretch.S.norm());
    CHECK((rotated.P - R * stretch.P).norm() < 1e-9 * stretch.P.norm());
    CHECK_CLOSE(rotated.energy_density / stretch.energy_density, 1., 1e-12);
  }

  using Vector = TrilinosWrappers::MPI::Vector;
  using Matrix = TrilinosWrappers::SparseMatrix;

  template <int dim>
  void
  reinit_matrix(const TiedCopyDoFs<dim> &dofs, Matrix &matrix)
  {
    AffineConstraints<double> none;
    none.close();
    TrilinosWrappers::SparsityPattern pattern(dofs.locally_owned_dofs(),
                                              dofs.locally_owned_dofs(),
                                              dofs.locally_relevant_dofs(),
                                              MPI_COMM_WORLD);
    ElasticAssembler<dim>(dofs, std::vector<PlyProperties<dim>>())
      .add_couplings(none, pattern);
    pattern.compress();
    matrix.reinit(pattern);
  }

  template <int dim>
  void
  check_derivatives(const unsigned int degree)
  {
    TwoPlies<dim>                 mesh(degree);
    const TiedCopyDoFs<dim>      &dofs = *mesh.dofs;
    TotalLagrangianAssembler<dim> assembler(dofs, mesh.plies);
    AffineConstraints<double>     none;
    none.close();
    Matrix K;
    reinit_matrix(dofs, K);

    // A 60 degree rotation with a few percent of strain on top, and a
    // random direction.
    const Tensor<2, dim>                   R = rotation<dim>(std::acos(0.5));
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> uniform(-1, 1);
    Vector u(dofs.locally_owned_dofs(), MPI_COMM_WORLD), d(u), f(u), fp(u),
      fm(u), Kd(u);
    for (const auto i : dofs.locally_owned_dofs())
      {
        const Point<dim>  &X = dofs.support_point(i);
        const unsigned int c = dofs.component(i);
        u(i)                 = (R * X)[c] - X[c] + 0.03 * uniform(random);
        d(i)                 = uniform(random);
      }
    u.compress(VectorOperation::insert);
    d.compress(VectorOperation::insert);

    const double W = assembler.assemble(u, none, f, nullptr, &K);
    CHECK(W > 0);
    K.vmult(Kd, d);
    const double h = 1e-6;
    Vector       up(u), um(u);
    up.add(h, d);
    um.add(-h, d);
    const double Wp = assembler.assemble(up, none, fp, nullptr, nullptr);
    const double Wm = assembler.assemble(um, none, fm, nullptr, nullptr);
    // dW/du . d = f . d.
    CHECK_CLOSE((Wp - Wm) / (2 * h) / (f * d), 1., 1e-6);
    // dF/du d = K d.
    Vector difference(fp);
    difference -= fm;
    difference /= 2 * h;
    difference -= Kd;
    std::cout << "  dim " << dim << ", Q" << degree
              << ": |K d| = " << Kd.l2_norm()
              << ", |FD - K d| = " << difference.l2_norm() << std::endl;
    CHECK(difference.l2_norm() < 1e-6 * Kd.l2_norm());
    // Symmetric: d2 . K d = d . K d2.
    Vector d2(d), Kd2(d);
    for (const auto i : dofs.locally_owned_dofs())
      d2(i) = uniform(random);
    d2.compress(VectorOperation::insert);
    K.vmult(Kd2, d2);
    CHECK_CLOSE((d2 * Kd) / (d * Kd2), 1., 1e-12);
  }

  /** Small displacements: F_int(u) = K u + O(u^2). */
  template <int dim>
  void
  check_small_strain_limit()
  {
    TwoPlies<dim>             mesh(2);
    const TiedCopyDoFs<dim>  &dofs = *mesh.dofs;
    AffineConstraints<double> none;
    none.close();
    Matrix K;
    reinit_matrix(dofs, K);
    ElasticAssembler<dim>(dofs, mesh.plies).assemble_matrix(none, K);
    std::mt19937                           random(3);
    std::uniform_real_distribution<double> uniform(-1, 1);
    Vector u(dofs.locally_owned_dofs(), MPI_COMM_WORLD), f(u), Ku(u);
    for (const auto i : dofs.locally_owned_dofs())
      u(i) = 1e-7 * uniform(random);
    u.compress(VectorOperation::insert);
    TotalLagrangianAssembler<dim>(dofs, mesh.plies)
      .assemble(u, none, f, nullptr, nullptr);
    K.vmult(Ku, u);
    f -= Ku;
    CHECK(f.l2_norm() < 1e-5 * Ku.l2_norm());
  }

  template <int dim>
  void
  check_estimator_objectivity()
  {
    TwoPlies<dim>            mesh(2);
    const TiedCopyDoFs<dim> &dofs = *mesh.dofs;
    // The interface of TwoPlies: the recovery is ply by ply.
    const auto interface = [](const auto &cell, const unsigned int f) {
      return std::abs(cell->face(f)->center()[dim - 1] - 0.5) < 1e-12;
    };
    const Tensor<2, dim> R = rotation<dim>(std::acos(0.5));
    Vector state(dofs.locally_owned_dofs(), MPI_COMM_WORLD), turned(state);
    for (const auto i : dofs.locally_owned_dofs())
      {
        const Point<dim>  &X = dofs.support_point(i);
        const unsigned int c = dofs.component(i);
        // A few percent of non-uniform strain.
        Point<dim> x = X;
        for (unsigned int k = 0; k < dim; ++k)
          x[k] += 0.02 * std::sin(2 * X[0] + k + 3 * X[dim - 1]);
        state(i)  = x[c] - X[c];
        turned(i) = (R * x)[c] - X[c];
      }
    state.compress(VectorOperation::insert);
    turned.compress(VectorOperation::insert);
    const auto estimate = [&](const Vector &u, const bool finite_strain) {
      return ErrorEstimator<dim>(dofs, mesh.plies, interface, finite_strain)
        .zienkiewicz_zhu(dofs.replicate(u));
    };
    const auto before = estimate(state, true), after = estimate(turned, true);
    CHECK(before.error > 0);
    CHECK_CLOSE(after.error / before.error, 1., 1e-10);
    CHECK_CLOSE(after.solution_norm / before.solution_norm, 1., 1e-10);
    for (unsigned int c = 0; c < before.cell_errors.size(); ++c)
      CHECK(std::abs(after.cell_errors[c] - before.cell_errors[c])
            <= 1e-5 * before.error);
    const auto small = estimate(turned, false);
    std::cout << "  dim " << dim << ": ZZ error " << before.error
              << ", turned by 60 degrees " << after.error
              << "; small-strain estimate of the turned state " << small.error
              << std::endl;
    CHECK(std::abs(small.error / before.error - 1) > 0.01);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_point<2>();
  check_point<3>();
  for (const unsigned int degree : {1u, 2u})
    {
      check_derivatives<2>(degree);
      check_derivatives<3>(degree);
    }
  check_small_strain_limit<2>();
  check_small_strain_limit<3>();
  check_estimator_objectivity<2>();
  check_estimator_objectivity<3>();
  return amfrac_test::failures;
}

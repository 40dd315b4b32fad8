// Cohesive interfaces whose local frame follows the deformed mid-surface
// (Kinematics = total Lagrangian):
//   - the frame itself: the reference frame at b = T, R(Q b) = R(b) Q^T
//     for a rotation Q, its first derivatives and the Hessian of
//     w . R(b) v against central differences at random convected tangents
//     (2D and 3D);
//   - objectivity of the interface elements: a rigid rotation (60 degrees
//     in 2D, 75 about an oblique axis in 3D) of a state with open, sliding
//     and closed points leaves every point's local gap and traction as
//     they were and rotates the nodal forces (|f| and f . w kept when w
//     turns with the body). The reference frame fails this, which the test
//     also checks (it is what the test could catch);
//   - the consistent tangent: dF/du d against central differences at the
//     rotated state, with gaps of the order of the mesh size so that the
//     frame's derivative is a sizable part of the tangent; the opening
//     gradient of opening control against the same differences of the
//     summed normal gap (Q1 and Q2, 2D and 3D); the tangent products of
//     the predictor and path following equal the assembled tangent; the
//     history transfer onto the same mesh rebuilds the state's gaps from
//     the displacement and the forces balance.
#include "../check.h"
#include "two_plies.h"

#include <amfrac/cohesive/interface_assembler.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <map>
#include <random>
#include <set>

using namespace amfrac;

namespace
{
  using Vector = TrilinosWrappers::MPI::Vector;
  using Matrix = TrilinosWrappers::SparseMatrix;
  using amfrac_test::ghosted;
  using amfrac_test::nodal_vector;
  using amfrac_test::writable_ghosts;

  std::mt19937                           random_engine(11);
  std::uniform_real_distribution<double> uniform(-1, 1);

  template <int dim>
  Tensor<1, dim>
  random_vector()
  {
    Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = uniform(random_engine);
    return v;
  }

  /** A rotation by @p angle about the axis @p axis (Rodrigues), in 2D
   * about the out-of-plane axis. */
  template <int dim>
  Tensor<2, dim>
  rotation(const double angle, Tensor<1, 3> axis)
  {
    if (dim == 2)
      {
        Tensor<2, dim> Q;
        Q[0][0] = Q[1][1] = std::cos(angle);
        Q[1][0]           = std::sin(angle);
        Q[0][1]           = -std::sin(angle);
        return Q;
      }
    axis /= axis.norm();
    Tensor<2, dim> Q;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        Q[i][j] = std::cos(angle) * (i == j)
                  + (1 - std::cos(angle)) * axis[i] * axis[j];
    // + sin(angle) [axis]x.
    const double s = std::sin(angle);
    Q[0][1] -= s * axis[2], Q[0][2] += s * axis[1];
    Q[1][0] += s * axis[2], Q[1][2] -= s * axis[0];
    Q[2][0] -= s * axis[1], Q[2][1] += s * axis[0];
    return Q;
  }

  template <int dim>
  Tensor<2, dim>
  rotation_60_75()
  {
    return rotation<dim>(dim == 2 ? std::acos(0.5) : 75 * M_PI / 180,
                         Tensor<1, 3>({0.3, 1., -0.5}));
  }

  // ---------------------------------------------------------------------
  // The frame.

  template <int dim>
  using Frame = cohesive::DeformedFrame<dim>;

  template <int dim>
  typename Frame<dim>::Tangents
  reference_tangents(const Tensor<2, dim> &reference)
  {
    typename Frame<dim>::Tangents T;
    for (unsigned int a = 0; a + 1 < dim; ++a)
      T[a] = reference[a + 1];
    return T;
  }

  /** d phi / d b_a[m] with phi = w . R(b) v, from the first derivatives. */
  template <int dim>
  double
  phi_gradient(const Frame<dim>     &frame,
               const unsigned int    a,
               const unsigned int    m,
               const Tensor<1, dim> &w,
               const Tensor<1, dim> &v)
  {
    return (w * frame.gap_derivative(a, v))[m];
  }

  template <int dim>
  void
  check_frame()
  {
    // An oblique reference frame (normal, tangent(s)).
    Tensor<2, dim> reference = rotation_60_75<dim>();
    // In 2D the tangent is the normal turned clockwise (the reference
    // frame of the interface elements).
    if (dim == 2)
      reference[1] = Tensor<1, dim>({reference[0][1], -reference[0][0]});
    const auto T = reference_tangents(reference);
    CHECK((Frame<dim>(T).rows() - reference).norm() < 1e-14);

    const Tensor<2, dim> Q = rotation<dim>(1.1, Tensor<1, 3>({1., -2., 0.7}));
    double               largest_first = 0, largest_second = 0;
    for (unsigned int trial = 0; trial < 5; ++trial)
      {
        // Stretched and sheared tangents.
        auto b = T;
        for (auto &v : b)
          v += 0.4 * random_vector<dim>();
        const Frame<dim> frame(b);
        CHECK((frame.rows() * transpose(frame.rows())
               - unit_symmetric_tensor<dim>())
                .norm()
              < 1e-14);
        auto rotated = b;
        for (auto &v : rotated)
          v = Q * v;
        CHECK((Frame<dim>(rotated).rows() - frame.rows() * transpose(Q)).norm()
              < 1e-14);

        const Tensor<1, dim> w = random_vector<dim>(), v = random_vector<dim>();
        const auto           hessian = frame.hessian(w, v);
        const double         h       = 1e-6;
        for (unsigned int a = 0; a + 1 < dim; ++a)
          for (unsigned int m = 0; m < dim; ++m)
            {
              auto plus = b, minus = b;
              plus[a][m] += h;
              minus[a][m] -= h;
              const Frame<dim> p(plus), q(minus);
              // First derivatives of every row.
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    const double fd
                      = (p.rows()[i][j] - q.rows()[i][j]) / (2 * h);
                    largest_first
                      = std::max(largest_first,
                                 std::abs(fd - frame.derivative(a)[i][j][m]));
                  }
              // Second derivatives of w . R v.
              for (unsigned int c = 0; c + 1 < dim; ++c)
                for (unsigned int l = 0; l < dim; ++l)
                  {
                    const double fd = (phi_gradient(p, c, l, w, v)
                                       - phi_gradient(q, c, l, w, v))
                                      / (2 * h);
                    largest_second
                      = std::max(largest_second,
                                 std::abs(fd - hessian[c][a][l][m]));
                  }
              // The contractions of the first derivatives.
              const Tensor<2, dim> G = frame.gap_derivative(a, v);
              const Tensor<2, dim> H = frame.traction_derivative(a, w);
              CHECK_CLOSE((w * G)[m], (v * H)[m], 1e-12);
            }
      }
    std::cout << "  " << dim
              << "D frame: largest error of the first derivatives "
              << largest_first << ", of the Hessian " << largest_second
              << std::endl;
    CHECK(largest_first < 1e-8);
    CHECK(largest_second < 1e-7);
  }

  // ---------------------------------------------------------------------
  // The interface elements.

  /** A soft elastic interface (stiffness of order one, strengths far
   * away): gaps of the order of the mesh size carry tractions of order
   * one, so that the frame's derivative weighs in the tangent. Normal and
   * shear stiffness and the contact penalty differ, so that a frame that
   * mixes the modes changes the tractions. */
  enum class Phase
  {
    elastic,
    softening,
    debonded
  };

  parameters::CohesiveInterfaces
  soft_interface(const Phase phase = Phase::elastic)
  {
    parameters::CohesiveInterfaces data;
    data.interfaces       = {0};
    data.normal_strength  = 1e4;
    data.shear_strength   = 1e4;
    data.G_Ic             = 1e9;
    data.G_IIc            = 1e9;
    data.normal_stiffness = 1.;
    data.shear_stiffness  = 0.4;
    data.contact_penalty  = 3.;
    data.stick_penalty    = 2.;
    data.friction         = 0.1;
    data.camanho_davila   = false;
    data.bk_exponent      = 2;
    data.viscosity        = 0;
    data.lobatto          = false;
    if (phase == Phase::softening)
      {
        // Past the onset everywhere, far from debonding.
        data.normal_strength = 0.02;
        data.shear_strength  = 0.03;
        data.G_Ic            = 0.5;
        data.G_IIc           = 1.;
      }
    if (phase == Phase::debonded)
      {
        // Debonded on the first half: contact with Coulomb friction there.
        data.precrack_interfaces = {0};
        data.precrack_region     = "x < 1";
      }
    return data;
  }

  template <int dim>
  struct Evaluation
  {
    Vector                                 force;
    std::vector<InterfacePointRecord<dim>> points;
  };

  /** The interface forces at @p u (and the tangent into @p K), and the
   * points' states there. */
  template <int dim>
  Evaluation<dim>
  evaluate(const TiedCopyDoFs<dim> &dofs,
           const bool               deformed,
           const Vector            &u,
           Matrix                  *K     = nullptr,
           const Phase              phase = Phase::elastic)
  {
    CohesiveInterfaces<dim> interfaces(soft_interface(phase), deformed);
    interfaces.setup(dofs, "");
    AffineConstraints<double> none;
    none.close();
    if (K)
      {
        TrilinosWrappers::SparsityPattern pattern(dofs.locally_owned_dofs(),
                                                  dofs.locally_owned_dofs(),
                                                  dofs.locally_relevant_dofs(),
                                                  MPI_COMM_WORLD);
        interfaces.add_couplings(none, pattern);
        pattern.compress();
        K->reinit(pattern);
      }
    const Vector relevant = ghosted(dofs, u);
    Vector       force    = writable_ghosts(dofs);
    interfaces.assemble(relevant, force, none, K);
    force.compress(VectorOperation::add);
    if (K)
      K->compress(VectorOperation::add);
    interfaces.commit();
    Evaluation<dim> result;
    result.force.reinit(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    result.force  = force;
    result.points = interfaces.output_points(relevant);
    return result;
  }

  /** The opening gradient of opening control at @p u. */
  template <int dim>
  Vector
  opening_gradient(const TiedCopyDoFs<dim> &dofs, const Vector &u)
  {
    CohesiveInterfaces<dim> interfaces(soft_interface(), true);
    interfaces.setup(dofs, "");
    Vector gradient = writable_ghosts(dofs);
    interfaces.add_opening_gradient(ghosted(dofs, u), gradient);
    gradient.compress(VectorOperation::add);
    Vector result(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    result = gradient;
    return result;
  }

  /** The integral of the normal gap over the interface: the opening that
   * opening control differentiates (all points bonded here). The faces of
   * this mesh are unit squares (segments), so a point's JxW is the
   * weight of its Gauss rule. */
  template <int dim>
  double
  summed_opening(const Evaluation<dim> &e, const unsigned int degree)
  {
    const QGauss<dim - 1> rule(degree + 1);
    double                sum = 0;
    for (unsigned int p = 0; p < e.points.size(); ++p)
      sum += rule.weight(p % rule.size()) * e.points[p].gap[0];
    return sum;
  }

  /** The product of the predictor and of path following, K_T(u) d with
   * the converged history and no state touched, is the assembled tangent
   * times d. */
  template <int dim>
  void
  check_tangent_product(const TiedCopyDoFs<dim> &dofs,
                        const Vector            &u,
                        const Vector            &d)
  {
    Matrix K;
    evaluate(dofs, true, u, &K);
    Vector Kd(d);
    K.vmult(Kd, d);
    CohesiveInterfaces<dim> interfaces(soft_interface(), true);
    interfaces.setup(dofs, "");
    Vector product = writable_ghosts(dofs);
    interfaces.add_tangent_product(ghosted(dofs, u), ghosted(dofs, d), product);
    product.compress(VectorOperation::add);
    Vector difference(Kd);
    difference = product;
    difference -= Kd;
    CHECK(difference.l2_norm() < 1e-13 * Kd.l2_norm());
  }

  /** tau_1 onto the same mesh: the gaps that rebase() computes from the
   * displacement are the state's (deformed frame), and the transferred
   * forces balance. */
  template <int dim>
  void
  check_transfer(const TiedCopyDoFs<dim> &dofs, const Vector &u)
  {
    AffineConstraints<double> none;
    none.close();
    const Vector            relevant = ghosted(dofs, u);
    Vector                  force    = writable_ghosts(dofs);
    CohesiveInterfaces<dim> old(soft_interface(), true);
    old.setup(dofs, "");
    old.assemble(relevant, force, none, nullptr);
    old.commit();
    CohesiveInterfaces<dim> now(soft_interface(), true);
    now.setup(dofs, "");
    const auto report
      = now.transfer(old.snapshot(MPI_COMM_WORLD), relevant, MPI_COMM_WORLD);
    const auto before = old.output_points(relevant);
    const auto after  = now.output_points(relevant);
    double     change = 0;
    for (unsigned int p = 0; p < before.size(); ++p)
      change = std::max(change, (before[p].gap - after[p].gap).norm());
    std::cout << "  transfer: largest change of a gap " << change
              << ", force imbalance " << report.force_imbalance << std::endl;
    CHECK(before.size() == after.size() && change < 1e-14);
    CHECK(report.force_imbalance < 1e-12);
  }

  template <int dim>
  void
  check_elements(const unsigned int degree)
  {
    amfrac_test::TwoPlies<dim> mesh(degree);
    const TiedCopyDoFs<dim>   &dofs = *mesh.dofs;
    const Tensor<2, dim>       Q    = rotation_60_75<dim>();
    // Open at one end of the interface (z = 1/2), closed at the other,
    // sliding along x (and y): the upper ply moved against the lower one,
    // both a little strained.
    const auto state = [&](const Point<dim> &X, const unsigned int ply) {
      Tensor<1, dim> u;
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = 0.02 * std::sin(3 * X[d] + d + ply);
      if (ply == 1)
        {
          u[0] += 0.3 * (X[0] - 0.5);
          if (dim == 3)
            u[1] += 0.1 * X[1] - 0.2 * X[0];
          u[dim - 1] += 0.25 * (X[0] - 1);
        }
      return u;
    };
    const Vector u = nodal_vector<dim>(dofs, state);
    const Vector rotated
      = nodal_vector<dim>(dofs, [&](const Point<dim> &X, const unsigned ply) {
          return Q * (X + state(X, ply)) - X;
        });
    // A test field and its rotation.
    const auto test = [](const Point<dim> &X, const unsigned int ply) {
      Tensor<1, dim> w;
      for (unsigned int d = 0; d < dim; ++d)
        w[d] = std::cos(2 * X[d] - d + 2 * ply);
      return w;
    };
    const Vector w = nodal_vector<dim>(dofs, test);
    const Vector w_rotated
      = nodal_vector<dim>(dofs, [&](const Point<dim> &X, const unsigned ply) {
          return Q * test(X, ply);
        });

    for (const bool deformed : {true, false})
      {
        const auto   a          = evaluate(dofs, deformed, u);
        const auto   b          = evaluate(dofs, deformed, rotated);
        double       gap_change = 0, traction_change = 0, scale = 0;
        unsigned int open = 0, closed = 0;
        for (unsigned int p = 0; p < a.points.size(); ++p)
          {
            gap_change = std::max(gap_change,
                                  (a.points[p].gap - b.points[p].gap).norm());
            traction_change
              = std::max(traction_change,
                         (a.points[p].traction - b.points[p].traction).norm());
            scale = std::max(scale, a.points[p].traction.norm());
            (a.points[p].gap[0] > 0 ? open : closed) += 1;
          }
        const double work_a = a.force * w, work_b = b.force * w_rotated;
        std::cout << "  " << dim << "D Q" << degree << ", "
                  << (deformed ? "deformed" : "reference")
                  << " frame: largest change of a point's gap under the "
                     "rotation "
                  << gap_change << ", of its traction " << traction_change
                  << " (tractions up to " << scale << "); f . w " << work_a
                  << " -> " << work_b << "; " << open << " points open, "
                  << closed << " closed" << std::endl;
        CHECK(open > 0 && closed > 0 && scale > 0.05);
        if (deformed)
          {
            CHECK(gap_change < 1e-13);
            CHECK(traction_change < 1e-12 * scale);
            CHECK_CLOSE(work_b / work_a, 1., 1e-12);
            CHECK_CLOSE(b.force.l2_norm() / a.force.l2_norm(), 1., 1e-12);
          }
        else
          {
            // The rotated jump is read in the unrotated frame.
            CHECK(gap_change > 0.1);
            CHECK(std::abs(work_b / work_a - 1) > 1e-2);
          }
      }

    // The tangent at the rotated state against central differences.
    Vector d(rotated);
    for (const auto i : dofs.locally_owned_dofs())
      d(i) = uniform(random_engine);
    d.compress(VectorOperation::insert);
    const double h = 1e-6;
    Vector       plus(rotated), minus(rotated);
    plus.add(h, d);
    minus.add(-h, d);
    const char *names[]
      = {"elastic", "softening", "half debonded (contact, friction)"};
    for (const Phase phase :
         {Phase::elastic, Phase::softening, Phase::debonded})
      {
        Matrix K;
        evaluate(dofs, true, rotated, &K, phase);
        Vector Kd(d);
        K.vmult(Kd, d);
        Vector fd = evaluate(dofs, true, plus, nullptr, phase).force;
        fd -= evaluate(dofs, true, minus, nullptr, phase).force;
        fd /= 2 * h;
        fd -= Kd;
        std::cout << "  " << dim << "D Q" << degree << ", "
                  << names[static_cast<int>(phase)]
                  << ": |K d| = " << Kd.l2_norm()
                  << ", |FD - K d| = " << fd.l2_norm() << std::endl;
        CHECK(fd.l2_norm() < 1e-7 * Kd.l2_norm());
        if (phase != Phase::elastic)
          continue;
        // Symmetric while bonded (B^T D B and the frame's second
        // derivative).
        Vector d2(d), Kd2(d);
        for (const auto i : dofs.locally_owned_dofs())
          d2(i) = uniform(random_engine);
        d2.compress(VectorOperation::insert);
        K.vmult(Kd2, d2);
        CHECK_CLOSE((d2 * Kd) / (d * Kd2), 1., 1e-12);
      }

    check_tangent_product(dofs, rotated, d);
    check_transfer(dofs, rotated);

    const auto p = evaluate(dofs, true, plus), m = evaluate(dofs, true, minus);
    const Vector gradient = opening_gradient(dofs, rotated);
    const double fd_opening
      = (summed_opening(p, degree) - summed_opening(m, degree)) / (2 * h);
    std::cout << "  opening gradient . d = " << gradient * d << ", differences "
              << fd_opening << std::endl;
    CHECK_CLOSE(gradient * d / fd_opening, 1., 1e-7);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_frame<2>();
  check_frame<3>();
  for (const unsigned int degree : {1u, 2u})
    {
      check_elements<2>(degree);
      check_elements<3>(degree);
    }
  return amfrac_test::failures;
}

#pragma once

// The manufactured solution of the tests: a rotated orthotropic ply with a
// smooth non-polynomial displacement u_k = sin(a_k . x + phi_k), its body
// force f = -div(C : eps(u)) and Dirichlet data from u on all faces.
#include <amfrac/geometry/laminate.h>
#include <amfrac/material/ply_table.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/symmetric_tensor.h>
#include <memory>

namespace amfrac_test
{
  using namespace dealii;

  const double wave[3][3] = {{1.1, 0.7, 0.9}, {0.6, 1.3, 0.8}, {0.9, 0.5, 1.2}};
  const double phase[3]   = {0.3, 1.1, 0.7};

  inline double
  argument(const Point<3> &p, const unsigned int k)
  {
    return wave[k][0] * p[0] + wave[k][1] * p[1] + wave[k][2] * p[2] + phase[k];
  }

  class Exact : public Function<3>
  {
  public:
    Exact()
      : Function<3>(3)
    {}

    double
    value(const Point<3> &p, const unsigned int k) const override
    {
      return std::sin(argument(p, k));
    }

    Tensor<1, 3>
    gradient(const Point<3> &p, const unsigned int k) const override
    {
      Tensor<1, 3> g;
      for (unsigned int d = 0; d < 3; ++d)
        g[d] = wave[k][d] * std::cos(argument(p, k));
      return g;
    }
  };

  /** f_i = -C_ijkl d_j d_l u_k = sum C_ijkl a^k_j a^k_l sin(a^k . x). */
  class BodyForce : public Function<3>
  {
  public:
    explicit BodyForce(const SymmetricTensor<4, 3> &C)
      : Function<3>(3)
      , C(C)
    {}

    double
    value(const Point<3> &p, const unsigned int i) const override
    {
      double f = 0;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int l = 0; l < 3; ++l)
            f += C[i][j][k][l] * wave[k][j] * wave[k][l]
                 * std::sin(argument(p, k));
      return f;
    }

  private:
    const SymmetricTensor<4, 3> C;
  };


  /** Pose the manufactured problem on @p simulator: the body force of the
   * scene's first ply and the exact displacement on all six faces. */
  inline void
  pose_manufactured(amfrac::Simulator<3>                 &simulator,
                    const amfrac::parameters::Parameters &prm,
                    const std::shared_ptr<Exact>         &exact)
  {
    const amfrac::Laminate laminate(prm.geometry, prm.materials);
    const auto plies = amfrac::make_ply_table<3>(laminate, prm.materials);
    simulator.set_body_force(
      std::make_shared<BodyForce>(plies[0].stiffness_3d));
    std::vector<amfrac::PrescribedDisplacement<3>> supports;
    for (types::boundary_id id = 0; id < 6; ++id)
      supports.push_back({"face" + std::to_string(id),
                          id,
                          exact,
                          {{true, true, true}},
                          nullptr});
    simulator.set_prescribed_displacements(supports);
  }
} // namespace amfrac_test

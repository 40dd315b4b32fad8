// The 2D in-plane model: the stacking homogenized by classical lamination
// theory. The membrane stiffness A/h against the textbook formulas (the
// reduced stiffness Q from the engineering constants, the Tsai-Pagano
// invariants for a quasi-isotropic laminate, a cross-ply by hand), the
// stress recovery, and the refusal of a stacking that couples membrane
// and bending.
#include "../check.h"

#include <amfrac/geometry/laminate.h>
#include <amfrac/material/ply_table.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/parameters/parameters.h>

using namespace amfrac;

namespace
{
  const double E1 = 161000, E2 = 11380, G12 = 5170, nu12 = 0.32;

  PlyProperties<2>
  homogenized(const std::string &stacking)
  {
    const auto prm = parameters::Parameters::from_string(
      "set Dimension = 2\nsubsection Geometry\n  set 2D model = in-plane\n"
      "  set Stacking sequence = "
      + stacking
      + "\n  set Ply thickness = 0.125\nend\nsubsection Materials\n"
        "  set E1 = 161000\n  set E2 = 11380\n  set E3 = 11380\n"
        "  set G12 = 5170\n  set G13 = 5170\n  set G23 = 3980\n"
        "  set nu12 = 0.32\n  set nu13 = 0.32\n  set nu23 = 0.44\nend\n");
    const Laminate laminate(prm.geometry, prm.materials);
    const auto     table = make_ply_table<2>(laminate, prm.materials);
    amfrac_test::check(table.size() == 1,
                       "one homogenized material",
                       __FILE__,
                       __LINE__);
    return table.front();
  }

  /** Plane-stress reduced stiffness of the ply in its material axes. */
  struct Reduced
  {
    double Q11, Q22, Q12, Q66;
    Reduced()
    {
      const double nu21 = nu12 * E2 / E1, d = 1 - nu12 * nu21;
      Q11 = E1 / d, Q22 = E2 / d, Q12 = nu12 * E2 / d, Q66 = G12;
    }
  };

  void
  quasi_isotropic()
  {
    const auto    C = homogenized("[45/90/-45/0]s").stiffness;
    const Reduced Q;
    const double  U1  = (3 * Q.Q11 + 3 * Q.Q22 + 2 * Q.Q12 + 4 * Q.Q66) / 8;
    const double  U4  = (Q.Q11 + Q.Q22 + 6 * Q.Q12 - 4 * Q.Q66) / 8;
    const double  tol = 1e-10 * U1;
    CHECK_CLOSE(C[0][0][0][0], U1, tol);
    CHECK_CLOSE(C[1][1][1][1], U1, tol);
    CHECK_CLOSE(C[0][0][1][1], U4, tol);
    CHECK_CLOSE(C[0][1][0][1], 0.5 * (U1 - U4), tol);
    CHECK_CLOSE(C[0][0][0][1], 0., tol);
    CHECK_CLOSE(C[1][1][0][1], 0., tol);
  }

  void
  cross_ply()
  {
    const auto    C = homogenized("[0/90]s").stiffness;
    const Reduced Q;
    const double  tol = 1e-10 * Q.Q11;
    CHECK_CLOSE(C[0][0][0][0], 0.5 * (Q.Q11 + Q.Q22), tol);
    CHECK_CLOSE(C[1][1][1][1], 0.5 * (Q.Q11 + Q.Q22), tol);
    CHECK_CLOSE(C[0][0][1][1], Q.Q12, tol);
    CHECK_CLOSE(C[0][1][0][1], Q.Q66, tol);
  }

  /** Under a uniaxial strain along x the 0-degree ply carries Q11 eps,
   * the 90-degree ply Q22 eps transverse to its fibres; the laminate's
   * stress is their average, sigma_zz = 0. The 90-degree ply fails first
   * (Yt = 50 MPa against Xt = 2000 MPa). */
  void
  stress_recovery()
  {
    const auto            laminate = homogenized("[0/90]s");
    const Reduced         Q;
    const double          eps = 1e-3;
    SymmetricTensor<2, 2> strain;
    strain[0][0]        = eps;
    const PlyStress s   = evaluate_ply_stress(laminate, strain);
    const double    tol = 1e-10 * Q.Q11 * eps;
    CHECK_CLOSE(s.model[0][0], 0.5 * (Q.Q11 + Q.Q22) * eps, tol);
    CHECK_CLOSE(s.model[1][1], Q.Q12 * eps, tol);
    CHECK_CLOSE(s.model[2][2], 0., tol);
    CHECK_CLOSE(s.material[1][1], Q.Q22 * eps, tol);
    CHECK_CLOSE(s.material[0][0], Q.Q12 * eps, tol);
    CHECK_CLOSE(s.material[2][2], 0., tol);
  }

  void
  unsymmetric_refused()
  {
    for (const std::string stacking : {"[0/90]", "[45/-45]"})
      {
        bool refused = false;
        try
          {
            homogenized(stacking);
          }
        catch (const InputError &e)
          {
            refused
              = std::string(e.what()).find("symmetric") != std::string::npos;
          }
        amfrac_test::check(refused,
                           stacking + " (membrane-bending coupling) refused",
                           __FILE__,
                           __LINE__);
      }
  }
} // namespace

int
main()
{
  quasi_isotropic();
  cross_ply();
  stress_recovery();
  unsymmetric_refused();
  return amfrac_test::summary();
}

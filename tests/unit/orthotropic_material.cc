// Rotated orthotropic stiffness and the Hoffman index.
#include "../check.h"

#include <amfrac/material/orthotropic.h>
#include <stdexcept>

using namespace amfrac;

namespace
{
  ElasticConstants
  carbon_epoxy()
  {
    ElasticConstants c;
    c.E1   = 135000;
    c.E2   = 10000;
    c.E3   = 9000;
    c.G12  = 5000;
    c.G13  = 4800;
    c.G23  = 3448;
    c.nu12 = 0.3;
    c.nu13 = 0.28;
    c.nu23 = 0.45;
    return c;
  }

  double
  max_difference(const SymmetricTensor<4, 3> &a, const SymmetricTensor<4, 3> &b)
  {
    double m = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            m = std::max(m, std::abs(a[i][j][k][l] - b[i][j][k][l]));
    return m;
  }

  /** Uniaxial compliance check: C^{-1} applied to a unit stress along
   * material axis 1 gives strain 1/E1 along 1 and -nu12/E1 along 2. */
  void
  check_compliance(const SymmetricTensor<4, 3> &C, const ElasticConstants &c)
  {
    const SymmetricTensor<4, 3> S = invert(C);
    SymmetricTensor<2, 3>       sigma;
    sigma[0][0]                     = 1;
    const SymmetricTensor<2, 3> eps = S * sigma;
    CHECK_CLOSE(eps[0][0], 1. / c.E1, 1e-12 / c.E1);
    CHECK_CLOSE(eps[1][1], -c.nu12 / c.E1, 1e-12 / c.E1);
    CHECK_CLOSE(eps[2][2], -c.nu13 / c.E1, 1e-12 / c.E1);
  }
} // namespace

int
main()
{
  const ElasticConstants      c = carbon_epoxy();
  const SymmetricTensor<4, 3> C = stiffness_in_material_axes(c);
  check_compliance(C, c);

  // Major symmetry and positive definiteness of the rotated tensor
  // (minor symmetries are built into SymmetricTensor).
  for (const double angle : {0., 30., 45., -60., 90.})
    {
      const SymmetricTensor<4, 3> Cr   = rotate(C, ply_rotation(angle));
      double                      asym = 0;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              asym = std::max(asym, std::abs(Cr[i][j][k][l] - Cr[k][l][i][j]));
      CHECK(asym < 1e-9 * c.E1);
      // Positive energy for pseudo-random strains.
      double min_energy = 1e300;
      for (unsigned int trial = 0; trial < 200; ++trial)
        {
          SymmetricTensor<2, 3> eps;
          for (unsigned int k = 0; k < 6; ++k)
            eps.access_raw_entry(k) = std::sin(1.7 * trial + 2.3 * k + 0.1);
          min_energy = std::min(min_energy, eps * Cr * eps / (eps * eps));
        }
      CHECK(min_energy > 0);
    }

  // 90 degrees swaps axes 1 and 2; 180 degrees is the identity.
  const SymmetricTensor<4, 3> C90  = rotate(C, ply_rotation(90));
  const SymmetricTensor<4, 3> C180 = rotate(C, ply_rotation(180));
  CHECK_CLOSE(C90[0][0][0][0], C[1][1][1][1], 1e-9 * c.E1);
  CHECK_CLOSE(C90[1][1][1][1], C[0][0][0][0], 1e-9 * c.E1);
  CHECK_CLOSE(C90[0][0][2][2], C[1][1][2][2], 1e-9 * c.E1);
  CHECK_CLOSE(C90[1][2][1][2], C[0][2][0][2], 1e-9 * c.E1);
  CHECK(max_difference(C180, C) < 1e-9 * c.E1);
  CHECK(max_difference(rotate(C90, ply_rotation(-90)), C) < 1e-9 * c.E1);

  // Non-positive-definite compliance and a non-positive modulus are
  // rejected with the reason.
  ElasticConstants bad = c;
  bad.nu12             = 4.0;
  bool thrown          = false;
  try
    {
      stiffness_in_material_axes(bad);
    }
  catch (const std::invalid_argument &e)
    {
      thrown
        = std::string(e.what()).find("positive definite") != std::string::npos;
    }
  CHECK(thrown);
  bad     = c;
  bad.G23 = 0;
  thrown  = false;
  try
    {
      stiffness_in_material_axes(bad);
    }
  catch (const std::invalid_argument &e)
    {
      thrown = std::string(e.what()).find("G23") != std::string::npos;
    }
  CHECK(thrown);

  // Hoffman: each uniaxial strength and each pure shear strength gives 1
  // (../shared/reference/README.md section 4).
  Strengths f;
  f.Xt                = 2000;
  f.Xc                = 1200;
  f.Yt                = 50;
  f.Yc                = 200;
  f.Zt                = 45;
  f.Zc                = 180;
  f.S12               = 80;
  f.S13               = 75;
  f.S23               = 60;
  const auto uniaxial = [&](const unsigned int i, const double s) {
    SymmetricTensor<2, 3> sigma;
    sigma[i][i] = s;
    return hoffman_index(sigma, f);
  };
  const auto shear
    = [&](const unsigned int i, const unsigned int j, const double s) {
        SymmetricTensor<2, 3> sigma;
        sigma[i][j] = s;
        return hoffman_index(sigma, f);
      };
  CHECK_CLOSE(uniaxial(0, f.Xt), 1, 1e-12);
  CHECK_CLOSE(uniaxial(0, -f.Xc), 1, 1e-12);
  CHECK_CLOSE(uniaxial(1, f.Yt), 1, 1e-12);
  CHECK_CLOSE(uniaxial(1, -f.Yc), 1, 1e-12);
  CHECK_CLOSE(uniaxial(2, f.Zt), 1, 1e-12);
  CHECK_CLOSE(uniaxial(2, -f.Zc), 1, 1e-12);
  CHECK_CLOSE(shear(0, 1, f.S12), 1, 1e-12);
  CHECK_CLOSE(shear(0, 2, -f.S13), 1, 1e-12);
  CHECK_CLOSE(shear(1, 2, f.S23), 1, 1e-12);
  CHECK(uniaxial(1, 0.5 * f.Yt) < 1);

  // A stress in laminate axes seen by a 90-degree ply: sigma_yy is the
  // ply's sigma_11.
  SymmetricTensor<2, 3> laminate;
  laminate[1][1]      = 7;
  laminate[0][1]      = 3;
  const auto material = to_material_axes(laminate, ply_rotation(90));
  CHECK_CLOSE(material[0][0], 7, 1e-12);
  CHECK_CLOSE(material[1][1], 0, 1e-12);
  CHECK_CLOSE(material[0][1], -3, 1e-12); // tau_12 = -tau_xy at +90

  // The sign of the angle: a +45 ply has its fibres along (1, 1), so
  // uniaxial sigma_xx = 1 gives tau_12 = -sin cos = -1/2 (classical
  // transformation), and the rotated stiffness couples sigma_xx with
  // gamma_xy positively for a fibre-dominated ply (Q16 > 0 at +45).
  SymmetricTensor<2, 3> sxx;
  sxx[0][0]        = 1;
  const auto at_45 = to_material_axes(sxx, ply_rotation(45));
  CHECK_CLOSE(at_45[0][1], -0.5, 1e-12);
  CHECK_CLOSE(at_45[0][0], 0.5, 1e-12);
  const auto C45 = rotate(C, ply_rotation(45));
  CHECK(C45[0][0][0][1] > 0);
  CHECK(rotate(C, ply_rotation(-45))[0][0][0][1] < 0);
  return amfrac_test::summary();
}

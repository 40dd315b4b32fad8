// The Camanho-Davila bilinear law with Benzeggagh-Kenane propagation at a
// single point: the work to full debonding under any fixed mode mix equals
// the BK fracture energy, the quadratic onset criterion, damaged-secant
// unloading, irreversibility when the mode mix changes, contact in
// compression, Coulomb friction once fully debonded, and the tangent
// against central differences in every branch.
#include "law_checks.h"

#include <amfrac/cohesive/camanho_davila_law.h>
#include <cmath>
#include <stdexcept>

using namespace amfrac::cohesive;
using dealii::Tensor;

namespace
{
  CamanhoDavilaProperties
  properties()
  {
    // AS4/PEEK (Camanho, Davila & de Moura 2003), ../shared/reference §1.
    CamanhoDavilaProperties p;
    p.normal_strength = 80;
    p.shear_strength  = 100;
    p.G_Ic            = 0.969;
    p.G_IIc           = 1.719;
    p.bk_exponent     = 2.284;
    p.stiffness       = 1e6;
    p.contact_penalty = 2e6;
    return p;
  }

  /** A gap of length @p length with mode mix B = G_II / G (the shear part
   * split over the two tangents in 3D). */
  template <int dim>
  Tensor<1, dim>
  mixed_gap(const double B, const double length)
  {
    Tensor<1, dim> g;
    g[0] = length * std::sqrt(1 - B);
    if (dim == 2)
      g[1] = length * std::sqrt(B);
    else
      {
        g[1]       = length * std::sqrt(B) * 0.6;
        g[dim - 1] = length * std::sqrt(B) * 0.8;
      }
    return g;
  }

  template <int dim>
  LawResponse<dim>
  law(const Tensor<1, dim> &gap, const PointHistory<dim> &history)
  {
    return camanho_davila_law<dim>(gap, history, properties());
  }

  /** Work along a straight path 0 -> end, which must debond the point. */
  template <int dim>
  double
  work_along(const Tensor<1, dim> &end, const unsigned int steps)
  {
    PointHistory<dim> final;
    const double      work
      = amfrac_test::work_along<dim>(law<dim>, end, steps, &final);
    CHECK(final.debonded);
    return work;
  }

  template <int dim>
  void
  check_tangent(const Tensor<1, dim>    &gap,
                const PointHistory<dim> &history,
                const char              *branch)
  {
    amfrac_test::check_tangent<dim>(law<dim>, gap, history, branch, 1e-6);
  }
  /** Coulomb friction once fully debonded (Friction coefficient > 0):
   * shear debonds the point, then under compression the faces stick on the
   * stick spring up to mu |sigma_N| and slide at it; reversal sticks first;
   * opening frees them; mu = 0 is the frictionless law exactly; tangents
   * in the stick and slip branches. */
  void
  check_friction(const CamanhoDavilaProperties &frictionless)
  {
    CamanhoDavilaProperties p = frictionless;
    p.friction                = 0.3;
    p.stick_penalty           = 5e5;
    p.validate();
    const auto with_friction
      = [&](const Tensor<1, 3> &gap, const PointHistory<3> &history) {
          return camanho_davila_law<3>(gap, history, p);
        };

    // Debond in mode II: the bond breaks at the final shear gap, where the
    // stick reference starts, so the tangential traction starts at zero.
    const double    g_f = 1.2 * p.final(1);
    PointHistory<3> h;
    for (unsigned int s = 1; s <= 40; ++s)
      h = with_friction(Tensor<1, 3>({0, g_f * s / 40., 0}), h).history;
    CHECK(h.debonded);
    CHECK_CLOSE(h.slip[0], g_f, 1e-15);

    // Pressed together, then pushed further along x: stick, then slide.
    const double gN      = -1e-5;
    const double sigma_f = p.friction * p.contact_penalty * -gN;
    const double stick_g = 0.5 * sigma_f / p.stick_penalty;
    const auto   stick = with_friction(Tensor<1, 3>({gN, g_f + stick_g, 0}), h);
    CHECK_CLOSE(stick.traction[0], p.contact_penalty * gN, 1e-9);
    CHECK_CLOSE(stick.traction[1], 0.5 * sigma_f, 1e-9 * sigma_f);
    const auto slide = with_friction(Tensor<1, 3>({gN, g_f + 0.01, 0}), h);
    CHECK_CLOSE(slide.traction[1], sigma_f, 1e-9 * sigma_f);
    CHECK_CLOSE(slide.history.slip[0],
                g_f + 0.01 - sigma_f / p.stick_penalty,
                1e-12);
    // Back by less than the stick range: elastic, the slip kept.
    const auto back
      = with_friction(Tensor<1, 3>(
                        {gN, g_f + 0.01 - 0.5 * sigma_f / p.stick_penalty, 0}),
                      slide.history);
    CHECK_CLOSE(back.traction[1], 0.5 * sigma_f, 1e-9 * sigma_f);
    CHECK(back.history.slip == slide.history.slip);
    // Opened: no traction, the faces slide freely.
    const auto open
      = with_friction(Tensor<1, 3>({1e-3, g_f, 0}), slide.history);
    CHECK(open.traction.norm() == 0);
    // Without friction the law is the frictionless one, history included.
    const auto none = camanho_davila_law<3>(Tensor<1, 3>({gN, g_f + 0.01, 0}),
                                            slide.history,
                                            frictionless);
    CHECK(none.traction[1] == 0 && none.history.slip == slide.history.slip);

    amfrac_test::check_tangent<3>(with_friction,
                                  Tensor<1, 3>({gN, g_f + stick_g, 1e-5}),
                                  h,
                                  "friction, stick",
                                  1e-6);
    amfrac_test::check_tangent<3>(with_friction,
                                  Tensor<1, 3>({gN, g_f + 0.01, 3e-3}),
                                  h,
                                  "friction, slip",
                                  1e-6);
  }
} // namespace

int
main()
{
  const CamanhoDavilaProperties p = properties();
  p.validate();

  // Any fixed mode mix, taken to full debonding: the work is the BK G_c.
  for (const double B : {0., 0.2, 0.5, 0.8, 1.})
    {
      const double Gc = p.fracture_energy(B);
      CHECK_CLOSE(work_along<3>(mixed_gap<3>(B, 1.5 * p.final(B)), 40000) / Gc,
                  1,
                  1e-6);
      CHECK_CLOSE(work_along<2>(mixed_gap<2>(B, 1.5 * p.final(B)), 40000) / Gc,
                  1,
                  1e-6);
    }
  CHECK_CLOSE(p.fracture_energy(0), p.G_Ic, 1e-15);
  CHECK_CLOSE(p.fracture_energy(1), p.G_IIc, 1e-15);

  // Onset: the quadratic criterion (<t_N>/N)^2 + (t_T/S)^2 = 1.
  const PointHistory<3> fresh;
  for (const double B : {0., 0.3, 0.7, 1.})
    {
      const auto r
        = camanho_davila_law<3>(mixed_gap<3>(B, p.onset(B)), fresh, p);
      const double tT = std::sqrt(r.traction[1] * r.traction[1]
                                  + r.traction[2] * r.traction[2]);
      CHECK_CLOSE(std::pow(r.traction[0] / p.normal_strength, 2)
                    + std::pow(tT / p.shear_strength, 2),
                  1,
                  1e-9);
      CHECK(r.history.kappa < 1e-9);
    }

  // Unloading and reloading follow the damaged secant to the origin.
  const double B1   = 0.4;
  const double m1   = 0.5 * (p.onset(B1) + p.final(B1));
  const auto   peak = camanho_davila_law<3>(mixed_gap<3>(B1, m1), fresh, p);
  const double d1   = peak.history.kappa;
  CHECK_CLOSE(d1,
              p.final(B1) * (m1 - p.onset(B1))
                / (m1 * (p.final(B1) - p.onset(B1))),
              1e-12);
  for (const double f : {0.75, 0.3, 0.01})
    {
      const auto back
        = camanho_davila_law<3>(mixed_gap<3>(B1, f * m1), peak.history, p);
      for (unsigned int i = 0; i < 3; ++i)
        CHECK_CLOSE(back.traction[i], f * peak.traction[i], 1e-9 * 100);
      CHECK(back.history.kappa == d1);
    }
  // A change of mode mix never heals: a smaller pure-shear gap whose own
  // damage would be lower keeps d1.
  const auto shear
    = camanho_davila_law<3>(Tensor<1, 3>({0, 1.05 * p.onset(1), 0}),
                            peak.history,
                            p);
  CHECK(shear.history.kappa == d1);
  CHECK_CLOSE(shear.traction[1],
              (1 - d1) * p.stiffness * 1.05 * p.onset(1),
              1e-9);

  // Compression: the contact penalty at any damage, the shear still damaged.
  for (const auto *h : {&fresh, &peak.history})
    {
      const auto r
        = camanho_davila_law<3>(Tensor<1, 3>({-1e-5, 1e-5, 0}), *h, p);
      CHECK_CLOSE(r.traction[0], -p.contact_penalty * 1e-5, 1e-12);
      CHECK_CLOSE(r.traction[1], (1 - h->kappa) * p.stiffness * 1e-5, 1e-9);
    }
  // Fully debonded (or pre-cracked): nothing in tension or shear.
  PointHistory<3> broken;
  broken.debonded = true;
  broken.kappa    = 1e300;
  const auto open
    = camanho_davila_law<3>(Tensor<1, 3>({1e-3, 2e-3, 0}), broken, p);
  CHECK(open.traction.norm() == 0);
  CHECK(open.history.kappa == 1);

  // Tangents in every branch.
  check_tangent<3>(mixed_gap<3>(0.5, 0.7 * p.onset(0.5)), fresh, "intact");
  check_tangent<3>(mixed_gap<3>(0.5, 1.8 * p.onset(0.5)),
                   fresh,
                   "mixed softening");
  check_tangent<3>(mixed_gap<3>(0, 1.8 * p.onset(0)),
                   fresh,
                   "mode I softening");
  // (near, not at, g_N = 0: <g_N> has a kink there)
  check_tangent<3>(mixed_gap<3>(0.95, 1.8 * p.onset(1)),
                   fresh,
                   "mode II softening");
  check_tangent<2>(mixed_gap<2>(0.3, 2.5 * p.onset(0.3)),
                   PointHistory<2>(),
                   "softening 2D");
  check_tangent<3>(mixed_gap<3>(B1, 0.5 * m1), peak.history, "unloading");
  check_tangent<3>(Tensor<1, 3>({-1e-5, 1.5 * p.onset(1), 0}),
                   fresh,
                   "compression with shear softening");
  check_tangent<3>(Tensor<1, 3>({-1e-5, 2e-3, 0}), broken, "debonded");

  check_friction(p);

  // Ill-posed data are rejected with the reason.
  for (int which = 0; which < 4; ++which)
    {
      CamanhoDavilaProperties bad = p;
      if (which == 0)
        bad.G_Ic = 0.4 * p.normal_strength * p.onset(0);
      else if (which == 1)
        bad.bk_exponent = 0;
      else if (which == 2)
        bad.friction = -0.1;
      else
        bad.friction = 0.3; // without a stick penalty
      bool thrown = false;
      try
        {
          bad.validate();
        }
      catch (const std::invalid_argument &e)
        {
          thrown = true;
          std::cout << "rejected: " << e.what() << std::endl;
        }
      CHECK(thrown);
    }
  return amfrac_test::summary();
}

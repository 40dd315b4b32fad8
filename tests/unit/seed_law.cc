// The seed's interface law at a single point (eqs. (1)-(13)): fracture
// energies, damaged-secant unloading, penalty contact, Coulomb friction
// after debonding, and the tangent against central finite differences in
// every branch.
#include "law_checks.h"

#include <amfrac/cohesive/seed_law.h>
#include <stdexcept>

using namespace amfrac::cohesive;
using dealii::Tensor;

namespace
{
  SeedLawProperties
  properties()
  {
    SeedLawProperties p;
    p.normal_strength  = 57; // Mi/Alfano DCB data (MPa, N/mm)
    p.shear_strength   = 80;
    p.G_Ic             = 0.28;
    p.G_IIc            = 0.6;
    p.normal_stiffness = 1e5; // MPa/mm
    p.shear_stiffness  = 1e5;
    p.contact_penalty  = 2e5;
    p.stick_penalty    = 1e5;
    p.friction         = 0.3;
    return p;
  }

  template <int dim>
  LawResponse<dim>
  law(const Tensor<1, dim> &gap, const PointHistory<dim> &history)
  {
    return seed_law<dim>(gap, history, properties());
  }

  template <int dim>
  double
  work_along(const Tensor<1, dim> &end, const unsigned int steps)
  {
    return amfrac_test::work_along<dim>(law<dim>, end, steps);
  }

  template <int dim>
  void
  check_tangent(const Tensor<1, dim>    &gap,
                const PointHistory<dim> &history,
                const char              *branch)
  {
    amfrac_test::check_tangent<dim>(law<dim>, gap, history, branch, 1e-4);
  }
} // namespace

int
main()
{
  const SeedLawProperties p = properties();
  p.validate();

  // Pure mode I and mode II to complete debonding: the work is G_c.
  CHECK_CLOSE(work_along<3>(Tensor<1, 3>({1.5 * p.gmax_N(), 0, 0}), 20000)
                / p.G_Ic,
              1,
              1e-6);
  CHECK_CLOSE(work_along<3>(Tensor<1, 3>({0, 0, 1.5 * p.gmax_T()}), 20000)
                / p.G_IIc,
              1,
              1e-6);
  CHECK_CLOSE(work_along<2>(Tensor<1, 2>({0, 1.5 * p.gmax_T()}), 20000)
                / p.G_IIc,
              1,
              1e-6);
  // Peak traction at g_0 equals the strength.
  const PointHistory<3> fresh;
  CHECK_CLOSE(seed_law<3>(Tensor<1, 3>({p.g0_N(), 0, 0}), fresh, p).traction[0],
              p.normal_strength,
              1e-9 * p.normal_strength);

  // Unloading and reloading follow the damaged secant to the origin.
  const double g1     = 0.5 * (p.g0_N() + p.gmax_N());
  const auto   peak   = seed_law<3>(Tensor<1, 3>({g1, 0, 0}), fresh, p);
  const double sigma1 = peak.traction[0];
  CHECK_CLOSE(sigma1,
              p.normal_strength * (p.gmax_N() - g1) / (p.gmax_N() - p.g0_N()),
              1e-9 * p.normal_strength);
  for (const double f : {0.75, 0.3, 0.01})
    {
      const auto back
        = seed_law<3>(Tensor<1, 3>({f * g1, 0, 0}), peak.history, p);
      CHECK_CLOSE(back.traction[0], f * sigma1, 1e-9 * p.normal_strength);
      CHECK(back.history.kappa == peak.history.kappa); // irreversible
    }

  // Compression: the penalty, intact or damaged.
  for (const auto *h : {&fresh, &peak.history})
    CHECK_CLOSE(seed_law<3>(Tensor<1, 3>({-1e-4, 0, 0}), *h, p).traction[0],
                -p.contact_penalty * 1e-4,
                1e-12);

  // Debond in shear, then compress and slide: sigma_T = mu <-sigma_N>,
  // opposing the slip; in tension after debonding, no shear traction.
  PointHistory<3> history;
  for (unsigned int s = 1; s <= 100; ++s)
    history
      = seed_law<3>(Tensor<1, 3>({0, 0.02 * s * p.gmax_T(), 0}), history, p)
          .history;
  CHECK(history.debonded);
  const double   gN      = -2e-4;
  const double   sigma_f = p.friction * p.contact_penalty * -gN;
  auto           slide   = history;
  LawResponse<3> r;
  for (unsigned int s = 1; s <= 50; ++s)
    {
      r     = seed_law<3>(Tensor<1, 3>({gN, 2 * p.gmax_T() + 1e-3 * s, 0}),
                      slide,
                      p);
      slide = r.history;
    }
  CHECK_CLOSE(r.traction[0], p.contact_penalty * gN, 1e-12);
  CHECK_CLOSE(r.traction[1], sigma_f, 1e-9 * sigma_f);
  CHECK_CLOSE(r.traction[2], 0, 1e-12);
  // Reversal: first elastic (stick), then sliding back at -sigma_f.
  const double g_back = 2 * p.gmax_T() + 0.05;
  const auto   stick  = seed_law<3>(
    Tensor<1, 3>({gN, g_back - 0.5 * sigma_f / p.stick_penalty, 0}), slide, p);
  CHECK_CLOSE(stick.traction[1], 0.5 * sigma_f, 1e-9 * sigma_f);
  const auto back = seed_law<3>(Tensor<1, 3>({gN, g_back - 0.1, 0}), slide, p);
  CHECK_CLOSE(back.traction[1], -sigma_f, 1e-9 * sigma_f);
  const auto open = seed_law<3>(Tensor<1, 3>({1e-3, g_back, 0}), slide, p);
  CHECK_CLOSE(open.traction[1], 0, 1e-12);

  // Tangents in every branch of eqs. (12)-(13).
  PointHistory<3> none;
  check_tangent<3>(Tensor<1, 3>(
                     {0.3 * p.g0_N(), 0.2 * p.g0_T(), 0.1 * p.g0_T()}),
                   none,
                   "intact");
  check_tangent<3>(Tensor<1, 3>(
                     {1.3 * p.g0_N(), 0.4 * p.g0_T(), -0.3 * p.g0_T()}),
                   none,
                   "softening, mixed mode, loading");
  check_tangent<2>(Tensor<1, 2>({1.5 * p.g0_N(), 0.7 * p.g0_T()}),
                   PointHistory<2>(),
                   "softening 2D");
  check_tangent<3>(Tensor<1, 3>({0.5 * g1, 0, 0}), peak.history, "unloading");
  check_tangent<3>(Tensor<1, 3>({-1e-4, 1.4 * p.g0_T(), 0.2 * p.g0_T()}),
                   none,
                   "compression with shear softening");
  check_tangent<3>(Tensor<1, 3>(
                     {gN, g_back - 0.5 * sigma_f / p.stick_penalty, 1e-5}),
                   slide,
                   "friction, stick");
  check_tangent<3>(Tensor<1, 3>({gN, g_back + 0.01, 0.004}),
                   slide,
                   "friction, slip");

  // Ill-posed data are rejected with the reason.
  SeedLawProperties bad = p;
  bad.G_Ic              = 0.5 * p.normal_strength * p.g0_N();
  bool thrown           = false;
  try
    {
      bad.validate();
    }
  catch (const std::invalid_argument &e)
    {
      thrown = std::string(e.what()).find("mode I") != std::string::npos;
    }
  CHECK(thrown);
  bad          = p;
  bad.friction = -0.1;
  thrown       = false;
  try
    {
      bad.validate();
    }
  catch (const std::invalid_argument &)
    {
      thrown = true;
    }
  CHECK(thrown);
  return amfrac_test::summary();
}

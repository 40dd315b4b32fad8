// Hoffman plasticity at a point (material axes):
//   - uniaxial stress in each direction, tension and compression, and pure
//     in-plane shear yield at the corresponding strength (Xt, Xc, Yt, Yc,
//     Zt, Zc, S12) and, with hardening h, stay on s times it,
//     s = 1 + h kappa;
//   - the consistent tangent equals central differences of the return
//     mapping at plastic states;
//   - load, unload (elastic, with the elastic stiffness) and reload: the
//     reloading is elastic up to the stress reached before and yields
//     there;
//   - below yield the stress is exactly D (eps - eps_p), as without
//     plasticity;
//   - at a converged plastic state the (elastic) response carries the
//     continuum elastic-plastic tangent, the limit of the consistent one.
// The uniaxial paths are driven by one strain component with the other
// five solved for zero stress by Newton with the tangent, which checks the
// tangent along the way.
#include "../check.h"

#include <amfrac/material/hoffman_plasticity.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

using namespace amfrac;
using Voigt = HoffmanPlasticity::Voigt;

namespace
{
  Strengths
  strengths()
  {
    Strengths f;
    f.Xt = 1500, f.Xc = 1200, f.Yt = 50, f.Yc = 200, f.Zt = 45, f.Zc = 180;
    f.S12 = 70, f.S13 = 75, f.S23 = 40;
    return f;
  }

  HoffmanPlasticity
  model(const double hardening)
  {
    ElasticConstants c;
    c.E1 = 135000, c.E2 = 10000, c.E3 = 9000;
    c.G12 = 5000, c.G13 = 4800, c.G23 = 3500;
    c.nu12 = 0.3, c.nu13 = 0.28, c.nu23 = 0.4;
    return HoffmanPlasticity(stiffness_in_material_axes(c),
                             strengths(),
                             hardening);
  }

  /** The response to strain component @p driven = @p value with the other
   * five such that their stresses vanish, from history @p old (Newton on
   * the five with the tangent, starting from @p strain, which is
   * updated). */
  HoffmanPlasticity::Response
  uniaxial(const HoffmanPlasticity        &m,
           const unsigned int              driven,
           const double                    value,
           const HoffmanPlasticity::State &old,
           Voigt                          &strain)
  {
    strain[driven] = value;
    HoffmanPlasticity::Response r;
    for (unsigned int it = 0; it < 50; ++it)
      {
        r = m.respond(strain, old);
        FullMatrix<double> K(5, 5);
        Vector<double>     rhs(5), x(5);
        double             residual = 0;
        for (unsigned int a = 0, i = 0; i < 6; ++i)
          if (i != driven)
            {
              rhs(a) = -r.stress[i];
              residual += r.stress[i] * r.stress[i];
              for (unsigned int b = 0, j = 0; j < 6; ++j)
                if (j != driven)
                  K(a, b++) = r.tangent[i][j];
              ++a;
            }
        if (std::sqrt(residual) < 1e-10)
          return r;
        K.gauss_jordan();
        K.vmult(x, rhs);
        for (unsigned int a = 0, i = 0; i < 6; ++i)
          if (i != driven)
            strain[i] += x(a++);
      }
    CHECK(false && "the uniaxial path did not converge");
    return r;
  }

  /** Uniaxial (or shear) loading along @p driven in the direction of
   * @p sign until the plastic strain is well developed: yields at
   * @p strength, then follows s times it. */
  void
  check_yield(const unsigned int driven,
              const double       sign,
              const double       strength,
              const double       modulus,
              const double       hardening)
  {
    const HoffmanPlasticity  m = model(hardening);
    HoffmanPlasticity::State state;
    Voigt                    strain{};
    double                   largest_elastic = 0;
    unsigned int             plastic_steps   = 0;
    for (unsigned int step = 1; step <= 60; ++step)
      {
        // Up to 2.45 times the yield strain strength / modulus (no step
        // lands on it).
        const auto r = uniaxial(m,
                                driven,
                                sign * step / 60. * 2.45 * strength / modulus,
                                state,
                                strain);
        CHECK(r.converged);
        const double stress = sign * r.stress[driven];
        if (!r.plastic)
          largest_elastic = std::max(largest_elastic, stress);
        else
          {
            ++plastic_steps;
            const double s = 1 + hardening * r.state.kappa;
            CHECK_CLOSE(stress / (s * strength), 1., 1e-9);
          }
        state = r.state;
      }
    CHECK(largest_elastic < strength);
    CHECK(plastic_steps > 5);
    CHECK(hardening == 0 || state.kappa > 0);
  }

  /** The tangent against central differences of the return mapping from
   * a plastic state, in all six directions. */
  void
  check_tangent(const double hardening)
  {
    const HoffmanPlasticity  m = model(hardening);
    HoffmanPlasticity::State state;
    Voigt                    strain{};
    // A plastic state in transverse tension with some shear.
    for (unsigned int step = 1; step <= 10; ++step)
      {
        strain[1] = 0.0008 * step, strain[5] = 0.0012 * step;
        state = m.respond(strain, state).state;
      }
    strain[1] += 0.0004, strain[5] += 0.0006, strain[3] = 0.0002;
    const auto r = m.respond(strain, state);
    CHECK(r.plastic && r.converged);
    double worst = 0, largest = 0;
    for (unsigned int j = 0; j < 6; ++j)
      {
        const double delta = 1e-8;
        Voigt        plus = strain, minus = strain;
        plus[j] += delta, minus[j] -= delta;
        const auto rp = m.respond(plus, state), rm = m.respond(minus, state);
        for (unsigned int i = 0; i < 6; ++i)
          {
            const double fd = (rp.stress[i] - rm.stress[i]) / (2 * delta);
            worst           = std::max(worst, std::abs(fd - r.tangent[i][j]));
            largest         = std::max(largest, std::abs(r.tangent[i][j]));
          }
      }
    std::cout << "  h = " << hardening
              << ": |FD - tangent| / |tangent| = " << worst / largest
              << std::endl;
    CHECK(worst < 1e-5 * largest);

    // From the converged state (on its yield surface) the response is
    // elastic and its tangent the continuum one, which the consistent
    // tangent of a vanishing further plastic step approaches.
    const auto on = m.respond(strain, r.state);
    CHECK(!on.plastic && on.on_surface);
    Voigt further = strain;
    for (unsigned int i = 0; i < 6; ++i)
      further[i]
        += 1e-9 * (r.state.plastic_strain[i] - state.plastic_strain[i]);
    const auto next = m.respond(further, r.state);
    CHECK(next.plastic);
    double difference = 0;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        difference = std::max(difference,
                              std::abs(on.tangent[i][j] - next.tangent[i][j]));
    CHECK(difference < 1e-6 * largest);
    // A virgin point is never on its surface.
    CHECK(!m.respond(Voigt{}, HoffmanPlasticity::State()).on_surface);
  }

  /** Transverse tension with hardening: load into plasticity, unload to
   * zero stress, reload. */
  void
  check_cycle()
  {
    const HoffmanPlasticity  m = model(20.);
    HoffmanPlasticity::State state;
    Voigt                    strain{};
    double                   peak = 0, peak_strain = 0;
    for (unsigned int step = 1; step <= 40; ++step)
      {
        const auto r = uniaxial(m, 1, 0.0002 * step, state, strain);
        state = r.state, peak = r.stress[1], peak_strain = strain[1];
      }
    CHECK(state.kappa > 0 && peak > strengths().Yt);
    // Unloading is elastic, with the slope of the first (elastic) step.
    HoffmanPlasticity::State unloaded = state;
    Voigt                    s1       = strain;
    const auto first  = uniaxial(m, 1, peak_strain - 0.0002, state, s1);
    const auto second = uniaxial(m, 1, peak_strain - 0.0004, state, s1);
    CHECK(!first.plastic && !second.plastic);
    const double slope = (first.stress[1] - second.stress[1]) / 0.0002;
    Voigt        s0{};
    HoffmanPlasticity::State fresh;
    const double initial = uniaxial(m, 1, 0.0002, fresh, s0).stress[1] / 0.0002;
    CHECK_CLOSE(slope / initial, 1., 1e-8);
    // Reloading: elastic below the previous peak, plastic just above.
    const auto below = uniaxial(m, 1, peak_strain - 1e-6, unloaded, s1);
    CHECK(!below.plastic && below.stress[1] < peak);
    const auto above = uniaxial(m, 1, peak_strain + 1e-5, unloaded, s1);
    CHECK(above.plastic);
    CHECK_CLOSE(above.stress[1] / peak, 1., 1e-3);
  }

  /** Below yield: exactly D (eps - eps_p). */
  void
  check_elastic()
  {
    ElasticConstants c;
    c.E1 = 135000, c.E2 = 10000, c.E3 = 9000;
    c.G12 = 5000, c.G13 = 4800, c.G23 = 3500;
    c.nu12 = 0.3, c.nu13 = 0.28, c.nu23 = 0.4;
    const SymmetricTensor<4, 3> C = stiffness_in_material_axes(c);
    const HoffmanPlasticity     m = model(0.);
    const Voigt strain{{0.001, -0.0003, 0.0001, 0.0002, -0.0001, 0.0005}};
    const auto  r = m.respond(strain, HoffmanPlasticity::State());
    CHECK(!r.plastic);
    for (unsigned int I = 0; I < 6; ++I)
      {
        double expected = 0;
        for (unsigned int J = 0; J < 6; ++J)
          expected += C[voigt_pairs[I][0]][voigt_pairs[I][1]][voigt_pairs[J][0]]
                       [voigt_pairs[J][1]]
                      * strain[J];
        CHECK(r.stress[I] == expected);
      }
  }
} // namespace

int
main()
{
  const Strengths f = strengths();
  for (const double h : {0., 10.})
    {
      check_yield(0, 1, f.Xt, 135000, h);
      check_yield(0, -1, f.Xc, 135000, h);
      check_yield(1, 1, f.Yt, 10000, h);
      check_yield(1, -1, f.Yc, 10000, h);
      check_yield(2, 1, f.Zt, 9000, h);
      check_yield(2, -1, f.Zc, 9000, h);
      check_yield(5, 1, f.S12, 5000, h);
      check_tangent(h);
    }
  // Strong hardening (h kappa about 20 at the end in transverse
  // compression): the local Newton's tolerances scale with s^2.
  check_yield(1, -1, f.Yc, 10000, 500.);
  check_cycle();
  check_elastic();
  return amfrac_test::failures;
}

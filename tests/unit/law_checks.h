#pragma once

// Checks shared by the unit tests of the interface laws: the work along a
// path (the area under the traction-separation curve) and the tangent
// against central differences. A law is any callable
// (gap, history) -> LawResponse<dim>.

#include "../check.h"

#include <algorithm>
#include <amfrac/cohesive/law_state.h>
#include <cmath>
#include <iostream>

namespace amfrac_test
{
  using amfrac::cohesive::PointHistory;
  using dealii::Tensor;

  /** Work of the traction along the straight path 0 -> @p end in @p steps
   * steps (trapezoidal rule); the history at the end goes to @p final. */
  template <int dim, typename Law>
  double
  work_along(const Law            &law,
             const Tensor<1, dim> &end,
             const unsigned int    steps,
             PointHistory<dim>    *final = nullptr)
  {
    PointHistory<dim> history;
    double            work = 0;
    Tensor<1, dim>    previous;
    for (unsigned int s = 1; s <= steps; ++s)
      {
        const auto r = law(end * (double(s) / steps), history);
        work += 0.5 * (r.traction + previous) * end / steps;
        previous = r.traction;
        history  = r.history;
      }
    if (final)
      *final = history;
    return work;
  }

  /** The law's tangent at @p gap against central differences of the
   * traction with the history held fixed (relative 1e-6 of the largest
   * entry); the step is 1e-7 max(|gap|, @p floor). */
  template <int dim, typename Law>
  void
  check_tangent(const Law               &law,
                const Tensor<1, dim>    &gap,
                const PointHistory<dim> &history,
                const char              *branch,
                const double             floor)
  {
    const auto   r     = law(gap, history);
    const double h     = 1e-7 * std::max(gap.norm(), floor);
    double       scale = 0, worst = 0;
    for (unsigned int j = 0; j < dim; ++j)
      {
        Tensor<1, dim> plus = gap, minus = gap;
        plus[j] += h;
        minus[j] -= h;
        const auto fd
          = (law(plus, history).traction - law(minus, history).traction)
            / (2 * h);
        for (unsigned int i = 0; i < dim; ++i)
          {
            worst = std::max(worst, std::abs(fd[i] - r.tangent[i][j]));
            scale = std::max(scale, std::abs(r.tangent[i][j]));
          }
      }
    const bool ok = worst <= 1e-6 * scale;
    CHECK(ok);
    if (!ok)
      std::cerr << "  tangent of branch '" << branch << "': error " << worst
                << " against " << scale << std::endl;
  }
} // namespace amfrac_test

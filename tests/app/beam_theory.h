#pragma once

// Beam-theory formulas shared by the delamination tests
// (../shared/reference/README.md sections 1 and 2).

#include <cmath>

namespace amfrac_test
{
  /** chi of the corrected beam theory: the crack length a + chi h accounts
   * for the rotation at the crack tip of an orthotropic arm. */
  inline double
  corrected_beam_chi(const double E11, const double E22, const double G13)
  {
    const double Gamma = 1.18 * std::sqrt(E11 * E22) / G13;
    const double ratio = Gamma / (1 + Gamma);
    return std::sqrt(E11 / (11 * G13) * (3 - 2 * ratio * ratio));
  }
} // namespace amfrac_test

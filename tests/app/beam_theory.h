#pragma once

// Shared by the delamination tests: beam-theory formulas
// (../shared/reference/README.md sections 1 and 2) and running a shipped
// scene.

#include <algorithm>
#include <amfrac/postprocess/history.h>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

  /** The propagation envelope of a DCB of width @p b, arms of thickness
   * @p h and modulus @p E11 (simple beam theory, reference section 1):
   * P = sqrt(2 (G b)^1.5 (E I)^0.5 / (3 delta)). */
  inline double
  dcb_envelope(const double G,
               const double b,
               const double E11,
               const double h,
               const double delta)
  {
    const double I = b * std::pow(h, 3) / 12;
    return std::sqrt(2 * std::pow(G * b, 1.5) * std::sqrt(E11 * I)
                     / (3 * delta));
  }

  /** The row of the largest load (column force_x-) of a history. */
  inline std::size_t
  peak_row(const amfrac::History &h)
  {
    std::size_t best = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      if (h.value(r, "force_x-") > h.value(best, "force_x-"))
        best = r;
    return best;
  }

  /** The row after the peak whose opening (column time) is nearest
   * @p delta. */
  inline std::size_t
  row_after_peak_at(const amfrac::History &h, const double delta)
  {
    std::size_t best = peak_row(h);
    for (std::size_t r = best; r < h.n_rows(); ++r)
      if (std::abs(h.value(r, "time") - delta)
          < std::abs(h.value(best, "time") - delta))
        best = r;
    return best;
  }

  /** The median of the column newton_iterations of a history. */
  inline double
  median_newton_iterations(const amfrac::History &h)
  {
    std::vector<double> iterations;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      iterations.push_back(h.value(r, "newton_iterations"));
    std::nth_element(iterations.begin(),
                     iterations.begin() + iterations.size() / 2,
                     iterations.end());
    return iterations[iterations.size() / 2];
  }

  /** The scene file @p path with, appended (later entries win), the load
   * span 0..@p end in @p steps steps, no field output, and the output
   * directory @p workdir: how the delamination tests run a shipped scene. */
  inline std::string
  scene_until(const std::string &path,
              const double       end,
              const unsigned int steps,
              const std::string &workdir)
  {
    std::ifstream     file(path);
    std::stringstream text;
    text << file.rdbuf() << "\nsubsection Time\n  set End time = " << end
         << "\n  set Number of steps = " << steps
         << "\nend\nsubsection Output\n  set Field format = none\n"
         << "  set Directory = " << workdir << "\nend\n";
    return text.str();
  }
} // namespace amfrac_test

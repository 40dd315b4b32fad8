#pragma once

// Shared by the delamination tests: beam-theory formulas
// (../shared/reference/README.md sections 1 and 2) and running a shipped
// scene.

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

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

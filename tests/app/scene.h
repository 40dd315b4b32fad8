#pragma once

// A scene file with text appended (later entries override earlier ones),
// and a run of it: how the application tests vary a shipped scene.

#include "../check.h"

#include <algorithm>
#include <amfrac/parameters/parameters.h>
#include <amfrac/postprocess/history.h>
#include <amfrac/simulator/simulator.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace amfrac_test
{
  /** The whole text of @p file (a .prm fragment to append). */
  inline std::string
  file_text(const std::string &file)
  {
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  inline amfrac::parameters::Parameters
  scene_with(const std::string &file, const std::string &appended)
  {
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf() << "\n" << appended << "\n";
    return amfrac::parameters::Parameters::from_string(text.str());
  }

  template <int dim>
  std::unique_ptr<amfrac::Simulator<dim>>
  run_scene(const std::string &file, const std::string &appended)
  {
    auto simulator
      = std::make_unique<amfrac::Simulator<dim>>(scene_with(file, appended),
                                                 MPI_COMM_WORLD);
    simulator->run();
    return simulator;
  }
  /** What every mesh change during a load history must keep (row @p r of
   * adaptivity.csv): the dissipated energy (1e-12, once there is some),
   * the debonded and damaged areas (never smaller), and the balance of the
   * two faces of the interface elements (round-off). */
  inline void
  check_transfer(const amfrac::History &changes, const std::size_t r)
  {
    const auto value
      = [&](const std::string &column) { return changes.value(r, column); };
    if (value("dissipated_before") > 1e-3)
      CHECK_CLOSE(value("dissipated_after") / value("dissipated_before"),
                  1.,
                  1e-12);
    CHECK(value("debonded_after") >= value("debonded_before") - 1e-12);
    CHECK(value("damaged_after") >= value("damaged_before") - 1e-12);
    CHECK(value("interface_force_imbalance") < 1e-10);
  }
  /** The largest magnitude of a column of a history; NaN if any value is
   * not a number (so that a check "largest < tolerance" fails). */
  inline double
  largest(const amfrac::History &h, const std::string &column)
  {
    double value = 0;
    for (std::size_t r = 0; r < h.n_rows(); ++r)
      {
        const double x = h.value(r, column);
        if (std::isnan(x))
          return x;
        value = std::max(value, std::abs(x));
      }
    return value;
  }
} // namespace amfrac_test

#pragma once

// A scene file with text appended (later entries override earlier ones),
// and a run of it: how the application tests vary a shipped scene.

#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace amfrac_test
{
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
} // namespace amfrac_test

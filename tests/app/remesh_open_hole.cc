// The seed's global remeshing (issue 8) on the open-hole plate of
// prm/open_hole_prism.prm with P1 wedges and an isotropic material with
// nu = 0 (tests/app/open_hole_isotropic.prm), whose 3D solution is the
// plane-stress one: a converged adaptive Q2 run of the plate in its plane
// (prm/open_hole_2d.prm) gives the load work W of the exact solution, and
// with a traction load the energy error of a run is
// ||u - u_h||^2 = W - W_h. Checked per cycle:
// - the energy norm of the ZZ estimator on wedges is the load work
//   (||u_h||^2 = W_h, 1e-6);
// - the ZZ estimate against the true energy error (effectivity between
//   0.5 and 1.5);
// - the true error falls every cycle, the relative ZZ error reaches the
//   target and the run stops there;
// - the carried solution (tau_2) keeps the energy norm of the old one
//   within 3 %, and its energy differs from the old one's by less than
//   the old mesh's relative energy error (ZZ squared);
// - the remeshed plate (from a coarse start, two remeshings) ends with a
//   smaller true error than uniform refinement of the same start (the
//   same grading towards the hole, every size divided by 8) with fewer
//   unknowns (measured: 47,538 unknowns and 1.11 % against 81,099 and
//   1.13 %);
// - Maximum cells caps the remeshed mesh (within 20 %) and stops the
//   cycles once the mesh is near it;
// - Strategy = uniform halves every cell's size (4x to 6.5x the cells, as
//   the field takes the smallest size around each vertex; within 20 % of
//   the prediction).
#include "scene.h"

using namespace amfrac;

namespace
{
  const char *settings = R"(
subsection Output
  set Field format = none
  set Directory    = remesh_open_hole_output
end
)";

  /** A coarse start (a quarter of the scene's elements), so that the
   * target takes two remeshings. */
  const char *coarse = R"(
subsection Geometry
  set Elements around hole = 12
  set Elements along width = 3
end
)";

  const char *remeshing = R"(
subsection Adaptivity
  set Refinement cycles = 5
  set Strategy          = error target
  set Target error      = 0.012
end
)";
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (argc < 4)
    {
      std::cerr << "usage: remesh_open_hole open_hole_prism.prm "
                   "open_hole_2d.prm open_hole_isotropic.prm\n";
      return 2;
    }
  const std::string isotropic = amfrac_test::file_text(argv[3]) + settings;

  const auto reference_run
    = amfrac_test::run_scene<2>(argv[2],
                                isotropic
                                  + "subsection Discretization\n"
                                    "  set Finite element degree = 2\nend\n"
                                    "subsection Adaptivity\n"
                                    "  set Refinement cycles = 7\n"
                                    "  set Refine fraction = 0.6\nend\n");
  const auto  &reference_history = reference_run->history();
  const double reference
    = reference_history.value(reference_history.n_rows() - 1, "load_work");

  const auto remeshed
    = amfrac_test::run_scene<3>(argv[1], isotropic + coarse + remeshing);
  const auto         &cycles = *remeshed->adaptivity_history();
  const double        target = 0.012;
  std::vector<double> true_errors;
  for (std::size_t c = 0; c < cycles.n_rows(); ++c)
    {
      const auto value
        = [&](const std::string &column) { return cycles.value(c, column); };
      const double work = value("load_work");
      CHECK_CLOSE(std::pow(value("energy_norm"), 2) / work, 1., 1e-6);
      const double error = std::sqrt(std::max(0., reference - work));
      true_errors.push_back(error / std::sqrt(reference));
      const double effectivity = value("zz_error") / error;
      if (root)
        std::cout << "cycle " << c << ": " << value("cells") << " cells, "
                  << value("unknowns") << " unknowns, ZZ relative "
                  << value("zz_relative_error") << ", true relative "
                  << true_errors.back() << ", effectivity " << effectivity
                  << "; carried energy norm changed by "
                  << value("transfer_energy_change") << ", "
                  << value("transfer_points_outside")
                  << " points outside, remesh " << value("remesh_seconds")
                  << " s, transfer " << value("transfer_seconds") << " s"
                  << std::endl;
      CHECK(effectivity > 0.5 && effectivity < 1.5);
      if (c > 0)
        {
          CHECK(true_errors[c] < true_errors[c - 1]);
          CHECK(value("transfer_energy_change") < 0.03);
          // The issue's criterion: the energy carried to the new mesh
          // differs from the old mesh's by less than the old mesh's
          // discretization error. In energy that error is the square of
          // the relative energy-norm error (Galerkin orthogonality), which
          // ZZ estimates; (2 + c) c bounds the relative energy change for
          // an energy-norm change c.
          const double change = value("transfer_energy_change");
          CHECK((2 + change) * change
                < std::pow(value("zz_relative_before_remeshing"), 2));
          CHECK(value("zz_relative_before_remeshing")
                == cycles.value(c - 1, "zz_relative_error"));
        }
      // The run stops once the target is met.
      const bool last = c + 1 == cycles.n_rows();
      CHECK((value("zz_relative_error") <= target) == last);
    }
  CHECK(cycles.n_rows() >= 3);

  const auto uniform = amfrac_test::run_scene<3>(
    argv[1],
    isotropic + coarse
      + "subsection Geometry\n  set Global refinements = 3\nend\n");
  const auto  &uniform_history = uniform->history();
  const double uniform_error
    = std::sqrt(std::max(0.,
                         reference
                           - uniform_history.value(uniform_history.n_rows() - 1,
                                                   "load_work")))
      / std::sqrt(reference);
  const double uniform_unknowns = uniform->dofs().n_dofs();
  const auto   last             = cycles.n_rows() - 1;
  if (root)
    std::cout << "uniform refinement: " << uniform_unknowns
              << " unknowns, true relative error " << uniform_error
              << std::endl;
  // The cell budget: the first remeshing would make about 6,900 cells;
  // with Maximum cells = 4000 its size field is scaled to that, and the
  // next cycle stops instead of remeshing.
  const auto budget = amfrac_test::run_scene<3>(
    argv[1],
    isotropic + coarse + remeshing
      + "subsection Adaptivity\n  set Maximum cells = 4000\nend\n");
  const auto &budget_cycles = *budget->adaptivity_history();
  if (root)
    std::cout << "Maximum cells = 4000: " << budget_cycles.n_rows()
              << " meshes, the last of "
              << budget_cycles.value(budget_cycles.n_rows() - 1, "cells")
              << " cells" << std::endl;
  CHECK(budget_cycles.n_rows() == 2);
  CHECK_CLOSE(budget_cycles.value(1, "predicted_cells"), 4000, 1e-9);
  CHECK_CLOSE(budget_cycles.value(1, "cells") / 4000, 1, 0.2);

  // Strategy = uniform halves every cell's in-plane size; the field's
  // smallest size around each vertex makes a graded mesh finer than 4x
  // (measured 5.6x, predicted 5.1x).
  const auto halved = amfrac_test::run_scene<3>(
    argv[1],
    isotropic + coarse
      + "subsection Adaptivity\n  set Refinement cycles = 1\n"
        "  set Strategy = uniform\nend\n");
  const auto  &halved_cycles = *halved->adaptivity_history();
  const double ratio
    = halved_cycles.value(1, "cells") / halved_cycles.value(0, "cells");
  if (root)
    std::cout << "Strategy = uniform: " << ratio << "x the cells" << std::endl;
  CHECK(halved_cycles.n_rows() == 2);
  CHECK(ratio > 4 && ratio < 6.5);
  CHECK_CLOSE(halved_cycles.value(1, "cells")
                / halved_cycles.value(1, "predicted_cells"),
              1,
              0.2);

  // At most the uniform error with fewer unknowns.
  CHECK(true_errors[last] < uniform_error);
  CHECK(cycles.value(last, "unknowns") < uniform_unknowns);
  return amfrac_test::summary();
}

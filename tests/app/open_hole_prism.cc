// The open-hole plate on a Gmsh prism mesh (prm/open_hole_prism.prm) with
// an isotropic material and nu = 0, whose 3D solution is exactly the plane
// stress one: P2 wedges against a converged adaptive Q2 run of the same
// plate in its plane (prm/open_hole_2d.prm, whose hole is on its circle).
// The wedges on the hole map it as a circle (HoleEdgeManifold), so the load
// work converges at the rate of P2 (h^4; on the polygon of straight-sided
// wedges it was h^2, with errors of 1.0e-4 and 2.4e-5), the stress
// concentration at the hole's edge matches the reference to 0.2 % (0.44 %
// and 0.19 % on the polygon) and Heywood's finite-width formula, and the
// edge is traction free.
#include "scene.h"

using namespace amfrac;

namespace
{
  /** The scene's settings besides the isotropic material (argv[3]). */
  const char *settings = R"(
subsection Discretization
  set Finite element degree = 2
end
subsection Output
  set Field format = none
  set Directory    = open_hole_prism_output
end
)";

  struct Result
  {
    double work, sigma_xx, sigma_yy;
  };

  template <int dim>
  Result
  run(const std::string &scene, const std::string &appended)
  {
    const auto  simulator = amfrac_test::run_scene<dim>(scene, appended);
    const auto &history   = simulator->history();
    const auto  last      = history.n_rows() - 1;
    return {history.value(last, "load_work"),
            history.value(last, "p0_stress_xx"),
            history.value(last, "p0_stress_yy")};
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (argc < 4)
    {
      std::cerr << "usage: open_hole_prism open_hole_prism.prm "
                   "open_hole_2d.prm open_hole_isotropic.prm\n";
      return 2;
    }
  const std::string   isotropic = amfrac_test::file_text(argv[3]) + settings;
  const Result        reference = run<2>(argv[2],
                                  isotropic
                                    + "subsection Adaptivity\n"
                                             "  set Refinement cycles = 7\n"
                                             "  set Refine fraction = 0.6\nend\n");
  std::vector<Result> prisms;
  for (const std::string refinements : {"0", "1"})
    prisms.push_back(run<3>(argv[1],
                            isotropic
                              + "subsection Geometry\n"
                                "  set Elements around hole = 48\n"
                                "  set Global refinements = "
                              + refinements
                              + "\nend\n"
                                "subsection Output\n"
                                "  set Point values = 36, 21, 0.5\nend\n"));

  const auto   scene     = parameters::Parameters::from_file(argv[1]);
  const double far_field = 100; // MPa, the scene's traction
  const double ratio   = 2 * scene.geometry.hole_radius / scene.geometry.width;
  const double heywood = (2 + std::pow(1 - ratio, 3)) / (1 - ratio);
  std::vector<double> errors;
  for (const auto &p : prisms)
    errors.push_back(std::abs(p.work / reference.work - 1));
  if (root)
    {
      std::cout << "2D reference: W = " << reference.work
                << ", K = " << reference.sigma_xx / far_field << " (Heywood "
                << heywood << ")" << std::endl;
      for (std::size_t i = 0; i < prisms.size(); ++i)
        std::cout << "prisms, " << i << " refinement(s): W = " << prisms[i].work
                  << " (relative error " << errors[i]
                  << "), K = " << prisms[i].sigma_xx / far_field
                  << ", sigma_yy at the edge " << prisms[i].sigma_yy
                  << std::endl;
    }
  CHECK(errors[0] < 2e-5);
  CHECK(errors[1] < 1.5e-6);
  // Halving the element size: h^4 divides the error by 16, h^2 by 4.
  CHECK(errors[0] > 10 * errors[1]);
  for (const auto &p : prisms)
    CHECK_CLOSE(p.sigma_xx / reference.sigma_xx, 1., 0.002);
  CHECK_CLOSE(prisms[1].sigma_xx / far_field, heywood, 0.015 * heywood);
  CHECK(std::abs(prisms[1].sigma_yy) < 0.005 * prisms[1].sigma_xx);
  return amfrac_test::summary();
}

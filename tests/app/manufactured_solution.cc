// Manufactured solution for a rotated orthotropic ply (30 degrees): a
// smooth non-polynomial displacement u_k = sin(a_k . x + phi_k), the body
// force f = -div(C : eps(u)) and Dirichlet data from u on all faces. The
// L2 and H1 errors must converge at rates p+1 and p (within 0.1) for Q1 and
// Q2 on hexahedra and for P1 and P2 on the same meshes split into wedges
// (prisms); the ConvergenceTables are printed and compared with numdiff
// against the stored regression values.
#include "../check.h"
#include "manufactured.h"

#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <fstream>

using namespace amfrac;

namespace
{
  using amfrac_test::Exact;

  const char *scene = R"(
set Dimension = 3
subsection Geometry
  set Stacking sequence     = [30]
  set Total thickness       = 1
  set Length                = 1
  set Width                 = 1
  set Elements along length = @N@
  set Elements along width  = @N@
  set Elements per ply      = @N@
  set Element shape         = @SHAPE@
end
subsection Discretization
  set Finite element degree = @DEGREE@
end
subsection Output
  set Field format = none
  set Directory    = manufactured_output
end
)";

} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool    root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ofstream table_file(argc > 1 ? argv[1] : "manufactured_solution.txt");
  for (const std::string shape : {"hexahedron", "prism"})
    for (const unsigned int degree : {1u, 2u})
      {
        const bool                      prisms = shape == "prism";
        ConvergenceTable                table;
        std::vector<double>             L2, H1;
        const std::vector<unsigned int> meshes
          = degree == 1 ? std::vector<unsigned int>{2, 4, 8, 16} :
                          std::vector<unsigned int>{2, 4, 8};
        for (const unsigned int n : meshes)
          {
            using amfrac_test::substitute;
            const auto prm = parameters::Parameters::from_string(
              substitute(substitute(substitute(scene, "@N@", std::to_string(n)),
                                    "@DEGREE@",
                                    std::to_string(degree)),
                         "@SHAPE@",
                         shape));
            auto         exact = std::make_shared<Exact>();
            Simulator<3> simulator(prm, MPI_COMM_WORLD);
            amfrac_test::pose_manufactured(simulator, prm, exact);
            simulator.run();

            L2.push_back(simulator.compute_error(*exact, VectorTools::L2_norm));
            H1.push_back(
              simulator.compute_error(*exact, VectorTools::H1_seminorm));
            table.add_value("cells", (prisms ? 2 : 1) * n * n * n);
            table.add_value("dofs", simulator.dofs().n_dofs());
            table.add_value("L2", L2.back());
            table.add_value("H1", H1.back());
          }
        table.set_scientific("L2", true);
        table.set_scientific("H1", true);
        table.set_precision("L2", 4);
        table.set_precision("H1", 4);
        table.evaluate_convergence_rates("L2",
                                         ConvergenceTable::reduction_rate_log2);
        table.evaluate_convergence_rates("H1",
                                         ConvergenceTable::reduction_rate_log2);
        if (root)
          {
            const std::string name
              = (prisms ? "prism P" : "Q") + std::to_string(degree);
            std::cout << name << std::endl;
            table.write_text(std::cout);
            table_file << name << std::endl;
            table.write_text(table_file);
          }

        // The rate of the finest refinement step: p+1 in L2, p in H1.
        const std::size_t last = L2.size() - 1;
        CHECK_CLOSE(std::log2(L2[last - 1] / L2[last]), degree + 1., 0.1);
        CHECK_CLOSE(std::log2(H1[last - 1] / H1[last]), double(degree), 0.1);
      }
  return amfrac_test::summary();
}

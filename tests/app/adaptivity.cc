// Error estimation and the refinement cycle.
//
// effectivity: the manufactured solution (tests/app/manufactured.h) on
//   uniform meshes; the ZZ estimate against the true energy error. The
//   effectivity index theta = ||e*|| / ||e|| must be within 0.9..1.1 on
//   the finest Q1 and Q2 meshes and move towards 1. An optional second
//   argument refines a region once more (e.g. "x < 0.5": hanging faces), a
//   third ("thin") makes the cube a plate 0.1 thick, one element through
//   it (window 0.8..1.2).
// peel: prm/adaptive_peel_2d.prm (a [0/90]s strip held on half of its
//   bottom face, singular where the hold ends) refined uniformly, by ZZ
//   and by Kelly. The true
//   energy error comes from the load work: ||u - u_h||_E^2 = W - W_h for a
//   load-driven scene with zero supports, W from a fine adaptive Q2 run.
//   Uniform refinement converges at a reduced rate; the adaptive cycles
//   must reach >= 0.9 of the optimal N^(-p/d) and the same error with
//   fewer unknowns.
// open_hole_2d: prm/open_hole_2d.prm (the open-hole laminate in its plane):
//   the stress concentration against Heywood's formula, the optimal rate
//   of uniform and ZZ refinement on a smooth problem, and the error target
//   reaching 1 % with 4x fewer unknowns than uniform refinement.
#include "../check.h"
#include "manufactured.h"

#include <amfrac/geometry/laminate.h>
#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <sstream>
#include <tuple>
#include <unistd.h>

using namespace amfrac;

namespace
{
  const char *cube = R"(
set Dimension = 3
subsection Geometry
  set Stacking sequence     = [30]
  set Total thickness       = @THICKNESS@
  set Length                = 1
  set Width                 = 1
  set Elements along length = @N@
  set Elements along width  = @N@
  set Elements per ply      = @LAYERS@
  set Refinement region     = @REGION@
end
subsection Discretization
  set Finite element degree = @DEGREE@
end
subsection Output
  set Field format = none
  set Directory    = adaptivity_effectivity
end
)";

  void
  effectivity(const bool root, const std::string &region, const bool thin)
  {
    // A plate 0.1 thick with one element through it cannot show the error
    // of its through-thickness variation, which grows as the in-plane mesh
    // is refined: a wider window there.
    const double window = thin ? 0.2 : 0.1;
    for (const unsigned int degree : {1u, 2u})
      {
        ConvergenceTable          table;
        std::vector<double>       theta;
        std::vector<unsigned int> meshes
          = degree == 1 ? std::vector<unsigned int>{4, 8, 16} :
                          std::vector<unsigned int>{2, 4, 8};
        for (const unsigned int n : meshes)
          {
            const auto prm
              = parameters::Parameters::from_string(amfrac_test::substitute(
                amfrac_test::substitute(
                  amfrac_test::substitute(
                    amfrac_test::substitute(
                      amfrac_test::substitute(cube, "@REGION@", region),
                      "@THICKNESS@",
                      thin ? "0.1" : "1"),
                    "@LAYERS@",
                    thin ? "1" : std::to_string(n)),
                  "@N@",
                  std::to_string(n)),
                "@DEGREE@",
                std::to_string(degree)));
            auto         exact = std::make_shared<amfrac_test::Exact>();
            Simulator<3> simulator(prm, MPI_COMM_WORLD);
            amfrac_test::pose_manufactured(simulator, prm, exact);
            simulator.run();
            const auto [estimate, error] = simulator.energy_errors(*exact);
            theta.push_back(estimate / error);
            table.add_value("cells", n * n * n);
            table.add_value("dofs", simulator.dofs().n_dofs());
            table.add_value("zz", estimate);
            table.add_value("true", error);
            table.add_value("theta", theta.back());
          }
        table.set_scientific("zz", true);
        table.set_scientific("true", true);
        table.evaluate_convergence_rates("true",
                                         ConvergenceTable::reduction_rate_log2);
        if (root)
          {
            std::cout << "Q" << degree << std::endl;
            table.write_text(std::cout);
          }
        // SPR: asymptotically exact for Q1 and Q2 on this smooth problem
        // (the coarsest Q2 mesh has no interior vertex: no full patch).
        amfrac_test::check(std::abs(theta.back() - 1) <= window,
                           "effectivity on the finest mesh within the window",
                           __FILE__,
                           __LINE__);
        if (!thin)
          amfrac_test::check(std::abs(theta.back() - 1) <= std::max(
                               std::abs(theta[theta.size() - 2] - 1), 0.05),
                             "effectivity tends to 1 (or stays within 5 %)",
                             __FILE__,
                             __LINE__);
      }
  }



  struct Run
  {
    std::vector<double> unknowns;
    std::vector<double> work;
    std::vector<double> zz;
    /** Stress at the first Output/Point values point (if any). */
    std::vector<double> probe_xx, probe_yy;
  };

  /** Every cycle of a 2D scene with @p settings appended to its
   * Adaptivity subsection. */
  Run
  cycles(const std::string &scene_file,
         const std::string &degree,
         const std::string &settings)
  {
    // Its own folder per process: ctest -j runs the tests that call this
    // side by side in one working directory.
    const std::string directory
      = "adaptivity_cycles_" + std::to_string(::getpid());
    std::ifstream      in(scene_file);
    std::ostringstream text;
    text << in.rdbuf() << "\nsubsection Discretization\n  set Finite element "
         << "degree = " << degree << "\nend\nsubsection Adaptivity\n"
         << settings << "\nend\nsubsection Output\n  set Field format = "
         << "none\n  set Directory = " << directory << "\nend\n";
    const auto   prm = parameters::Parameters::from_string(text.str());
    Simulator<2> simulator(prm, MPI_COMM_WORLD);
    simulator.run();
    (void)simulator;
    Run           run;
    std::ifstream csv(directory + "/adaptivity.csv");
    std::string   line, header;
    std::getline(csv, header);
    const auto column = [&](const std::string &name) {
      std::istringstream names(header);
      std::string        cell;
      for (unsigned int k = 0; std::getline(names, cell, ','); ++k)
        if (cell == name)
          return k;
      return numbers::invalid_unsigned_int;
    };
    const unsigned int c_unknowns = column("unknowns"),
                       c_work = column("load_work"), c_zz = column("zz_error"),
                       c_xx = column("p0_stress_xx"),
                       c_yy = column("p0_stress_yy");
    if (c_unknowns == numbers::invalid_unsigned_int
        || c_work == numbers::invalid_unsigned_int
        || c_zz == numbers::invalid_unsigned_int)
      throw std::runtime_error("adaptivity.csv lacks a column");
    while (std::getline(csv, line))
      {
        std::istringstream  cells(line);
        std::string         cell;
        std::vector<double> row;
        while (std::getline(cells, cell, ','))
          row.push_back(std::stod(cell));
        run.unknowns.push_back(row[c_unknowns]);
        run.work.push_back(row[c_work]);
        run.zz.push_back(row[c_zz]);
        if (c_xx != numbers::invalid_unsigned_int)
          {
            run.probe_xx.push_back(row[c_xx]);
            run.probe_yy.push_back(row[c_yy]);
          }
      }
    return run;
  }

  /** Least-squares slope of log(error) against log(unknowns) over the
   * last @p n points. */
  double
  rate(const std::vector<double> &unknowns,
       const std::vector<double> &error,
       const unsigned int         n)
  {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = error.size() - n; i < error.size(); ++i)
      {
        const double x = std::log(unknowns[i]), y = std::log(error[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
      }
    return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
  }

  void
  singular(const std::string &scene_file, const bool root)
  {
    const Run    reference = cycles(scene_file,
                                 "2",
                                 "set Refinement cycles = 9\n"
                                    "set Refine fraction = 0.6");
    const double W         = reference.work.back();
    struct Case
    {
      const char *name;
      const char *settings;
    };
    const Case cases[]
      = {{"uniform", "set Refinement cycles = 4\nset Strategy = uniform"},
         {"zz", "set Refinement cycles = 8\nset Refine fraction = 0.5"},
         {"kelly",
          "set Refinement cycles = 8\nset Refine fraction = 0.5\n"
          "set Estimator = kelly"}};
    std::vector<double> rates, finest_error, finest_unknowns;
    std::vector<Run>    runs;
    for (const auto &c : cases)
      {
        const Run           run = cycles(scene_file, "1", c.settings);
        std::vector<double> error;
        for (const double w : run.work)
          error.push_back(std::sqrt(std::max(W - w, 0.)));
        rates.push_back(rate(run.unknowns, error, 3));
        // On uniform meshes the singularity dominates and ZZ underestimates
        // (0.90 on the last one); on the adapted meshes it is resolved.
        if (std::string(c.name) != "uniform")
          amfrac_test::check(std::abs(run.zz.back() / error.back() - 1) <= 0.1,
                             std::string(c.name)
                               + ": ZZ effectivity on the last mesh within "
                                 "0.9..1.1 (four plies, singular)",
                             __FILE__,
                             __LINE__);
        runs.push_back(run);
        runs.back().work = error;
        finest_error.push_back(error.back());
        finest_unknowns.push_back(run.unknowns.back());
        if (root)
          {
            std::cout << c.name << ": rate " << rates.back() << std::endl;
            for (std::size_t i = 0; i < error.size(); ++i)
              std::cout << "  " << run.unknowns[i] << " unknowns, error "
                        << error[i] << ", zz " << run.zz[i] << ", theta "
                        << run.zz[i] / error[i] << std::endl;
          }
      }
    // The unknowns an adaptive run needs for the error of the finest
    // uniform mesh (first cycle at or below it).
    for (unsigned int k = 1; k < 3; ++k)
      {
        double needed = 0;
        for (std::size_t i = 0; i < runs[k].work.size() && needed == 0; ++i)
          if (runs[k].work[i] <= finest_error[0])
            needed = runs[k].unknowns[i];
        if (root)
          std::cout << cases[k].name << " reaches the finest uniform error "
                    << finest_error[0] << " with " << needed << " unknowns ("
                    << finest_unknowns[0] << " uniform)" << std::endl;
        amfrac_test::check(needed > 0 && 4 * needed <= finest_unknowns[0],
                           "adaptive: the finest uniform error with 4x fewer "
                           "unknowns",
                           __FILE__,
                           __LINE__);
      }
    // Optimal for Q1 in 2D: N^(-1/2).
    amfrac_test::check(rates[0] < 0.4,
                       "uniform refinement converges at a reduced rate",
                       __FILE__,
                       __LINE__);
    amfrac_test::check(rates[1] >= 0.9 * 0.5,
                       "ZZ refinement reaches 0.9 of N^(-1/2)",
                       __FILE__,
                       __LINE__);
    amfrac_test::check(rates[2] >= 0.9 * 0.5,
                       "Kelly refinement reaches 0.9 of N^(-1/2)",
                       __FILE__,
                       __LINE__);
  }

  /** Relative energy errors sqrt((W - W_h) / W) of a run. */
  std::vector<double>
  relative_errors(const Run &run, const double W)
  {
    std::vector<double> error;
    for (const double w : run.work)
      error.push_back(std::sqrt(std::max(W - w, 0.) / W));
    return error;
  }

  /** Unknowns at which a run first reaches @p target, and by log-log
   * interpolation between the cycles around it (0, 0 if never). */
  std::pair<double, double>
  unknowns_at(const Run                 &run,
              const std::vector<double> &error,
              const double               target)
  {
    for (std::size_t i = 0; i < error.size(); ++i)
      if (error[i] <= target)
        {
          if (i == 0)
            return {run.unknowns[0], run.unknowns[0]};
          const double s = std::log(error[i - 1] / target)
                           / std::log(error[i - 1] / error[i]);
          return {run.unknowns[i],
                  run.unknowns[i - 1]
                    * std::pow(run.unknowns[i] / run.unknowns[i - 1], s)};
        }
    return {0, 0};
  }

  /**
   * The open-hole laminate in its plane (prm/open_hole_2d.prm: a
   * quasi-isotropic laminate, in-plane isotropic, a hole of diameter d in
   * a strip of width W under tension). The stress concentration at the
   * hole's edge against Heywood's finite-width formula for the gross
   * section, K = (2 + (1 - d/W)^3) / (1 - d/W); the true energy error
   * from the load work against a fine adaptive Q2 run. The solution is
   * smooth: uniform Q1 converges at the optimal N^(-1/2), and the ZZ
   * refinement reaches 1 % with at least 4 times fewer unknowns than the
   * first uniform mesh that does.
   */
  void
  open_hole_in_plane(const std::string &scene_file, const bool root)
  {
    const Run reference
      = cycles(scene_file,
               "2",
               "set Refinement cycles = 7\nset Refine fraction = 0.6");
    const double W         = reference.work.back();
    const auto   prm       = parameters::Parameters::from_file(scene_file);
    const double ratio     = 2 * prm.geometry.hole_radius / prm.geometry.width;
    const double heywood   = (2 + std::pow(1 - ratio, 3)) / (1 - ratio);
    const double far_field = 100; // MPa, the scene's traction
    if (root)
      std::cout << "reference: " << reference.unknowns.back()
                << " unknowns, W = " << W
                << ", K = " << reference.probe_xx.back() / far_field
                << " (Heywood " << heywood << "), sigma_yy at the edge "
                << reference.probe_yy.back() << std::endl;
    CHECK_CLOSE(reference.probe_xx.back() / far_field,
                heywood,
                0.015 * heywood);
    amfrac_test::check(std::abs(reference.probe_yy.back())
                         < 0.005 * reference.probe_xx.back(),
                       "the hole's edge is traction free",
                       __FILE__,
                       __LINE__);

    const Run uniform
      = cycles(scene_file,
               "1",
               "set Refinement cycles = 4\nset Strategy = uniform");
    const Run target = cycles(scene_file,
                              "1",
                              "set Refinement cycles = 12\nset Strategy = "
                              "error target\nset Target error = 0.01");
    const Run zz
      = cycles(scene_file,
               "1",
               "set Refinement cycles = 8\nset Refine fraction = 0.5");
    const auto   uniform_error = relative_errors(uniform, W);
    const auto   target_error  = relative_errors(target, W);
    const auto   zz_error      = relative_errors(zz, W);
    const double uniform_rate  = rate(uniform.unknowns, uniform_error, 3);
    const double zz_rate       = rate(zz.unknowns, zz_error, 3);
    const auto   uniform_1     = unknowns_at(uniform, uniform_error, 0.01);
    const auto   target_1      = unknowns_at(target, target_error, 0.01);
    if (root)
      {
        for (const auto &[name, run, error] :
             {std::tuple{"uniform", &uniform, &uniform_error},
              std::tuple{"zz target 1 %", &target, &target_error},
              std::tuple{"zz", &zz, &zz_error}})
          for (std::size_t i = 0; i < error->size(); ++i)
            std::cout << "  " << name << ": " << run->unknowns[i]
                      << " unknowns, error " << (*error)[i] << ", theta "
                      << run->zz[i] / ((*error)[i] * std::sqrt(W)) << std::endl;
        std::cout << "rates: uniform " << uniform_rate << ", zz " << zz_rate
                  << "; 1 %: uniform " << uniform_1.first << " ("
                  << uniform_1.second << " interpolated), zz target "
                  << target_1.first << " (" << target_1.second << ")"
                  << std::endl;
      }
    // Optimal for Q1 in 2D: N^(-1/2), for uniform and adaptive meshes.
    amfrac_test::check(uniform_rate >= 0.9 * 0.5,
                       "uniform Q1 at 0.9 of N^(-1/2) (smooth solution)",
                       __FILE__,
                       __LINE__);
    amfrac_test::check(zz_rate >= 0.9 * 0.5,
                       "ZZ refinement at 0.9 of N^(-1/2)",
                       __FILE__,
                       __LINE__);
    amfrac_test::check(target_error.back() <= 0.01,
                       "the error target stops at a true error <= 1 %",
                       __FILE__,
                       __LINE__);
    amfrac_test::check(target_1.first > 0
                         && 4 * target_1.first <= uniform_1.first,
                       "1 % with 4x fewer unknowns than uniform refinement",
                       __FILE__,
                       __LINE__);
    amfrac_test::check(target_1.second > 0
                         && 3.5 * target_1.second <= uniform_1.second,
                       "interpolated to 1 %: 3.5x fewer unknowns",
                       __FILE__,
                       __LINE__);
    const double theta = zz.zz.back() / (zz_error.back() * std::sqrt(W));
    CHECK_CLOSE(theta, 1., 0.3);
  }

  /** The open-hole mesh of prm/open_hole_plate.prm refined twice on its
   * manifolds: volume, hole surface and end faces against the exact
   * geometry, plies in place. */
  void
  open_hole(const std::string &scene_file)
  {
    const auto       prm = parameters::Parameters::from_file(scene_file);
    const Laminate   laminate(prm.geometry, prm.materials);
    Triangulation<3> mesh;
    make_laminate_mesh<3>(prm.geometry, laminate, mesh);
    mesh.refine_global(2);
    const double L = prm.geometry.length, W = prm.geometry.width,
                 r = prm.geometry.hole_radius, t = laminate.thickness();
    double volume = 0, hole = 0, end = 0, top = 0;
    bool   plies_in_place = true;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        volume += cell->measure();
        const double z = cell->center()[2];
        plies_in_place
          = plies_in_place && z > laminate.ply_boundaries[cell->material_id()]
            && z < laminate.ply_boundaries[cell->material_id() + 1];
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto id = cell->face(f)->boundary_id();
              hole += id == 6 ? cell->face(f)->measure() : 0.;
              end += id == 1 ? cell->face(f)->measure() : 0.;
              top += id == 5 ? cell->face(f)->measure() : 0.;
            }
      }
    std::cout << "volume " << volume << ", hole " << hole << ", end " << end
              << ", top " << top << std::endl;
    // Straight-sided cells on a circle of 128 segments: 1e-3 relative.
    CHECK_CLOSE(volume / ((L * W - M_PI * r * r) * t), 1., 1e-3);
    CHECK_CLOSE(hole / (2 * M_PI * r * t), 1., 1e-3);
    CHECK_CLOSE(end / (W * t), 1., 1e-12);
    CHECK_CLOSE(top / (L * W - M_PI * r * r), 1., 1e-3);
    amfrac_test::check(plies_in_place,
                       "every cell between its ply's boundaries",
                       __FILE__,
                       __LINE__);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "effectivity")
    effectivity(root,
                argc > 2 ? argv[2] : "",
                argc > 3 && std::string(argv[3]) == "thin");
  else if (mode == "hole" && argc > 2)
    open_hole(argv[2]);
  else if (mode == "peel" && argc > 2)
    singular(argv[2], root);
  else if (mode == "open_hole_2d" && argc > 2)
    open_hole_in_plane(argv[2], root);
  else
    {
      std::cerr
        << "usage: app_adaptivity effectivity [REGION [thin]] | peel SCENE.prm | "
           "hole SCENE.prm | open_hole_2d SCENE.prm"
        << std::endl;
      return 2;
    }
  return amfrac_test::summary();
}

// Patch test: on a randomly distorted mesh of a [0/45/90/-30] laminate, a
// piecewise-linear displacement field that is an exact elasticity solution
// (uniform in-plane strain, through-thickness strains chosen per ply so that
// the laminate is traction free on z = const planes) is reproduced to
// round-off by Q1 and Q2, also where part of the mesh is refined (hanging
// nodes). The same in 2D plane strain (y through the thickness), and in 3D
// on the distorted mesh split into wedges (P1 and P2 prisms, no refinement:
// wedges cannot be refined). Runs on any number of MPI ranks.
#include "../check.h"

#include <amfrac/parameters/parameters.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

using namespace amfrac;

namespace
{
  const double eps_xx = 1e-3, eps_yy = -4e-4, gamma_xy = 6e-4;

  /** u(x) = E x + g(z), g piecewise linear through the plies. */
  class LaminatePatchField : public Function<3>
  {
  public:
    LaminatePatchField(const Laminate                      &laminate,
                       const std::vector<PlyProperties<3>> &plies)
      : Function<3>(3)
      , laminate(laminate)
    {
      // Per ply: the strains eps_xz, eps_yz, eps_zz that make
      // sigma_xz = sigma_yz = sigma_zz = 0 for the given in-plane strains.
      const unsigned int out[3][2] = {{0, 2}, {1, 2}, {2, 2}};
      for (const auto &ply : plies)
        {
          const auto            &C = ply.stiffness_3d;
          FullMatrix<double>     A(3, 3);
          dealii::Vector<double> rhs(3), x(3);
          for (unsigned int r = 0; r < 3; ++r)
            {
              const unsigned int i = out[r][0], j = out[r][1];
              for (unsigned int k = 0; k < 3; ++k)
                A(r, k) = (k == 2 ? 1. : 2.) * C[i][j][out[k][0]][out[k][1]];
              rhs(r) = -(C[i][j][0][0] * eps_xx + C[i][j][1][1] * eps_yy
                         + 2 * C[i][j][0][1] * 0.5 * gamma_xy);
            }
          A.gauss_jordan();
          A.vmult(x, rhs);
          through_thickness.push_back({{x(0), x(1), x(2)}});
        }
    }

    double
    value(const Point<3> &p, const unsigned int component) const override
    {
      // Integrate the piecewise-constant gradients d(u_x, u_y, u_z)/dz =
      // (2 eps_xz, 2 eps_yz, eps_zz) from z = 0.
      double g[3] = {0, 0, 0};
      for (unsigned int k = 0; k < laminate.n_plies(); ++k)
        {
          const double z0 = laminate.ply_boundaries[k];
          const double z1 = std::min(p[2], laminate.ply_boundaries[k + 1]);
          if (z1 <= z0)
            break;
          g[0] += 2 * through_thickness[k][0] * (z1 - z0);
          g[1] += 2 * through_thickness[k][1] * (z1 - z0);
          g[2] += through_thickness[k][2] * (z1 - z0);
        }
      const double in_plane[3] = {eps_xx * p[0] + 0.5 * gamma_xy * p[1],
                                  0.5 * gamma_xy * p[0] + eps_yy * p[1],
                                  0.};
      return in_plane[component] + g[component];
    }

    Tensor<1, 3>
    gradient(const Point<3> &p, const unsigned int component) const override
    {
      unsigned int k = 0;
      while (k + 1 < laminate.n_plies()
             && p[2] > laminate.ply_boundaries[k + 1])
        ++k;
      const auto  &t = through_thickness[k];
      Tensor<1, 3> g;
      if (component == 0)
        g = Tensor<1, 3>({eps_xx, 0.5 * gamma_xy, 2 * t[0]});
      else if (component == 1)
        g = Tensor<1, 3>({0.5 * gamma_xy, eps_yy, 2 * t[1]});
      else
        g = Tensor<1, 3>({0., 0., t[2]});
      return g;
    }

  private:
    const Laminate                    &laminate;
    std::vector<std::array<double, 3>> through_thickness;
  };

  /** Plane strain, y through the thickness: u = (eps_xx x + g_x(y),
   * g_y(y)) with eps_xy, eps_yy per ply such that sigma_xy = sigma_yy = 0. */
  class PlaneStrainPatchField : public Function<2>
  {
  public:
    PlaneStrainPatchField(const Laminate                      &laminate,
                          const std::vector<PlyProperties<2>> &plies)
      : Function<2>(2)
      , laminate(laminate)
    {
      for (const auto &ply : plies)
        {
          const auto &C = ply.stiffness;
          // Unknowns (eps_xy, eps_yy); rows sigma_xy = 0, sigma_yy = 0.
          const double a11 = 2 * C[0][1][0][1], a12 = C[0][1][1][1];
          const double a21 = 2 * C[1][1][0][1], a22 = C[1][1][1][1];
          const double b1  = -C[0][1][0][0] * eps_xx;
          const double b2  = -C[1][1][0][0] * eps_xx;
          const double det = a11 * a22 - a12 * a21;
          through_thickness.push_back(
            {{(b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det}});
        }
    }

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      double g[2] = {0, 0};
      for (unsigned int k = 0; k < laminate.n_plies(); ++k)
        {
          const double y0 = laminate.ply_boundaries[k];
          const double y1 = std::min(p[1], laminate.ply_boundaries[k + 1]);
          if (y1 <= y0)
            break;
          g[0] += 2 * through_thickness[k][0] * (y1 - y0);
          g[1] += through_thickness[k][1] * (y1 - y0);
        }
      return (component == 0 ? eps_xx * p[0] : 0.) + g[component];
    }

    Tensor<1, 2>
    gradient(const Point<2> &p, const unsigned int component) const override
    {
      unsigned int k = 0;
      while (k + 1 < laminate.n_plies()
             && p[1] > laminate.ply_boundaries[k + 1])
        ++k;
      const auto &t = through_thickness[k];
      return component == 0 ? Tensor<1, 2>({eps_xx, 2 * t[0]}) :
                              Tensor<1, 2>({0., t[1]});
    }

  private:
    const Laminate                    &laminate;
    std::vector<std::array<double, 2>> through_thickness;
  };

  const char *scene = R"(
set Dimension = @DIM@
subsection Geometry
  set Stacking sequence     = [0/45/90/-30]
  set Ply thickness         = 0.25, 0.15, 0.3, 0.2
  set Length                = 4
  set Width                 = 3
  set Elements along length = 4
  set Elements along width  = 3
  set Elements per ply      = 2
  set Mesh distortion       = 0.25
  set Element shape         = @SHAPE@
@REGION@
end
subsection Discretization
  set Finite element degree = @DEGREE@
end
subsection Output
  set Field format = none
  set Directory    = patch_test_output
end
)";


  /** Prescribe the field on the lateral faces (the thickness faces stay
   * traction free) and compare. */
  template <int dim, typename Field>
  void
  check_patch(const std::string &degree,
              const bool         prisms    = false,
              const std::string &mesh_file = "",
              const bool         refine    = false)
  {
    using amfrac_test::substitute;
    const std::string region = prisms || (!mesh_file.empty() && !refine) ?
                                 "" :
                                 "  set Refinement region     = x < 1.5\n"
                                 "  set Region refinements    = 1";
    std::string       text   = substitute(
      substitute(substitute(substitute(scene, "@DIM@", std::to_string(dim)),
                            "@DEGREE@",
                            degree),
                 "@SHAPE@",
                 prisms ? "prism" : "hexahedron"),
      "@REGION@",
      region);
    // A Gmsh file instead of the distorted box (and once refined, by
    // Gmsh, or else in the Refinement region).
    if (!mesh_file.empty())
      text = substitute(text,
                        "set Mesh distortion       = 0.25",
                        "set Mesh file = " + mesh_file
                          + "\n  set Global refinements = "
                          + (refine ? "0" : "1"));
    const auto     prm = parameters::Parameters::from_string(text);
    const Laminate laminate(prm.geometry, prm.materials);
    const auto     plies = make_ply_table<dim>(laminate, prm.materials);
    auto           exact = std::make_shared<Field>(laminate, plies);

    Simulator<dim>                           simulator(prm, MPI_COMM_WORLD);
    std::vector<PrescribedDisplacement<dim>> supports;
    std::array<bool, dim>                    all;
    all.fill(true);
    for (types::boundary_id id = 0; id < 2 * (dim - 1); ++id)
      supports.push_back(
        {"side" + std::to_string(id), id, exact, all, nullptr});
    simulator.set_prescribed_displacements(supports);
    simulator.run();

    const Functions::ZeroFunction<dim> zero(dim);
    const double error = simulator.compute_error(*exact, VectorTools::L2_norm);
    const double norm  = simulator.compute_error(zero, VectorTools::L2_norm);
    const double h1 = simulator.compute_error(*exact, VectorTools::H1_seminorm);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout
        << dim << "D " << (prisms ? "prism P" : "Q") << degree
        << (mesh_file.empty() ? "" : " on " + mesh_file) << ", "
        << simulator.dofs().copy_handler().get_triangulation().n_active_cells()
        << " cells"
        << ": relative L2 error " << error / norm << ", H1 seminorm error "
        << h1 << std::endl;
    CHECK(error / norm < 1e-10);
    CHECK(h1 < 1e-10);
    CHECK(norm > 1e-4); // the field is not trivially zero
    // The mesh is made of the shape asked for.
    CHECK(simulator.dofs().reference_cell()
          == (prisms ? ReferenceCells::Wedge :
                       ReferenceCells::get_hypercube<dim>()));
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // argv[1]: the folder of the Gmsh meshes (tests/app/meshes).
  const std::string meshes = argc > 1 ? std::string(argv[1]) + "/" : "";
  for (const std::string degree : {"1", "2"})
    {
      check_patch<3, LaminatePatchField>(degree);
      check_patch<3, LaminatePatchField>(degree, /*prisms=*/true);
      check_patch<2, PlaneStrainPatchField>(degree);
      if (!meshes.empty())
        {
          // Unstructured triangles of a disk (.geo) as wedges, and the
          // quadrilaterals of a trapezoid (.msh) as hexahedra.
          check_patch<3, LaminatePatchField>(degree, true, meshes + "disk.geo");
          check_patch<3, LaminatePatchField>(degree,
                                             false,
                                             meshes + "trapezoid_quads.msh");
          // 3D .msh files, the plies from their physical volumes: the
          // disk's wedges, and hexahedra extruded along x (turned by the
          // reader).
          check_patch<3, LaminatePatchField>(degree,
                                             true,
                                             meshes + "disk_plies.msh");
          check_patch<3, LaminatePatchField>(degree,
                                             false,
                                             meshes + "block_plies_x.msh");
          // Unstructured hexahedra of a 3D .geo whose neighbours number
          // their vertices from unrelated corners, refined in a region
          // (hanging nodes across such faces).
          check_patch<3, LaminatePatchField>(degree,
                                             false,
                                             meshes + "trapezoid_plies.geo",
                                             /*refine=*/true);
        }
    }
  return amfrac_test::summary();
}

#include <algorithm>
#include <amfrac/geometry/hole_edge_manifold.h>
#include <amfrac/geometry/in_plane_refinement.h>
#include <amfrac/geometry/laminate.h>
#include <amfrac/geometry/plane_mesh.h>
#include <amfrac/geometry/volume_mesh.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <map>
#include <numeric>
#include <random>
#include <sstream>

namespace amfrac
{
  Laminate::Laminate(const parameters::Geometry  &geometry,
                     const parameters::Materials &materials)
    : plies(geometry.plies)
    , in_plane(geometry.in_plane)
  {
    ply_boundaries.push_back(0);
    for (unsigned int p = 0; p < plies.size(); ++p)
      {
        material_of_ply.push_back(materials.index_of(plies[p].material));
        ply_boundaries.push_back(ply_boundaries.back()
                                 + geometry.ply_thickness[p]);
      }
  }



  namespace
  {
    /**
     * Move interior vertices randomly (reproducibly: the same on every MPI
     * rank) by up to @p amount element sizes. A vertex on a ply boundary
     * keeps its thickness coordinate so that plies stay flat layers.
     */
    template <int dim>
    void
    distort_interior_vertices(Triangulation<dim>            &tria,
                              const std::vector<double>     &layer_planes,
                              const double                   amount,
                              const Point<dim>              &box,
                              const std::array<double, dim> &h)
    {
      const unsigned int thickness_axis = dim - 1;
      const double       tol            = 1e-10 * box.norm();
      std::vector<bool>  moved(tria.n_vertices(), false);
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int index = cell->vertex_index(v);
            if (moved[index])
              continue;
            moved[index]   = true;
            Point<dim>  &p = cell->vertex(v);
            std::mt19937 generator(1234567u + 7919u * index);
            std::uniform_real_distribution<double> shift(-amount, amount);
            bool                                   on_boundary = false;
            for (unsigned int d = 0; d < dim; ++d)
              on_boundary = on_boundary || std::abs(p[d]) < tol * 1e3
                            || std::abs(p[d] - box[d]) < tol * 1e3;
            if (on_boundary)
              continue;
            const bool on_ply_boundary
              = std::any_of(layer_planes.begin(),
                            layer_planes.end(),
                            [&](const double z) {
                              return std::abs(p[thickness_axis] - z) < tol;
                            });
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double delta = shift(generator) * h[d];
                if (d != thickness_axis || !on_ply_boundary)
                  p[d] += delta;
              }
          }
    }

    /** Every step split into @p parts equal steps. */
    std::vector<double>
    subdivide_steps(const std::vector<double> &steps, const unsigned int parts)
    {
      std::vector<double> fine;
      for (const double step : steps)
        fine.insert(fine.end(), parts, step / parts);
      return fine;
    }

    /** @p n steps over @p length, shortest at both ends and growing
     * geometrically towards the middle so that the longest is @p ratio
     * times the shortest (a symmetric grading; ratio 1: uniform). */
    std::vector<double>
    graded_steps(const unsigned int n, const double length, const double ratio)
    {
      const unsigned int half = (n + 1) / 2;
      const double growth = half > 1 ? std::pow(ratio, 1. / (half - 1)) : 1.;
      std::vector<double> steps(n);
      for (unsigned int i = 0; i < n; ++i)
        steps[i] = std::pow(growth, std::min(i, n - 1 - i));
      const double sum = std::accumulate(steps.begin(), steps.end(), 0.);
      for (double &step : steps)
        step *= length / sum;
      return steps;
    }

    /** Boundary ids 0..2*dim-1 on the faces x-, x+, y-, y+, (z-, z+) of
     * the box [0, box] (deal.II's colorize numbering). */
    template <int dim>
    void
    colorize_box_faces(const Point<dim> &box, Triangulation<dim> &tria)
    {
      const double tol = 1e-10 * box.norm();
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<dim> c = cell->face(f)->center();
              for (unsigned int d = 0; d < dim; ++d)
                {
                  if (std::abs(c[d]) < tol)
                    cell->face(f)->set_boundary_id(2 * d);
                  else if (std::abs(c[d] - box[d]) < tol)
                    cell->face(f)->set_boundary_id(2 * d + 1);
                }
            }
    }

    /** The structured box of subdivided_hyper_rectangle with the same
     * vertices, every hexahedron split into two wedges: the in-plane
     * diagonal alternates like a chessboard so that the mesh has no
     * preferred direction, and no diagonal ends in the corner of the box
     * (with an even number of cells per side): a corner triangle would be
     * one element stiff in the plate's corner, where a simply supported
     * plate has its concentrated corner force. */
    template <int dim>
    void
    make_prism_box(const std::vector<std::vector<double>> &steps,
                   const Point<dim>                       &box,
                   Triangulation<dim>                     &triangulation)
    {
      if constexpr (dim != 3)
        {
          (void)steps;
          (void)box;
          (void)triangulation;
          throw InputError("Geometry/Element shape",
                           "prisms need Dimension = 3");
        }
      else
        {
          std::array<std::vector<double>, 3> coordinates;
          for (unsigned int d = 0; d < 3; ++d)
            {
              coordinates[d] = {0.};
              for (const double step : steps[d])
                coordinates[d].push_back(coordinates[d].back() + step);
            }
          const unsigned int nx = steps[0].size(), ny = steps[1].size(),
                             nz = steps[2].size();
          const auto vertex
            = [&](unsigned int i, unsigned int j, unsigned int k) {
                return (k * (ny + 1) + j) * (nx + 1) + i;
              };
          std::vector<Point<3>> vertices;
          for (unsigned int k = 0; k <= nz; ++k)
            for (unsigned int j = 0; j <= ny; ++j)
              for (unsigned int i = 0; i <= nx; ++i)
                vertices.emplace_back(coordinates[0][i],
                                      coordinates[1][j],
                                      coordinates[2][k]);
          std::vector<CellData<3>> cells;
          const unsigned int       layer = vertex(0, 0, 1);
          for (unsigned int k = 0; k < nz; ++k)
            for (unsigned int j = 0; j < ny; ++j)
              for (unsigned int i = 0; i < nx; ++i)
                {
                  // The quad a b c d counterclockwise from +z; both
                  // triangles keep that orientation, so the wedges have a
                  // positive Jacobian.
                  const unsigned int a = vertex(i, j, k), b = a + 1,
                                     c = vertex(i + 1, j + 1, k), d = c - 1;
                  const std::array<std::array<unsigned int, 3>, 2> triangles
                    = (i + j) % 2 == 1 ?
                        std::array<std::array<unsigned int, 3>, 2>{
                          {{{a, b, c}}, {{a, c, d}}}} :
                        std::array<std::array<unsigned int, 3>, 2>{
                          {{{a, b, d}}, {{b, c, d}}}};
                  for (const auto &triangle : triangles)
                    {
                      CellData<3> cell(6);
                      for (unsigned int v = 0; v < 3; ++v)
                        {
                          cell.vertices[v]     = triangle[v];
                          cell.vertices[v + 3] = triangle[v] + layer;
                        }
                      cells.push_back(cell);
                    }
                }
          triangulation.create_triangulation(vertices, cells, SubCellData());
          colorize_box_faces(box, triangulation);
        }
    }
    /** Thickness coordinates of the element layers: Elements per ply
     * equal layers in every ply. */
    std::vector<double>
    layer_coordinates(const parameters::Geometry &geometry,
                      const Laminate             &laminate)
    {
      std::vector<double> z{0.};
      for (unsigned int p = 0; p < laminate.n_plies(); ++p)
        for (unsigned int k = 1; k <= geometry.elements_per_ply; ++k)
          z.push_back(
            laminate.ply_boundaries[p]
            + (laminate.ply_boundaries[p + 1] - laminate.ply_boundaries[p]) * k
                / geometry.elements_per_ply);
      return z;
    }


    /** An extruded open-hole plate gets HoleEdgeManifold (manifold id 2)
     * on every cell, face and edge, so that P2 wedges map the hole as a
     * circle, not as the polygon of Gmsh's nodes on it. On the whole mesh,
     * not only around the hole: deal.II 9.4's MappingFE asserts (in debug
     * builds) that all manifold ids of a cell are equal, and a neighbour
     * of a hole cell would share faces with id 2. Away from the hole the
     * manifold is flat. */
    void
    attach_hole_edge_manifold(const parameters::Geometry &geometry,
                              Triangulation<3>           &triangulation)
    {
      triangulation.set_all_manifold_ids(2);
      triangulation.set_manifold(2,
                                 HoleEdgeManifold(Point<3>(0.5
                                                             * geometry.length,
                                                           0.5 * geometry.width,
                                                           0),
                                                  geometry.hole_radius));
    }


    /** The laminate of a 3D Geometry/Mesh file, its plies from the
     * file's physical volumes; false if the file is 2D. */
    bool
    make_volume_laminate(const parameters::Geometry &geometry,
                         const Laminate             &laminate,
                         Triangulation<3>           &triangulation)
    {
      const std::string &file = geometry.mesh_file;
      const std::string  extension
        = file.size() > 4 ? file.substr(file.size() - 4) : "";
      if (extension != ".msh" && extension != ".geo")
        return false;
      const VolumeMesh volume = make_mesh_on_root<VolumeMesh>(
        [&]() {
          return read_volume_mesh(file,
                                  laminate.n_plies(),
                                  geometry.global_refinements);
        },
        triangulation.get_communicator());
      if (volume.empty())
        return false;
      const bool wedges = volume.cells[0].size() == 6;
      if (wedges != geometry.prisms)
        throw InputError("Geometry/Element shape",
                         std::string(geometry.prisms ? "prism" : "hexahedron")
                           + " does not match '" + file + "', a mesh of "
                           + (wedges ? "wedges (set Element shape = prism)" :
                                       "hexahedra (set Element shape = "
                                       "hexahedron)"));
      create_volume_mesh(volume, triangulation);
      return true;
    }


    /** The laminate of a Gmsh mesh (Geometry/Mesh file, or an open hole
     * on prisms; @p given: a remeshing's in-plane mesh): a 2D mesh is
     * extruded through the element layers. Returns whether the file gave
     * the plies (a 3D file). */
    template <int dim>
    bool
    make_gmsh_laminate(const parameters::Geometry &geometry,
                       const Laminate             &laminate,
                       Triangulation<dim>         &triangulation,
                       const PlaneMesh            *given)
    {
      if constexpr (dim != 3)
        {
          (void)laminate;
          (void)triangulation;
          (void)given;
          throw InputError(geometry.mesh_file.empty() ?
                             "Geometry/Element shape" :
                             "Geometry/Mesh file",
                           "a Gmsh mesh is extruded: it needs Dimension = 3");
        }
      else
        {
          if (!given && make_volume_laminate(geometry, laminate, triangulation))
            return true;
          const PlaneMesh plane
            = given ? *given :
                      make_mesh_on_root<PlaneMesh>(
                        [&]() {
                          if (geometry.mesh_file.empty())
                            return mesh_open_hole_plane(geometry.length,
                                                        geometry.width,
                                                        geometry.hole_radius,
                                                        open_hole_element_size(
                                                          geometry));
                          return read_plane_mesh(
                            geometry.mesh_file,
                            std::pow(0.5, geometry.global_refinements),
                            geometry.global_refinements);
                        },
                        triangulation.get_communicator());
          const bool mixed
            = !plane.triangles.empty() && !plane.quadrilaterals.empty();
          if (!mixed && geometry.prisms && !plane.quadrilaterals.empty())
            throw InputError("Geometry/Element shape",
                             "prism needs a mesh of triangles, and '"
                               + geometry.mesh_file
                               + "' has quadrilaterals (set Element shape = "
                                 "hexahedron)");
          if (!mixed && !geometry.prisms && !plane.triangles.empty())
            throw InputError("Geometry/Element shape",
                             "hexahedron needs a mesh of quadrilaterals, and "
                             "'"
                               + geometry.mesh_file
                               + "' has triangles (set Element shape = prism, "
                                 "or recombine the mesh in Gmsh)");
          extrude_plane_mesh(plane,
                             layer_coordinates(geometry, laminate),
                             triangulation);
          if (geometry.mesh_file.empty() && geometry.hole_radius > 0)
            attach_hole_edge_manifold(geometry, triangulation);
          return false;
        }
    }
  } // namespace



  PlaneMesh
  mesh_laminate_plane(const parameters::Geometry &geometry,
                      const InPlaneSize          &size,
                      const MPI_Comm              comm)
  {
    return make_mesh_on_root<PlaneMesh>(
      [&]() {
        if (geometry.mesh_file.empty())
          return mesh_open_hole_plane(geometry.length,
                                      geometry.width,
                                      geometry.hole_radius,
                                      size);
        return read_plane_mesh(geometry.mesh_file, size);
      },
      comm);
  }



  template <int dim>
  bool
  make_laminate_mesh(const parameters::Geometry &geometry,
                     const Laminate             &laminate,
                     Triangulation<dim>         &triangulation,
                     const bool                  region_along_plies,
                     const PlaneMesh            *plane)
  {
    // A 2D in-plane model meshes the laminate's (x, y) plane with one
    // (homogenized) material; otherwise the last axis is the thickness
    // and every ply is a layer of elements with its own material id.
    const bool                       in_plane = dim == 2 && geometry.in_plane;
    const bool                       has_width_axis = dim == 3 || in_plane;
    std::vector<std::vector<double>> steps(dim);
    steps[0] = graded_steps(geometry.elements_along_length,
                            geometry.length,
                            geometry.edge_grading);
    if (has_width_axis)
      steps[1] = graded_steps(geometry.elements_along_width,
                              geometry.width,
                              geometry.edge_grading);
    if (!in_plane)
      for (unsigned int p = 0; p < laminate.n_plies(); ++p)
        steps[dim - 1].insert(steps[dim - 1].end(),
                              geometry.elements_per_ply,
                              (laminate.ply_boundaries[p + 1]
                               - laminate.ply_boundaries[p])
                                / geometry.elements_per_ply);

    Point<dim> box;
    box[0] = geometry.length;
    if (has_width_axis)
      box[1] = geometry.width;
    if (!in_plane)
      box[dim - 1] = laminate.thickness();
    const bool from_gmsh
      = !geometry.mesh_file.empty()
        || (geometry.prisms && (geometry.hole_radius > 0 || plane));
    bool plies_from_file = false;
    if (from_gmsh)
      plies_from_file
        = make_gmsh_laminate(geometry, laminate, triangulation, plane);
    else if (geometry.hole_radius > 0)
      make_open_hole_mesh(geometry, laminate, triangulation);
    else if (geometry.prisms)
      {
        // Wedges cannot be refined: the refinements are made by
        // subdividing every step before the mesh is built.
        const unsigned int parts = 1u << geometry.global_refinements;
        for (auto &axis : steps)
          axis = subdivide_steps(axis, parts);
        make_prism_box(steps, box, triangulation);
      }
    else
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, steps, Point<dim>(), box, /*colorize=*/true);

    for (const auto &cell : triangulation.active_cell_iterators())
      if (!plies_from_file)
        {
          const double z     = cell->center()[dim - 1];
          const auto   upper = std::upper_bound(laminate.ply_boundaries.begin(),
                                              laminate.ply_boundaries.end(),
                                              z);
          cell->set_material_id(
            in_plane ?
              0 :
              std::min<unsigned int>(upper - laminate.ply_boundaries.begin()
                                       - 1,
                                     laminate.n_plies() - 1));
        }
    // Wedges cannot be refined, and Gmsh meshes are refined by Gmsh.
    if (!geometry.prisms && !from_gmsh)
      triangulation.refine_global(geometry.global_refinements);

    if (geometry.mesh_distortion > 0)
      {
        std::array<double, dim> h;
        const double scale = std::pow(0.5, geometry.global_refinements);
        // The shortest step, so that a graded mesh does not tangle.
        h[0] = scale
               * graded_steps(geometry.elements_along_length,
                              geometry.length,
                              geometry.edge_grading)[0];
        if (has_width_axis)
          h[1] = scale
                 * graded_steps(geometry.elements_along_width,
                                geometry.width,
                                geometry.edge_grading)[0];
        if (!in_plane)
          h[dim - 1] = scale
                       * *std::min_element(geometry.ply_thickness.begin(),
                                           geometry.ply_thickness.end())
                       / geometry.elements_per_ply;
        distort_interior_vertices<dim>(triangulation,
                                       in_plane ? std::vector<double>() :
                                                  laminate.ply_boundaries,
                                       geometry.mesh_distortion,
                                       box,
                                       h);
      }

    if (!geometry.imperfection.empty())
      {
        const auto imperfection
          = make_expression_function<dim>(parameters::split_expressions(
                                            geometry.imperfection),
                                          dim,
                                          "",
                                          "Geometry/Imperfection");
        GridTools::transform(
          [&](const Point<dim> &p) {
            Point<dim> moved = p;
            for (unsigned int d = 0; d < dim; ++d)
              moved[d] += imperfection->value(p, d);
            if (!std::isfinite(moved.norm()))
              {
                std::ostringstream where;
                where << "is not finite (NaN or inf) at (" << p << ")";
                throw InputError("Geometry/Imperfection", where.str());
              }
            return moved;
          },
          triangulation);
      }

    if (!geometry.refinement_region.empty())
      {
        // The expression's "time" is h, the cell's longest edge.
        const auto region
          = make_expression_function<dim>({geometry.refinement_region},
                                          1,
                                          "",
                                          "Geometry/Refinement region",
                                          "h");
        for (unsigned int r = 0; r < geometry.region_refinements; ++r)
          {
            for (const auto &cell : triangulation.active_cell_iterators())
              {
                double h = 0;
                for (const unsigned int l : cell->line_indices())
                  h = std::max(h, cell->line(l)->diameter());
                region->set_time(h);
                if (region->value(cell->center()) != 0.)
                  cell->set_refine_flag();
              }
            if (dim == 3 && region_along_plies)
              keep_refinement_in_plane(
                triangulation, RefinementCase<dim>(RefinementCase<3>::cut_xy));
            triangulation.execute_coarsening_and_refinement();
          }
      }
    return plies_from_file;
  }

  namespace
  {
    /** The in-plane mesh of an open-hole plate: deal.II's plate with a
     * hole (whose inner square has 2 cells across), refined on its
     * manifolds until about Elements along width cells span the width,
     * then flattened into a coarse mesh that can be extruded. */
    void
    make_hole_plate_2d(const parameters::Geometry &geometry,
                       Triangulation<2>           &flat)
    {
      const double     L = geometry.length, W = geometry.width;
      const double     outer = 0.5 * std::min(L, W);
      const Point<2>   center(0.5 * L, 0.5 * W);
      Triangulation<2> plate;
      GridGenerator::plate_with_a_hole(plate,
                                       geometry.hole_radius,
                                       outer,
                                       0.5 * W - outer,
                                       0.5 * W - outer,
                                       0.5 * L - outer,
                                       0.5 * L - outer,
                                       center,
                                       0,
                                       1,
                                       1.,
                                       2,
                                       /*colorize=*/true);
      TransfiniteInterpolationManifold<2> tfi;
      tfi.initialize(plate);
      plate.set_manifold(1, tfi);
      const double cells_across = 2. * W / (2. * outer);
      const int    refinements
        = std::max(0,
                   static_cast<int>(std::lround(
                     std::log2(geometry.elements_along_width / cells_across))));
      plate.refine_global(refinements);
      GridGenerator::flatten_triangulation(plate, flat);
    }

    /** The ids and manifolds of an open-hole plate (2D, or extruded to
     * 3D): boundary ids renumbered by @p renumber (the hole becomes 6),
     * the hole's faces on @p hole (manifold id 0), transfinite
     * interpolation (id 1) in the square around the hole, where deal.II's
     * plate with a hole has its curved cells. */
    template <int dim>
    void
    attach_hole_manifolds(
      const parameters::Geometry                             &geometry,
      const std::map<types::boundary_id, types::boundary_id> &renumber,
      const Manifold<dim>                                    &hole,
      Triangulation<dim>                                     &triangulation)
    {
      const double box = 0.5 * std::min(geometry.length, geometry.width);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (std::abs(cell->center()[0] - 0.5 * geometry.length) < box
            && std::abs(cell->center()[1] - 0.5 * geometry.width) < box)
          cell->set_all_manifold_ids(1);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto id = cell->face(f)->boundary_id();
              if (renumber.count(id))
                cell->face(f)->set_boundary_id(renumber.at(id));
              if (cell->face(f)->boundary_id() == 6)
                cell->face(f)->set_all_manifold_ids(0);
            }
      triangulation.set_manifold(0, hole);
      TransfiniteInterpolationManifold<dim> tfi;
      tfi.initialize(triangulation);
      triangulation.set_manifold(1, tfi);
    }
  } // namespace



  template <>
  void
  make_open_hole_mesh(const parameters::Geometry &geometry,
                      const Laminate             &laminate,
                      Triangulation<3>           &triangulation)
  {
    Triangulation<2> flat;
    make_hole_plate_2d(geometry, flat);
    GridGenerator::extrude_triangulation(flat,
                                         layer_coordinates(geometry, laminate),
                                         triangulation);
    // Extrusion keeps the 2D ids on the side walls (4: the hole) and gives
    // the bottom and top 5 and 6; amfrac's are z- = 4, z+ = 5, hole = 6.
    const Point<3> center(0.5 * geometry.length, 0.5 * geometry.width, 0);
    attach_hole_manifolds<3>(geometry,
                             {{4, 6}, {5, 4}, {6, 5}},
                             CylindricalManifold<3>(Tensor<1, 3>({0., 0., 1.}),
                                                    center),
                             triangulation);
  }



  template <>
  void
  make_open_hole_mesh(const parameters::Geometry &geometry,
                      const Laminate &,
                      Triangulation<2> &triangulation)
  {
    if (!geometry.in_plane)
      throw InputError("Geometry/Hole radius",
                       "an open hole needs Dimension = 3 or 2D model = "
                       "in-plane");
    make_hole_plate_2d(geometry, triangulation);
    // The same ids and manifolds as the extruded 3D plate.
    attach_hole_manifolds<2>(geometry,
                             {{4, 6}},
                             SphericalManifold<2>(Point<2>(
                               0.5 * geometry.length, 0.5 * geometry.width)),
                             triangulation);
  }



  template bool
  make_laminate_mesh<2>(const parameters::Geometry &,
                        const Laminate &,
                        Triangulation<2> &,
                        const bool,
                        const PlaneMesh *);
  template bool
  make_laminate_mesh<3>(const parameters::Geometry &,
                        const Laminate &,
                        Triangulation<3> &,
                        const bool,
                        const PlaneMesh *);
} // namespace amfrac

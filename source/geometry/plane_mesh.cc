#include <algorithm>
#include <amfrac/geometry/gmsh_session.h>
#include <amfrac/geometry/plane_mesh.h>
#include <amfrac/geometry/volume_mesh.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>
#include <fstream>
#include <gmsh.h>
#include <map>
#include <sstream>

namespace amfrac
{
  namespace
  {
    const std::string mesh_file = "Geometry/Mesh file";

    double
    signed_area(const PlaneMesh &plane, const unsigned int *v)
    {
      const Tensor<1, 2> a = plane.points[v[1]] - plane.points[v[0]];
      const Tensor<1, 2> b = plane.points[v[2]] - plane.points[v[0]];
      return a[0] * b[1] - a[1] * b[0];
    }

    /** Everything the current Gmsh model has meshed in 2D: its nodes
     * (those of the 2D elements, renumbered from 0), triangles and
     * quadrilaterals turned counterclockwise, and the boundary edges of
     * its physical curves. */
    PlaneMesh
    collect_plane_mesh(const std::string &parameter)
    {
      std::vector<std::size_t> node_tags;
      std::vector<double>      coordinates, parametric;
      gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
      std::map<std::size_t, std::size_t> node_of_tag;
      for (std::size_t i = 0; i < node_tags.size(); ++i)
        node_of_tag[node_tags[i]] = i;

      PlaneMesh                           plane;
      std::map<std::size_t, unsigned int> point_of_node;
      const auto                          point = [&](std::size_t tag) {
        const auto found = point_of_node.find(tag);
        if (found != point_of_node.end())
          return found->second;
        const std::size_t i = node_of_tag.at(tag);
        const double      x = coordinates[3 * i], y = coordinates[3 * i + 1];
        if (std::abs(coordinates[3 * i + 2])
            > 1e-9 * (1 + std::abs(x) + std::abs(y)))
          throw InputError(parameter,
                           "node " + std::to_string(tag)
                             + " is not in the plane z = 0: the mesh must "
                                                        "be the 2D in-plane outline of the laminate");
        plane.points.emplace_back(x, y);
        point_of_node[tag] = plane.points.size() - 1;
        return point_of_node[tag];
      };

      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, 2);
      for (std::size_t t = 0; t < types.size(); ++t)
        {
          if (types[t] != 2 && types[t] != 3)
            throw InputError(parameter,
                             "the mesh has elements of type '"
                               + GmshSession::element_name(types[t])
                               + "': only 3-node triangles and 4-node "
                                 "quadrilaterals can be extruded (mesh with "
                                 "Mesh.ElementOrder = 1)");
          const int n_nodes = types[t] == 2 ? 3 : 4;
          for (std::size_t e = 0; e < tags[t].size(); ++e)
            {
              std::array<unsigned int, 4> v{};
              for (int k = 0; k < n_nodes; ++k)
                v[k] = point(nodes[t][n_nodes * e + k]);
              if (signed_area(plane, v.data()) < 0)
                std::reverse(v.begin(), v.begin() + n_nodes);
              if (n_nodes == 3)
                plane.triangles.push_back({{v[0], v[1], v[2]}});
              else
                plane.quadrilaterals.push_back(v);
            }
        }
      if (plane.triangles.empty() && plane.quadrilaterals.empty())
        throw InputError(parameter,
                         "the file has no 2D elements (a .geo needs a plane "
                         "surface, a .msh its 2D mesh)");

      GmshSession::for_each_physical_group(
        1, [&](const std::string &name, const std::vector<int> &curves) {
          const types::boundary_id id = boundary_id_of_curve(name);
          for (const int curve : curves)
            {
              std::vector<std::size_t> line_tags, line_nodes;
              gmsh::model::mesh::getElementsByType(1,
                                                   line_tags,
                                                   line_nodes,
                                                   curve);
              for (std::size_t e = 0; e < line_tags.size(); ++e)
                if (point_of_node.count(line_nodes[2 * e])
                    && point_of_node.count(line_nodes[2 * e + 1]))
                  {
                    plane.edges.push_back(
                      {{point_of_node[line_nodes[2 * e]],
                        point_of_node[line_nodes[2 * e + 1]]}});
                    plane.edge_ids.push_back(id);
                  }
            }
        });
      return plane;
    }

    /** Vertex v of the layer k of an extruded mesh of @p n points. */
    unsigned int
    layer_vertex(const unsigned int v,
                 const unsigned int k,
                 const std::size_t  n)
    {
      return k * n + v;
    }
  } // namespace



  types::boundary_id
  boundary_id_of_curve(const std::string &name)
  {
    const std::array<const char *, 4> sides = {{"x-", "x+", "y-", "y+"}};
    for (unsigned int i = 0; i < sides.size(); ++i)
      if (Utilities::trim(name) == sides[i])
        return i;
    return 6;
  }



  namespace
  {
    /** Make @p size the only element size of the next Gmsh mesh (not the
     * geometry's points, curvature or boundary). */
    void
    use_size_field(const std::function<double(const Point<2> &)> &size)
    {
      gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
      // A .geo's own factor and bounds would scale or clamp the field.
      gmsh::option::setNumber("Mesh.MeshSizeFactor", 1);
      gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
      gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
      gmsh::model::mesh::setSizeCallback(
        [size](int, int, double x, double y, double) {
          return size(Point<2>(x, y));
        });
    }
  } // namespace



  PlaneMesh
  read_plane_mesh(const std::string &file,
                  const double       size_factor,
                  const unsigned int refinements)
  {
    if (!std::ifstream(file))
      throw InputError(mesh_file, "cannot open '" + file + "'");
    const std::string extension
      = file.size() > 4 ? file.substr(file.size() - 4) : "";
    if (extension != ".geo" && extension != ".msh")
      throw InputError(mesh_file,
                       "'" + file + "' is neither a .geo nor a .msh file");
    GmshSession session;
    GmshSession::run(mesh_file, file, [&]() {
      gmsh::open(file);
      GmshSession::check(mesh_file, "to read '" + file + "'");
      if (extension == ".geo")
        {
          gmsh::option::setNumber("Mesh.MeshSizeFactor", size_factor);
          gmsh::model::mesh::generate(2);
        }
      else
        for (unsigned int r = 0; r < refinements; ++r)
          gmsh::model::mesh::refine();
      GmshSession::check(mesh_file, "to mesh '" + file + "'");
    });
    return collect_plane_mesh(mesh_file);
  }



  PlaneMesh
  read_plane_mesh(const std::string                             &file,
                  const std::function<double(const Point<2> &)> &size)
  {
    if (!std::ifstream(file))
      throw InputError(mesh_file, "cannot open '" + file + "'");
    GmshSession session;
    GmshSession::run(mesh_file, file, [&]() {
      gmsh::open(file);
      GmshSession::check(mesh_file, "to read '" + file + "'");
      // The file may have meshed itself on opening (a Mesh command).
      gmsh::model::mesh::clear();
      use_size_field(size);
      gmsh::model::mesh::generate(2);
      GmshSession::check(mesh_file, "to remesh '" + file + "'");
    });
    return collect_plane_mesh(mesh_file);
  }



  PlaneMesh
  mesh_open_hole_plane(const double                                   length,
                       const double                                   width,
                       const double                                   radius,
                       const std::function<double(const Point<2> &)> &size)
  {
    const std::string parameter = "Geometry/Hole radius";
    GmshSession       session;
    gmsh::model::add("open hole");
    const int plate = gmsh::model::occ::addRectangle(0, 0, 0, length, width);
    if (radius > 0)
      {
        const int hole = gmsh::model::occ::addDisk(
          0.5 * length, 0.5 * width, 0, radius, radius);
        gmsh::vectorpair              cut;
        std::vector<gmsh::vectorpair> map;
        gmsh::model::occ::cut({{2, plate}}, {{2, hole}}, cut, map);
      }
    gmsh::model::occ::synchronize();

    // Name the curves by where their bounding boxes lie.
    gmsh::vectorpair curves;
    gmsh::model::getEntities(curves, 1);
    std::map<types::boundary_id, std::vector<int>> curves_of_id;
    const double tol = 1e-6 * std::max(length, width);
    for (const auto &[dim, curve] : curves)
      {
        double x0, y0, z0, x1, y1, z1;
        gmsh::model::getBoundingBox(dim, curve, x0, y0, z0, x1, y1, z1);
        const types::boundary_id id = x1 < tol          ? 0 :
                                      x0 > length - tol ? 1 :
                                      y1 < tol          ? 2 :
                                      y0 > width - tol  ? 3 :
                                                          6;
        curves_of_id[id].push_back(curve);
      }
    const std::array<const char *, 7> names
      = {{"x-", "x+", "y-", "y+", "", "", "hole"}};
    for (const auto &[id, tags] : curves_of_id)
      gmsh::model::setPhysicalName(1,
                                   gmsh::model::addPhysicalGroup(1, tags),
                                   names[id]);

    use_size_field(size);
    gmsh::model::mesh::generate(2);
    GmshSession::check(parameter, "to mesh the open-hole plate");
    return collect_plane_mesh(parameter);
  }



  std::function<double(const Point<2> &)>
  open_hole_element_size(const parameters::Geometry &geometry)
  {
    const double scale = std::pow(0.5, geometry.global_refinements);
    const double far   = geometry.width / geometry.elements_along_width;
    const double at_hole
      = 2 * M_PI * geometry.hole_radius / geometry.elements_around_hole;
    const Point<2> centre(0.5 * geometry.length, 0.5 * geometry.width);
    const double   radius = geometry.hole_radius;
    // The whole field is halved per refinement, its grading too.
    return [=](const Point<2> &p) {
      const double distance = std::max(0., p.distance(centre) - radius);
      return scale * std::min(far, at_hole + 0.25 * distance);
    };
  }



  template <class Mesh>
  Mesh
  make_mesh_on_root(const std::function<Mesh()> &make, const MPI_Comm comm)
  {
    Mesh        mesh;
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          mesh = make();
        }
      catch (const InputError &e)
        {
          error = e.what();
        }
      // Anything else Gmsh throws must not leave the other ranks waiting
      // in the broadcast.
      catch (const std::exception &e)
        {
          error = std::string("meshing the laminate failed: ") + e.what();
        }
      catch (...)
        {
          error = "meshing the laminate failed in Gmsh";
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
    return Utilities::MPI::broadcast(comm, mesh, 0);
  }

  template PlaneMesh
  make_mesh_on_root(const std::function<PlaneMesh()> &, const MPI_Comm);
  template VolumeMesh
  make_mesh_on_root(const std::function<VolumeMesh()> &, const MPI_Comm);



  void
  extrude_plane_mesh(const PlaneMesh           &plane,
                     const std::vector<double> &z,
                     Triangulation<3>          &triangulation)
  {
    if (!plane.triangles.empty() && !plane.quadrilaterals.empty())
      throw InputError(mesh_file,
                       "the in-plane mesh has both triangles and "
                       "quadrilaterals: mixed prism/hexahedron meshes are "
                       "not supported yet (mesh with triangles only, or "
                       "recombine all of them)");
    const std::size_t     n = plane.points.size();
    std::vector<Point<3>> vertices;
    for (const double level : z)
      for (const auto &p : plane.points)
        vertices.emplace_back(p[0], p[1], level);

    std::vector<CellData<3>> cells;
    if (!plane.triangles.empty())
      for (unsigned int k = 0; k + 1 < z.size(); ++k)
        for (const auto &triangle : plane.triangles)
          {
            // Counterclockwise from +z: a positive wedge.
            CellData<3> cell(6);
            for (unsigned int v = 0; v < 3; ++v)
              {
                cell.vertices[v]     = layer_vertex(triangle[v], k, n);
                cell.vertices[v + 3] = layer_vertex(triangle[v], k + 1, n);
              }
            cells.push_back(cell);
          }
    else
      {
        // deal.II needs the lines of the quadrilaterals consistently
        // oriented; the hexahedra extruded from them are then too.
        std::vector<CellData<2>> quads;
        for (const auto &q : plane.quadrilaterals)
          {
            CellData<2> quad;
            quad.vertices = {q[0], q[1], q[3], q[2]}; // lexicographic
            quads.push_back(quad);
          }
        GridTools::consistently_order_cells(quads);
        for (auto &quad : quads)
          {
            if (signed_area(plane, quad.vertices.data()) < 0)
              std::swap(quad.vertices[1], quad.vertices[2]); // transpose
            for (unsigned int k = 0; k + 1 < z.size(); ++k)
              {
                CellData<3> cell(8);
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    cell.vertices[v] = layer_vertex(quad.vertices[v], k, n);
                    cell.vertices[v + 4]
                      = layer_vertex(quad.vertices[v], k + 1, n);
                  }
                cells.push_back(cell);
              }
          }
      }
    triangulation.create_triangulation(vertices, cells, SubCellData());

    std::map<std::pair<unsigned int, unsigned int>, types::boundary_id>
      id_of_edge;
    for (std::size_t e = 0; e < plane.edges.size(); ++e)
      id_of_edge[std::minmax(plane.edges[e][0], plane.edges[e][1])]
        = plane.edge_ids[e];
    const double tol = 1e-9 * (z.back() - z.front());
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto   face = cell->face(f);
            const double zc   = face->center()[2];
            if (std::abs(zc - z.front()) < tol)
              face->set_boundary_id(4);
            else if (std::abs(zc - z.back()) < tol)
              face->set_boundary_id(5);
            else
              {
                // A side face: its vertices are those of an edge of
                // the plane in two layers.
                std::vector<unsigned int> bottom;
                for (const unsigned int v : face->vertex_indices())
                  bottom.push_back(face->vertex_index(v) % n);
                std::sort(bottom.begin(), bottom.end());
                bottom.erase(std::unique(bottom.begin(), bottom.end()),
                             bottom.end());
                const auto found = bottom.size() == 2 ?
                                     id_of_edge.find({bottom[0], bottom[1]}) :
                                     id_of_edge.end();
                face->set_boundary_id(
                  found == id_of_edge.end() ? 6 : found->second);
              }
          }
  }
} // namespace amfrac

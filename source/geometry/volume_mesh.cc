#include <algorithm>
#include <amfrac/geometry/gmsh_session.h>
#include <amfrac/geometry/volume_mesh.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace amfrac
{
  namespace
  {
    const std::string mesh_file = "Geometry/Mesh file";

    /** The name of the box face @p id (0..5), "other" for 6. */
    std::string
    side_name(const types::boundary_id id)
    {
      const std::array<const char *, 7> names
        = {{"x-", "x+", "y-", "y+", "z-", "z+", "other"}};
      return names[std::min<types::boundary_id>(id, 6)];
    }

    /** Gmsh's element types of first-order hexahedra and wedges. */
    constexpr int gmsh_hexahedron = 5, gmsh_wedge = 6;

    /** A deal.II hexahedron's vertices are numbered lexicographically,
     * Gmsh's counterclockwise around the bottom and then the top face. */
    constexpr std::array<unsigned int, 8> gmsh_of_hexahedron_vertex
      = {{0, 1, 3, 2, 4, 5, 7, 6}};

    /** The mean edge of a lexicographic hexahedron along its axis @p a. */
    Tensor<1, 3>
    hexahedron_axis(const std::vector<Point<3>>     &points,
                    const std::vector<unsigned int> &v,
                    const unsigned int               a)
    {
      Tensor<1, 3> axis;
      for (unsigned int i = 0; i < 8; ++i)
        if ((i & (1u << a)) == 0)
          axis += points[v[i | (1u << a)]] - points[v[i]];
      return axis / 4;
    }

    /** Renumber the lexicographic hexahedron @p v so that its third axis
     * is the one closest to z (refinement in the plies' plane cuts the
     * first two) and its Jacobian is positive. The permutation is cyclic,
     * which keeps the orientation. */
    void
    orient_hexahedron(const std::vector<Point<3>> &points,
                      std::vector<unsigned int>   &v)
    {
      unsigned int thickness_axis = 2;
      double       best           = -1;
      for (unsigned int a = 0; a < 3; ++a)
        {
          const Tensor<1, 3> axis  = hexahedron_axis(points, v, a);
          const double       along = std::abs(axis[2]) / axis.norm();
          if (along > best)
            {
              best           = along;
              thickness_axis = a;
            }
        }
      const unsigned int        shift = (thickness_axis + 1) % 3;
      std::vector<unsigned int> turned(8);
      for (unsigned int i = 0; i < 8; ++i)
        {
          // New axis n is old axis (n + shift) % 3.
          unsigned int old = 0;
          for (unsigned int n = 0; n < 3; ++n)
            if (i & (1u << n))
              old |= 1u << ((n + shift) % 3);
          turned[i] = v[old];
        }
      v = turned;
      // Local axis 0 closest to x (Process zone directions = x, y cut the
      // local axes): swap axes 0 and 1 and mirror axis 2, which keeps the
      // orientation.
      const Tensor<1, 3> axis_0 = hexahedron_axis(points, v, 0),
                         axis_1 = hexahedron_axis(points, v, 1);
      if (std::abs(axis_1[0]) / axis_1.norm()
          > std::abs(axis_0[0]) / axis_0.norm())
        {
          for (unsigned int i = 0; i < 8; ++i)
            turned[i] = v[((i & 1u) << 1 | (i & 2u) >> 1 | (i & 4u)) ^ 4u];
          v = turned;
        }
      const double volume = cross_product_3d(hexahedron_axis(points, v, 0),
                                             hexahedron_axis(points, v, 1))
                            * hexahedron_axis(points, v, 2);
      if (volume < 0)
        for (unsigned int i = 0; i < 8; i += 2)
          std::swap(v[i], v[i + 1]);
    }

    /** A wedge with its bottom triangle counterclockwise seen from its
     * top: a positive Jacobian. */
    void
    orient_wedge(const std::vector<Point<3>> &points,
                 std::vector<unsigned int>   &v)
    {
      const Tensor<1, 3> a = points[v[1]] - points[v[0]];
      const Tensor<1, 3> b = points[v[2]] - points[v[0]];
      const Tensor<1, 3> c = points[v[3]] - points[v[0]];
      if (cross_product_3d(a, b) * c < 0)
        {
          std::swap(v[1], v[2]);
          std::swap(v[4], v[5]);
        }
    }

    /** Reads the current Gmsh model into a VolumeMesh. */
    class VolumeMeshReader
    {
    public:
      explicit VolumeMeshReader(const std::string &file)
        : file(file)
      {
        std::vector<std::size_t> node_tags;
        std::vector<double>      coordinates, parametric;
        gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
        for (std::size_t i = 0; i < node_tags.size(); ++i)
          node_coordinates[node_tags[i]] = Point<3>(coordinates[3 * i],
                                                    coordinates[3 * i + 1],
                                                    coordinates[3 * i + 2]);
      }

      void
      collect_cells()
      {
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, 3);
        for (std::size_t t = 0; t < types.size(); ++t)
          {
            if (types[t] != gmsh_hexahedron && types[t] != gmsh_wedge)
              throw InputError(mesh_file,
                               "'" + file + "' has elements of type '"
                                 + GmshSession::element_name(types[t])
                                 + "': a 3D mesh must be made of 8-node "
                                   "hexahedra or 6-node wedges (extrude a "
                                   "2D mesh ply by ply with Layers, "
                                   "Mesh.ElementOrder = 1)");
            const int n_nodes = types[t] == gmsh_hexahedron ? 8 : 6;
            for (std::size_t e = 0; e < tags[t].size(); ++e)
              add_cell(tags[t][e], &nodes[t][n_nodes * e], n_nodes);
          }
        const bool wedges
          = std::any_of(mesh.cells.begin(),
                        mesh.cells.end(),
                        [](const auto &v) { return v.size() == 6; });
        const bool hexahedra
          = std::any_of(mesh.cells.begin(),
                        mesh.cells.end(),
                        [](const auto &v) { return v.size() == 8; });
        if (wedges && hexahedra)
          throw InputError(mesh_file,
                           "'" + file
                             + "' has both hexahedra and wedges: mixed "
                               "prism/hexahedron meshes are not supported "
                               "yet");
      }

      void
      assign_plies(const unsigned int n_plies)
      {
        unassigned = n_plies;
        mesh.ply_of_cell.assign(mesh.cells.size(), unassigned);
        std::vector<bool> named(n_plies, false);
        GmshSession::for_each_physical_group(
          3, [&](const std::string &name, const std::vector<int> &volumes) {
            const int ply = ply_of_name(name, n_plies);
            if (ply < 0)
              return;
            named[ply] = true;
            for (const int volume : volumes)
              for (const std::size_t tag : element_tags(3, volume))
                set_ply(tag, ply);
          });
        for (unsigned int p = 0; p < n_plies; ++p)
          if (!named[p])
            throw InputError(mesh_file,
                             "'" + file + "' has no physical volume named 'ply "
                               + std::to_string(p + 1) + "' (the Stacking "
                               + "sequence has " + std::to_string(n_plies)
                               + " plies: name them 'ply 1' to 'ply "
                               + std::to_string(n_plies)
                               + "' from the bottom up)");
        for (unsigned int p = 0; p < n_plies; ++p)
          if (std::count(mesh.ply_of_cell.begin(), mesh.ply_of_cell.end(), p)
              == 0)
            throw InputError(mesh_file,
                             "the physical volume 'ply " + std::to_string(p + 1)
                               + "' of '" + file + "' has no 3D elements");
        for (const auto &[tag, cell] : cell_of_element)
          if (mesh.ply_of_cell[cell] == unassigned)
            throw InputError(mesh_file,
                             "element " + std::to_string(tag) + " of '" + file
                               + "' is in no physical volume 'ply k'");
      }

      void
      collect_boundary_faces()
      {
        GmshSession::for_each_physical_group(
          2, [&](const std::string &name, const std::vector<int> &surfaces) {
            for (const int surface : surfaces)
              add_faces(surface, boundary_id_of_surface(name));
          });
      }

      VolumeMesh mesh;

    private:
      const std::string                   file;
      std::map<std::size_t, Point<3>>     node_coordinates;
      std::map<std::size_t, unsigned int> point_of_node;
      std::map<std::size_t, unsigned int> cell_of_element;
      /** The ply of a cell no physical volume has named yet. */
      unsigned int unassigned = 0;

      unsigned int
      point(const std::size_t tag)
      {
        const auto found = point_of_node.find(tag);
        if (found != point_of_node.end())
          return found->second;
        mesh.points.push_back(node_coordinates.at(tag));
        return point_of_node[tag] = mesh.points.size() - 1;
      }

      void
      add_cell(const std::size_t  tag,
               const std::size_t *nodes,
               const int          n_nodes)
      {
        std::vector<unsigned int> v(n_nodes);
        for (int k = 0; k < n_nodes; ++k)
          v[k] = point(nodes[n_nodes == 8 ? gmsh_of_hexahedron_vertex[k] : k]);
        if (n_nodes == 8)
          orient_hexahedron(mesh.points, v);
        else
          orient_wedge(mesh.points, v);
        cell_of_element[tag] = mesh.cells.size();
        mesh.cells.push_back(v);
      }

      /** The ply index of a physical volume called "ply k" (k from 1),
       * -1 for another name. */
      int
      ply_of_name(const std::string &name, const unsigned int n_plies) const
      {
        static const std::regex ply_name(R"(\s*ply\s*([0-9]{1,6})\s*)",
                                         std::regex::icase);
        std::smatch             match;
        if (!std::regex_match(name, match, ply_name))
          return -1;
        const unsigned long k = std::stoul(match[1]);
        if (k < 1 || k > n_plies)
          throw InputError(mesh_file,
                           "'" + file + "' has a physical volume named '" + name
                             + "', but the Stacking sequence has "
                             + std::to_string(n_plies) + " plies");
        return k - 1;
      }

      static std::vector<std::size_t>
      element_tags(const int dim, const int entity)
      {
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
        std::vector<std::size_t> all;
        for (const auto &of_type : tags)
          all.insert(all.end(), of_type.begin(), of_type.end());
        return all;
      }

      void
      set_ply(const std::size_t tag, const unsigned int ply)
      {
        const unsigned int cell  = cell_of_element.at(tag);
        unsigned int      &given = mesh.ply_of_cell[cell];
        if (given != ply && given != unassigned)
          throw InputError(mesh_file,
                           "element " + std::to_string(tag) + " of '" + file
                             + "' is in the physical volumes 'ply "
                             + std::to_string(given + 1) + "' and 'ply "
                             + std::to_string(ply + 1) + "'");
        given = ply;
      }

      void
      add_faces(const int surface, const types::boundary_id id)
      {
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, 2, surface);
        for (std::size_t t = 0; t < types.size(); ++t)
          {
            const std::size_t n_nodes = types[t] == 2 ? 3 : 4;
            if (types[t] != 2 && types[t] != 3)
              continue;
            for (std::size_t e = 0; e < tags[t].size(); ++e)
              {
                std::vector<unsigned int> face;
                for (std::size_t k = 0; k < n_nodes; ++k)
                  {
                    const auto found
                      = point_of_node.find(nodes[t][n_nodes * e + k]);
                    if (found != point_of_node.end())
                      face.push_back(found->second);
                  }
                if (face.size() != n_nodes && id < 6)
                  throw InputError(mesh_file,
                                   "the physical surface named '"
                                     + side_name(id) + "' of '" + file
                                     + "' has nodes that no 3D element of "
                                       "the file has (mesh the surfaces "
                                       "with the volumes, or Coherence Mesh)");
                if (face.size() != n_nodes)
                  continue; // an unnamed surface apart from the volumes
                std::sort(face.begin(), face.end());
                mesh.faces.push_back(face);
                mesh.face_ids.push_back(id);
              }
          }
      }
    };

    /** The boundary id of every boundary face from the file's physical
     * surfaces (6 where it has none). Refuses a face that two named
     * surfaces claim, and a named surface that is not on the boundary. */
    void
    set_boundary_ids(const VolumeMesh &mesh, Triangulation<3> &triangulation)
    {
      std::map<std::vector<unsigned int>, types::boundary_id> id_of_face;
      for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        {
          const auto [at, added]
            = id_of_face.emplace(mesh.faces[f], mesh.face_ids[f]);
          if (!added && at->second != mesh.face_ids[f])
            {
              // A named side wins over another surface (id 6); two
              // different named sides are a contradiction.
              if (at->second < 6 && mesh.face_ids[f] < 6)
                throw InputError(mesh_file,
                                 "a face is in the physical surfaces '"
                                   + side_name(at->second) + "' and '"
                                   + side_name(mesh.face_ids[f]) + "'");
              at->second = std::min(at->second, mesh.face_ids[f]);
            }
        }
      std::size_t named_found = 0;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            std::vector<unsigned int> vertices;
            for (const unsigned int v : face->vertex_indices())
              vertices.push_back(face->vertex_index(v));
            std::sort(vertices.begin(), vertices.end());
            const auto found = id_of_face.find(vertices);
            face->set_boundary_id(found == id_of_face.end() ? 6 :
                                                              found->second);
            named_found += found != id_of_face.end() && found->second < 6;
          }
      const std::size_t named
        = std::count_if(id_of_face.begin(),
                        id_of_face.end(),
                        [](const auto &entry) { return entry.second < 6; });
      if (named_found != named)
        throw InputError(mesh_file,
                         std::to_string(named - named_found)
                           + " face(s) of the physical surfaces named x-, "
                             "x+, y-, y+, z-, z+ are not on the boundary of "
                             "the laminate (or not faces of its elements)");
    }

    /** Refuses boundary faces that lie on one another: plies meshed as
     * separate bodies, which nothing would join (a ply interface needs
     * shared nodes, from which the DoF layer makes the cohesive copies). */
    void
    refuse_unjoined_faces(const Triangulation<3> &triangulation)
    {
      const double tol = 1e-9 * GridTools::diameter(triangulation);
      std::vector<std::pair<Point<3>, unsigned int>> centres;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            centres.emplace_back(cell->face(f)->center(), cell->material_id());
      std::sort(centres.begin(),
                centres.end(),
                [](const auto &a, const auto &b) {
                  return a.first[0] < b.first[0];
                });
      for (std::size_t i = 0; i < centres.size(); ++i)
        for (std::size_t j = i + 1;
             j < centres.size()
             && centres[j].first[0] - centres[i].first[0] < tol;
             ++j)
          if (centres[i].first.distance(centres[j].first) < tol)
            {
              std::ostringstream where;
              where << "ply " << centres[i].second + 1 << " and ply "
                    << centres[j].second + 1
                    << " have boundary faces on one another at ("
                    << centres[i].first
                    << "): they are separate meshes, which nothing joins "
                       "(share the nodes: Coherence Mesh, or "
                       "BooleanFragments of the volumes)";
              throw InputError(mesh_file, where.str());
            }
    }

    /** Refuses plies numbered from the top: where ply a lies on ply b,
     * a must be above b (the Stacking sequence counts from the bottom). */
    void
    refuse_plies_upside_down(const Triangulation<3> &triangulation)
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (!cell->at_boundary(f)
              && cell->neighbor(f)->material_id() > cell->material_id())
            {
              const Tensor<1, 3> up
                = cell->neighbor(f)->center() - cell->center();
              if (up[2] < -0.5 * up.norm())
                {
                  std::ostringstream where;
                  where << "'ply " << cell->neighbor(f)->material_id() + 1
                        << "' lies under 'ply " << cell->material_id() + 1
                        << "' at (" << cell->face(f)->center()
                        << "): name the plies from the bottom up, as the "
                           "Stacking sequence counts them";
                  throw InputError(mesh_file, where.str());
                }
            }
    }
  } // namespace



  types::boundary_id
  boundary_id_of_surface(const std::string &name)
  {
    for (types::boundary_id i = 0; i < 6; ++i)
      if (Utilities::trim(name) == side_name(i))
        return i;
    return 6;
  }



  VolumeMesh
  read_volume_mesh(const std::string &file,
                   const unsigned int n_plies,
                   const unsigned int refinements)
  {
    if (!std::ifstream(file))
      throw InputError(mesh_file, "cannot open '" + file + "'");
    GmshSession session;
    bool        three_d = false;
    GmshSession::run(mesh_file, file, [&]() {
      gmsh::open(file);
      GmshSession::check(mesh_file, "to read '" + file + "'");
      three_d = gmsh::model::getDimension() == 3;
      if (!three_d)
        return;
      if (file.size() > 4 && file.substr(file.size() - 4) == ".geo")
        {
          // The file may have meshed itself on opening (a Mesh command).
          gmsh::model::mesh::clear();
          gmsh::model::mesh::generate(3);
          GmshSession::check(mesh_file, "to mesh '" + file + "'");
        }
      for (unsigned int r = 0; r < refinements; ++r)
        gmsh::model::mesh::refine();
      GmshSession::check(mesh_file, "to refine '" + file + "'");
    });
    if (!three_d)
      return VolumeMesh();
    VolumeMeshReader reader(file);
    reader.collect_cells();
    if (reader.mesh.empty())
      throw InputError(mesh_file, "'" + file + "' has no 3D elements");
    reader.assign_plies(n_plies);
    reader.collect_boundary_faces();
    return reader.mesh;
  }



  void
  create_volume_mesh(const VolumeMesh &mesh, Triangulation<3> &triangulation)
  {
    std::vector<CellData<3>> cells;
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
      {
        CellData<3> cell(mesh.cells[c].size());
        std::copy(mesh.cells[c].begin(),
                  mesh.cells[c].end(),
                  cell.vertices.begin());
        cell.material_id = mesh.ply_of_cell[c];
        cells.push_back(cell);
      }
    try
      {
        triangulation.create_triangulation(mesh.points, cells, SubCellData());
      }
    catch (const std::exception &e)
      {
        throw InputError(mesh_file,
                         std::string("deal.II cannot make a mesh of it: ")
                           + e.what());
      }
    set_boundary_ids(mesh, triangulation);
    refuse_unjoined_faces(triangulation);
    refuse_plies_upside_down(triangulation);
  }



  void
  refuse_interfaces_between_distant_plies(
    const Triangulation<3>          &triangulation,
    const std::vector<unsigned int> &interfaces,
    const std::string               &parameter)
  {
    if (interfaces.empty())
      return;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f))
          {
            const unsigned int a     = cell->material_id(),
                               b     = cell->neighbor(f)->material_id();
            const unsigned int lower = std::min(a, b), upper = std::max(a, b);
            if (upper <= lower + 1)
              continue;
            const auto listed
              = std::lower_bound(interfaces.begin(), interfaces.end(), lower);
            if (listed != interfaces.end() && *listed < upper)
              throw InputError(
                parameter,
                "ply " + std::to_string(lower + 1) + " touches ply "
                  + std::to_string(upper + 1)
                  + " of the Geometry/Mesh file (a ply drop between them), "
                    "and interface "
                  + std::to_string(*listed) + " (between ply "
                  + std::to_string(*listed + 1) + " and ply "
                  + std::to_string(*listed + 2)
                  + ") is listed: an interface between plies that are not "
                    "neighbours in the Stacking sequence is not supported "
                    "yet");
          }
  }
} // namespace amfrac

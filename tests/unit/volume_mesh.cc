// A laminate's 3D .msh: the reader turns Gmsh's hexahedra so that their
// third axis is the thickness, takes the ply of every cell from its
// physical volume's name and the boundary ids from the physical surfaces,
// and refuses files that do not say which ply an element is in.

#include "../check.h"

#include <amfrac/geometry/gmsh_session.h>
#include <amfrac/geometry/volume_mesh.h>
#include <amfrac/parameters/input_error.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <functional>
#include <map>

using namespace amfrac;

namespace
{
  /** Runs @p read and checks that it throws an InputError naming the
   * Mesh file whose message contains @p words. */
  void
  check_refused(const std::function<void()> &read, const std::string &words)
  {
    try
      {
        read();
        CHECK(false && "an InputError was expected");
        std::cerr << "  (expected: " << words << ")" << std::endl;
      }
    catch (const InputError &e)
      {
        const std::string message = e.what();
        std::cout << "refused: " << message << std::endl;
        CHECK(message.find("Geometry/Mesh file") != std::string::npos);
        CHECK(message.find(words) != std::string::npos);
      }
  }

  /** Reading @p file of @p n_plies plies and making its mesh throws an
   * InputError naming the Mesh file with @p words. */
  void
  check_file_refused(const std::string &file,
                     const unsigned int n_plies,
                     const std::string &words)
  {
    check_refused(
      [&] {
        Triangulation<3> tria;
        create_volume_mesh(read_volume_mesh(file, n_plies, 0), tria);
      },
      words);
  }

  /** The block of block_plies_x.geo: 4 x 3 x 0.9 mm, plies at z = 0,
   * 0.25, 0.4, 0.7, 0.9; its hexahedra were extruded along x. */
  void
  check_block(const std::string &file, const unsigned int refinements)
  {
    const std::vector<double> z = {0, 0.25, 0.4, 0.7, 0.9};
    Triangulation<3>          tria;
    create_volume_mesh(read_volume_mesh(file, 4, refinements), tria);
    CHECK(tria.n_active_cells() == (4u * 3 * 8) << (3 * refinements));
    double volume = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        // The third axis is the thickness: vertices 0 and 4 differ in z.
        const Tensor<1, 3> axis = cell->vertex(4) - cell->vertex(0);
        CHECK(std::abs(axis[0]) + std::abs(axis[1]) < 1e-12);
        CHECK(std::abs(axis[2]) > 0.05 / (1 << refinements));
        // Local axis 0 along x (Process zone directions = x).
        const Tensor<1, 3> along = cell->vertex(1) - cell->vertex(0);
        CHECK(std::abs(along[1]) + std::abs(along[2]) < 1e-12);
        CHECK(cell->measure() > 0);
        volume += cell->measure();
        const double zc  = cell->center()[2];
        unsigned int ply = 0;
        while (zc > z[ply + 1])
          ++ply;
        CHECK(cell->material_id() == ply);
      }
    CHECK_CLOSE(volume, 4 * 3 * 0.9, 1e-12);

    // Every boundary face has the id of its side of the box.
    std::map<types::boundary_id, double> area;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<3>           c        = face->center();
          const types::boundary_id expected = c[0] < 1e-9     ? 0 :
                                              c[0] > 4 - 1e-9 ? 1 :
                                              c[1] < 1e-9     ? 2 :
                                              c[1] > 3 - 1e-9 ? 3 :
                                              c[2] < 1e-9     ? 4 :
                                                                5;
          CHECK(face->boundary_id() == expected);
          area[face->boundary_id()] += face->measure();
        }
    CHECK_CLOSE(area[0], 3 * 0.9, 1e-12);
    CHECK_CLOSE(area[5], 4 * 3, 1e-12);
  }

  /** A physical volume called @p name of @p volumes. */
  void
  name_volumes(const std::vector<int> &volumes, const std::string &name)
  {
    gmsh::model::setPhysicalName(3,
                                 gmsh::model::addPhysicalGroup(3, volumes),
                                 name);
  }

  /** A Gmsh 2.2 .msh written by hand (Gmsh itself would not write the
   * inverted or unjoined elements these tests need). */
  struct HandMesh
  {
    struct Element
    {
      int              type, group;
      std::vector<int> nodes;
    };
    std::vector<Point<3>>                    nodes;
    std::vector<Element>                     elements;
    std::vector<std::pair<int, std::string>> volumes, surfaces;

    /** The unit cube at height @p z0 (nodes 8 k + 1 .. 8 k + 8 for the
     * k-th call, bottom counterclockwise then top). */
    std::vector<int>
    add_cube(const double z0)
    {
      std::vector<int> added;
      for (const double z : {z0, z0 + 1})
        for (const auto &[x, y] : std::vector<std::pair<double, double>>{
               {0, 0}, {1, 0}, {1, 1}, {0, 1}})
          {
            nodes.emplace_back(x, y, z);
            added.push_back(nodes.size());
          }
      return added;
    }

    void
    write(const std::string &file) const
    {
      std::ofstream out(file);
      out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n"
          << volumes.size() + surfaces.size() << "\n";
      for (const auto &[tag, name] : volumes)
        out << "3 " << tag << " \"" << name << "\"\n";
      for (const auto &[tag, name] : surfaces)
        out << "2 " << tag << " \"" << name << "\"\n";
      out << "$EndPhysicalNames\n$Nodes\n" << nodes.size() << "\n";
      for (std::size_t n = 0; n < nodes.size(); ++n)
        out << n + 1 << " " << nodes[n] << "\n";
      out << "$EndNodes\n$Elements\n" << elements.size() << "\n";
      for (std::size_t e = 0; e < elements.size(); ++e)
        {
          out << e + 1 << " " << elements[e].type << " 2 " << elements[e].group
              << " " << elements[e].group;
          for (const int n : elements[e].nodes)
            out << " " << n;
          out << "\n";
        }
      out << "$EndElements\n";
    }
  };

  /** Hexahedra and wedges given with a negative orientation are turned
   * over; the third axis of the hexahedron stays the thickness. */
  void
  check_inverted_elements()
  {
    HandMesh   hexahedron;
    const auto v = hexahedron.add_cube(0);
    // The top face first: a negative Gmsh hexahedron.
    hexahedron.elements.push_back(
      {5, 1, {v[4], v[5], v[6], v[7], v[0], v[1], v[2], v[3]}});
    hexahedron.volumes = {{1, "ply 1"}};
    hexahedron.write("inverted_hexahedron.msh");
    Triangulation<3> tria;
    create_volume_mesh(read_volume_mesh("inverted_hexahedron.msh", 1, 0), tria);
    const auto cell = tria.begin_active();
    CHECK(cell->measure() > 0);
    const Tensor<1, 3> axis = cell->vertex(4) - cell->vertex(0);
    CHECK(std::abs(std::abs(axis[2]) - 1) < 1e-12);
    // Local axis 0 along x.
    CHECK(std::abs(std::abs((cell->vertex(1) - cell->vertex(0))[0]) - 1)
          < 1e-12);

    // Numbered from the corner (1, 0, 0), first along y: turned so that
    // local axis 0 is x again (Process zone directions cut local axes).
    HandMesh   rotated;
    const auto r = rotated.add_cube(0);
    rotated.elements.push_back(
      {5, 1, {r[1], r[2], r[3], r[0], r[5], r[6], r[7], r[4]}});
    rotated.volumes = {{1, "ply 1"}};
    rotated.write("rotated_hexahedron.msh");
    Triangulation<3> turned_tria;
    create_volume_mesh(read_volume_mesh("rotated_hexahedron.msh", 1, 0),
                       turned_tria);
    const auto turned_cell = turned_tria.begin_active();
    CHECK(turned_cell->measure() > 0);
    CHECK(std::abs(
            std::abs((turned_cell->vertex(1) - turned_cell->vertex(0))[0]) - 1)
          < 1e-12);
    CHECK(std::abs(
            std::abs((turned_cell->vertex(4) - turned_cell->vertex(0))[2]) - 1)
          < 1e-12);

    HandMesh   wedge;
    const auto w = wedge.add_cube(0);
    // Clockwise seen from the top: a negative wedge.
    wedge.elements.push_back({6, 1, {w[0], w[2], w[1], w[4], w[6], w[5]}});
    wedge.volumes = {{1, "ply 1"}};
    wedge.write("inverted_wedge.msh");
    const VolumeMesh turned = read_volume_mesh("inverted_wedge.msh", 1, 0);
    const auto      &c      = turned.cells[0];
    const auto      &p      = turned.points;
    CHECK(cross_product_3d(p[c[1]] - p[c[0]], p[c[2]] - p[c[0]])
            * (p[c[3]] - p[c[0]])
          > 0);
  }

  /** Two cubes stacked: @p shared_nodes or each with its own. */
  HandMesh
  two_cubes(const bool         shared_nodes,
            const std::string &lower,
            const std::string &upper)
  {
    HandMesh   mesh;
    const auto a = mesh.add_cube(0);
    auto       b = shared_nodes ? std::vector<int>() : mesh.add_cube(1);
    if (shared_nodes)
      {
        const auto top = mesh.add_cube(1);
        b = {a[4], a[5], a[6], a[7], top[4], top[5], top[6], top[7]};
      }
    mesh.elements.push_back({5, 1, a});
    mesh.elements.push_back({5, 2, b});
    mesh.volumes = {{1, lower}, {2, upper}};
    return mesh;
  }

  void
  check_inconsistent_files()
  {
    two_cubes(false, "ply 1", "ply 2").write("unjoined.msh");
    check_file_refused("unjoined.msh",
                       2,
                       "ply 1 and ply 2 have boundary faces on one another");

    two_cubes(true, "ply 2", "ply 1").write("upside_down.msh");
    check_file_refused("upside_down.msh", 2, "'ply 2' lies under 'ply 1'");

    // The interface between the cubes named as a side.
    HandMesh   inside = two_cubes(true, "ply 1", "ply 2");
    const auto top    = inside.elements[0].nodes;
    inside.elements.push_back({3, 3, {top[4], top[5], top[6], top[7]}});
    inside.surfaces = {{3, "z+"}};
    inside.write("inside.msh");
    check_file_refused("inside.msh",
                       2,
                       "are not on the boundary of the laminate");

    // The bottom named twice.
    HandMesh   twice  = two_cubes(true, "ply 1", "ply 2");
    const auto bottom = twice.elements[0].nodes;
    twice.elements.push_back(
      {3, 3, {bottom[0], bottom[1], bottom[2], bottom[3]}});
    twice.elements.push_back(
      {3, 4, {bottom[0], bottom[1], bottom[2], bottom[3]}});
    twice.surfaces = {{3, "z-"}, {4, "x-"}};
    twice.write("named_twice.msh");
    check_file_refused("named_twice.msh", 2, "is in the physical surfaces");
  }

  /** A Gmsh model of boxes written to @p file: @p build makes it. */
  void
  write_model(const std::string &file, const std::function<void()> &build)
  {
    GmshSession session;
    gmsh::model::add("test");
    build();
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::generate(3);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::write(file);
  }

  /** The unit square at x0 extruded by one layer into a hexahedral (or,
   * not recombined, a wedge) volume; returns the volume's tag. */
  int
  extruded_square(const double x0, const bool recombine)
  {
    namespace geo = gmsh::model::geo;
    const int p1 = geo::addPoint(x0, 0, 0), p2 = geo::addPoint(x0 + 1, 0, 0),
              p3 = geo::addPoint(x0 + 1, 1, 0), p4 = geo::addPoint(x0, 1, 0);
    const int loop    = geo::addCurveLoop({geo::addLine(p1, p2),
                                           geo::addLine(p2, p3),
                                           geo::addLine(p3, p4),
                                           geo::addLine(p4, p1)});
    const int surface = geo::addPlaneSurface({loop});
    if (recombine)
      geo::mesh::setRecombine(2, surface);
    gmsh::vectorpair out;
    geo::extrude({{2, surface}}, 0, 0, 0.5, out, {1}, {}, true);
    return out[1].second;
  }

  void
  check_bad_files()
  {
    write_model("two_boxes.msh", [] {
      const int first  = extruded_square(0, true);
      const int second = extruded_square(1, true);
      gmsh::model::geo::synchronize();
      name_volumes({first}, "ply 1");
      name_volumes({second}, "core");
    });
    check_file_refused("two_boxes.msh", 1, "is in no physical volume 'ply k'");
    check_file_refused("two_boxes.msh", 2, "no physical volume named 'ply 2'");

    write_model("twice.msh", [] {
      const int box = extruded_square(0, true);
      gmsh::model::geo::synchronize();
      name_volumes({box}, "ply 1");
      name_volumes({box}, "ply 2");
    });
    check_file_refused("twice.msh",
                       2,
                       "is in the physical volumes 'ply 1' and 'ply 2'");

    write_model("mixed.msh", [] {
      const int hexahedra = extruded_square(0, true);
      const int wedges    = extruded_square(1, false);
      gmsh::model::geo::synchronize();
      name_volumes({hexahedra, wedges}, "ply 1");
    });
    check_file_refused("mixed.msh", 1, "has both hexahedra and wedges");

    write_model("tetrahedra.msh", [] {
      gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
      gmsh::model::occ::synchronize();
      name_volumes({1}, "ply 1");
    });
    check_file_refused("tetrahedra.msh",
                       1,
                       "has elements of type 'Tetrahedron 4'");
    check_file_refused("missing.msh", 1, "cannot open 'missing.msh'");
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // argv[1]: the folder of the Gmsh meshes (tests/app/meshes).
  const std::string meshes = std::string(argc > 1 ? argv[1] : ".") + "/";
  check_block(meshes + "block_plies_x.msh", 0);
  // Each refinement splits every hexahedron into eight, plies and sides
  // kept.
  check_block(meshes + "block_plies_x.msh", 1);
  check_inverted_elements();
  check_inconsistent_files();
  // A 2D mesh is not a volume mesh: the caller extrudes it.
  CHECK(read_volume_mesh(meshes + "trapezoid_quads.msh", 1, 0).empty());
  check_file_refused(meshes + "block_plies_x.msh",
                     3,
                     "named 'ply 4', but the Stacking sequence has 3 plies");
  check_bad_files();
  return amfrac_test::summary();
}

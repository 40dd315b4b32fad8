// tau_1 for bulk quadrature history (QuadratureHistoryTransfer) on a
// two-ply cross-section, recovery degree 1 and 2, through a refinement
// (isotropic and along the plies) and then a coarsening of part of it with
// refinement elsewhere:
// - smooth components that are constant per ply, or linear per ply, stay
//   exactly that (they are in the recovery space, which is free across
//   plies), also a third smooth component (a second projection pass);
// - a non-decreasing component (random) is kept on kept cells, injected
//   from the parent's nearest point on refined cells, and is the largest
//   value of the children on coarsened cells: never below the old value
//   at the same place;
// - with keep_unchanged_cells, cells the change keeps keep every
//   component exactly, also a field outside the recovery space.
#include "../check.h"

#include <amfrac/adaptivity/history_transfer.h>
#include <amfrac/geometry/laminate.h>
#include <amfrac/parameters/parameters.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <map>
#include <random>

using namespace amfrac;

namespace
{
  using Transfer                   = QuadratureHistoryTransfer<2>;
  constexpr unsigned int n_history = 4;

  /** The exact smooth fields: constant, linear and constant per ply. */
  double
  exact(const unsigned int c, const unsigned int ply, const Point<2> &p)
  {
    switch (c)
      {
        case 0:
          return ply == 0 ? 1.5 : -0.25;
        case 1:
          return ply == 0 ? 2 + 0.3 * p[0] - 1.1 * p[1] :
                            -1 + 0.7 * p[0] + 0.4 * p[1];
        default:
          return ply == 0 ? 10. : 20.;
      }
  }

  struct Mesh
  {
    Triangulation<2>                        tria;
    std::map<CellId, std::vector<double>>   non_decreasing;
    std::map<CellId, std::vector<Point<2>>> points;
  };

  /** Real positions of the quadrature points, per active cell. */
  void
  record(Mesh &mesh, const Quadrature<2> &quadrature, const Transfer::Field &f)
  {
    const FE_Q<2> linear(1);
    FEValues<2>   values(linear, quadrature, update_quadrature_points);
    mesh.non_decreasing.clear();
    mesh.points.clear();
    for (const auto &cell : mesh.tria.active_cell_iterators())
      {
        values.reinit(cell);
        mesh.points[cell->id()] = values.get_quadrature_points();
        std::vector<double> d;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          d.push_back(f[cell->active_cell_index()][q * n_history + 3]);
        mesh.non_decreasing[cell->id()] = d;
      }
  }

  void
  check_smooth(const Mesh &mesh, const Transfer::Field &f, const double tol)
  {
    double worst = 0;
    for (const auto &cell : mesh.tria.active_cell_iterators())
      {
        const auto &points = mesh.points.at(cell->id());
        for (unsigned int q = 0; q < points.size(); ++q)
          for (const unsigned int c : {0u, 1u, 2u})
            worst = std::max(worst,
                             std::abs(
                               f[cell->active_cell_index()][q * n_history + c]
                               - exact(c, cell->material_id(), points[q])));
      }
    std::cout << "  smooth components: largest error " << worst << std::endl;
    amfrac_test::check(worst < tol,
                       "constant and linear per ply survive exactly",
                       __FILE__,
                       __LINE__);
  }

  /** The non-decreasing component against the old one at the same place:
   * equal to the nearest old point of the same old cell (kept or parent),
   * or the largest of the old children. */
  void
  check_non_decreasing(const Mesh            &before,
                       const Mesh            &after,
                       const Transfer::Field &f)
  {
    bool ok = true;
    for (const auto &cell : after.tria.active_cell_iterators())
      {
        const auto &points = after.points.at(cell->id());
        const auto  value  = [&](const unsigned int q) {
          return f[cell->active_cell_index()][q * n_history + 3];
        };
        auto old = before.points.find(cell->id());
        if (old == before.points.end() && cell->level() > 0)
          old = before.points.find(cell->parent()->id());
        if (old != before.points.end())
          {
            const auto &old_values = before.non_decreasing.at(old->first);
            for (unsigned int q = 0; q < points.size(); ++q)
              {
                unsigned int nearest = 0;
                for (unsigned int k = 1; k < old->second.size(); ++k)
                  if (points[q].distance(old->second[k])
                      < points[q].distance(old->second[nearest]))
                    nearest = k;
                ok = ok && value(q) == old_values[nearest];
              }
            continue;
          }
        double largest = -1;
        for (const auto &[id, values] : before.non_decreasing)
          if (cell->id().is_parent_of(id))
            for (const double v : values)
              largest = std::max(largest, v);
        for (unsigned int q = 0; q < points.size(); ++q)
          ok = ok && largest >= 0 && value(q) == largest;
      }
    amfrac_test::check(ok,
                       "non-decreasing: kept, injected, or the largest of "
                       "the children",
                       __FILE__,
                       __LINE__);
  }

  void
  run(const unsigned int degree)
  {
    std::cout << "recovery degree " << degree << std::endl;
    const auto prm = parameters::Parameters::from_string(
      "set Dimension = 2\nsubsection Geometry\n"
      "  set Stacking sequence = [0/90]\n  set Ply thickness = 0.5\n"
      "  set Length = 4\n  set Elements along length = 4\n"
      "  set Elements per ply = 2\nend\n");
    const Laminate laminate(prm.geometry, prm.materials);
    Mesh           mesh;
    make_laminate_mesh<2>(prm.geometry, laminate, mesh.tria);
    const QGauss<2>                        quadrature(3);
    std::mt19937                           random(42);
    std::uniform_real_distribution<double> damage(0, 1);

    // The initial field.
    Transfer::Field field(mesh.tria.n_active_cells(),
                          std::vector<double>(quadrature.size() * n_history));
    {
      const FE_Q<2> linear(1);
      FEValues<2>   values(linear, quadrature, update_quadrature_points);
      for (const auto &cell : mesh.tria.active_cell_iterators())
        {
          values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              auto *at = &field[cell->active_cell_index()][q * n_history];
              for (const unsigned int c : {0u, 1u, 2u})
                at[c]
                  = exact(c, cell->material_id(), values.quadrature_point(q));
              at[3] = damage(random);
            }
        }
    }
    record(mesh, quadrature, field);
    Transfer transfer(mesh.tria,
                      degree,
                      quadrature,
                      {Transfer::Rule::smooth,
                       Transfer::Rule::smooth,
                       Transfer::Rule::smooth,
                       Transfer::Rule::non_decreasing});

    // Refine: isotropically for x < 2, along the plies for x > 3.
    for (const auto &cell : mesh.tria.active_cell_iterators())
      if (cell->center()[0] < 2)
        cell->set_refine_flag();
      else if (cell->center()[0] > 3)
        cell->set_refine_flag(RefinementCase<2>::cut_x);
    mesh.tria.prepare_coarsening_and_refinement();
    transfer.prepare(field);
    Mesh before;
    before.non_decreasing = mesh.non_decreasing;
    before.points         = mesh.points;
    mesh.tria.execute_coarsening_and_refinement();
    field = transfer.interpolate();
    record(mesh, quadrature, field);
    check_smooth(mesh, field, 1e-10);
    check_non_decreasing(before, mesh, field);

    // Coarsen the children with x < 1, refine the cells with 2 < x < 3.
    for (const auto &cell : mesh.tria.active_cell_iterators())
      if (cell->center()[0] < 1 && cell->level() > 0)
        cell->set_coarsen_flag();
      else if (cell->center()[0] > 2 && cell->center()[0] < 3)
        cell->set_refine_flag();
    mesh.tria.prepare_coarsening_and_refinement();
    transfer.prepare(field);
    before.non_decreasing           = mesh.non_decreasing;
    before.points                   = mesh.points;
    const unsigned int cells_before = mesh.tria.n_active_cells();
    mesh.tria.execute_coarsening_and_refinement();
    field = transfer.interpolate();
    record(mesh, quadrature, field);
    std::cout << "  " << cells_before << " -> " << mesh.tria.n_active_cells()
              << " cells" << std::endl;
    check_smooth(mesh, field, 1e-10);
    check_non_decreasing(before, mesh, field);
  }

  /** keep_unchanged_cells: a field outside the recovery space (random
   * per point) keeps its values exactly on the cells the change keeps,
   * in the smooth components too; without it the projection changes
   * them. */
  void
  run_kept_cells()
  {
    const auto prm = parameters::Parameters::from_string(
      "set Dimension = 2\nsubsection Geometry\n"
      "  set Stacking sequence = [0/90]\n  set Ply thickness = 0.5\n"
      "  set Length = 4\n  set Elements along length = 4\n"
      "  set Elements per ply = 2\nend\n");
    const Laminate laminate(prm.geometry, prm.materials);
    for (const bool keep : {true, false})
      {
        Triangulation<2> tria;
        make_laminate_mesh<2>(prm.geometry, laminate, tria);
        const QGauss<2>                        quadrature(2);
        std::mt19937                           random(7);
        std::uniform_real_distribution<double> noise(0, 1);
        Transfer::Field                        field(tria.n_active_cells(),
                              std::vector<double>(quadrature.size() * 2));
        for (auto &values : field)
          for (double &v : values)
            v = noise(random);
        Transfer                              transfer(tria,
                          1,
                          quadrature,
                          {Transfer::Rule::smooth,
                                                        Transfer::Rule::non_decreasing},
                          keep);
        std::map<CellId, std::vector<double>> old;
        for (const auto &cell : tria.active_cell_iterators())
          {
            old[cell->id()] = field[cell->active_cell_index()];
            if (cell->center()[0] < 2)
              cell->set_refine_flag();
          }
        tria.prepare_coarsening_and_refinement();
        transfer.prepare(field);
        tria.execute_coarsening_and_refinement();
        field                = transfer.interpolate();
        unsigned int kept    = 0;
        bool         smooth  = true; // smooth components kept exactly
        bool         damaged = true; // non-decreasing kept exactly
        for (const auto &cell : tria.active_cell_iterators())
          if (const auto was = old.find(cell->id()); was != old.end())
            {
              ++kept;
              const auto &now = field[cell->active_cell_index()];
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  smooth  = smooth && now[2 * q] == was->second[2 * q];
                  damaged = damaged && now[2 * q + 1] == was->second[2 * q + 1];
                }
            }
        std::cout << "  keep unchanged cells " << keep << ": " << kept
                  << " kept cells, smooth values unchanged " << smooth
                  << std::endl;
        CHECK(kept == 8);
        CHECK(damaged);
        CHECK(smooth == keep);
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run(1);
  run(2);
  run_kept_cells();
  return amfrac_test::summary();
}

// The seed's transfer between unrelated meshes (NonMatchingTransfer, for
// global remeshing, issue 8) on a two-ply [0/90] laminate, from hexahedra
// to prisms of another in-plane mesh and back, degree 1 and 2:
// - tau_2: a field linear in each ply, with a jump across the ply interface
//   (as across a released interface), arrives exactly (1e-12) at every copy
//   of the new mesh, each side of the jump from its own ply;
// - tau_2: a smooth field converges at the interpolation order p + 1 of the
//   old mesh (maximum over the new copies, the old in-plane mesh refined
//   twice; the rate of the last step within 0.25);
// - tau_1: a Gauss-point variable constant in each ply stays that constant
//   at the new points (1e-12);
// - tau_1: a damage-like variable (random) never decreases: each new point
//   is at least every old value of the old cell it lies in, and the largest
//   damage survives a coarser new mesh.
// - tau_1: a hardening variable (Rule::injected, kappa) on a finer new mesh
//   takes the value of the old point nearest to it in its old cell, below
//   the damage rule's largest value of that cell wherever the old cell's
//   values differ; the largest value survives a coarser new mesh.
// Both meshes are replicated (parallel::shared): runs on any number of
// ranks with the same results.
#include "../check.h"

#include <amfrac/adaptivity/mesh_transfer.h>
#include <amfrac/geometry/laminate.h>
#include <amfrac/parameters/parameters.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/fe/fe_values.h>
#include <random>

using namespace amfrac;

namespace
{
  constexpr int dim = 3;
  using Transfer    = NonMatchingTransfer<dim>;

  /** A laminate mesh and its copy layer, from a scene's Geometry. */
  struct Mesh
  {
    parameters::Parameters               prm;
    Laminate                             laminate;
    parallel::shared::Triangulation<dim> triangulation;
    std::unique_ptr<TiedCopyDoFs<dim>>   dofs;

    Mesh(const std::string &shape,
         const unsigned int nx,
         const unsigned int ny,
         const unsigned int degree)
      : prm(parameters::Parameters::from_string(
        "set Dimension = 3\nsubsection Geometry\n"
        "  set Stacking sequence = [0/90]\n  set Ply thickness = 0.5\n"
        "  set Length = 3\n  set Width = 2\n"
        "  set Elements along length = "
        + std::to_string(nx)
        + "\n  set Elements along width = " + std::to_string(ny)
        + "\n  set Elements per ply = 2\n  set Element shape = " + shape
        + "\nend\n"))
      , laminate(prm.geometry, prm.materials)
      , triangulation(MPI_COMM_WORLD)
    {
      make_laminate_mesh(prm.geometry, laminate, triangulation);
      dofs = std::make_unique<TiedCopyDoFs<dim>>(
        triangulation,
        degree,
        shape == "prism" ? ReferenceCells::Wedge :
                           ReferenceCells::get_hypercube<dim>());
      // The ply interface is released: the copies on it are not tied.
      dofs->distribute([](const auto &cell, const unsigned int f) {
        return cell->material_id() != cell->neighbor(f)->material_id();
      });
    }
  };

  /** @p f(ply, point, component) at every copy of @p mesh. */
  template <typename Function>
  Vector<double>
  at_copies(const Mesh &mesh, const Function &f)
  {
    const auto                          &fe = mesh.dofs->get_fe();
    Vector<double>                       copies(mesh.dofs->n_copies());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : mesh.dofs->copy_handler().active_cell_iterators())
      {
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          copies[indices[i]]
            = f(cell->material_id(),
                mesh.dofs->get_linear_mapping().transform_unit_to_real_cell(
                  cell, fe.unit_support_point(i)),
                fe.system_to_component_index(i).first);
      }
    return copies;
  }

  double
  linear_per_ply(const unsigned int ply, const Point<dim> &p, unsigned int c)
  {
    const double base = ply == 0 ? 0.3 : -1.2;
    return base + (c + 1) * p[0] - 0.7 * p[1] + (ply == 0 ? 2. : -3.) * p[2];
  }

  double
  smooth(const unsigned int, const Point<dim> &p, const unsigned int c)
  {
    return std::sin(1.3 * p[0] + 0.4 * c) * std::cos(0.9 * p[1]) + 0.5 * p[2];
  }

  double
  largest_difference(const Vector<double> &a, const Vector<double> &b)
  {
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  }

  void
  check_linear(const Mesh &from, const Mesh &to)
  {
    const Transfer transfer(*from.dofs, *to.dofs);
    const auto     moved = transfer.nodal(at_copies(from, linear_per_ply));
    const double   error
      = largest_difference(moved, at_copies(to, linear_per_ply));
    std::cout << "linear field per ply: largest error " << error << ", "
              << transfer.n_outside() << " copies outside" << std::endl;
    CHECK(error < 1e-12);
    CHECK(transfer.n_outside() == 0);
  }

  void
  check_smooth_rate(const unsigned int degree)
  {
    const Mesh          to("prism", 7, 5, 2);
    std::vector<double> errors;
    for (const unsigned int n : {3u, 6u, 12u})
      {
        const Mesh     from("hexahedron", n, n, degree);
        const Transfer transfer(*from.dofs, *to.dofs);
        errors.push_back(
          largest_difference(transfer.nodal(at_copies(from, smooth)),
                             at_copies(to, smooth)));
      }
    const double rate = std::log2(errors[1] / errors[2]);
    std::cout << "smooth field, old Q" << degree << " refined: errors "
              << errors[0] << ", " << errors[1] << ", " << errors[2]
              << ", rate " << rate << std::endl;
    // Only the in-plane mesh is refined (2 elements per ply throughout):
    // the field is linear through the thickness, which both degrees carry.
    CHECK(rate > degree + 1 - 0.25);
  }

  void
  check_constant_per_ply(const Mesh &from, const Mesh &to)
  {
    const auto      old_points = from.dofs->cell_quadrature(3);
    const auto      new_points = to.dofs->cell_quadrature(2);
    Transfer::Field field(from.triangulation.n_active_cells(),
                          std::vector<double>(old_points.size() * 2));
    for (const auto &cell : from.triangulation.active_cell_iterators())
      for (unsigned int q = 0; q < old_points.size(); ++q)
        {
          field[cell->active_cell_index()][2 * q]
            = cell->material_id() ? 7. : -2.;
          field[cell->active_cell_index()][2 * q + 1] = 0.125;
        }
    const Transfer transfer(*from.dofs, *to.dofs);
    const auto     moved
      = transfer.quadrature(field,
                            old_points,
                            {Transfer::Rule::smooth, Transfer::Rule::smooth},
                            new_points);
    double error = 0;
    for (const auto &cell : to.triangulation.active_cell_iterators())
      for (unsigned int q = 0; q < new_points.size(); ++q)
        {
          const auto &v = moved[cell->active_cell_index()];
          error
            = std::max(error,
                       std::abs(v[2 * q] - (cell->material_id() ? 7. : -2.)));
          error = std::max(error, std::abs(v[2 * q + 1] - 0.125));
        }
    std::cout << "constant per ply: largest error " << error << std::endl;
    CHECK(error < 1e-12);
  }

  void
  check_damage(const Mesh &from, const Mesh &to)
  {
    const auto   old_points = from.dofs->cell_quadrature(2);
    const auto   new_points = to.dofs->cell_quadrature(2);
    std::mt19937 generator(42);
    std::uniform_real_distribution<double> uniform(0, 1);
    Transfer::Field field(from.triangulation.n_active_cells());
    double          largest = 0;
    for (auto &values : field)
      for (unsigned int q = 0; q < old_points.size(); ++q)
        {
          // Most points undamaged, a few damaged: a sparse field that an
          // averaging rule would lower.
          const double d = uniform(generator) < 0.1 ? uniform(generator) : 0;
          values.push_back(d);
          largest = std::max(largest, d);
        }
    const Transfer transfer(*from.dofs, *to.dofs);
    const auto     moved = transfer.quadrature(field,
                                           old_points,
                                           {Transfer::Rule::non_decreasing},
                                           new_points);
    // Each new point against the old cell around it.
    const CellLocator<dim> old_cells(*from.dofs);
    FEValues<dim>          values(to.dofs->get_mapping(),
                         to.dofs->get_fe(),
                         new_points,
                         update_quadrature_points);
    unsigned int           lowered = 0;
    double                 new_max = 0;
    for (const auto &cell : to.dofs->copy_handler().active_cell_iterators())
      {
        values.reinit(cell);
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const double d   = moved[cell->active_cell_index()][q];
            new_max          = std::max(new_max, d);
            const auto found = old_cells.locate(values.quadrature_point(q),
                                                cell->material_id());
            for (const double old : field[found.cell->active_cell_index()])
              lowered += d < old ? 1 : 0;
          }
      }
    std::cout << "damage: " << lowered << " points lowered, largest " << new_max
              << " (old " << largest << ")" << std::endl;
    CHECK(lowered == 0);
    CHECK(new_max == largest);
  }

  /** An old field that differs at every point of a cell: the x coordinate
   * of the point in its reference cell plus the cell's index. */
  Transfer::Field
  distinct_field(const Mesh &from, const Quadrature<dim> &points)
  {
    Transfer::Field field(from.triangulation.n_active_cells());
    for (const auto &cell : from.triangulation.active_cell_iterators())
      for (unsigned int q = 0; q < points.size(); ++q)
        field[cell->active_cell_index()].push_back(
          points.point(q)[0] + 0.01 * cell->active_cell_index());
    return field;
  }

  void
  check_injected(const Mesh &from, const Mesh &to, const bool finer)
  {
    const auto points = from.dofs->cell_quadrature(2);
    const auto field  = distinct_field(from, points);
    // Two components per point: 0 injected (the field), 1 nearest (the
    // point's own number, q + n_q * cell: the field repeats along y and
    // z, and a wrong pick there would go unseen).
    auto twice = field;
    for (auto &values_of_cell : twice)
      {
        std::vector<double> both;
        const double        cell = &values_of_cell - &twice[0];
        for (unsigned int q = 0; q < values_of_cell.size(); ++q)
          both.insert(both.end(),
                      {values_of_cell[q], q + points.size() * cell});
        values_of_cell = both;
      }
    const Transfer transfer(*from.dofs, *to.dofs);
    const auto     moved
      = transfer.quadrature(twice,
                            points,
                            {Transfer::Rule::injected, Transfer::Rule::nearest},
                            points);
    const CellLocator<dim> old_cells(*from.dofs);
    FEValues<dim>          values(to.dofs->get_mapping(),
                         to.dofs->get_fe(),
                         points,
                         update_quadrature_points);
    unsigned int           wrong = 0, below = 0, not_nearest = 0;
    double                 old_max = 0, new_max = 0;
    for (const auto &values_of_cell : field)
      for (const double v : values_of_cell)
        old_max = std::max(old_max, v);
    for (const auto &cell : to.dofs->copy_handler().active_cell_iterators())
      {
        values.reinit(cell);
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const double value   = moved[cell->active_cell_index()][2 * q];
            new_max              = std::max(new_max, value);
            const auto   found   = old_cells.locate(values.quadrature_point(q),
                                                cell->material_id());
            const auto  &old     = field[found.cell->active_cell_index()];
            unsigned int nearest = 0;
            for (unsigned int p = 1; p < points.size(); ++p)
              if (points.point(p).distance(found.unit)
                  < points.point(nearest).distance(found.unit))
                nearest = p;
            // A finer new cell holds at most one old point here (the
            // mesh is 3 times finer in the plane): the value is the
            // nearest point's unless that point lies in it and is larger.
            wrong += finer && value < old[nearest] ? 1 : 0;
            // Rule::nearest: that point's own number, finer or coarser.
            const double number
              = nearest
                + points.size() * double(found.cell->active_cell_index());
            not_nearest
              += moved[cell->active_cell_index()][2 * q + 1] != number ? 1 : 0;
            below += value < *std::max_element(old.begin(), old.end()) ? 1 : 0;
          }
      }
    std::cout << "injected (" << (finer ? "finer" : "coarser") << "): " << wrong
              << " points below their nearest old point, " << below
              << " below the largest of their old cell; largest " << new_max
              << " (old " << old_max << "); nearest: " << not_nearest
              << " points differ from their nearest old point" << std::endl;
    CHECK(wrong == 0);
    CHECK(not_nearest == 0);
    if (finer)
      CHECK(below > moved.size());
    else
      CHECK(new_max == old_max);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {1u, 2u})
    {
      const Mesh hexahedra("hexahedron", 6, 4, degree);
      const Mesh prisms("prism", 5, 7, degree);
      check_linear(hexahedra, prisms);
      check_linear(prisms, hexahedra);
      check_smooth_rate(degree);
    }
  const Mesh fine("hexahedron", 9, 6, 1), coarse("prism", 3, 2, 1);
  check_constant_per_ply(fine, coarse);
  check_constant_per_ply(coarse, fine);
  check_damage(fine, coarse);
  check_damage(coarse, fine);
  check_injected(coarse, fine, true);
  check_injected(fine, coarse, false);
  return amfrac_test::summary();
}

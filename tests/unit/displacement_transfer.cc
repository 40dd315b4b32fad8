// The seed's tau_2 on the tied-copy DoF layer (issue 4): a displacement moves
// to the new mesh by deal.II's SolutionTransfer on the copy space
// (TiedCopyDoFs::expand_all), back to the reduced unknowns by
// TiedCopyDoFs::gather, and the hanging-node constraints of the new mesh.
// On a two-ply mesh whose ply interface is released (a cohesive interface,
// so the field jumps across it):
// - a field that is a polynomial of degree p in each ply survives
//   refinement, and coarsening followed by refinement elsewhere, exactly;
// - any field of the space survives refinement exactly: a refined cell's
//   children carry the parent's polynomial (checked at the children's
//   support points), and a cell left alone keeps its values (to the
//   round-off of averaging the tied copies).
#include "../check.h"

#include <amfrac/dofs/tied_copy_dofs.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/solution_transfer.h>
#include <map>
#include <random>

using namespace amfrac;

namespace
{
  constexpr int dim  = 2;
  using CellIterator = TiedCopyDoFs<dim>::CellIterator;

  /** A quadratic field per ply (material id), discontinuous across. */
  double
  ply_field(const unsigned int ply, const Point<dim> &p, const unsigned int c)
  {
    const double x = p[0], y = p[1];
    if (ply == 0)
      return c == 0 ? x * x + y - 0.5 * x * y : 2 * x * y - y * y;
    return c == 0 ? 1 - 2 * x + y * y : x * x + 0.25;
  }

  /** Evaluate @p f(cell, point, component) at every copy. */
  template <typename Function>
  Vector<double>
  at_copies(const TiedCopyDoFs<dim> &dofs, const Function &f)
  {
    const auto                          &fe = dofs.get_fe();
    const MappingQ1<dim>                 mapping;
    Vector<double>                       copies(dofs.n_copies());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          copies[indices[i]]
            = f(cell,
                mapping.transform_unit_to_real_cell(cell,
                                                    fe.unit_support_point(i)),
                fe.system_to_component_index(i).first);
      }
    return copies;
  }

  /** Move @p reduced to the mesh after the flags that are set. */
  TrilinosWrappers::MPI::Vector
  transfer(Triangulation<dim>                  &tria,
           TiedCopyDoFs<dim>                   &dofs,
           const TiedCopyDoFs<dim>::FaceFilter &released,
           const TrilinosWrappers::MPI::Vector &reduced)
  {
    Vector<double> copies;
    dofs.expand_all(dofs.replicate(reduced), copies);
    SolutionTransfer<dim, Vector<double>> moving(dofs.copy_handler());
    moving.prepare_for_coarsening_and_refinement(copies);
    tria.execute_coarsening_and_refinement();
    dofs.distribute(released);
    Vector<double> new_copies(dofs.n_copies());
    moving.interpolate(copies, new_copies);
    TrilinosWrappers::MPI::Vector result(dofs.locally_owned_dofs(),
                                         MPI_COMM_WORLD);
    dofs.gather(new_copies, result);
    Vector<double> all = dofs.replicate(result);
    dofs.hanging_node_constraints().distribute(all);
    for (const auto i : dofs.locally_owned_dofs())
      result[i] = all[i];
    result.compress(VectorOperation::insert);
    return result;
  }

  /** The field from copy values (groups averaged) on the reduced space. */
  TrilinosWrappers::MPI::Vector
  reduce(const TiedCopyDoFs<dim> &dofs, const Vector<double> &copies)
  {
    TrilinosWrappers::MPI::Vector reduced(dofs.locally_owned_dofs(),
                                          MPI_COMM_WORLD);
    dofs.gather(copies, reduced);
    return reduced;
  }

  double
  max_difference(const Vector<double> &a, const Vector<double> &b)
  {
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Triangulation<dim>               tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {4, 2},
                                            Point<dim>(0, 0),
                                            Point<dim>(2, 1));
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(cell->center()[1] > 0.5 ? 1 : 0);
  const TiedCopyDoFs<dim>::FaceFilter released
    = [](const auto &cell, const unsigned int f) {
        return !cell->at_boundary(f)
               && cell->neighbor(f)->material_id() != cell->material_id();
      };
  TiedCopyDoFs<dim> dofs(tria, 2);
  dofs.distribute(released);
  const auto exact = [&]() {
    return at_copies(dofs,
                     [](const CellIterator &cell,
                        const Point<dim>   &p,
                        const unsigned int  c) {
                       return ply_field(cell->material_id(), p, c);
                     });
  };
  auto field = reduce(dofs, exact());
  {
    Vector<double> copies;
    dofs.expand_all(dofs.replicate(field), copies);
    CHECK(max_difference(copies, exact()) < 1e-14);
  }

  // Refine some cells on both sides of the interface and elsewhere, then
  // coarsen part of them back while refining others.
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->center()[0] < 1)
      cell->set_refine_flag();
  field = transfer(tria, dofs, released, field);
  Vector<double> copies;
  dofs.expand_all(dofs.replicate(field), copies);
  const double refined_error = max_difference(copies, exact());
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->level() == 1 && cell->center()[0] < 0.5)
      cell->set_coarsen_flag();
    else if (cell->level() == 0 && cell->center()[0] > 1.5)
      cell->set_refine_flag();
  field = transfer(tria, dofs, released, field);
  dofs.expand_all(dofs.replicate(field), copies);
  const double coarsened_error = max_difference(copies, exact());
  std::cout << "per-ply quadratic field after refinement " << refined_error
            << ", after coarsening and refinement " << coarsened_error
            << " (cells " << tria.n_active_cells() << ")" << std::endl;
  CHECK(refined_error < 1e-13);
  CHECK(coarsened_error < 1e-13);

  // A random field of the space (hanging entries constrained): refinement
  // keeps it exactly.
  std::mt19937                           random(42);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Vector<double>                         values(dofs.n_dofs());
  for (auto &v : values)
    v = uniform(random);
  dofs.hanging_node_constraints().distribute(values);
  for (const auto i : dofs.locally_owned_dofs())
    field[i] = values[i];
  field.compress(VectorOperation::insert);
  dofs.expand_all(dofs.replicate(field), copies);
  // Old values per cell, and the old polynomial on each refined cell.
  std::map<CellId, Vector<double>> before;
  const auto                      &fe = dofs.get_fe();
  for (const auto &cell : dofs.copy_handler().active_cell_iterators())
    {
      Vector<double> local(fe.n_dofs_per_cell());
      cell->get_dof_values(copies, local);
      before[cell->id()] = local;
    }
  std::vector<CellId> refined;
  for (const auto &cell : tria.active_cell_iterators())
    if ((cell->active_cell_index() % 3) == 0)
      {
        cell->set_refine_flag();
        refined.push_back(cell->id());
      }
  const auto old_field
    = [&](const CellIterator &cell, const Point<dim> &p, const unsigned int c) {
        // The parent's values at the child's support point: the parent is
        // still in the hierarchy, so its shape functions can be evaluated.
        const auto           parent = cell->parent();
        const MappingQ1<dim> mapping;
        const Point<dim> unit  = mapping.transform_real_to_unit_cell(parent, p);
        const auto      &old   = before.at(parent->id());
        double           value = 0;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (fe.system_to_component_index(i).first == c)
            value += old[i] * fe.shape_value(i, unit);
        return value;
      };
  field = transfer(tria, dofs, released, field);
  dofs.expand_all(dofs.replicate(field), copies);
  double children_error = 0, kept_error = 0;
  for (const auto &cell : dofs.copy_handler().active_cell_iterators())
    {
      Vector<double> local(fe.n_dofs_per_cell());
      cell->get_dof_values(copies, local);
      if (before.count(cell->id()) != 0)
        {
          for (unsigned int i = 0; i < local.size(); ++i)
            kept_error = std::max(kept_error,
                                  std::abs(local[i] - before[cell->id()][i]));
          continue;
        }
      const MappingQ1<dim> mapping;
      for (unsigned int i = 0; i < local.size(); ++i)
        children_error
          = std::max(children_error,
                     std::abs(
                       local[i]
                       - old_field(cell,
                                   mapping.transform_unit_to_real_cell(
                                     cell, fe.unit_support_point(i)),
                                   fe.system_to_component_index(i).first)));
    }
  std::cout << "random field: " << refined.size()
            << " cells refined, children against the parent's polynomial "
            << children_error << ", cells left alone " << kept_error
            << std::endl;
  CHECK(children_error < 1e-12);
  CHECK(kept_error < 1e-14);
  return amfrac_test::summary();
}

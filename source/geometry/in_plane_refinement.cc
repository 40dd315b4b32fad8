#include <amfrac/geometry/in_plane_refinement.h>
#include <deal.II/grid/grid_tools.h>

namespace amfrac
{
  template <int dim>
  void
  keep_refinement_in_plane(Triangulation<dim>       &triangulation,
                           const RefinementCase<dim> cut)
  {
    if (dim == 2)
      return;
    const auto cells_at = GridTools::vertex_to_cell_map(triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->refine_flag_set())
        cell->set_refine_flag(cut);
    for (bool changed = true; changed;)
      {
        changed = false;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->refine_flag_set())
            for (const unsigned int v : cell->vertex_indices())
              for (const auto &other : cells_at[cell->vertex_index(v)])
                if (other->is_active() && other->level() < cell->level()
                    && !other->refine_flag_set())
                  {
                    other->clear_coarsen_flag();
                    other->set_refine_flag(cut);
                    changed = true;
                  }
      }
  }



  template <int dim>
  bool
  flagged_through_thickness(const Triangulation<dim> &triangulation)
  {
    if (dim == 2)
      return false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->refine_flag_set() & RefinementCase<dim>::cut_axis(dim - 1))
        return true;
    return false;
  }



  template void
  keep_refinement_in_plane(Triangulation<2> &, const RefinementCase<2>);
  template void
  keep_refinement_in_plane(Triangulation<3> &, const RefinementCase<3>);
  template bool
  flagged_through_thickness(const Triangulation<2> &);
  template bool
  flagged_through_thickness(const Triangulation<3> &);
} // namespace amfrac

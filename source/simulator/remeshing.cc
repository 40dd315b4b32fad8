#include <amfrac/adaptivity/mesh_transfer.h>
#include <amfrac/adaptivity/remeshing.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/function.h>
#include <deal.II/numerics/rtree.h>
#include <limits>
#include <stdexcept>
#include <utility>

namespace amfrac
{
  namespace
  {
    namespace bgi = boost::geometry::index;

    /** The copy values of @p from on the cells of @p to, a layer of the
     * same element on a copy of the mesh (the same cells in the same
     * order). */
    template <int dim>
    dealii::Vector<double>
    copies_on(const TiedCopyDoFs<dim>      &from,
              const dealii::Vector<double> &from_copies,
              const TiedCopyDoFs<dim>      &to)
    {
      dealii::Vector<double> copies(to.copy_handler().n_dofs());
      dealii::Vector<double> local(from.get_fe().n_dofs_per_cell());
      auto                   other = to.copy_handler().begin_active();
      for (const auto &cell : from.copy_handler().active_cell_iterators())
        {
          if (cell->center().distance(other->center())
              > 1e-12 * cell->diameter())
            throw std::logic_error("remeshing: the copy of the mesh has its "
                                   "cells in another order");
          cell->get_dof_values(from_copies, local);
          other->set_dof_values(local, copies);
          ++other;
        }
      return copies;
    }
  } // namespace



  template <int dim>
  bool
  Simulator<dim>::remesh()
  {
    std::vector<dealii::Vector<double>> copies(1);
    dealii::Vector<double>              carried;
    dof_layer.expand_all(error_estimator().replicate(relevant_solution),
                         copies[0]);
    const double old_norm = last_zz.solution_norm;
    if (!remesh_carrying(copies, [&](const auto &transfer, const auto &old) {
          carried = transfer.nodal(old[0]);
        }))
      {
        pcout << "  the mesh has " << triangulation.n_active_cells()
              << " cells, about Adaptivity/Maximum cells: the cycles stop"
              << std::endl;
        return false;
      }
    first_guess.reinit(dof_layer.locally_owned_dofs(), comm);
    dof_layer.gather(carried, first_guess);

    Vector relevant(dof_layer.locally_owned_dofs(),
                    dof_layer.locally_relevant_dofs(),
                    comm);
    relevant               = first_guess;
    const auto   estimator = error_estimator();
    const double moved_norm
      = estimator.energy_error(estimator.replicate(relevant),
                               Functions::ZeroFunction<dim>(dim));
    auto &event = last_remeshing;
    event.energy_change
      = old_norm > 0 ? std::abs(moved_norm / old_norm - 1) : 0;
    pcout << "  remeshed: the energy norm of the carried solution differs by "
          << event.energy_change << std::endl;
    return true;
  }



  template <int dim>
  bool
  Simulator<dim>::remesh_carrying(
    const std::vector<dealii::Vector<double>> &copies,
    const Carry                               &carry)
  {
    // The size field lives in the plane of a 3D laminate.
    if constexpr (dim != 3)
      throw std::logic_error("remeshing is for 3D prism meshes");
    else
      {
        const auto    &adaptivity = parameters.adaptivity;
        RemeshingEvent event;
        event.zz_relative_before     = last_zz.relative();
        event.zz_relative_reached    = std::numeric_limits<double>::quiet_NaN();
        const unsigned int old_cells = triangulation.n_active_cells();

        // The size field: every cell's size by the seed's rule, or halved.
        RemeshingRule rule;
        rule.degree   = parameters.discretization.degree;
        rule.min_size = adaptivity.min_element_size;
        std::vector<double> sizes;
        if (!process_zone_sizes.empty())
          {
            sizes = std::exchange(process_zone_sizes, {});
            for (double &size : sizes)
              size = std::max(size, rule.min_size);
          }
        else if (adaptivity.strategy
                 == parameters::Adaptivity::Strategy::uniform)
          for (const auto &cell : triangulation.active_cell_iterators())
            sizes.push_back(std::max(rule.min_size, 0.5 * in_plane_size(cell)));
        else
          {
            // The same equal share as the refinement of hexahedra.
            const double target = adaptivity.target_error;
            const double share  = target * last_zz.solution_norm
                                 / std::sqrt((1 - target * target) * old_cells);
            sizes
              = rule.new_sizes(triangulation, last_estimate.cell_errors, share);
          }
        InPlaneSizeField field(triangulation, sizes);
        const double     layers = double(old_cells) / field.n_triangles();
        event.predicted_cells   = layers * field.predicted_triangles();
        if (adaptivity.max_cells > 0
            && event.predicted_cells > adaptivity.max_cells)
          {
            if (old_cells >= 0.9 * adaptivity.max_cells)
              return false;
            field.scale(
              std::sqrt(event.predicted_cells / adaptivity.max_cells));
            event.predicted_cells = adaptivity.max_cells;
          }
        event.smallest_size = field.range().first;

        // The old mesh and its field stay for the transfer.
        Timer              watch;
        Triangulation<dim> old_mesh;
        old_mesh.copy_triangulation(triangulation);
        TiedCopyDoFs<dim> old_layer(old_mesh,
                                    dof_layer.get_fe().degree,
                                    dof_layer.reference_cell());
        old_layer.distribute();
        std::vector<dealii::Vector<double>> old_copies;
        for (const auto &field : copies)
          old_copies.push_back(copies_on(dof_layer, field, old_layer));

        {
          TimerOutput::Scope scope(timer, "remesh (Gmsh)");
          // Gmsh first: if it fails, the mesh and the state are untouched.
          PlaneMesh plane
            = mesh_laminate_plane(parameters.geometry, field.function(), comm);
          triangulation.clear();
          make_laminate_mesh(
            parameters.geometry, laminate, triangulation, false, &plane);
          remeshed_plane = std::move(plane);
          rebuild_after_mesh_change();
        }
        event.mesh_seconds = watch.wall_time();

        watch.restart();
        {
          TimerOutput::Scope             scope(timer, "transfer");
          const NonMatchingTransfer<dim> transfer(old_layer, dof_layer);
          carry(transfer, old_copies);
          event.outside = transfer.n_outside();
        }
        event.transfer_seconds = watch.wall_time();
        last_remeshing         = event;
        pcout << "  remeshed: " << old_cells << " -> "
              << triangulation.n_global_active_cells() << " cells (predicted "
              << static_cast<unsigned long>(event.predicted_cells)
              << "), smallest size " << event.smallest_size
              << " mm; Gmsh and setup " << event.mesh_seconds << " s, transfer "
              << event.transfer_seconds << " s (" << event.outside
              << " points outside the old mesh)" << std::endl;
        return true;
      }
  }

  template <int dim>
  bool
  Simulator<dim>::plan_process_zone_remeshing()
  {
    if constexpr (dim != 3)
      throw std::logic_error("remeshing is for 3D prism meshes");
    else
      {
        const unsigned int n = parameters.adaptivity.process_zone_elements;
        // Minimum element size bounds the remeshed sizes: a front whose
        // l_cz / n lies below it is fine at that size, or the rule would
        // remesh after every step.
        const double smallest = parameters.adaptivity.min_element_size;
        // The fronts in the plane: the size field is an in-plane one.
        auto front = interfaces->front_points(process_zone_lengths(), comm);
        if (front.empty())
          return false;
        for (auto &[point, reach] : front)
          point[2] = 0;
        const auto          tree = pack_rtree(front);
        std::vector<double> sizes(triangulation.n_active_cells());
        bool                needed = false;
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            Point<3> center = cell->center();
            center[2]       = 0;
            std::vector<std::pair<Point<3>, double>> closest;
            tree.query(bgi::nearest(center, 1), std::back_inserter(closest));
            const double reach = closest[0].second;
            const double h     = std::max(reach / n, smallest);
            const double size  = in_plane_size(cell);
            const double distance
              = std::max(0., center.distance(closest[0].first) - 0.5 * size);
            // 1.5: Gmsh's triangles are about, not exactly, their size.
            needed = needed || (distance <= reach && size > 1.5 * h);
            sizes[cell->active_cell_index()]
              = distance <= 2 * reach ?
                  h :
                  std::min(std::max(h, first_mesh_size),
                           h + 0.5 * (distance - 2 * reach));
          }
        if (needed)
          process_zone_sizes = std::move(sizes);
        return needed;
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace amfrac

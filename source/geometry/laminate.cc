#include <algorithm>
#include <amfrac/geometry/laminate.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <random>

namespace amfrac
{
  Laminate::Laminate(const parameters::Geometry  &geometry,
                     const parameters::Materials &materials)
    : plies(geometry.plies)
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
                              const Laminate                &laminate,
                              const double                   amount,
                              const Point<dim>              &box,
                              const std::array<double, dim> &h)
    {
      const unsigned int thickness_axis = dim - 1;
      const double       tol            = 1e-10 * laminate.thickness();
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
              = std::any_of(laminate.ply_boundaries.begin(),
                            laminate.ply_boundaries.end(),
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
  } // namespace



  template <int dim>
  void
  make_laminate_mesh(const parameters::Geometry &geometry,
                     const Laminate             &laminate,
                     Triangulation<dim>         &triangulation)
  {
    std::vector<std::vector<double>> steps(dim);
    steps[0].assign(geometry.elements_along_length,
                    geometry.length / geometry.elements_along_length);
    if (dim == 3)
      steps[1].assign(geometry.elements_along_width,
                      geometry.width / geometry.elements_along_width);
    for (unsigned int p = 0; p < laminate.n_plies(); ++p)
      steps[dim - 1].insert(steps[dim - 1].end(),
                            geometry.elements_per_ply,
                            (laminate.ply_boundaries[p + 1]
                             - laminate.ply_boundaries[p])
                              / geometry.elements_per_ply);

    Point<dim> box;
    box[0] = geometry.length;
    if (dim == 3)
      box[1] = geometry.width;
    box[dim - 1] = laminate.thickness();
    GridGenerator::subdivided_hyper_rectangle(
      triangulation, steps, Point<dim>(), box, /*colorize=*/true);

    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const double z     = cell->center()[dim - 1];
        const auto   upper = std::upper_bound(laminate.ply_boundaries.begin(),
                                            laminate.ply_boundaries.end(),
                                            z);
        cell->set_material_id(
          std::min<unsigned int>(upper - laminate.ply_boundaries.begin() - 1,
                                 laminate.n_plies() - 1));
      }
    triangulation.refine_global(geometry.global_refinements);

    if (geometry.mesh_distortion > 0)
      {
        std::array<double, dim> h;
        const double scale = std::pow(0.5, geometry.global_refinements);
        h[0] = scale * geometry.length / geometry.elements_along_length;
        if (dim == 3)
          h[1] = scale * geometry.width / geometry.elements_along_width;
        h[dim - 1] = scale
                     * *std::min_element(geometry.ply_thickness.begin(),
                                         geometry.ply_thickness.end())
                     / geometry.elements_per_ply;
        distort_interior_vertices<dim>(
          triangulation, laminate, geometry.mesh_distortion, box, h);
      }

    if (!geometry.refinement_region.empty())
      {
        const auto region = make_expression_function<dim>(
          {geometry.refinement_region}, 1, "", "Geometry/Refinement region");
        for (unsigned int r = 0; r < geometry.region_refinements; ++r)
          {
            for (const auto &cell : triangulation.active_cell_iterators())
              if (region->value(cell->center()) != 0.)
                cell->set_refine_flag();
            triangulation.execute_coarsening_and_refinement();
          }
      }
  }

  template void
  make_laminate_mesh<2>(const parameters::Geometry &,
                        const Laminate &,
                        Triangulation<2> &);
  template void
  make_laminate_mesh<3>(const parameters::Geometry &,
                        const Laminate &,
                        Triangulation<3> &);
} // namespace amfrac

#include <Epetra_BlockMap.h>
#include <Epetra_MultiVector.h>
#include <amfrac/assembly/element_kernel.h>
#include <amfrac/assembly/face_hoffman_screen.h>
#include <amfrac/assembly/shape_key.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

namespace amfrac
{
  namespace
  {
    /** The material-axes stress components a screen's matrix columns
     * hold, in this order (HoffmanIndex's). */
    constexpr unsigned int components[6][2]
      = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

  } // namespace



  template <int dim>
  Quadrature<dim>
  face_centre_points()
  {
    std::vector<Point<dim>> centres(GeometryInfo<dim>::faces_per_cell);
    for (unsigned int f = 0; f < centres.size(); ++f)
      for (unsigned int d = 0; d < dim; ++d)
        centres[f][d] = d == f / 2 ? double(f % 2) : 0.5;
    return Quadrature<dim>(centres);
  }



  template <int dim>
  FaceHoffmanScreen<dim>::FaceHoffmanScreen(
    const TiedCopyDoFs<dim>               &dofs,
    const std::vector<PlyProperties<dim>> &plies,
    const std::vector<Cell>               &given)
    : dofs(dofs)
    , dofs_per_cell(dofs.get_fe().n_dofs_per_cell())
  {
    const CellShapes<dim> sorted
      = sort_into_shapes(dofs.copy_handler(), dofs.get_fe().degree > 1);

    // The shapes of the screened cells get their matrices, numbered in
    // the order the cells first use them.
    FEValues<dim>                    values(dofs.get_mapping(),
                         dofs.get_fe(),
                         face_centre_points<dim>(),
                         update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<int>                 screen_shape(sorted.first_cell.size(), -1);
    for (const Cell &cell : given)
      {
        const PlyProperties<dim> &ply = plies[cell->material_id()];
        if (!covers(ply))
          continue;
        const unsigned int sorted_shape
          = sorted.shape_of_cell[cell->active_cell_index()];
        int &shape = screen_shape[sorted_shape];
        if (shape < 0)
          {
            shape = hoffman.size();
            hoffman.emplace_back(ply.strengths);
            values.reinit(sorted.first_cell[sorted_shape]);
            for (unsigned int f = 0; f < n_faces; ++f)
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                {
                  const auto stress = evaluate_ply_stress(
                    ply, values[displacement].symmetric_gradient(j, f));
                  for (const auto &c : components)
                    matrices.push_back(stress.material[c[0]][c[1]]);
                  matrices.insert(matrices.end(), column_padding, 0.);
                }
          }
        cells.push_back(cell);
        shape_of_cell.push_back(shape);
      }
    find_partners();
  }



  template <int dim>
  void
  FaceHoffmanScreen<dim>::find_partners()
  {
    std::vector<int> screened(
      dofs.copy_handler().get_triangulation().n_active_cells(), -1);
    for (unsigned int c = 0; c < cells.size(); ++c)
      screened[cells[c]->active_cell_index()] = c;
    partner.assign(cells.size() * n_faces, -1);
    partner_face.assign(cells.size() * n_faces, 0);
    for (unsigned int c = 0; c < cells.size(); ++c)
      for (unsigned int f = 0; f < n_faces; ++f)
        {
          const Cell &cell = cells[c];
          if (cell->at_boundary(f) || !cell->neighbor(f)->is_active()
              || cell->neighbor_is_coarser(f))
            continue;
          const auto neighbor = cell->neighbor(f);
          const int  other    = screened[neighbor->active_cell_index()];
          if (other >= 0 && neighbor->material_id() == cell->material_id())
            {
              partner[c * n_faces + f]      = other;
              partner_face[c * n_faces + f] = cell->neighbor_of_neighbor(f);
            }
        }
  }



  template <int dim>
  FaceHoffmanScreen<dim>::~FaceHoffmanScreen() = default;



  template <int dim>
  bool
  FaceHoffmanScreen<dim>::covers(const PlyProperties<dim> &ply)
  {
    return ply.layers.empty();
  }



  template <int dim>
  void
  FaceHoffmanScreen<dim>::locate_dofs(const Vector &state) const
  {
    const Epetra_BlockMap &map = state.trilinos_vector().Map();
    located_map                = std::make_unique<Epetra_BlockMap>(map);
    local_dofs.resize(cells.size() * dofs_per_cell);
    std::vector<types::global_dof_index> indices(dofs_per_cell);
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        dofs.get_dof_indices(cells[c], indices);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const int local = map.LID(
              static_cast<TrilinosWrappers::types::int_type>(indices[i]));
            AssertThrow(local >= 0,
                        ExcMessage("FaceHoffmanScreen: the state lacks a "
                                   "dof of a screened cell"));
            local_dofs[c * dofs_per_cell + i] = local;
          }
      }
  }



  template <int dim>
  void
  FaceHoffmanScreen<dim>::face_stress(const unsigned int c,
                                      const unsigned int f,
                                      const double      *all,
                                      const double       scale,
                                      double            *stress) const
  {
    const unsigned int n = dofs_per_cell;
    gathered_columns_product(
      &matrices[(shape_of_cell[c] * n_faces + f) * n * column_length],
      n,
      &local_dofs[c * n],
      all,
      stress);
    for (unsigned int k = 0; k < 6; ++k)
      stress[k] *= scale;
  }



  template <int dim>
  std::vector<typename FaceHoffmanScreen<dim>::Index>
  FaceHoffmanScreen<dim>::failing(const Vector                    &state,
                                  const std::vector<std::uint8_t> &face_bits,
                                  const std::vector<double> &strength_scale,
                                  const double               limit) const
  {
    if (!located_map
        || located_map->DataPtr() != state.trilinos_vector().Map().DataPtr())
      locate_dofs(state);
    const double      *all = state.trilinos_vector()[0];
    std::vector<Index> result;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const unsigned int active = cells[c]->active_cell_index();
        const std::uint8_t bits   = face_bits[active];
        for (unsigned int f = 0; f < n_faces; ++f)
          {
            if ((bits & (1u << f)) == 0)
              continue;
            const int    other = partner[c * n_faces + f];
            const double scale = 1. / strength_scale[active * n_faces + f];
            const HoffmanIndex &index_of = hoffman[shape_of_cell[c]];
            double              stress[column_length];
            face_stress(c, f, all, scale, stress);
            double index = index_of(stress);
            if (other >= 0)
              {
                const unsigned int other_active
                  = cells[other]->active_cell_index();
                const unsigned int other_face = partner_face[c * n_faces + f];
                const bool         other_set
                  = (face_bits[other_active] >> other_face) & 1u;
                // The pair is the lower cell's (of those with the bit).
                if (other_set && other_active < active)
                  continue;
                double other_stress[column_length], mean[6];
                face_stress(other, other_face, all, scale, other_stress);
                for (unsigned int k = 0; k < 6; ++k)
                  mean[k] = 0.5 * (stress[k] + other_stress[k]);
                // A side fails (as the one-sided check of a face split
                // between ranks) and so does the mean.
                const double side
                  = other_set ? std::max(index, index_of(other_stress)) : index;
                index = std::min(side, index_of(mean));
              }
            // A NaN fails too: the caller's second round decides.
            if (!(index < limit))
              result.push_back({cells[c], f, index});
          }
      }
    return result;
  }



  template Quadrature<2>
  face_centre_points();
  template Quadrature<3>
  face_centre_points();
  template class FaceHoffmanScreen<2>;
  template class FaceHoffmanScreen<3>;
} // namespace amfrac

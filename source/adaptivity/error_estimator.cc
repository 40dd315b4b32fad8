#include <amfrac/adaptivity/error_estimator.h>
#include <amfrac/assembly/displacement_gradients.h>
#include <amfrac/base/nearest_points.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <limits>
#include <stdexcept>

namespace amfrac
{
  namespace
  {
    /** The largest diagonal stiffness entry of all plies (MPa). */
    template <int dim>
    double
    largest_stiffness(const std::vector<PlyProperties<dim>> &plies)
    {
      double E = 0;
      for (const auto &ply : plies)
        for (unsigned int d = 0; d < dim; ++d)
          E = std::max(E, ply.stiffness[d][d][d][d]);
      return E;
    }
  } // namespace



  namespace
  {
    /** The cell @p cell of a triangulation as an iterator of @p handler
     * (the displacement and the recovery layer share the mesh). */
    template <int dim, typename Iterator>
    typename DoFHandler<dim>::active_cell_iterator
    on_handler(const Iterator &cell, const DoFHandler<dim> &handler)
    {
      return typename DoFHandler<dim>::active_cell_iterator(
        &handler.get_triangulation(), cell->level(), cell->index(), &handler);
    }
  } // namespace



  template <int dim>
  ErrorEstimator<dim>::ErrorEstimator(
    const TiedCopyDoFs<dim>               &dofs,
    const std::vector<PlyProperties<dim>> &plies,
    const FaceFilter                      &released,
    const bool                             finite_strain)
    : dofs(dofs)
    , plies(plies)
    , released(released)
    , finite_strain(finite_strain)
    , comm(dofs.copy_handler().get_triangulation().get_communicator())
  {
    for (const auto &ply : plies)
      compliance.push_back(invert(ply.stiffness));
  }



  template <int dim>
  dealii::Vector<double>
  ErrorEstimator<dim>::replicate(
    const TrilinosWrappers::MPI::Vector &owned) const
  {
    return dofs.replicate(owned);
  }



  template <int dim>
  void
  ErrorEstimator<dim>::cell_stresses(
    const typename TiedCopyDoFs<dim>::CellIterator &cell,
    const dealii::Vector<double>                   &u,
    const FEValuesBase<dim, dim>                   &values,
    std::vector<SymmetricTensor<2, dim>>           &stress) const
  {
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    dofs.get_dof_indices(cell, indices);
    std::vector<double> local(indices.size());
    for (unsigned int i = 0; i < indices.size(); ++i)
      local[i] = u[indices[i]];
    stress.resize(values.n_quadrature_points);
    const auto &C = plies[cell->material_id()].stiffness;
    if (finite_strain)
      {
        std::vector<Tensor<2, dim>> gradients(values.n_quadrature_points);
        values[FEValuesExtractors::Vector(0)]
          .get_function_gradients_from_local_dof_values(local, gradients);
        for (unsigned int q = 0; q < gradients.size(); ++q)
          stress[q] = C * green_lagrange_strain(gradients[q]);
        return;
      }
    values[FEValuesExtractors::Vector(0)]
      .get_function_symmetric_gradients_from_local_dof_values(local, stress);
    for (auto &s : stress)
      s = C * s;
  }



  template <int dim>
  typename ErrorEstimator<dim>::Estimate
  ErrorEstimator<dim>::finish(dealii::Vector<float> &local,
                              double                 norm_squared) const
  {
    Estimate estimate;
    estimate.cell_errors.reinit(local.size());
    Utilities::MPI::sum(local, comm, estimate.cell_errors);
    double sum = 0;
    for (float &e : estimate.cell_errors)
      {
        sum += e;
        e = std::sqrt(e);
      }
    estimate.error         = std::sqrt(sum);
    estimate.solution_norm = std::sqrt(Utilities::MPI::sum(norm_squared, comm));
    return estimate;
  }



  namespace
  {
    /** Monomials of total degree <= @p degree at @p x. */
    template <int dim>
    std::vector<double>
    monomials(const Point<dim> &x, const unsigned int degree)
    {
      std::vector<double> values{1.};
      for (unsigned int d = 0; d < dim; ++d)
        values.push_back(x[d]);
      if (degree >= 2)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = a; b < dim; ++b)
            values.push_back(x[a] * x[b]);
      return values;
    }
  } // namespace



  template <int dim>
  std::vector<dealii::Vector<double>>
  ErrorEstimator<dim>::recover_stress(const TiedCopyDoFs<dim>      &recovery,
                                      const dealii::Vector<double> &u) const
  {
    constexpr unsigned int n_stress
      = SymmetricTensor<2, dim>::n_independent_components;
    const auto &triangulation = dofs.copy_handler().get_triangulation();
    const auto &fe            = dofs.get_fe();
    const auto  cells_at      = GridTools::vertex_to_cell_map(triangulation);

    // Stresses at sample points, cell by cell on demand: the Gauss points
    // of degree p (superconvergent on regular meshes), and the same with
    // p + 1 points through the thickness for patches that cannot see the
    // thickness variation otherwise (a ply one element thick has its
    // superconvergent points at one (Q1) or two (Q2) heights only).
    struct Samples
    {
      FEValues<dim>                                     values;
      std::vector<std::vector<SymmetricTensor<2, dim>>> stress;
      std::vector<std::vector<Point<dim>>>              points;
    };
    // On wedges the in-plane points are the triangle's Gauss points of
    // the same order (its centroid for P1).
    const auto          flags   = update_gradients | update_quadrature_points;
    const Mapping<dim> &mapping = dofs.get_mapping();
    Samples             superconvergent{
      FEValues<dim>(mapping, fe, dofs.cell_quadrature(fe.degree), flags),
      {},
      {}};
    Samples thickness{FEValues<dim>(mapping,
                                    fe,
                                    dofs.cell_quadrature(fe.degree,
                                                         fe.degree + 1),
                                    flags),
                      {},
                      {}};
    for (Samples *samples : {&superconvergent, &thickness})
      {
        samples->stress.resize(triangulation.n_active_cells());
        samples->points.resize(triangulation.n_active_cells());
      }
    const auto sample = [&](Samples &samples, const auto &tria_cell) {
      const unsigned int k = tria_cell->active_cell_index();
      if (samples.stress[k].empty())
        {
          const auto cell = on_handler(tria_cell, dofs.copy_handler());
          samples.values.reinit(cell);
          cell_stresses(cell, u, samples.values, samples.stress[k]);
          samples.points[k] = samples.values.get_quadrature_points();
        }
    };

    // The patches a rank needs: those of every vertex of a cell that
    // shares a vertex with an owned cell, so that each node of an owned
    // cell sees all its patches, summed in vertex order (the same on every
    // rank). A hanging vertex of an owned cell takes its value from the
    // vertices of the coarse cell it hangs on: their nodes need all their
    // patches too (without them the hanging values, and the estimate,
    // depended on the partition).
    std::vector<bool> needed(triangulation.n_vertices(), false);
    const auto        mark_patches_of = [&](const auto &cell) {
      for (const unsigned int v : cell->vertex_indices())
        for (const auto &neighbor : cells_at[cell->vertex_index(v)])
          for (const unsigned int w : neighbor->vertex_indices())
            needed[neighbor->vertex_index(w)] = true;
    };
    const auto has_vertex = [](const auto &cell, const unsigned int v) {
      for (const unsigned int i : cell->vertex_indices())
        if (cell->vertex_index(i) == v)
          return true;
      return false;
    };
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          mark_patches_of(cell);
          // The cells a vertex of this one hangs on.
          for (const unsigned int v : cell->vertex_indices())
            for (const auto &neighbor : cells_at[cell->vertex_index(v)])
              if (!has_vertex(neighbor, cell->vertex_index(v)))
                mark_patches_of(neighbor);
        }

    // Sums of the fits at the nodes: [0, n_stress) values and n_stress the
    // count, from fits of full rank; then the same from rank-deficient
    // fits (patches at corners, plies one element thick), used only where
    // no full fit reaches.
    std::vector<dealii::Vector<double>> sums(
      2 * (n_stress + 1), dealii::Vector<double>(recovery.n_dofs()));
    const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    const unsigned int n_terms = monomials(Point<dim>(), fe.degree).size();
    // Least-squares fit of the patch (v, ply) through @p samples in scaled
    // local coordinates (normal equations; a pseudo-inverse drops what the
    // samples cannot see); true if the fit has full rank.
    const auto fit = [&](Samples                 &samples,
                         const unsigned int       v,
                         const types::material_id ply,
                         const Point<dim>        &center,
                         const double             h,
                         FullMatrix<double>      &coefficients) {
      LAPACKFullMatrix<double> normal(n_terms, n_terms);
      FullMatrix<double>       rhs(n_terms, n_stress);
      for (const auto &cell : cells_at[v])
        if (cell->material_id() == ply)
          {
            sample(samples, cell);
            const unsigned int k = cell->active_cell_index();
            for (unsigned int q = 0; q < samples.points[k].size(); ++q)
              {
                const auto p = monomials<dim>(
                  Point<dim>((samples.points[k][q] - center) / h), fe.degree);
                for (unsigned int i = 0; i < n_terms; ++i)
                  {
                    for (unsigned int j = 0; j < n_terms; ++j)
                      normal(i, j) += p[i] * p[j];
                    for (unsigned int c = 0; c < n_stress; ++c)
                      rhs(i, c)
                        += p[i] * samples.stress[k][q].access_raw_entry(c);
                  }
              }
          }
      normal.compute_inverse_svd(1e-10);
      for (unsigned int c = 0; c < n_stress; ++c)
        {
          dealii::Vector<double> b(n_terms), x(n_terms);
          for (unsigned int i = 0; i < n_terms; ++i)
            b[i] = rhs(i, c);
          normal.vmult(x, b);
          for (unsigned int i = 0; i < n_terms; ++i)
            coefficients(i, c) = x[i];
        }
      return normal.singular_value(n_terms - 1)
             > 1e-10 * normal.singular_value(0);
    };

    for (unsigned int v = 0; v < needed.size(); ++v)
      {
        if (!needed[v])
          continue;
        std::set<types::material_id> plies_here;
        for (const auto &cell : cells_at[v])
          plies_here.insert(cell->material_id());
        for (const auto ply : plies_here)
          {
            const Point<dim> &center = triangulation.get_vertices()[v];
            double            h      = 0;
            for (const auto &cell : cells_at[v])
              if (cell->material_id() == ply)
                h = std::max(h, cell->diameter());
            FullMatrix<double> coefficients(n_terms, n_stress);
            bool               full_rank
              = fit(superconvergent, v, ply, center, h, coefficients);
            if (!full_rank)
              full_rank = fit(thickness, v, ply, center, h, coefficients);
            const unsigned int set = full_rank ? 0 : n_stress + 1;
            // The fit goes to the nodes of the patch cells that have v as a
            // vertex: a coarse cell next to a hanging vertex gives samples
            // but no nodes (its far nodes would be an extrapolation, and a
            // rank owning a cell there would not see this patch).
            for (const auto &tria_cell : cells_at[v])
              if (tria_cell->material_id() == ply && has_vertex(tria_cell, v))
                {
                  const auto cell
                    = on_handler(tria_cell, recovery.copy_handler());
                  recovery.get_dof_indices(cell, indices);
                  for (unsigned int j = 0; j < n_nodes; ++j)
                    {
                      const auto key
                        = indices[fe.component_to_system_index(0, j)];
                      const auto p = monomials<dim>(
                        Point<dim>((recovery.support_point(key) - center) / h),
                        fe.degree);
                      sums[set + n_stress][key] += 1;
                      for (unsigned int c = 0; c < n_stress; ++c)
                        for (unsigned int i = 0; i < n_terms; ++i)
                          sums[set + c][key] += p[i] * coefficients(i, c);
                    }
                }
          }
      }
    const auto &hanging = recovery.hanging_node_constraints();
    const auto &partial = n_stress + 1;
    for (unsigned int c = 0; c < n_stress; ++c)
      {
        for (types::global_dof_index i = 0; i < sums[c].size(); ++i)
          if (sums[n_stress][i] > 0)
            sums[c][i] /= sums[n_stress][i];
          else if (sums[partial + n_stress][i] > 0)
            sums[c][i] = sums[partial + c][i] / sums[partial + n_stress][i];
        hanging.distribute(sums[c]);
      }
    sums.resize(n_stress);
    return sums;
  }



  template <int dim>
  typename ErrorEstimator<dim>::Estimate
  ErrorEstimator<dim>::zienkiewicz_zhu(const dealii::Vector<double> &u) const
  {
    const auto &triangulation = dofs.copy_handler().get_triangulation();
    const auto &fe            = dofs.get_fe();
    // Continuous inside a ply, free across plies and released faces.
    TiedCopyDoFs<dim> recovery(triangulation, fe.degree, dofs.reference_cell());
    recovery.distribute([this](const auto &cell, const unsigned int f) {
      return !cell->at_boundary(f)
             && (cell->neighbor(f)->material_id() != cell->material_id()
                 || (released && released(cell, f)));
    });
    const auto recovered = recover_stress(recovery, u);

    constexpr unsigned int n_stress
      = SymmetricTensor<2, dim>::n_independent_components;
    const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
    FEValues<dim>      values(dofs.get_mapping(),
                         fe,
                         dofs.cell_quadrature(fe.degree + 1),
                         update_values | update_gradients | update_JxW_values);
    std::vector<SymmetricTensor<2, dim>> stress;
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    dealii::Vector<float>                local(triangulation.n_active_cells());
    double                               norm_squared = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell_stresses(cell, u, values, stress);
          const auto same = on_handler(cell, recovery.copy_handler());
          recovery.get_dof_indices(same, indices);
          const auto &S = compliance[cell->material_id()];
          double      e = 0;
          for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
            {
              SymmetricTensor<2, dim> smooth;
              for (unsigned int j = 0; j < n_nodes; ++j)
                {
                  const unsigned int k = fe.component_to_system_index(0, j);
                  const double phi     = values.shape_value_component(k, q, 0);
                  for (unsigned int c = 0; c < n_stress; ++c)
                    smooth.access_raw_entry(c)
                      += phi * recovered[c][indices[k]];
                }
              const SymmetricTensor<2, dim> difference = smooth - stress[q];
              e += difference * (S * difference) * values.JxW(q);
              norm_squared += stress[q] * (S * stress[q]) * values.JxW(q);
            }
          local[cell->active_cell_index()] = e;
        }
    return finish(local, norm_squared);
  }



  template <int dim>
  typename ErrorEstimator<dim>::Estimate
  ErrorEstimator<dim>::kelly(const dealii::Vector<double> &u,
                             const Boundary               &boundary) const
  {
    // Parameters::check_prism_input() refuses it: the face rules below
    // are for the quadrilateral faces of hypercubes.
    AssertThrow(dofs.reference_cell().is_hyper_cube(),
                ExcMessage("the Kelly estimator is for hexahedral and "
                           "quadrilateral meshes"));
    const auto       &fe    = dofs.get_fe();
    const UpdateFlags flags = update_gradients | update_normal_vectors
                              | update_JxW_values | update_quadrature_points;
    const QGauss<dim - 1> rule(fe.degree + 1);
    const Mapping<dim>   &mapping = dofs.get_mapping();
    FEFaceValues<dim>     face(mapping, fe, rule, flags),
      other_face(mapping, fe, rule, flags);
    FESubfaceValues<dim> subface(mapping, fe, rule, flags),
      other_subface(mapping, fe, rule, flags);
    std::vector<SymmetricTensor<2, dim>> mine, theirs;

    // int |(s_mine - s_theirs) n|^2 over one face seen from both sides.
    // The two sides' quadrature points are paired by position, not by
    // index: the face orientations of a neighbour may differ (extruded and
    // curved meshes), and a fine face next to a coarse one on a curved
    // manifold sits slightly off the coarse subface.
    const auto jump = [&](const auto                   &cell,
                          const FEValuesBase<dim, dim> &here,
                          const auto                   &neighbor,
                          const FEValuesBase<dim, dim> &there) {
      cell_stresses(cell, u, here, mine);
      cell_stresses(neighbor, u, there, theirs);
      const unsigned int n       = here.n_quadrature_points;
      double             spacing = std::numeric_limits<double>::max();
      for (unsigned int q = 1; q < n; ++q)
        spacing = std::min(
          spacing, here.quadrature_point(0).distance(here.quadrature_point(q)));
      double     largest_distance = 0;
      const auto match            = nearest_points(here.get_quadrature_points(),
                                        there.get_quadrature_points(),
                                        largest_distance);
      if (largest_distance > 0.25 * spacing)
        throw std::logic_error("Kelly estimator: the face quadrature "
                               "points of two neighbours do not pair up");
      double sum = 0;
      for (unsigned int q = 0; q < n; ++q)
        {
          const Tensor<1, dim> t
            = (mine[q] - theirs[match[q]]) * here.normal_vector(q);
          sum += t * t * here.JxW(q);
        }
      return sum;
    };
    // int |s n - t_applied|^2 over a loaded or free boundary face.
    const auto residual = [&](const auto &cell, const unsigned int f) {
      face.reinit(cell, f);
      cell_stresses(cell, u, face, mine);
      const auto  id    = cell->face(f)->boundary_id();
      const auto *loads = boundary.loads;
      double      sum   = 0;
      for (unsigned int q = 0; q < face.n_quadrature_points; ++q)
        {
          const Point<dim> &x = face.quadrature_point(q);
          Tensor<1, dim>    t = mine[q] * face.normal_vector(q);
          if (loads && loads->tractions.count(id))
            {
              loads->tractions.at(id)->set_time(boundary.time);
              for (unsigned int d = 0; d < dim; ++d)
                t[d] -= loads->tractions.at(id)->value(x, d);
            }
          if (loads && loads->pressures.count(id))
            {
              loads->pressures.at(id)->set_time(boundary.time);
              t += loads->pressures.at(id)->value(x) * face.normal_vector(q);
            }
          sum += t * t * face.JxW(q);
        }
      return sum;
    };
    std::set<types::boundary_id> patch_faces;
    if (boundary.loads)
      for (const auto &patch : boundary.loads->patches)
        patch_faces.insert(patch.boundary_id);

    const double          scale = 1. / (24. * largest_stiffness(plies));
    dealii::Vector<float> local(
      dofs.copy_handler().get_triangulation().n_active_cells());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double sum = 0;
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                const auto id = cell->face(f)->boundary_id();
                if (!boundary.supported.count(id) && !patch_faces.count(id))
                  sum += residual(cell, f);
              }
            else if (released && released(cell, f))
              continue;
            else if (cell->face(f)->has_children())
              for (unsigned int s = 0; s < cell->face(f)->n_children(); ++s)
                {
                  const auto child = cell->neighbor_child_on_subface(f, s);
                  subface.reinit(cell, f, s);
                  other_face.reinit(child, cell->neighbor_of_neighbor(f));
                  sum += jump(cell, subface, child, other_face);
                }
            else if (cell->neighbor_is_coarser(f))
              {
                const auto neighbor = cell->neighbor(f);
                const auto [nf, ns] = cell->neighbor_of_coarser_neighbor(f);
                face.reinit(cell, f);
                other_subface.reinit(neighbor, nf, ns);
                sum += jump(cell, face, neighbor, other_subface);
              }
            else
              {
                const auto neighbor = cell->neighbor(f);
                face.reinit(cell, f);
                other_face.reinit(neighbor, cell->neighbor_of_neighbor(f));
                sum += jump(cell, face, neighbor, other_face);
              }
          local[cell->active_cell_index()] = scale * cell->diameter() * sum;
        }
    return finish(local, 0.);
  }



  template <int dim>
  double
  ErrorEstimator<dim>::energy_error(const dealii::Vector<double> &u,
                                    const Function<dim>          &exact) const
  {
    const auto                          &fe = dofs.get_fe();
    FEValues<dim>                        values(dofs.get_mapping(),
                         fe,
                         dofs.cell_quadrature(fe.degree + 2),
                         update_gradients | update_JxW_values
                           | update_quadrature_points);
    std::vector<SymmetricTensor<2, dim>> stress;
    std::vector<Tensor<1, dim>>          gradients(dim);
    double                               sum = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell_stresses(cell, u, values, stress);
          const auto &C = plies[cell->material_id()].stiffness;
          const auto &S = compliance[cell->material_id()];
          for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
            {
              Tensor<2, dim> grad;
              for (unsigned int d = 0; d < dim; ++d)
                grad[d] = exact.gradient(values.quadrature_point(q), d);
              const SymmetricTensor<2, dim> error
                = stress[q] - C * symmetrize(grad);
              sum += error * (S * error) * values.JxW(q);
            }
        }
    return std::sqrt(Utilities::MPI::sum(sum, comm));
  }

  template class ErrorEstimator<2>;
  template class ErrorEstimator<3>;
} // namespace amfrac

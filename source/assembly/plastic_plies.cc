#include <algorithm>
#include <amfrac/assembly/displacement_gradients.h>
#include <amfrac/assembly/plastic_plies.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <numeric>
#include <sstream>

namespace amfrac
{
  namespace
  {
    using Voigt     = HoffmanPlasticity::Voigt;
    using Stiffness = HoffmanPlasticity::Stiffness;

    /** The Voigt index of the symmetric 3x3 pair (i, j) (voigt_pairs:
     * 11, 22, 33, 23, 13, 12). */
    constexpr unsigned int
    voigt_index(const unsigned int i, const unsigned int j)
    {
      return i == j ? i : 6 - i - j;
    }

    /** T with eps_material = T eps_laminate for Voigt vectors with
     * engineering shear, for the ply rotation @p R. */
    Stiffness
    strain_rotation(const Tensor<2, 3> &R)
    {
      Stiffness T{};
      for (unsigned int J = 0; J < 6; ++J)
        {
          const unsigned int    k = voigt_pairs[J][0], l = voigt_pairs[J][1];
          SymmetricTensor<2, 3> unit;
          unit[k][l]                           = k == l ? 1. : 0.5;
          const SymmetricTensor<2, 3> material = to_material_axes(unit, R);
          for (unsigned int I = 0; I < 6; ++I)
            {
              const unsigned int i = voigt_pairs[I][0], j = voigt_pairs[I][1];
              T[I][J] = (i == j ? 1. : 2.) * material[i][j];
            }
        }
      return T;
    }

    /** A model strain in the ply's material axes (@p T from
     * strain_rotation()) as a Voigt vector with engineering shear (plane
     * strain: no strain along the width). */
    template <int dim>
    Voigt
    to_material_voigt(const SymmetricTensor<2, dim> &strain, const Stiffness &T)
    {
      Voigt laminate{};
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          laminate[voigt_index(laminate_axis<dim>(a), laminate_axis<dim>(b))]
            = (a == b ? 1. : 2.) * strain[a][b];
      Voigt material{};
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = 0; J < 6; ++J)
          material[I] += T[I][J] * laminate[J];
      return material;
    }

    /** A material-axes Voigt stress (or engineering-shear strain, with
     * @p shear_factor 1/2) as a laminate-axes 3D tensor. */
    SymmetricTensor<2, 3>
    to_laminate_tensor(const Voigt        &v,
                       const Tensor<2, 3> &R,
                       const double        shear_factor)
    {
      Tensor<2, 3> material;
      for (unsigned int I = 0; I < 6; ++I)
        {
          const unsigned int i = voigt_pairs[I][0], j = voigt_pairs[I][1];
          material[i][j] = material[j][i] = (i == j ? 1. : shear_factor) * v[I];
        }
      return symmetrize(R * material * transpose(R));
    }

    /** A material-axes Voigt tangent (engineering shear strains) in the
     * model's axes. It need not have the major symmetry. */
    template <int dim>
    SymmetricTensor<4, dim>
    tangent_in_model(const Stiffness &D, const Tensor<2, 3> &R)
    {
      SymmetricTensor<4, 3> material;
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = 0; J < 6; ++J)
          material[voigt_pairs[I][0]][voigt_pairs[I][1]][voigt_pairs[J][0]]
                  [voigt_pairs[J][1]]
            = D[I][J];
      return restrict_to_model<dim>(rotate(material, R));
    }

    /** A point that never yielded: its response is the elastic one. */
    bool
    virgin(const HoffmanPlasticity::State &state)
    {
      return state.kappa == 0
             && voigt_dot(state.plastic_strain, state.plastic_strain) == 0;
    }
  } // namespace



  template <int dim>
  PlasticPlies<dim>::PlasticPlies(const TiedCopyDoFs<dim>               &dofs,
                                  const std::vector<PlyProperties<dim>> &plies,
                                  const bool finite_strain)
    : dofs(dofs)
    , plies(plies)
    , quadrature(dofs.cell_quadrature(dofs.get_fe().degree + 1))
    , finite_strain(finite_strain)
  {
    for (const auto &ply : plies)
      strain_maps.push_back(strain_rotation(ply.rotation));
    for (const auto &ply : plies)
      laws.push_back(ply.plastic ? std::make_unique<HoffmanPlasticity>(
                       rotate(ply.stiffness_3d, transpose(ply.rotation)),
                       ply.strengths,
                       ply.hardening) :
                                   nullptr);
  }



  template <int dim>
  bool
  PlasticPlies<dim>::is_plastic(
    const typename TiedCopyDoFs<dim>::CellIterator &cell) const
  {
    return cell->is_locally_owned() && laws[cell->material_id()] != nullptr;
  }



  template <int dim>
  void
  PlasticPlies<dim>::setup()
  {
    const auto &tria = dofs.copy_handler().get_triangulation();
    history.assign(tria.n_active_cells(), {});
    yielded.assign(tria.n_active_cells(), false);
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (is_plastic(cell))
        history[cell->active_cell_index()].resize(quadrature.size());
    last_tangent_plastic = false;
    factorized_plastic   = false;
  }



  template <int dim>
  template <typename Visitor>
  void
  PlasticPlies<dim>::for_each_plastic_cell(const Visitor &visit,
                                           const bool     yielded_only) const
  {
    FEValues<dim>                        values(dofs.get_mapping(),
                         dofs.get_fe(),
                         quadrature,
                         update_gradients | update_JxW_values);
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (is_plastic(cell)
          && (!yielded_only || yielded[cell->active_cell_index()]))
        {
          values.reinit(cell);
          dofs.get_dof_indices(cell, indices);
          visit(cell, indices, values);
        }
  }



  namespace
  {
    /** The local values of a ghosted vector on a cell. */
    void
    local_values(const TrilinosWrappers::MPI::Vector        &v,
                 const std::vector<types::global_dof_index> &indices,
                 dealii::Vector<double>                     &local)
    {
      for (unsigned int k = 0; k < indices.size(); ++k)
        local(k) = v(indices[k]);
    }

    /** The displacement gradients of the local values @p u at every
     * point of @p values and the strain: sym(grad u), or with @p finite
     * the Green-Lagrange strain. */
    template <int dim>
    void
    strains(const FEValues<dim>                  &values,
            const dealii::Vector<double>         &u,
            const bool                            finite,
            std::vector<SymmetricTensor<2, dim>> &result,
            std::vector<Tensor<2, dim>>          &gradients)
    {
      displacement_gradients(values, u, gradients);
      result.resize(gradients.size());
      for (unsigned int q = 0; q < gradients.size(); ++q)
        result[q] = strain_measure(gradients[q], finite);
    }

    /** The strain alone. */
    template <int dim>
    void
    strains(const FEValues<dim>                  &values,
            const dealii::Vector<double>         &u,
            const bool                            finite,
            std::vector<SymmetricTensor<2, dim>> &result)
    {
      static thread_local std::vector<Tensor<2, dim>> gradients;
      strains(values, u, finite, result, gradients);
    }

    /** The returned @p stress (material-axes Voigt) less the elastic
     * stress C @p strain of the total strain, in the model's axes. */
    template <int dim>
    SymmetricTensor<2, dim>
    excess_stress(const Voigt                   &stress,
                  const PlyProperties<dim>      &ply,
                  const SymmetricTensor<2, dim> &strain)
    {
      return restrict_to_model<dim>(
               to_laminate_tensor(stress, ply.rotation, 1.))
             - ply.stiffness * strain;
    }

    /** The strain variation of every shape function at point @p q: the
     * symmetric gradient, or with @p grad_u (finite strain) the variation
     * of the Green-Lagrange strain sym(F^T grad phi_i). */
    template <int dim>
    void
    strain_variations(const FEValues<dim>                  &values,
                      const unsigned int                    q,
                      const Tensor<2, dim>                 *grad_u,
                      std::vector<SymmetricTensor<2, dim>> &result)
    {
      const FEValuesExtractors::Vector displacement(0);
      const auto                      &fe = values.get_fe();
      result.resize(fe.n_dofs_per_cell());
      if (!grad_u)
        {
          for (unsigned int i = 0; i < result.size(); ++i)
            result[i] = values[displacement].symmetric_gradient(i, q);
          return;
        }
      const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + *grad_u;
      for (unsigned int i = 0; i < result.size(); ++i)
        result[i]
          = symmetrize(outer_product(F[fe.system_to_component_index(i).first],
                                     values.shape_grad(i, q)));
    }

    /** The geometric part of the finite-strain tangent of the stress
     * @p excess (times JxW): grad phi_i . excess grad phi_j for shapes of
     * the same component, added to @p K. */
    template <int dim>
    void
    add_geometric_tangent(const FEValues<dim>           &values,
                          const unsigned int             q,
                          const SymmetricTensor<2, dim> &excess,
                          FullMatrix<double>            &K)
    {
      const auto &fe = values.get_fe();
      for (unsigned int i = 0; i < K.m(); ++i)
        {
          const Tensor<1, dim> S_g = excess * values.shape_grad(i, q);
          for (unsigned int j = 0; j < K.n(); ++j)
            if (fe.system_to_component_index(j).first
                == fe.system_to_component_index(i).first)
              K(i, j) += S_g * values.shape_grad(j, q);
        }
    }
  } // namespace



  template <int dim>
  bool
  PlasticPlies<dim>::add_correction(
    const Vector                    &relevant_u,
    const AffineConstraints<double> &constraints,
    Vector                          &force,
    Matrix                          *tangent,
    const bool                       return_map)
  {
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    dealii::Vector<double>               u(n), f(n);
    FullMatrix<double>                   K(n, n);
    std::vector<SymmetricTensor<2, dim>> grads(n), eps;
    std::vector<Tensor<2, dim>>          H;
    bool                                 converged = true, plastic = false;
    last_failure.clear();
    for_each_plastic_cell([&](const auto &cell,
                              const auto &indices,
                              const auto &values) {
      const auto &ply   = plies[cell->material_id()];
      const auto &law   = *laws[cell->material_id()];
      const auto &state = history[cell->active_cell_index()];
      local_values(relevant_u, indices, u);
      strains(values, u, finite_strain, eps, H);
      const auto &T    = strain_maps[cell->material_id()];
      f                = 0;
      K                = 0;
      bool any_tangent = false, any_force = false;
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Voigt strain = to_material_voigt(eps[q], T);
          auto        response
            = return_map ?
                law.respond(strain, state[q]) :
                HoffmanPlasticity::Response{
                  law.elastic_stress(strain, state[q]), {}, state[q]};
          if (!response.plastic && virgin(state[q]))
            continue;
          if (!response.converged && converged)
            {
              converged = false;
              std::ostringstream where;
              where << "the Hoffman return mapping did not converge in ply "
                    << cell->material_id() << " near (" << cell->center()
                    << ")";
              last_failure = where.str();
            }
          const SymmetricTensor<2, dim> excess
            = excess_stress(response.stress, ply, eps[q]);
          const double JxW = values.JxW(q);
          strain_variations(values, q, finite_strain ? &H[q] : nullptr, grads);
          for (unsigned int i = 0; i < n; ++i)
            f(i) += excess * grads[i] * JxW;
          any_force           = true;
          const bool material = response.plastic || response.on_surface;
          // With finite strain, the excess stress of a point that has
          // yielded also has its geometric stiffness.
          if (!tangent || !(material || finite_strain))
            continue;
          plastic = any_tangent = true;
          if (finite_strain)
            add_geometric_tangent(values, q, excess * JxW, K);
          if (!material)
            continue;
          const SymmetricTensor<4, dim> difference
            = tangent_in_model<dim>(response.tangent, ply.rotation)
              - ply.stiffness;
          for (unsigned int j = 0; j < n; ++j)
            {
              const SymmetricTensor<2, dim> column
                = difference * grads[j] * JxW;
              for (unsigned int i = 0; i < n; ++i)
                K(i, j) += grads[i] * column;
            }
        }
      if (any_force)
        for (unsigned int k = 0; k < n; ++k)
          force(indices[k]) += f(k);
      if (any_tangent)
        constraints.distribute_local_to_global(K, indices, *tangent);
    });
    if (tangent)
      {
        tangent->compress(VectorOperation::add);
        last_tangent_plastic = plastic;
      }
    return converged;
  }



  template <int dim>
  void
  PlasticPlies<dim>::add_tangent_product(const Vector &relevant_u,
                                         const Vector &relevant_direction,
                                         Vector       &product) const
  {
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    dealii::Vector<double>               u(n), d(n);
    std::vector<SymmetricTensor<2, dim>> eps, deps, grads;
    std::vector<Tensor<2, dim>>          H, H_d;
    for_each_plastic_cell([&](const auto &cell,
                              const auto &indices,
                              const auto &values) {
      const auto &ply   = plies[cell->material_id()];
      const auto &law   = *laws[cell->material_id()];
      const auto &state = history[cell->active_cell_index()];
      local_values(relevant_u, indices, u);
      local_values(relevant_direction, indices, d);
      strains(values, u, finite_strain, eps, H);
      strains(values, d, false, deps, H_d);
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const auto response
            = law.respond(to_material_voigt(eps[q],
                                            strain_maps[cell->material_id()]),
                          state[q]);
          const bool material = response.plastic || response.on_surface;
          if (!material && (!finite_strain || virgin(state[q])))
            continue;
          const double JxW = values.JxW(q);
          strain_variations(values, q, finite_strain ? &H[q] : nullptr, grads);
          // The variation of the strain along d: sym(grad d), or
          // sym(F^T grad d) = sym(grad d + H^T grad d) with finite strain.
          const SymmetricTensor<2, dim> strain_rate
            = finite_strain ? symmetrize(H_d[q] + transpose(H[q]) * H_d[q]) :
                              deps[q];
          SymmetricTensor<2, dim> stress;
          if (material)
            stress = (tangent_in_model<dim>(response.tangent, ply.rotation)
                      - ply.stiffness)
                     * strain_rate * JxW;
          // The geometric part: grad phi_i . excess grad d_(c_i).
          Tensor<2, dim> geometric;
          if (finite_strain)
            geometric
              = H_d[q]
                * Tensor<2, dim>(excess_stress(response.stress, ply, eps[q]))
                * JxW;
          for (unsigned int i = 0; i < n; ++i)
            {
              product(indices[i]) += stress * grads[i];
              if (finite_strain)
                product(indices[i])
                  += geometric[dofs.get_fe().system_to_component_index(i).first]
                     * values.shape_grad(i, q);
            }
        }
    });
  }



  template <int dim>
  double
  PlasticPlies<dim>::commit(const Vector &relevant_u,
                            const Vector &relevant_previous)
  {
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    dealii::Vector<double>               u(n), previous(n);
    std::vector<SymmetricTensor<2, dim>> eps, previous_eps;
    double                               work = 0;
    n_yielding                                = 0;
    for_each_plastic_cell(
      [&](const auto &cell, const auto &indices, const auto &values) {
        const auto &law   = *laws[cell->material_id()];
        const auto &T     = strain_maps[cell->material_id()];
        auto       &state = history[cell->active_cell_index()];
        local_values(relevant_u, indices, u);
        strains(values, u, finite_strain, eps);
        bool previous_known = false;
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const auto response
              = law.respond(to_material_voigt(eps[q], T), state[q]);
            if (!response.plastic)
              continue;
            ++n_yielding;
            yielded[cell->active_cell_index()] = true;
            if (!previous_known)
              {
                local_values(relevant_previous, indices, previous);
                strains(values, previous, finite_strain, previous_eps);
                previous_known = true;
              }
            // sigma_n = C (eps_n - eps_p,n): the elastic response of the
            // previous strain from the same history.
            const Voigt before
              = law.elastic_stress(to_material_voigt(previous_eps[q], T),
                                   state[q]);
            Voigt mean, increment;
            for (unsigned int k = 0; k < 6; ++k)
              {
                mean[k]      = 0.5 * (before[k] + response.stress[k]);
                increment[k] = response.state.plastic_strain[k]
                               - state[q].plastic_strain[k];
              }
            work += voigt_dot(mean, increment) * values.JxW(q);
            state[q] = response.state;
          }
      });
    return Utilities::MPI::sum(
      work, dofs.copy_handler().get_triangulation().get_communicator());
  }



  template <int dim>
  double
  PlasticPlies<dim>::stored_energy_correction(const Vector &relevant_u) const
  {
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    dealii::Vector<double>               u(n);
    std::vector<SymmetricTensor<2, dim>> eps;
    double                               energy = 0;
    for_each_plastic_cell(
      [&](const auto &cell, const auto &indices, const auto &values) {
        const auto &ply   = plies[cell->material_id()];
        const auto &state = history[cell->active_cell_index()];
        local_values(relevant_u, indices, u);
        strains(values, u, finite_strain, eps);
        for (const unsigned int q : values.quadrature_point_indices())
          {
            if (virgin(state[q]))
              continue;
            // In laminate axes: eps_p : C : (eps_p / 2 - eps).
            const SymmetricTensor<2, 3> plastic
              = to_laminate_tensor(state[q].plastic_strain, ply.rotation, 0.5);
            const SymmetricTensor<2, 3> strain = embed_in_3d<dim>(eps[q]);
            energy += plastic * (ply.stiffness_3d * (0.5 * plastic - strain))
                      * values.JxW(q);
          }
      },
      true);
    return Utilities::MPI::sum(
      energy, dofs.copy_handler().get_triangulation().get_communicator());
  }



  namespace
  {
    void
    write_state(const HoffmanPlasticity::State &state, double *out)
    {
      for (unsigned int k = 0; k < 6; ++k)
        out[k] = state.plastic_strain[k];
      out[6] = state.kappa;
    }

    HoffmanPlasticity::State
    read_state(const double *in)
    {
      HoffmanPlasticity::State state;
      for (unsigned int k = 0; k < 6; ++k)
        state.plastic_strain[k] = in[k];
      state.kappa = in[6];
      return state;
    }
  } // namespace



  template <int dim>
  std::vector<std::vector<double>>
  PlasticPlies<dim>::gather_field() const
  {
    const unsigned int  n_q   = quadrature.size();
    const unsigned int  width = n_q * n_components;
    std::vector<double> flat(history.size() * width, 0.);
    for (std::size_t c = 0; c < history.size(); ++c)
      for (unsigned int q = 0; q < history[c].size(); ++q)
        write_state(history[c][q], &flat[c * width + q * n_components]);
    // Each cell is owned by one rank: the sum is that rank's values.
    Utilities::MPI::sum(
      flat, dofs.copy_handler().get_triangulation().get_communicator(), flat);
    std::vector<std::vector<double>> field(history.size());
    for (std::size_t c = 0; c < history.size(); ++c)
      field[c].assign(flat.begin() + c * width, flat.begin() + (c + 1) * width);
    return field;
  }



  template <int dim>
  void
  PlasticPlies<dim>::set_field(const std::vector<std::vector<double>> &field)
  {
    AssertThrow(field.size() == history.size(),
                ExcMessage("the plastic history field has "
                           + std::to_string(field.size()) + " cells, the mesh "
                           + std::to_string(history.size())));
    for (std::size_t c = 0; c < history.size(); ++c)
      {
        for (unsigned int q = 0; q < history[c].size(); ++q)
          history[c][q] = read_state(&field[c][q * n_components]);
        update_yielded(c);
      }
  }



  template <int dim>
  void
  PlasticPlies<dim>::update_yielded(const std::size_t c)
  {
    yielded[c] = std::any_of(history[c].begin(),
                             history[c].end(),
                             [](const State &state) { return !virgin(state); });
  }



  template <int dim>
  std::vector<double>
  PlasticPlies<dim>::owned_values() const
  {
    const unsigned int  width = quadrature.size() * n_components;
    std::vector<double> values;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &state = history[cell->active_cell_index()];
          values.resize(values.size() + width, 0.);
          for (unsigned int q = 0; q < state.size(); ++q)
            write_state(state[q],
                        &values[values.size() - width + q * n_components]);
        }
    return values;
  }



  template <int dim>
  void
  PlasticPlies<dim>::set_cell_values(
    const typename TiedCopyDoFs<dim>::CellIterator &cell,
    const double                                   *values)
  {
    auto &state = history[cell->active_cell_index()];
    for (unsigned int q = 0; q < state.size(); ++q)
      state[q] = read_state(values + q * n_components);
    update_yielded(cell->active_cell_index());
  }



  template <int dim>
  typename PlasticPlies<dim>::CellMeans
  PlasticPlies<dim>::cell_means() const
  {
    const std::size_t n_cells = history.size();
    // Six laminate-axes components and kappa per cell, summed over ranks.
    std::vector<double> flat(n_cells * 7, 0.);
    for_each_plastic_cell(
      [&](const auto &cell, const auto &, const auto &values) {
        const auto  &ply    = plies[cell->material_id()];
        const auto  &state  = history[cell->active_cell_index()];
        double      *mean   = &flat[cell->active_cell_index() * 7];
        const double volume = std::accumulate(values.get_JxW_values().begin(),
                                              values.get_JxW_values().end(),
                                              0.);
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const double                w = values.JxW(q) / volume;
            const SymmetricTensor<2, 3> plastic
              = to_laminate_tensor(state[q].plastic_strain, ply.rotation, 0.5);
            for (unsigned int k = 0; k < 6; ++k)
              mean[k] += w * plastic[voigt_pairs[k][0]][voigt_pairs[k][1]];
            mean[6] += w * state[q].kappa;
          }
      },
      true);
    Utilities::MPI::sum(
      flat, dofs.copy_handler().get_triangulation().get_communicator(), flat);
    CellMeans means;
    means.plastic_strain.resize(n_cells);
    means.kappa.resize(n_cells);
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        for (unsigned int k = 0; k < 6; ++k)
          means.plastic_strain[c][voigt_pairs[k][0]][voigt_pairs[k][1]]
            = flat[c * 7 + k];
        means.kappa[c] = flat[c * 7 + 6];
      }
    return means;
  }



  template <int dim>
  double
  PlasticPlies<dim>::max_kappa() const
  {
    double largest = 0;
    for (const auto &cell_states : history)
      for (const auto &state : cell_states)
        largest = std::max(largest, state.kappa);
    return Utilities::MPI::max(
      largest, dofs.copy_handler().get_triangulation().get_communicator());
  }



  template class PlasticPlies<2>;
  template class PlasticPlies<3>;
} // namespace amfrac

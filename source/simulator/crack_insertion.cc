// Crack insertion by node duplication inside plies (subsection Crack
// insertion): the Hoffman check on the interior faces after a converged
// load step, the choice of the faces, their release in the tied-copy DoF
// layer and the move of the Newton state to the new numbering.
#include <algorithm>
#include <amfrac/base/face_within.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <amfrac/simulator/simulator.h>
#include <array>
#include <cmath>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/matrix_free/fe_point_evaluation.h>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>

namespace amfrac
{
  namespace
  {
    Strengths
    scaled(Strengths s, const double factor)
    {
      for (double *value :
           {&s.Xt, &s.Xc, &s.Yt, &s.Yc, &s.Zt, &s.Zc, &s.S12, &s.S13, &s.S23})
        *value *= factor;
      return s;
    }

    /** Unit normal of a face from its vertices (the sign does not matter
     * to the callers). */
    template <int dim>
    Tensor<1, dim>
    face_normal(const typename Triangulation<dim>::cell_iterator &cell,
                const unsigned int                                f)
    {
      const auto     face = cell->face(f);
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> edge = face->vertex(1) - face->vertex(0);
          n[0]                      = edge[1];
          n[1]                      = -edge[0];
        }
      else
        n = cross_product_3d(face->vertex(3) - face->vertex(0),
                             face->vertex(2) - face->vertex(1));
      return n / n.norm();
    }

    /** The model-plane block of a 3x3 model-axes stress. */
    template <int dim>
    SymmetricTensor<2, dim>
    model_block(const SymmetricTensor<2, 3> &stress)
    {
      SymmetricTensor<2, dim> block;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          block[a][b] = stress[a][b];
      return block;
    }

    /** A face as its cell's CellId (binary) and face number. */
    using FaceKey = std::array<unsigned int, 5>;

    template <int dim>
    FaceKey
    key_of(const typename Triangulation<dim>::cell_iterator &cell,
           const unsigned int                                f)
    {
      const auto id = cell->id().template to_binary<dim>();
      return {{id[0], id[1], id[2], id[3], f}};
    }

    /** The key of a face seen from its lower cell (the smaller CellId). */
    template <int dim>
    FaceKey
    lower_key(const typename Triangulation<dim>::cell_iterator &cell,
              const unsigned int                                f)
    {
      const auto neighbor = cell->neighbor(f);
      return cell->id() < neighbor->id() ?
               key_of<dim>(cell, f) :
               key_of<dim>(neighbor, cell->neighbor_of_neighbor(f));
    }

    /** An interior face with an active neighbour of the same level
     * (neither side hanging). */
    template <typename CellIterator>
    bool
    regular_interior_face(const CellIterator &cell, const unsigned int f)
    {
      return !cell->at_boundary(f) && cell->neighbor(f)->is_active()
             && !cell->neighbor_is_coarser(f);
    }

    /** The Hoffman index beyond which a face cracks, and the smallest
     * traction a crack starts from (relative to the largest strength). */
    constexpr double hoffman_limit     = 1.;
    constexpr double traction_fraction = 1e-9;
  } // namespace



  template <int dim>
  typename Simulator<dim>::FaceValues
  Simulator<dim>::strength_scale_by_face() const
  {
    constexpr unsigned int n_faces = GeometryInfo<dim>::faces_per_cell;
    FaceValues             values;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (unsigned int f = 0; f < n_faces; ++f)
        if (regular_interior_face(cell, f))
          values[{cell->id(), f}]
            = crack_strength_scale[cell->active_cell_index() * n_faces + f];
    return values;
  }



  template <int dim>
  void
  Simulator<dim>::evaluate_strength_scale(const FaceValues *previous)
  {
    const auto scale
      = make_expression_function<dim>({parameters.cracks.strength_scale},
                                      1,
                                      parameters.boundary_conditions.constants,
                                      "Crack insertion/Strength scale");
    // The value a face had before the mesh change: its own, or its
    // parent face's (a refined cell's child on that face).
    const auto inherited = [&](const auto &cell, const unsigned int f) {
      if (previous == nullptr)
        return std::numeric_limits<double>::quiet_NaN();
      auto found = previous->find({cell->id(), f});
      if (found != previous->end())
        return found->second;
      if (cell->level() > 0
          && face_within(cell->face(f), cell->parent()->face(f)))
        {
          found = previous->find({cell->parent()->id(), f});
          if (found != previous->end())
            return found->second;
        }
      return std::numeric_limits<double>::quiet_NaN();
    };
    constexpr unsigned int n_faces = GeometryInfo<dim>::faces_per_cell;
    crack_strength_scale.assign(triangulation.n_active_cells() * n_faces, 1.);
    // Every rank visits every face of the replicated mesh in the same
    // order, once (from its lower cell), and both sides share the value.
    for (const auto &cell : triangulation.active_cell_iterators())
      for (unsigned int f = 0; f < n_faces; ++f)
        {
          if (!regular_interior_face(cell, f)
              || !(cell->id() < cell->neighbor(f)->id()))
            continue;
          const auto         neighbor = cell->neighbor(f);
          const unsigned int nf       = cell->neighbor_of_neighbor(f);
          double             value    = inherited(cell, f);
          if (std::isnan(value))
            value = inherited(neighbor, nf);
          if (std::isnan(value))
            {
              const Point<dim> centre = cell->face(f)->center();
              value                   = scale->value(centre);
              if (!(value > 0) || !std::isfinite(value))
                {
                  std::ostringstream where;
                  where << "is " << value << " at " << centre
                        << ": strengths must stay positive and finite";
                  throw InputError("Crack insertion/Strength scale",
                                   where.str());
                }
            }
          crack_strength_scale[cell->active_cell_index() * n_faces + f] = value;
          crack_strength_scale[neighbor->active_cell_index() * n_faces + nf]
            = value;
        }
  }



  template <int dim>
  bool
  Simulator<dim>::crack_candidate(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                f) const
  {
    if (cell->at_boundary(f))
      return false;
    const auto neighbor = cell->neighbor(f);
    // Regular faces inside one ply: a hanging face would need the crack on
    // its coarse parent.
    if (!neighbor->is_active() || cell->neighbor_is_coarser(f)
        || neighbor->material_id() != cell->material_id())
      return false;
    const auto &selected = parameters.cracks.plies;
    if (!selected.empty()
        && !std::binary_search(selected.begin(),
                               selected.end(),
                               cell->material_id()))
      return false;
    if (interfaces->is_crack(cell, f))
      return false;
    using Candidates = parameters::CrackInsertion::Candidates;
    if (parameters.cracks.candidates != Candidates::all)
      {
        // Through the thickness: the normal lies in the ply plane (the
        // thickness axis is the last model axis).
        const double         within = std::sin(6. * numbers::PI / 180.);
        const Tensor<1, dim> n      = face_normal<dim>(cell, f);
        if (std::abs(n[dim - 1]) > within)
          return false;
        if (parameters.cracks.candidates == Candidates::matrix)
          {
            // Parallel to the fibres: the normal is normal to axis 1.
            const Tensor<2, 3> &R     = plies[cell->material_id()].rotation;
            double              along = 0;
            for (unsigned int a = 0; a < dim; ++a)
              along += n[a] * R[laminate_axis<dim>(a)][0];
            if (std::abs(along) > within)
              return false;
          }
      }
    // A region expression that is not finite there (NaN) selects nothing.
    const double inside = crack_region->value(cell->face(f)->center());
    return std::isfinite(inside) && inside != 0.;
  }



  template <int dim>
  std::vector<PlyStress>
  Simulator<dim>::cell_stresses(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                                        &values,
    const Vector                                         &state) const
  {
    values.reinit(cell);
    std::vector<types::global_dof_index> dofs(
      dof_layer.get_fe().n_dofs_per_cell());
    dof_layer.get_dof_indices(cell, dofs);
    // Each entry read once (a Trilinos element access looks the index
    // up), then the strains from the local values.
    std::vector<double> local(dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      local[i] = state(dofs[i]);
    std::vector<SymmetricTensor<2, dim>> strains(values.n_quadrature_points);
    values[FEValuesExtractors::Vector(0)]
      .get_function_symmetric_gradients_from_local_dof_values(local, strains);
    std::vector<PlyStress> result;
    for (const auto &strain : strains)
      result.push_back(evaluate_ply_stress(plies[cell->material_id()], strain));
    return result;
  }



  template <int dim>
  void
  Simulator<dim>::find_crack_candidates() const
  {
    if (candidates_found
        && candidate_faces.size() == triangulation.n_active_cells())
      return;
    candidates_found = true;
    candidate_cells.clear();
    constexpr unsigned int n_faces = GeometryInfo<dim>::faces_per_cell;
    candidate_faces.assign(triangulation.n_active_cells(), 0);
    for (const auto &cell : dof_layer.copy_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        std::uint8_t &bits = candidate_faces[cell->active_cell_index()];
        for (unsigned int f = 0; f < n_faces; ++f)
          if (crack_candidate(cell, f))
            bits |= std::uint8_t(1u << f);
        if (bits != 0)
          candidate_cells.push_back(cell);
      }
    // The screen pays in explicit runs, which check after every step; a
    // static run checks after a converged step and keeps the memory (on
    // meshes of unequal cells, a matrix per cell).
    if (parameters.time.explicit_dynamics)
      crack_screen = std::make_unique<FaceHoffmanScreen<dim>>(dof_layer,
                                                              plies,
                                                              candidate_cells);
  }



  template <int dim>
  void
  Simulator<dim>::forget_crack_candidates()
  {
    candidates_found = false;
    candidate_cells.clear();
    candidate_faces.clear();
    crack_screen.reset();
  }



  template <int dim>
  std::vector<typename Simulator<dim>::FailingFace>
  Simulator<dim>::faces_to_crack(const unsigned int max_faces) const
  {
    constexpr unsigned int n_faces = GeometryInfo<dim>::faces_per_cell;

    // Round 1: each rank's cells at the centres of their candidate faces;
    // a face goes on to round 2 if one of its sides fails on its own, and
    // round 2 decides on the mean of the two sides. (The index is not
    // convex for every set of strengths: the mean may fail where neither
    // side does, and such a face does not crack.) In explicit runs the screen
    // evaluates the cells of plain plies (a face with both cells on this rank
    // once, reported only if its mean fails too, with a margin for round-off so
    // that round 2 decides every face near the limit as before); one FEValues
    // the rest and round 2 (the face centres in reference coordinates are the
    // same for every cell), built when needed: in explicit runs, where most
    // checks find nothing, its construction would cost more than the screen.
    std::unique_ptr<FEValues<dim>> at_centres;
    const auto                     stresses_of = [&](const auto &cell) {
      if (!at_centres)
        at_centres = std::make_unique<FEValues<dim>>(dof_layer.get_mapping(),
                                                     dof_layer.get_fe(),
                                                     face_centre_points<dim>(),
                                                     update_gradients);
      return cell_stresses(cell, *at_centres, relevant_solution);
    };
    std::vector<unsigned int> local_failing;
    find_crack_candidates();
    if (crack_screen)
      for (const auto &face : crack_screen->failing(relevant_solution,
                                                    candidate_faces,
                                                    crack_strength_scale,
                                                    hoffman_limit - 1e-9))
        {
          const FaceKey key = lower_key<dim>(face.cell, face.face);
          local_failing.insert(local_failing.end(), key.begin(), key.end());
        }
    for (const auto &cell : candidate_cells)
      {
        const std::uint8_t bits = candidate_faces[cell->active_cell_index()];
        if (bits == 0
            || (crack_screen
                && FaceHoffmanScreen<dim>::covers(plies[cell->material_id()])))
          continue;
        const auto stresses = stresses_of(cell);
        for (unsigned int f = 0; f < n_faces; ++f)
          {
            if ((bits & (1u << f)) == 0)
              continue;
            const double scale
              = crack_strength_scale[cell->active_cell_index() * n_faces + f];
            const auto &strengths = plies[cell->material_id()].strengths;
            if (hoffman_index(stresses[f].material, scaled(strengths, scale))
                < hoffman_limit)
              continue;
            const FaceKey key = lower_key<dim>(cell, f);
            local_failing.insert(local_failing.end(), key.begin(), key.end());
          }
      }
    // Most checks of an explicit run find nothing: one reduction says so,
    // cheaper than gathering (serialized) lists.
    if (Utilities::MPI::max(local_failing.empty() ? 0u : 1u, comm) == 0)
      return {};
    std::set<FaceKey> failing_set;
    for (const auto &part : Utilities::MPI::all_gather(comm, local_failing))
      for (std::size_t i = 0; i + 4 < part.size(); i += 5)
        failing_set.insert(FaceKey{
          {part[i], part[i + 1], part[i + 2], part[i + 3], part[i + 4]}});
    if (failing_set.empty())
      return {};
    const std::vector<FaceKey> failing(failing_set.begin(), failing_set.end());

    // Round 2: both sides of every failing face, from their owners (the
    // stresses of round 1 again, for these few cells).
    const auto cell_of = [&](const FaceKey &key) {
      return triangulation.create_cell_iterator(
        CellId(std::array<unsigned int, 4>{{key[0], key[1], key[2], key[3]}}));
    };
    const auto         &handler = dof_layer.copy_handler();
    std::vector<double> contributions;
    for (unsigned int i = 0; i < failing.size(); ++i)
      {
        const auto         cell     = cell_of(failing[i]);
        const unsigned int f        = failing[i][4];
        const auto         neighbor = cell->neighbor(f);
        for (const auto &[side, face] :
             {std::make_pair(cell, f),
              std::make_pair(neighbor, cell->neighbor_of_neighbor(f))})
          {
            if (!side->is_locally_owned())
              continue;
            const typename DoFHandler<dim>::active_cell_iterator on_copies(
              &triangulation, side->level(), side->index(), &handler);
            const PlyStress stress = stresses_of(on_copies)[face];
            contributions.push_back(i);
            for (const auto &pair : voigt_pairs)
              contributions.push_back(stress.material[pair[0]][pair[1]]);
            for (const auto &pair : voigt_pairs)
              contributions.push_back(stress.model[pair[0]][pair[1]]);
          }
      }
    std::vector<SymmetricTensor<2, 3>> material(failing.size()),
      model(failing.size());
    std::vector<unsigned int> n_sides(failing.size(), 0);
    for (const auto &part : Utilities::MPI::all_gather(comm, contributions))
      for (std::size_t j = 0; j + 12 < part.size(); j += 13)
        {
          const auto i = static_cast<unsigned int>(part[j]);
          ++n_sides[i];
          for (unsigned int v = 0; v < 6; ++v)
            {
              material[i][voigt_pairs[v][0]][voigt_pairs[v][1]]
                += 0.5 * part[j + 1 + v];
              model[i][voigt_pairs[v][0]][voigt_pairs[v][1]]
                += 0.5 * part[j + 7 + v];
            }
        }

    // The same on every rank: index, normal and alignment of each face.
    std::vector<FailingFace> candidates;
    for (unsigned int i = 0; i < failing.size(); ++i)
      {
        if (n_sides[i] != 2)
          continue;
        const auto         cell = cell_of(failing[i]);
        const unsigned int f    = failing[i][4];
        const double       scale
          = crack_strength_scale[cell->active_cell_index() * n_faces + f];
        const Strengths strengths
          = scaled(plies[cell->material_id()].strengths, scale);
        const double index = hoffman_index(material[i], strengths);
        if (index < hoffman_limit)
          continue;
        const Tensor<1, dim>          n      = face_normal<dim>(cell, f);
        const SymmetricTensor<2, dim> stress = model_block<dim>(model[i]);
        const Tensor<1, dim>          t      = stress * n;
        const double                  normal = t * n;
        const double tau     = std::sqrt(std::pow(std::max(normal, 0.), 2)
                                     + (t - normal * n).norm_square());
        const double largest = std::max({strengths.Xt,
                                         strengths.Xc,
                                         strengths.Yt,
                                         strengths.Yc,
                                         strengths.S12});
        if (!(tau > traction_fraction * largest))
          continue;
        // The critical plane: normal to the largest principal stress if it
        // is tensile, else the plane of the largest shear.
        const auto     principal = eigenvectors(stress);
        Tensor<1, dim> e         = principal[0].second;
        if (!(principal[0].first > 0))
          {
            e = principal[0].second + principal[dim - 1].second;
            e /= e.norm();
          }
        candidates.push_back({cell, f, index, std::abs(n * e)});
      }

    // Each cell nominates its failing face best aligned with the critical
    // plane (then the larger index, then the smaller key).
    const auto better = [](const FailingFace &a, const FailingFace &b) {
      if (std::abs(a.alignment - b.alignment) > 1e-9)
        return a.alignment > b.alignment;
      return a.hoffman > b.hoffman;
    };
    std::map<CellId, unsigned int> best;
    for (unsigned int j = 0; j < candidates.size(); ++j)
      {
        const auto &c = candidates[j];
        for (const CellId id : {c.cell->id(), c.cell->neighbor(c.face)->id()})
          {
            const auto found = best.find(id);
            if (found == best.end() || better(c, candidates[found->second]))
              best[id] = j;
          }
      }
    std::set<unsigned int> nominated;
    for (const auto &entry : best)
      nominated.insert(entry.second);
    std::vector<FailingFace> result;
    for (const unsigned int j : nominated)
      result.push_back(candidates[j]);
    // The most critical first; candidates are in key order, and the sort
    // is stable, so equal indices keep it.
    std::stable_sort(result.begin(),
                     result.end(),
                     [](const FailingFace &a, const FailingFace &b) {
                       return a.hoffman > b.hoffman;
                     });
    if (result.size() > max_faces)
      result.resize(max_faces);
    return result;
  }



  template <int dim>
  typename CohesiveInterfaces<dim>::CrackReport
  Simulator<dim>::rebuild_crack_elements(const Vector &converged,
                                         const Vector &onset)
  {
    // One point evaluator for all points (an FEValues per point was half
    // of the cost of an insertion event).
    const auto                 &mapping = dof_layer.get_mapping();
    const auto                 &fe      = dof_layer.get_fe();
    FEPointEvaluation<dim, dim> evaluator(mapping, fe, update_gradients);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<double>                  values(fe.n_dofs_per_cell());
    const auto                           stress_at = [&](const auto       &cell,
                               const Point<dim> &point,
                               const Vector     &state) {
      const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, point);
      evaluator.reinit(cell, ArrayView<const Point<dim>>(&unit, 1));
      dof_layer.get_dof_indices(cell, dofs);
      for (unsigned int i = 0; i < dofs.size(); ++i)
        values[i] = state(dofs[i]);
      evaluator.evaluate(make_array_view(values), EvaluationFlags::gradients);
      const Tensor<2, dim> gradient = evaluator.get_gradient(0);
      return evaluate_ply_stress(plies[cell->material_id()],
                                 symmetrize(gradient))
        .model;
    };
    const auto traction
      = [&](const typename DoFHandler<dim>::active_cell_iterator &lower,
            const typename DoFHandler<dim>::active_cell_iterator &upper,
            const Point<dim>                                     &point,
            const Tensor<1, dim>                                 &normal,
            const bool                                            at_onset) {
          const Vector &state = at_onset ? onset : converged;
          return model_block<dim>(0.5
                                  * (stress_at(lower, point, state)
                                     + stress_at(upper, point, state)))
                 * normal;
        };
    const auto toughness
      = [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
          return plies[cell->material_id()].fracture_energy;
        };
    return interfaces->rebuild(dof_layer, traction, toughness);
  }



  template <int dim>
  typename Simulator<dim>::InsertionReport
  Simulator<dim>::insert_cracks(const double t_previous,
                                const double t,
                                const bool   check_onset)
  {
    std::vector<FailingFace> chosen;
    {
      TimerOutput::Scope scope(timer, "crack check");
      chosen = faces_to_crack(parameters.cracks.faces_per_round);
    }
    InsertionReport result;
    if (chosen.empty())
      return result;
    result.hoffman = chosen.front().hoffman;
    if (check_onset && result.hoffman > 1 + parameters.cracks.onset_tolerance)
      {
        result.overshoot = true;
        return result;
      }
    TimerOutput::Scope scope(timer, "crack insertion");
    for (const FailingFace &face : chosen)
      interfaces->add_crack(face.cell, face.face);

    // The copies do not change: only the ties do. Carry both states
    // through them.
    dealii::Vector<double> trial_copies, converged_copies;
    dof_layer.expand_all(dof_layer.replicate(solution), trial_copies);
    dof_layer.expand_all(dof_layer.replicate(newton->converged_solution),
                         converged_copies);
    rebuild_after_mesh_change(true);
    Vector trial(dof_layer.locally_owned_dofs(), comm);
    dof_layer.gather(trial_copies, trial);
    make_constraints(t, constraints, false);
    constraints.distribute(trial);
    Vector converged(dof_layer.locally_owned_dofs(), comm);
    dof_layer.gather(converged_copies, converged);
    make_constraints(t_previous, constraints, false);
    constraints.distribute(converged);
    // Both states with the ghosts of the new numbering: a crack starts
    // from the converged state's traction, the trial state's sets its
    // onset.
    const auto ghosted = [&](const Vector &owned) {
      Vector v(dof_layer.locally_owned_dofs(),
               dof_layer.locally_relevant_dofs(),
               comm);
      v = owned;
      return v;
    };
    const auto report
      = rebuild_crack_elements(ghosted(converged), ghosted(trial));
    // The matrix pattern takes the couplings of the new crack elements.
    setup_newton();
    solution = trial;

    // The reactions of the converged state on the new numbering start the
    // trapezoidal rule of the external work of the step solved again.
    newton->converged_solution = converged;
    // The impactor (setup_newton() sets it up on the regrouped copies)
    // placed at t_previous, so that the converged state's residual holds
    // its contact.
    if (impactor)
      impactor->move_to(t_previous);
    assembler.assemble_load(loads, t_previous, newton->external_load);
    update_residual(newton->converged_solution, nullptr);
    const auto balance         = balance_inserted_tractions();
    newton->previous_residual  = newton->residual;
    newton->previous_load      = newton->external_load;
    newton->insertion_settling = true;

    std::ostringstream line;
    line << "  t=" << t << ": " << chosen.size()
         << " face(s) cracked (Hoffman index up to " << chosen.front().hoffman
         << "), " << report.new_points << " interface points, "
         << interfaces->n_crack_faces() << " crack faces in all, "
         << dof_layer.n_dofs() << " unknowns";
    pcout << line.str() << std::endl;
    std::vector<std::pair<std::string, double>> event
      = {{"time", t},
         {"faces", chosen.size()},
         {"crack_faces", interfaces->n_crack_faces()},
         {"unknowns", dof_layer.n_dofs()},
         {"hoffman", chosen.front().hoffman}};
    event.insert(event.end(), balance.begin(), balance.end());
    // The regrouped impactor at the converged state: the same force as
    // before the insertion (the copies of a split node share its contact
    // and friction), up to round-off.
    if (impactor)
      event.emplace_back(
        "impactor_force_jump",
        (impactor->force_on_laminate() - newton->sphere_force).norm());
    log_crack_event(event);
    result.inserted = chosen.size();
    return result;
  }



  template <int dim>
  std::vector<std::pair<std::string, double>>
  Simulator<dim>::balance_inserted_tractions()
  {
    if (!parameters.cracks.balance_tractions)
      return {};
    NewtonState &n     = *newton;
    const auto  &owned = dof_layer.locally_owned_dofs();
    Vector       free_rows(owned, comm), touched(owned, comm);
    for (const auto i : owned)
      free_rows(i) = n.increment_constraints.is_constrained(i) ? 0 : 1;
    free_rows.compress(VectorOperation::insert);
    const auto on_touched = [&]() {
      Vector r = n.condensed_residual;
      r.scale(touched);
      return r.l2_norm();
    };
    // The residual's condensation (hanging rows to their masters,
    // constrained rows cleared), for the rows the new points reach.
    const auto condense_force = [&](Vector &force) {
      if (n.hanging)
        n.hanging->condense(force);
      Vector condensed(force);
      condense(force, condensed);
      force = condensed;
    };
    const auto report
      = interfaces->balance_new_cracks(n.condensed_residual,
                                       free_rows,
                                       dof_layer.locally_relevant_dofs(),
                                       condense_force,
                                       touched);
    const double before = on_touched();
    update_residual(n.converged_solution, nullptr);
    return {{"residual_before", before},
            {"residual_after", on_touched()},
            {"largest_correction", report.largest_correction},
            {"balance_iterations", report.iterations},
            {"balance_limited", report.limited}};
  }



  template <int dim>
  unsigned int
  Simulator<dim>::count_fragments() const
  {
    std::set<std::pair<CellId, unsigned int>> separated;
    for (const auto &[id, f] : interfaces->separated_faces(comm))
      {
        const auto cell = triangulation.create_cell_iterator(id);
        separated.insert({id, f});
        separated.insert(
          {cell->neighbor(f)->id(), cell->neighbor_of_neighbor(f)});
      }
    std::vector<unsigned int> parent(triangulation.n_active_cells());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&](unsigned int i) {
      while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          // Fully debonded faces and unbonded interfaces separate bodies.
          if (cell->at_boundary(f) || cell->neighbor(f)->has_children()
              || separated.count({cell->id(), f}) > 0 || is_unbonded(cell, f))
            continue;
          const unsigned int a   = root(cell->active_cell_index());
          const unsigned int b   = root(cell->neighbor(f)->active_cell_index());
          parent[std::max(a, b)] = std::min(a, b);
        }
    unsigned int n = 0;
    for (unsigned int i = 0; i < parent.size(); ++i)
      n += root(i) == i ? 1 : 0;
    return n;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace amfrac

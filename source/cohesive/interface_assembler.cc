#include <algorithm>
#include <amfrac/base/nearest_points.h>
#include <amfrac/base/reference_cells.h>
#include <amfrac/cohesive/interface_assembler.h>
#include <amfrac/parameters/expressions.h>
#include <amfrac/parameters/input_error.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <limits>
#include <map>

namespace amfrac
{
  namespace
  {
    cohesive::SeedLawProperties
    law_properties(const parameters::CohesiveInterfaces &data)
    {
      cohesive::SeedLawProperties p;
      p.normal_strength  = data.normal_strength;
      p.shear_strength   = data.shear_strength;
      p.G_Ic             = data.G_Ic;
      p.G_IIc            = data.G_IIc;
      p.normal_stiffness = data.normal_stiffness;
      p.shear_stiffness  = data.shear_stiffness;
      p.contact_penalty  = data.contact_penalty;
      p.stick_penalty    = data.stick_penalty;
      p.friction         = data.friction;
      return p;
    }

    cohesive::CamanhoDavilaProperties
    camanho_davila_properties(const parameters::CohesiveInterfaces &data)
    {
      cohesive::CamanhoDavilaProperties p;
      p.normal_strength = data.normal_strength;
      p.shear_strength  = data.shear_strength;
      p.G_Ic            = data.G_Ic;
      p.G_IIc           = data.G_IIc;
      p.bk_exponent     = data.bk_exponent;
      p.stiffness       = data.normal_stiffness;
      p.contact_penalty = data.contact_penalty;
      p.friction        = data.friction;
      p.stick_penalty   = data.stick_penalty;
      return p;
    }

    /** Rows: the unit normal @p n, then tangents (along x where possible,
     * so that on a laminate interface they are the x and y axes). */
    template <int dim>
    Tensor<2, dim>
    local_frame(const Tensor<1, dim> &n)
    {
      Tensor<2, dim> frame;
      frame[0] = n;
      if (dim == 2)
        {
          frame[1][0] = n[1];
          frame[1][1] = -n[0];
          return frame;
        }
      Tensor<1, dim> axis;
      axis[std::abs(n[0]) < 0.9 ? 0 : 1] = 1;
      Tensor<1, dim> t1                  = axis - (axis * n) * n;
      t1 /= t1.norm();
      frame[1] = t1;
      frame[2] = cross_product_3d(n, t1);
      return frame;
    }

    /** @p cell in the reference coordinates of its level-0 ancestor (any
     * refinement case, isotropic or anisotropic). */
    template <int dim>
    std::pair<Point<dim>, Point<dim>>
    coarse_cell_box(typename Triangulation<dim>::cell_iterator cell)
    {
      Point<dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = 1;
      while (cell->level() > 0)
        {
          const auto         parent = cell->parent();
          const unsigned int child  = parent->child_iterator_to_index(cell);
          const auto         cut    = parent->refinement_case();
          lower
            = GeometryInfo<dim>::child_to_cell_coordinates(lower, child, cut);
          upper
            = GeometryInfo<dim>::child_to_cell_coordinates(upper, child, cut);
          cell = parent;
        }
      return {lower, upper};
    }
  } // namespace



  template <int dim>
  hp::QCollection<dim - 1>
  CohesiveInterfaces<dim>::face_rules(const TiedCopyDoFs<dim> &dofs,
                                      const unsigned int       n_nodes) const
  {
    if (!data.lobatto)
      return dofs.face_quadrature(n_nodes);
    if (dofs.reference_cell().is_hyper_cube())
      return hp::QCollection<dim - 1>(QGaussLobatto<dim - 1>(n_nodes));
    // Nodal integration on a wedge: the vertex rule on its triangles (P1
    // only: a quadratic triangle has no nodal rule with positive weights,
    // parameters refuse it), Gauss-Lobatto on its quadrilaterals.
    AssertThrow(n_nodes == 2, ExcNotImplemented());
    hp::QCollection<dim - 1> rules;
    for (unsigned int f = 0; f < dofs.reference_cell().n_faces(); ++f)
      {
        const auto face = dofs.reference_cell().face_reference_cell(f);
        if (face.is_hyper_cube())
          rules.push_back(QGaussLobatto<dim - 1>(2));
        else
          {
            std::vector<Point<dim - 1>> vertices;
            for (const unsigned int v : face.vertex_indices())
              vertices.push_back(face.template vertex<dim - 1>(v));
            rules.push_back(Quadrature<dim - 1>(
              vertices,
              std::vector<double>(vertices.size(),
                                  face.volume() / vertices.size())));
          }
      }
    return rules;
  }



  template <int dim>
  CohesiveInterfaces<dim>::CohesiveInterfaces(
    const parameters::CohesiveInterfaces &data,
    const bool                            deformed_frame)
    : data(data)
    , deformed_frame(deformed_frame)
    , law(law_properties(data))
    , camanho_davila(camanho_davila_properties(data))
  {}



  template <int dim>
  bool
  CohesiveInterfaces<dim>::is_cohesive(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face) const
  {
    if (cell->at_boundary(face))
      return false;
    const unsigned int a = cell->material_id();
    const unsigned int b = cell->neighbor(face)->material_id();
    if (a + 1 != b && b + 1 != a)
      return false;
    return std::binary_search(data.interfaces.begin(),
                              data.interfaces.end(),
                              std::min(a, b));
  }



  template <int dim>
  typename TiedCopyDoFs<dim>::FaceFilter
  CohesiveInterfaces<dim>::released_faces() const
  {
    return [this](const CellIterator &cell, const unsigned int face) {
      return is_cohesive(cell, face) || is_crack(cell, face);
    };
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::check_conforming(
    const DoFHandler<dim> &handler) const
  {
    // Every rank scans the whole (replicated) mesh, so all ranks agree.
    for (const auto &cell : handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (is_cohesive(cell, f)
            && (cell->neighbor(f)->has_children()
                || cell->neighbor_is_coarser(f)))
          throw InputError(
            "Geometry/Refinement region",
            "refines one side of cohesive interface "
              + std::to_string(
                std::min(cell->material_id(), cell->neighbor(f)->material_id()))
              + " only: interface elements need matching faces, so refine "
                "both plies alike");
  }



  template <int dim>
  typename CohesiveInterfaces<dim>::Element
  CohesiveInterfaces<dim>::make_element(const TiedCopyDoFs<dim> &dofs,
                                        const CellIterator      &cell,
                                        const unsigned int       face,
                                        FEFaceValues<dim>       &lower,
                                        FEFaceValues<dim>       &upper) const
  {
    const auto        &fe            = dofs.get_fe();
    const auto         neighbor      = cell->neighbor(face);
    const unsigned int neighbor_face = cell->neighbor_of_neighbor(face);
    lower.reinit(cell, face);
    upper.reinit(neighbor, neighbor_face);

    Element element;
    element.coarse_cell = cell->id().get_coarse_cell_id();
    element.cell        = cell->id();
    element.face        = face;
    if constexpr (dim == 3)
      if (cell->face(face)->reference_cell() == ReferenceCells::Triangle)
        for (const unsigned int l : cell->face(face)->line_indices())
          element.triangle_edge
            = std::max(element.triangle_edge,
                       cell->face(face)->line(l)->diameter());
    element.active_cell = cell->active_cell_index();
    element.box         = coarse_cell_box<dim>(cell);
    element.interface   = is_crack(cell, face) ?
                            data.interfaces.size() :
                            std::lower_bound(data.interfaces.begin(),
                                           data.interfaces.end(),
                                           std::min(cell->material_id(),
                                                    neighbor->material_id()))
                            - data.interfaces.begin();
    std::vector<types::global_dof_index> lower_dofs(fe.n_dofs_per_cell()),
      upper_dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(lower_dofs);
    neighbor->get_dof_indices(upper_dofs);
    const auto        &lower_local = dofs.dofs_on_face(face);
    const auto        &upper_local = dofs.dofs_on_face(neighbor_face);
    const unsigned int n_q         = lower.n_quadrature_points;
    element.shape.reinit(n_q, lower_local.size() + upper_local.size());

    // The face orientations of the two cells may differ: pair the points
    // by position.
    double     largest_distance = 0;
    const auto match            = nearest_points(lower.get_quadrature_points(),
                                      upper.get_quadrature_points(),
                                      largest_distance);
    Assert(largest_distance < 1e-8 * cell->diameter(), ExcInternalError());
    (void)largest_distance;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        element.JxW.push_back(lower.JxW(q));
        element.points.push_back(lower.quadrature_point(q));
        element.unit_points.push_back(real_to_unit<dim>(
          dofs.get_linear_mapping(), cell, lower.quadrature_point(q)));
        element.frame.push_back(local_frame<dim>(lower.normal_vector(q)));
      }
    for (unsigned int k = 0; k < lower_local.size(); ++k)
      {
        element.copies.push_back(lower_dofs[lower_local[k]]);
        element.dofs.push_back(dofs.reduced_index(element.copies.back()));
        element.component.push_back(
          fe.system_to_component_index(lower_local[k]).first);
        for (unsigned int q = 0; q < n_q; ++q)
          element.shape(q, k) = -lower.shape_value(lower_local[k], q);
      }
    for (unsigned int k = 0; k < upper_local.size(); ++k)
      {
        const unsigned int column = lower_local.size() + k;
        element.copies.push_back(upper_dofs[upper_local[k]]);
        element.dofs.push_back(dofs.reduced_index(element.copies.back()));
        element.component.push_back(
          fe.system_to_component_index(upper_local[k]).first);
        for (unsigned int q = 0; q < n_q; ++q)
          element.shape(q, column)
            = upper.shape_value(upper_local[k], match[q]);
      }
    if (deformed_frame)
      {
        // The mid-surface (u_lower + u_upper) / 2 along the reference
        // tangents: half of each face's shape gradient along them.
        for (unsigned int a = 0; a + 1 < dim; ++a)
          {
            FullMatrix<double> &d = element.tangent_shape[a];
            d.reinit(n_q, element.dofs.size());
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const Tensor<1, dim> &T = element.frame[q][a + 1];
                for (unsigned int k = 0; k < lower_local.size(); ++k)
                  d(q, k) = 0.5 * (lower.shape_grad(lower_local[k], q) * T);
                for (unsigned int k = 0; k < upper_local.size(); ++k)
                  d(q, lower_local.size() + k)
                    = 0.5 * (upper.shape_grad(upper_local[k], match[q]) * T);
              }
          }
      }
    element.converged.resize(n_q);
    element.trial.resize(n_q);
    element.assembled.resize(n_q);
    element.factorized.resize(n_q);
    element.status.resize(n_q, 0);
    element.pre_crack.resize(n_q, 0);
    return element;
  }



  template <int dim>
  unsigned long
  CohesiveInterfaces<dim>::setup(const TiedCopyDoFs<dim> &dofs,
                                 const std::string       &constants)
  {
    check_conforming(dofs.copy_handler());
    make_elements(dofs);

    const MPI_Comm comm
      = dofs.copy_handler().get_triangulation().get_communicator();
    if (data.precrack_interfaces.empty())
      return 0;
    const auto region
      = make_expression_function<dim>({data.precrack_region},
                                      1,
                                      constants,
                                      "Cohesive interfaces/Pre-crack region");
    unsigned long cracked = 0, candidates = 0;
    for (Element &element : elements)
      {
        // Inserted cracks are no ply interface: no pre-crack there.
        if (element.interface >= data.interfaces.size())
          continue;
        candidates += element.points.size();
        if (!std::binary_search(data.precrack_interfaces.begin(),
                                data.precrack_interfaces.end(),
                                data.interfaces[element.interface]))
          continue;
        for (unsigned int q = 0; q < element.points.size(); ++q)
          {
            if (region->value(element.points[q]) == 0.)
              continue;
            ++cracked;
            // Fully debonded from the start, with nothing dissipated: the
            // pre-crack is not part of the energy ledger.
            auto &history        = element.converged[q].history;
            history.kappa        = std::numeric_limits<double>::max();
            history.debonded     = true;
            element.trial[q]     = element.converged[q];
            element.pre_crack[q] = 1;
          }
      }
    cracked    = Utilities::MPI::sum(cracked, comm);
    candidates = Utilities::MPI::sum(candidates, comm);
    require(cracked < candidates,
            "Cohesive interfaces/Pre-crack region",
            "covers every point of every cohesive interface: the plies "
            "would not be bonded anywhere");
    return cracked;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::make_elements(const TiedCopyDoFs<dim> &dofs)
  {
    unbuilt.clear();
    fresh.clear();
    set_point_regions(dofs.get_fe().degree + 1);
    std::vector<std::pair<CellIterator, unsigned int>> faces;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            const bool lower_side
              = (is_cohesive(cell, f)
                 && cell->neighbor(f)->material_id() > cell->material_id())
                || (is_crack(cell, f) && cell->id() < cell->neighbor(f)->id());
            if (lower_side)
              faces.emplace_back(cell, f);
          }
    elements = build_elements(dofs, faces);
  }



  template <int dim>
  std::vector<typename CohesiveInterfaces<dim>::Element>
  CohesiveInterfaces<dim>::build_elements(
    const TiedCopyDoFs<dim>                                  &dofs,
    const std::vector<std::pair<CellIterator, unsigned int>> &faces) const
  {
    const unsigned int n_nodes = dofs.get_fe().degree + 1;
    // The bulk's map: an interface face with an edge on a curved hole is
    // integrated over the same curved face as the solid around it.
    const auto &mapping = dofs.get_mapping();
    const auto  flags   = update_values | update_quadrature_points
                       | update_JxW_values | update_normal_vectors
                       | (deformed_frame ? update_gradients : update_default);
    const auto           rules = face_rules(dofs, n_nodes);
    FEFaceValues<dim>    lower(mapping, dofs.get_fe(), rules, flags);
    FEFaceValues<dim>    upper(mapping, dofs.get_fe(), rules, flags);
    std::vector<Element> built;
    for (const auto &[cell, f] : faces)
      built.push_back(make_element(dofs, cell, f, lower, upper));
    return built;
  }



  template <int dim>
  std::size_t
  CohesiveInterfaces<dim>::n_local_points() const
  {
    std::size_t n = 0;
    for (const Element &element : elements)
      n += element.points.size();
    return n;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::add_couplings(
    const AffineConstraints<double>   &constraints,
    TrilinosWrappers::SparsityPattern &pattern) const
  {
    for (const Element &element : elements)
      constraints.add_entries_local_to_global(element.dofs, pattern, false);
  }



  template <int dim>
  typename CohesiveInterfaces<dim>::PointState
  CohesiveInterfaces<dim>::evaluate(const PointState     &converged,
                                    const Tensor<1, dim> &gap,
                                    Tensor<2, dim>       &tangent) const
  {
    const auto response
      = converged.toughness > 0 ?
          cohesive::camanho_davila_law<dim>(gap + converged.offset,
                                            converged.history,
                                            crack_law(converged)) :
        data.camanho_davila ?
          cohesive::camanho_davila_law<dim>(gap,
                                            converged.history,
                                            camanho_davila) :
          cohesive::seed_law<dim>(gap, converged.history, law);
    PointState state = converged;
    state.history    = response.history;
    state.gap        = gap;
    state.traction   = response.traction;
    tangent          = response.tangent;
    // Viscous regularization (Gao & Bower 2004) of the bonded phase: a
    // traction eta (g - g_old) / dt that gives a softening point the
    // positive stiffness eta / dt, so that a step cut back far enough gets
    // through a local snap-back. Its work is reported on its own.
    state.viscous_work = converged.viscous_work;
    state.viscous      = 0;
    if (data.viscosity > 0 && !converged.history.debonded)
      {
        const double         rate = data.viscosity / time_step;
        const Tensor<1, dim> step = gap - converged.gap;
        state.viscous             = rate * step;
        state.viscous_work += rate * step * step;
        for (unsigned int d = 0; d < dim; ++d)
          tangent[d][d] += rate;
      }
    // Trapezoidal work increment; the work done while bonded is the
    // fracture budget, the work after debonding goes to friction (and to
    // the contact penalty, which stores it).
    const double increment
      = 0.5 * (converged.traction + state.traction) * (gap - converged.gap);
    state.bond_work     = converged.bond_work;
    state.friction_work = converged.friction_work;
    if (converged.history.debonded)
      state.friction_work += increment;
    else
      state.bond_work += increment;
    return state;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::assemble(
    const Vector                    &solution,
    Vector                          &force,
    const AffineConstraints<double> &constraints,
    Matrix                          *tangent)
  {
    FullMatrix<double>     K;
    dealii::Vector<double> r, u;
    Tensor<2, dim>         D;
    if (tangent)
      {
        unchanged        = true;
        previous_changes = changes;
        changes          = 0;
      }
    for (Element &element : elements)
      {
        const unsigned int n = element.dofs.size();
        u.reinit(n);
        r.reinit(n);
        if (tangent)
          K.reinit(n, n);
        for (unsigned int k = 0; k < n; ++k)
          u(k) = solution(element.dofs[k]);
        if (deformed_frame)
          {
            // The tangent changes with the frame in every iteration:
            // never reuse a factorization.
            deformed_element(
              element, u, r, tangent ? &K : nullptr, &element.trial);
            unchanged = false;
            if (tangent)
              for (unsigned int q = 0; q < element.JxW.size(); ++q)
                count_contact_change(element, q);
            force.add(element.dofs, r);
            if (tangent)
              constraints.distribute_local_to_global(K, element.dofs, *tangent);
            continue;
          }
        for (unsigned int q = 0; q < element.JxW.size(); ++q)
          {
            Tensor<1, dim> global_gap;
            for (unsigned int k = 0; k < n; ++k)
              global_gap[element.component[k]] += element.shape(q, k) * u(k);
            const Tensor<1, dim> traction
              = point_force(element, q, global_gap, D);
            const Tensor<2, dim> &F = element.frame[q];
            for (unsigned int k = 0; k < n; ++k)
              r(k) += element.shape(q, k) * traction[element.component[k]];
            if (!tangent)
              continue;
            count_contact_change(element, q);
            const Tensor<2, dim> D_global
              = transpose(F) * D * F * element.JxW[q];
            unchanged = unchanged && D_global == element.factorized[q];
            element.assembled[q] = D_global;
            for (unsigned int k = 0; k < n; ++k)
              {
                const double sk = element.shape(q, k);
                if (sk == 0)
                  continue;
                for (unsigned int l = 0; l < n; ++l)
                  K(k, l)
                    += sk * element.shape(q, l)
                       * D_global[element.component[k]][element.component[l]];
              }
          }
        force.add(element.dofs, r);
        if (tangent)
          constraints.distribute_local_to_global(K, element.dofs, *tangent);
      }
  }



  template <int dim>
  Tensor<1, dim>
  CohesiveInterfaces<dim>::point_force(Element              &element,
                                       const unsigned int    q,
                                       const Tensor<1, dim> &global_gap,
                                       Tensor<2, dim>       &tangent) const
  {
    const Tensor<2, dim> &F = element.frame[q];
    element.trial[q] = evaluate(element.converged[q], F * global_gap, tangent);
    return transpose(F) * (element.trial[q].traction + element.trial[q].viscous)
           * element.JxW[q];
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::set_local_indices(
    const Utilities::MPI::Partitioner &partitioner)
  {
    for (Element &element : elements)
      {
        element.local_dofs.clear();
        for (const auto i : element.dofs)
          element.local_dofs.push_back(partitioner.global_to_local(i));
        element.start = {0};
        element.nonzero.clear();
        for (unsigned int q = 0; q < element.JxW.size(); ++q)
          {
            for (unsigned int k = 0; k < element.dofs.size(); ++k)
              if (element.shape(q, k) != 0)
                element.nonzero.emplace_back(k, element.shape(q, k));
            element.start.push_back(element.nonzero.size());
          }
      }
    std::vector<types::global_dof_index> targets;
    std::vector<OrderedSums::Key>        keys;
    first_slot.clear();
    for (const Element &element : elements)
      {
        first_slot.push_back(targets.size());
        const auto cell = element.cell.template to_binary<dim>();
        for (unsigned int k = 0; k < element.dofs.size(); ++k)
          {
            targets.push_back(element.dofs[k]);
            keys.push_back(OrderedSums::Key{
              {cell[0], cell[1], cell[2], cell[3], element.face, k}});
          }
      }
    force_sums.reinit(targets, keys, partitioner);
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::add_forces(const double *u, double *f)
  {
    // The explicit path has small-strain plies (parameters refuse total
    // Lagrangian kinematics there).
    Assert(!deformed_frame, ExcNotImplemented());
    Tensor<2, dim> D;
    double        *slots = force_sums.slots();
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        Element &element = elements[e];
        double  *r       = slots + first_slot[e];
        std::fill(r, r + element.dofs.size(), 0.);
        for (unsigned int q = 0; q < element.JxW.size(); ++q)
          {
            const auto first = element.nonzero.begin() + element.start[q];
            const auto last  = element.nonzero.begin() + element.start[q + 1];
            Tensor<1, dim> global_gap;
            for (auto entry = first; entry != last; ++entry)
              global_gap[element.component[entry->first]]
                += entry->second * u[element.local_dofs[entry->first]];
            const Tensor<1, dim> traction
              = point_force(element, q, global_gap, D);
            for (auto entry = first; entry != last; ++entry)
              r[entry->first]
                += entry->second * traction[element.component[entry->first]];
            element.converged[q] = element.trial[q];
          }
      }
    force_sums.add_to(f);
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::count_contact_change(Element           &element,
                                                const unsigned int q)
  {
    const PointState &s = element.trial[q];
    if (!s.history.debonded)
      return;
    // Open, sticking or slipping (the Coulomb limit reached).
    double tangential = 0;
    for (unsigned int i = 1; i < dim; ++i)
      tangential += s.traction[i] * s.traction[i];
    const double  limit  = friction_of(s) * -s.traction[0];
    unsigned char status = 0;
    if (s.gap[0] + s.offset[0] < 0)
      status = std::sqrt(tangential) < (1 - 1e-10) * limit ? 1 : 2;
    if (status != element.status[q])
      ++changes;
    element.status[q] = status;
  }



  template <int dim>
  unsigned long
  CohesiveInterfaces<dim>::contact_changes(const MPI_Comm comm) const
  {
    return Utilities::MPI::sum(changes + previous_changes, comm);
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::add_tangent_product(const Vector &solution,
                                               const Vector &direction,
                                               Vector       &product) const
  {
    dealii::Vector<double> r, u, d;
    FullMatrix<double>     K;
    Tensor<2, dim>         D;
    for (const Element &element : elements)
      {
        const unsigned int n = element.dofs.size();
        r.reinit(n);
        if (deformed_frame)
          {
            u.reinit(n), d.reinit(n), K.reinit(n, n);
            for (unsigned int k = 0; k < n; ++k)
              {
                u(k) = solution(element.dofs[k]);
                d(k) = direction(element.dofs[k]);
              }
            deformed_element(element, u, r, &K, nullptr);
            K.vmult(r, d);
            product.add(element.dofs, r);
            continue;
          }
        for (unsigned int q = 0; q < element.JxW.size(); ++q)
          {
            Tensor<1, dim> gap, dgap;
            for (unsigned int k = 0; k < n; ++k)
              {
                gap[element.component[k]]
                  += element.shape(q, k) * solution(element.dofs[k]);
                dgap[element.component[k]]
                  += element.shape(q, k) * direction(element.dofs[k]);
              }
            const Tensor<2, dim> &F = element.frame[q];
            evaluate(element.converged[q], F * gap, D);
            const Tensor<1, dim> dtraction
              = transpose(F) * (D * (F * dgap)) * element.JxW[q];
            for (unsigned int k = 0; k < n; ++k)
              r(k) += element.shape(q, k) * dtraction[element.component[k]];
          }
        product.add(element.dofs, r);
      }
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::add_opening_gradient(const Vector &solution,
                                                Vector       &gradient) const
  {
    dealii::Vector<double>      r, u;
    std::vector<Tensor<1, dim>> B;
    Tensor<1, dim>              g;
    for (const Element &element : elements)
      {
        const unsigned int n = element.dofs.size();
        r.reinit(n);
        u.reinit(n);
        if (deformed_frame)
          for (unsigned int k = 0; k < n; ++k)
            u(k) = solution(element.dofs[k]);
        for (unsigned int q = 0; q < element.JxW.size(); ++q)
          {
            if (element.converged[q].history.debonded)
              continue;
            if (deformed_frame)
              deformed_kinematics(element, q, u, g, B);
            for (unsigned int k = 0; k < n; ++k)
              r(k) += (deformed_frame ?
                         B[k][0] :
                         element.shape(q, k)
                           * element.frame[q][0][element.component[k]])
                      * element.JxW[q];
          }
        gradient.add(element.dofs, r);
      }
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::mark_factorized()
  {
    for (Element &element : elements)
      element.factorized = element.assembled;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::commit()
  {
    for (Element &element : elements)
      element.converged = element.trial;
  }



  template <int dim>
  double
  CohesiveInterfaces<dim>::stored_energy(const PointState &s) const
  {
    // The secant law unloads to the origin: what is stored is half of
    // traction times gap while bonded; after debonding the contact penalty
    // and the elastic stick stretch store energy.
    // A crack's law is that of the offset gap (the offset is 0 elsewhere).
    const Tensor<1, dim> gap = s.gap + s.offset;
    if (!s.history.debonded)
      return 0.5 * s.traction * gap;
    double tangential = 0;
    for (unsigned int i = 1; i < dim; ++i)
      tangential += s.traction[i] * s.traction[i];
    return 0.5 * s.traction[0] * gap[0]
           + (tangential > 0 ? 0.5 * tangential / stick_penalty_of(s) : 0.);
  }



  template <int dim>
  double
  CohesiveInterfaces<dim>::friction_of(const PointState &state) const
  {
    // Only crack points carry a toughness of their own.
    return state.toughness > 0 ? crack_friction : data.friction;
  }



  template <int dim>
  double
  CohesiveInterfaces<dim>::stick_penalty_of(const PointState &state) const
  {
    return state.toughness > 0 ? crack_penalty : law.stick_penalty;
  }



  template <int dim>
  double
  CohesiveInterfaces<dim>::damage(const PointState &state) const
  {
    if (state.history.debonded)
      return 1.;
    return data.camanho_davila || state.toughness > 0 ?
             state.history.kappa :
             cohesive::seed_damage(state.history.kappa, law);
  }



  template <int dim>
  std::vector<InterfacePointRecord<dim>>
  CohesiveInterfaces<dim>::output_points(const Vector &solution) const
  {
    using Record = InterfacePointRecord<dim>;
    std::vector<Record> result;
    result.reserve(n_local_points());
    for (const Element &element : elements)
      {
        // The first half of the dofs is the lower face (negative shape
        // values in the gap table), the second half the upper face.
        const unsigned int n = element.dofs.size();
        for (unsigned int q = 0; q < element.points.size(); ++q)
          {
            const PointState &s = element.converged[q];
            Record            r;
            r.position  = element.points[q];
            r.interface = element.interface < data.interfaces.size() ?
                            data.interfaces[element.interface] :
                            Record::crack;
            for (unsigned int k = 0; k < n; ++k)
              r.displacement[element.component[k]]
                += 0.5 * (k < n / 2 ? -1 : 1) * element.shape(q, k)
                   * solution(element.dofs[k]);
            r.damage   = damage(s);
            r.gap      = s.gap;
            r.traction = s.traction;
            r.status   = s.history.debonded ?
                           (s.gap[0] < 0 ? Record::contact : Record::debonded) :
                         r.damage > 0 ? Record::softening :
                                        Record::intact;
            result.push_back(r);
          }
      }
    return result;
  }



  template <int dim>
  std::vector<typename CohesiveInterfaces<dim>::Ledger>
  CohesiveInterfaces<dim>::ledger(const MPI_Comm comm) const
  {
    std::vector<Ledger> result(data.interfaces.size()
                               + (cracks_enabled() ? 1 : 0));
    for (const Element &element : elements)
      {
        Ledger &l = result[element.interface];
        for (unsigned int q = 0; q < element.JxW.size(); ++q)
          {
            const PointState &s      = element.converged[q];
            const double      JxW    = element.JxW[q];
            const double      stored = stored_energy(s);
            l.work += (s.bond_work + s.friction_work + s.viscous_work) * JxW;
            l.viscous += s.viscous_work * JxW;
            l.stored += stored * JxW;
            // A crack starts holding s.inserted (0 elsewhere) before its
            // traction did any work.
            l.inserted += s.inserted * JxW;
            if (s.history.debonded)
              {
                l.dissipated += (s.bond_work + s.inserted) * JxW;
                l.friction += (s.friction_work - stored) * JxW;
                l.debonded += JxW;
              }
            else
              l.dissipated += (s.bond_work + s.inserted - stored) * JxW;
            if (s.history.kappa > 0)
              l.damaged += JxW;
            l.min_opening = std::min(l.min_opening, s.gap[0] + s.offset[0]);
          }
      }
    for (Ledger &l : result)
      {
        double *sums[] = {&l.work,
                          &l.stored,
                          &l.viscous,
                          &l.dissipated,
                          &l.friction,
                          &l.debonded,
                          &l.damaged,
                          &l.inserted};
        for (double *value : sums)
          *value = Utilities::MPI::sum(*value, comm);
        l.min_opening = Utilities::MPI::min(l.min_opening, comm);
      }
    return result;
  }

  template <int dim>
  void
  CohesiveInterfaces<dim>::add_penalty_row_sums(Vector &row_sums) const
  {
    for (const Element &e : elements)
      {
        const double k = e.interface == data.interfaces.size() ?
                           crack_penalty :
                           largest_ply_penalty();
        for (unsigned int q = 0; q < e.JxW.size(); ++q)
          for (unsigned int a = 0; a < e.dofs.size(); ++a)
            {
              if (e.shape(q, a) == 0)
                continue;
              double row = 0;
              for (unsigned int b = 0; b < e.dofs.size(); ++b)
                if (e.component[b] == e.component[a])
                  row += std::abs(e.shape(q, b));
              row_sums(e.dofs[a])
                += k * e.JxW[q] * std::abs(e.shape(q, a)) * row;
            }
      }
  }



  template <int dim>
  double
  CohesiveInterfaces<dim>::largest_ply_penalty() const
  {
    const double shear = data.shear_stiffness;
    return std::max({data.normal_stiffness,
                     shear,
                     data.contact_penalty,
                     data.stick_penalty > 0 ? data.stick_penalty : shear});
  }



  template <int dim>
  double
  CohesiveInterfaces<dim>::crack_frequency_squared(
    const TiedCopyDoFs<dim> &dofs,
    const std::function<void(const CellIterator &, dealii::Vector<double> &)>
                                                                  &element_mass,
    const std::function<bool(const CellIterator &, unsigned int)> &may_crack,
    Point<dim>                                                    &where,
    const double contact_penalty,
    const std::function<bool(const CellIterator &, unsigned int)> &in_contact)
    const
  {
    const auto        &fe      = dofs.get_fe();
    const unsigned int n       = fe.n_dofs_per_cell();
    const unsigned int n_nodes = fe.degree + 1;
    // The interface elements' own rules and map (make_elements()).
    FEFaceValues<dim>      face_values(dofs.get_mapping(),
                                  fe,
                                  face_rules(dofs, n_nodes),
                                  update_values | update_JxW_values);
    dealii::Vector<double> mass(n), rows(n);
    double                 largest = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        rows = 0;
        for (const unsigned int f : cell->face_indices())
          {
            double k = 0;
            if (is_crack(cell, f) || may_crack(cell, f))
              k = crack_penalty;
            else if (is_cohesive(cell, f))
              k = largest_ply_penalty();
            if (contact_penalty > 0
                && (cell->at_boundary(f) || is_crack(cell, f)
                    || may_crack(cell, f)
                    || (in_contact && in_contact(cell, f))))
              k += contact_penalty;
            if (k == 0)
              continue;
            face_values.reinit(cell, f);
            // The other side's shape values at a point mirror this
            // side's: the row sum over both sides is twice this side's.
            for (const unsigned int q : face_values.quadrature_point_indices())
              for (unsigned int a = 0; a < n; ++a)
                {
                  const double Na = std::abs(face_values.shape_value(a, q));
                  if (Na == 0)
                    continue;
                  double row = 0;
                  for (unsigned int b = 0; b < n; ++b)
                    if (fe.system_to_component_index(b).first
                        == fe.system_to_component_index(a).first)
                      row += std::abs(face_values.shape_value(b, q));
                  rows(a) += 2 * k * face_values.JxW(q) * Na * row;
                }
          }
        if (rows.l1_norm() == 0)
          continue;
        element_mass(cell, mass);
        for (unsigned int a = 0; a < n; ++a)
          if (rows(a) / mass(a) > largest)
            {
              largest = rows(a) / mass(a);
              where   = dofs.get_mapping().transform_unit_to_real_cell(
                cell, fe.unit_support_point(a));
            }
      }
    return largest;
  }



  template class CohesiveInterfaces<2>;
  template class CohesiveInterfaces<3>;
} // namespace amfrac

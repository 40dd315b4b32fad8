// Inserted intra-ply cracks in CohesiveInterfaces: the set of released
// faces, the extrinsic law of their points, the rebuild of the interface
// elements after the DoF layer released new faces, and (static runs) the
// tractions of a round's new points balanced to the split copies.
#include <algorithm>
#include <amfrac/base/face_within.h>
#include <amfrac/cohesive/interface_assembler.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <functional>
#include <iterator>
#include <sstream>

namespace amfrac
{
  namespace
  {
    /** sqrt(<t_N>^2 + |t_T|^2) of a local-frame traction: what the
     * Camanho-Davila law compares with its onset traction. */
    template <int dim>
    double
    effective_traction(const Tensor<1, dim> &local)
    {
      double value = std::max(local[0], 0.) * std::max(local[0], 0.);
      for (unsigned int i = 1; i < dim; ++i)
        value += local[i] * local[i];
      return std::sqrt(value);
    }



    template <int dim>
    double
    squared_norm(const std::vector<Tensor<1, dim>> &v, const MPI_Comm comm)
    {
      double sum = 0;
      for (const auto &t : v)
        sum += t * t;
      return Utilities::MPI::sum(sum, comm);
    }

    /** The owned entries of @p from (writable ghosts or not) into
     * @p to, times @p mask. */
    void
    copy_masked(const TrilinosWrappers::MPI::Vector &from,
                const TrilinosWrappers::MPI::Vector &mask,
                TrilinosWrappers::MPI::Vector       &to)
    {
      for (const auto i : to.locally_owned_elements())
        to(i) = from(i) * mask(i);
      to.compress(VectorOperation::insert);
    }
  } // namespace



  template <int dim>
  void
  CohesiveInterfaces<dim>::enable_cracks(const double penalty,
                                         const double friction)
  {
    Assert(penalty > 0, ExcMessage("the crack penalty must be positive"));
    crack_penalty  = penalty;
    crack_friction = friction;
  }



  template <int dim>
  bool
  CohesiveInterfaces<dim>::is_crack(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face) const
  {
    return !cracked.empty() && !cell->at_boundary(face)
           && cracked.count({cell->id(), face}) > 0;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::add_crack(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face)
  {
    Assert(!cell->at_boundary(face) && cell->neighbor(face)->is_active()
             && !cell->neighbor_is_coarser(face),
           ExcMessage("a crack needs a regular interior face"));
    // A face added again (from its other side, as add_cracks() does) is
    // one face to build.
    if (!cracked.insert({cell->id(), face}).second)
      return;
    cracked.insert(
      {cell->neighbor(face)->id(), cell->neighbor_of_neighbor(face)});
    unbuilt.emplace_back(cell->id(), face);
  }



  template <int dim>
  std::vector<std::int64_t>
  CohesiveInterfaces<dim>::crack_keys() const
  {
    // Both sides of every face (the set holds both): add_cracks() releases
    // each face from either side, so nothing needs the neighbour here.
    std::vector<std::int64_t> keys;
    for (const auto &[id, face] : cracked)
      {
        const auto binary = id.template to_binary<dim>();
        keys.insert(keys.end(), binary.begin(), binary.end());
        keys.push_back(face);
      }
    return keys;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::add_cracks(const Triangulation<dim>        &tria,
                                      const std::vector<std::int64_t> &keys)
  {
    for (std::size_t i = 0; i + 4 < keys.size(); i += 5)
      {
        std::array<unsigned int, 4> binary;
        for (unsigned int k = 0; k < 4; ++k)
          binary[k] = static_cast<unsigned int>(keys[i + k]);
        const auto   face = static_cast<unsigned int>(keys[i + 4]);
        const CellId id(binary);
        const auto   cell = tria.create_cell_iterator(id);
        if (!cell->is_active() || face >= cell->n_faces()
            || cell->at_boundary(face) || !cell->neighbor(face)->is_active()
            || cell->neighbor_is_coarser(face))
          throw InputError("the checkpoint's crack faces do not fit the "
                           "mesh of these parameters: the checkpoint is of "
                           "another scene");
        add_crack(cell, face);
      }
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::follow_mesh_change(const Triangulation<dim> &tria)
  {
    if (cracked.empty())
      return;
    // A refined cell's crack face goes to the children that lie on it
    // (any refinement case: a child touching face f has its own face f in
    // the parent's face f). Cracked cells are never coarsened
    // (match_flags()), so every key still names a cell.
    std::set<std::pair<CellId, unsigned int>> updated;
    const std::function<void(const typename Triangulation<dim>::cell_iterator &,
                             unsigned int)>
      add = [&](const auto &cell, const unsigned int f) {
        if (cell->is_active())
          {
            updated.insert({cell->id(), f});
            return;
          }
        for (const auto &child : cell->child_iterators())
          if (face_within(child->face(f), cell->face(f)))
            add(child, f);
      };
    for (const auto &[id, f] : cracked)
      add(tria.create_cell_iterator(id), f);
    cracked = std::move(updated);
    for (const auto &[id, f] : cracked)
      {
        const auto cell = tria.create_cell_iterator(id);
        AssertThrow(!cell->at_boundary(f) && cell->neighbor(f)->is_active()
                      && !cell->neighbor_is_coarser(f)
                      && cracked.count({cell->neighbor(f)->id(),
                                        cell->neighbor_of_neighbor(f)})
                           > 0,
                    ExcMessage("a crack face is no longer a regular face "
                               "with the crack on both sides after the mesh "
                               "changed"));
      }
  }



  template <int dim>
  cohesive::CamanhoDavilaProperties
  CohesiveInterfaces<dim>::crack_law(const PointState &state) const
  {
    cohesive::CamanhoDavilaProperties p;
    p.normal_strength = state.strength;
    p.shear_strength  = state.strength;
    p.G_Ic            = state.toughness;
    p.G_IIc           = state.toughness;
    p.bk_exponent     = 1;
    p.stiffness       = crack_penalty;
    p.contact_penalty = crack_penalty;
    p.friction        = crack_friction;
    p.stick_penalty   = crack_penalty;
    return p;
  }



  template <int dim>
  typename CohesiveInterfaces<dim>::CrackReport
  CohesiveInterfaces<dim>::rebuild(
    const TiedCopyDoFs<dim>                           &dofs,
    const CrackTraction                               &traction,
    const std::function<double(const CellIterator &)> &toughness)
  {
    // New cracks start from the reference frame's traction (parameters
    // refuse crack insertion with total Lagrangian kinematics).
    Assert(!deformed_frame, ExcNotImplemented());
    // The elements there move to the new numbering.
    for (Element &element : elements)
      for (unsigned int k = 0; k < element.copies.size(); ++k)
        element.dofs[k] = dofs.reduced_index(element.copies[k]);
    // The new cracks' elements, from the lower side (the smaller CellId),
    // on the rank that owns it, in the order of make_elements().
    const auto &handler = dofs.copy_handler();
    const auto &tria    = handler.get_triangulation();
    std::vector<std::pair<CellIterator, unsigned int>> faces;
    for (const auto &[id, f] : unbuilt)
      {
        const auto   cell = tria.create_cell_iterator(id);
        CellIterator side(&tria, cell->level(), cell->index(), &handler);
        unsigned int face = f;
        if (side->neighbor(f)->id() < side->id())
          {
            face = side->neighbor_of_neighbor(f);
            side = side->neighbor(f);
          }
        if (side->is_locally_owned())
          faces.emplace_back(side, face);
      }
    unbuilt.clear();
    std::sort(faces.begin(), faces.end(), [](const auto &a, const auto &b) {
      return std::make_pair(a.first->active_cell_index(), a.second)
             < std::make_pair(b.first->active_cell_index(), b.second);
    });
    std::vector<Element> added = build_elements(dofs, faces);

    CrackReport report;
    std::string failure;
    for (Element &element : added)
      {
        Assert(element.interface == data.interfaces.size(), ExcInternalError());
        const auto         cell = tria.create_cell_iterator(element.cell);
        CellIterator       lower(&tria, cell->level(), cell->index(), &handler);
        const CellIterator upper = lower->neighbor(element.face);
        const double       G     = toughness(lower);

        // The face centre's traction sets the onset of the whole face, so
        // that a point where the stress happens to be low (a bending
        // gradient across a Q1 face) does not get an onset near zero.
        Point<dim> centre;
        for (const auto &p : element.points)
          centre += p / double(element.points.size());
        const Tensor<2, dim> &F             = element.frame[0];
        const double          face_strength = effective_traction<dim>(
          F * traction(lower, upper, centre, F[0], true));
        for (unsigned int q = 0; q < element.points.size(); ++q)
          {
            const Tensor<2, dim> &frame = element.frame[q];
            const Point<dim>     &x     = element.points[q];
            const Tensor<1, dim>  T0
              = frame * traction(lower, upper, x, frame[0], false);
            const Tensor<1, dim> onset
              = frame * traction(lower, upper, x, frame[0], true);
            PointState &s    = element.converged[q];
            s                = PointState();
            s.offset         = T0 / crack_penalty;
            s.traction       = T0;
            s.strength       = std::max({effective_traction<dim>(T0),
                                         effective_traction<dim>(onset),
                                         face_strength});
            s.toughness      = G;
            s.inserted       = 0.5 * T0 * s.offset;
            element.trial[q] = s;
            report.inserted_energy += s.inserted * element.JxW[q];
            ++report.new_points;
            // The bilinear law needs its final opening 2 G / strength
            // beyond the onset strength / K.
            if (failure.empty()
                && !(crack_penalty > s.strength * s.strength / (2 * G)))
              {
                std::ostringstream message;
                message << "a crack inserted at " << element.points[q]
                        << " starts at the traction " << s.strength
                        << " MPa, and its bilinear law needs a penalty above "
                           "traction^2 / (2 Gc) = "
                        << s.strength * s.strength / (2 * G)
                        << " N/mm^3: raise it (or Materials/Gc)";
                failure = message.str();
              }
            if (failure.empty() && !(s.strength > 0))
              failure = "a crack would start without traction";
          }
      }
    std::vector<std::pair<unsigned int, unsigned int>> added_keys;
    for (const Element &element : added)
      added_keys.emplace_back(element.active_cell, element.face);
    // Both lists are in the order of the active cells, then faces.
    std::vector<Element> merged;
    merged.reserve(elements.size() + added.size());
    std::merge(std::make_move_iterator(elements.begin()),
               std::make_move_iterator(elements.end()),
               std::make_move_iterator(added.begin()),
               std::make_move_iterator(added.end()),
               std::back_inserter(merged),
               [](const Element &a, const Element &b) {
                 return std::make_pair(a.active_cell, a.face)
                        < std::make_pair(b.active_cell, b.face);
               });
    elements = std::move(merged);
    fresh.clear();
    for (unsigned int e = 0; e < elements.size(); ++e)
      if (std::binary_search(added_keys.begin(),
                             added_keys.end(),
                             std::make_pair(elements[e].active_cell,
                                            elements[e].face)))
        fresh.push_back(e);
    const MPI_Comm comm = tria.get_communicator();
    if (Utilities::MPI::max(failure.empty() ? 0 : 1, comm) > 0)
      {
        const auto all = Utilities::MPI::all_gather(comm, failure);
        for (const auto &message : all)
          if (!message.empty())
            throw InputError("Crack insertion/Penalty stiffness", message);
      }
    report.new_points      = Utilities::MPI::sum(report.new_points, comm);
    report.inserted_energy = Utilities::MPI::sum(report.inserted_energy, comm);
    return report;
  }



  template <int dim>
  std::vector<std::pair<CellId, unsigned int>>
  CohesiveInterfaces<dim>::separated_faces(const MPI_Comm comm) const
  {
    std::vector<unsigned int> local;
    for (const Element &element : elements)
      if (std::all_of(element.converged.begin(),
                      element.converged.end(),
                      [](const PointState &s) { return s.history.debonded; }))
        {
          const auto id = element.cell.template to_binary<dim>();
          local.insert(local.end(), id.begin(), id.end());
          local.push_back(element.face);
        }
    std::vector<std::pair<CellId, unsigned int>> result;
    for (const auto &part : Utilities::MPI::all_gather(comm, local))
      for (std::size_t i = 0; i + 4 < part.size(); i += 5)
        {
          std::array<unsigned int, 4> id;
          std::copy(part.begin() + i, part.begin() + i + 4, id.begin());
          result.emplace_back(CellId(id), part[i + 4]);
        }
    return result;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::spread_fresh(
    const std::vector<Tensor<1, dim>> &tractions,
    Vector                            &force,
    const bool                         absolute) const
  {
    force = 0;
    dealii::Vector<double> r;
    unsigned int           point = 0;
    for (const unsigned int e : fresh)
      {
        const Element &element = elements[e];
        r.reinit(element.dofs.size());
        for (unsigned int q = 0; q < element.JxW.size(); ++q, ++point)
          {
            const Tensor<1, dim> t
              = std::sqrt(element.JxW[q]) * tractions[point];
            for (unsigned int k = 0; k < element.dofs.size(); ++k)
              {
                const double shape = element.shape(q, k);
                r(k) += (absolute ? std::abs(shape) : shape)
                        * t[element.component[k]];
              }
          }
        force.add(element.dofs, r);
      }
    force.compress(VectorOperation::add);
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::gather_fresh(
    const Vector                &values,
    std::vector<Tensor<1, dim>> &tractions) const
  {
    tractions.clear();
    for (const unsigned int e : fresh)
      {
        const Element &element = elements[e];
        for (unsigned int q = 0; q < element.JxW.size(); ++q)
          {
            Tensor<1, dim> t;
            for (unsigned int k = 0; k < element.dofs.size(); ++k)
              t[element.component[k]]
                += element.shape(q, k) * values(element.dofs[k]);
            tractions.push_back(std::sqrt(element.JxW[q]) * t);
          }
      }
  }



  template <int dim>
  typename CohesiveInterfaces<dim>::BalanceReport
  CohesiveInterfaces<dim>::balance_new_cracks(
    const Vector                        &residual,
    const Vector                        &free_rows,
    const IndexSet                      &relevant,
    const std::function<void(Vector &)> &condense,
    Vector                              &touched)
  {
    const MPI_Comm  comm  = residual.get_mpi_communicator();
    const IndexSet &owned = residual.locally_owned_elements();
    Vector          spread;
    spread.reinit(owned, relevant, comm, true);
    Vector ghosted(owned, relevant, comm);

    // The free rows the new points act on (with |shape|, so that the two
    // faces at a crack tip's node, which cancel, still count).
    std::size_t n_points = 0;
    for (const unsigned int e : fresh)
      n_points += elements[e].JxW.size();
    Tensor<1, dim> unit;
    for (unsigned int d = 0; d < dim; ++d)
      unit[d] = 1;
    spread_fresh(std::vector<Tensor<1, dim>>(n_points, unit), spread, true);
    Vector reach(owned, comm);
    for (const auto i : owned)
      reach(i) = spread(i);
    reach.compress(VectorOperation::insert);
    condense(reach);
    for (const auto i : owned)
      touched(i) = reach(i) != 0 && free_rows(i) > 0 ? 1 : 0;
    touched.compress(VectorOperation::insert);

    // CGLS for min |B z + P r| with B = P S (P: the free rows). From z = 0
    // it converges to the least-norm z, i.e. the least sum of
    // JxW |delta|^2 with delta = z / sqrt(JxW).
    Vector rhs(owned, comm), Bp(owned, comm);
    copy_masked(residual, free_rows, rhs);
    rhs *= -1;
    std::vector<Tensor<1, dim>> z(n_points), s, p;
    const auto                  apply_transpose = [&]() {
      ghosted = rhs;
      gather_fresh(ghosted, s);
    };
    apply_transpose();
    p                    = s;
    double        gamma  = squared_norm(s, comm);
    const double  gamma0 = gamma;
    BalanceReport report;
    while (gamma > 1e-28 * gamma0 && gamma > 0 && report.iterations < 200)
      {
        spread_fresh(p, spread);
        copy_masked(spread, free_rows, Bp);
        const double Bp2 = Bp * Bp;
        if (!(Bp2 > 0))
          break;
        const double alpha = gamma / Bp2;
        for (std::size_t i = 0; i < z.size(); ++i)
          z[i] += alpha * p[i];
        rhs.add(-alpha, Bp);
        apply_transpose();
        const double gamma_new = squared_norm(s, comm);
        for (std::size_t i = 0; i < p.size(); ++i)
          p[i] = s[i] + (gamma_new / gamma) * p[i];
        gamma = gamma_new;
        ++report.iterations;
      }
    apply_corrections(z, report);
    report.limited = Utilities::MPI::sum(report.limited, comm);
    report.largest_correction
      = Utilities::MPI::max(report.largest_correction, comm);
    return report;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::apply_corrections(
    const std::vector<Tensor<1, dim>> &z,
    BalanceReport                     &report)
  {
    unsigned int point = 0;
    for (const unsigned int e : fresh)
      {
        Element &element = elements[e];
        for (unsigned int q = 0; q < element.JxW.size(); ++q, ++point)
          {
            PointState          &state = element.converged[q];
            const Tensor<1, dim> change
              = element.frame[q] * (z[point] / std::sqrt(element.JxW[q]));
            const Tensor<1, dim> T = state.traction + change;
            // A corrected traction above the onset raises it, with a
            // margin of 1e-6: a point exactly on its onset surface would
            // take the elastic or the softening branch by round-off (and
            // one rank count against two would differ).
            const double strength
              = std::max(state.strength,
                         (1 + 1e-6) * effective_traction<dim>(T));
            // The bilinear law needs a penalty above strength^2 / (2 Gc):
            // a point that would need more keeps the stress's traction.
            if (!(crack_penalty > strength * strength / (2 * state.toughness)))
              {
                ++report.limited;
                continue;
              }
            report.largest_correction
              = std::max(report.largest_correction, change.norm());
            state.traction   = T;
            state.offset     = T / crack_penalty;
            state.strength   = strength;
            state.inserted   = 0.5 * T * state.offset;
            element.trial[q] = state;
          }
      }
  }



  template class CohesiveInterfaces<2>;
  template class CohesiveInterfaces<3>;
} // namespace amfrac

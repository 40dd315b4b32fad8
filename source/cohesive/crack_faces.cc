// Inserted intra-ply cracks in CohesiveInterfaces: the set of released
// faces, the extrinsic law of their points and the rebuild of the interface
// elements after the DoF layer released new faces.
#include <algorithm>
#include <amfrac/base/face_within.h>
#include <amfrac/cohesive/interface_assembler.h>
#include <amfrac/parameters/input_error.h>
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
    elements            = std::move(merged);
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



  template class CohesiveInterfaces<2>;
  template class CohesiveInterfaces<3>;
} // namespace amfrac

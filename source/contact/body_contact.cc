#include <algorithm>
#include <amfrac/base/concatenate.h>
#include <amfrac/base/cross_matrix.h>
#include <amfrac/base/point_order.h>
#include <amfrac/contact/body_contact.h>
#include <chrono>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <limits>
#include <map>
#include <numeric>

namespace amfrac
{
  namespace
  {
    using Clock = std::chrono::steady_clock;

    double
    seconds_since(const Clock::time_point start)
    {
      return std::chrono::duration<double>(Clock::now() - start).count();
    }

    /** A grid cell's key: three 21-bit indices. */
    std::uint64_t
    grid_key(const std::array<long, 3> &index)
    {
      constexpr std::uint64_t mask = (1u << 21) - 1;
      return ((std::uint64_t(index[0]) & mask) << 42)
             | ((std::uint64_t(index[1]) & mask) << 21)
             | (std::uint64_t(index[2]) & mask);
    }

    /** The area (length in 2D) of a flat bilinear face. */
    template <int dim, std::size_t n>
    double
    face_measure(const std::array<Point<dim>, n> &v)
    {
      if constexpr (dim == 2)
        return v[0].distance(v[1]);
      else
        return 0.5 * cross_product_3d(v[3] - v[0], v[2] - v[1]).norm();
    }
  } // namespace



  template <int dim>
  BodyContact<dim>::BodyContact(const parameters::Contact &p, MPI_Comm comm)
    : comm(comm)
    , penalty(p.penalty)
    , friction_coefficient(p.friction)
    , tangential_factor(p.tangential_factor)
  {}



  template <int dim>
  template <typename Carried, typename Parent>
  void
  BodyContact<dim>::inherit_history(
    std::map<std::pair<unsigned int, unsigned int>, Carried>      &old,
    const std::map<std::pair<unsigned int, unsigned int>, Parent> &parent_of)
  {
    // The heirs of each old node: the node that kept its key, and the new
    // ones (a crack insertion's copies) whose own first corner was one of
    // its corners, at the same place.
    std::map<std::pair<unsigned int, unsigned int>, std::vector<unsigned int>>
      heirs;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        if (old.count(nodes[i].key) > 0)
          {
            heirs[nodes[i].key].push_back(i);
            continue;
          }
        const auto parent = parent_of.find(nodes[i].key);
        if (parent != parent_of.end()
            && parent->second.reference == nodes[i].reference
            && old.count(parent->second.key) > 0)
          heirs[parent->second.key].push_back(i);
      }
    // The copies share the stick force by their stiffness, so that the
    // force on the place and the spring energy (|F|^2 / 2 k_t summed) stay.
    for (const auto &[key, indices] : heirs)
      {
        const Carried &parent = old.at(key);
        Assert(!parent.history.carried, ExcInternalError());
        double total = 0;
        for (const unsigned int i : indices)
          total += nodes[i].stiffness;
        for (const unsigned int i : indices)
          {
            const double share
              = indices.size() == 1 ? 1. : nodes[i].stiffness / total;
            history[i] = parent.history;
            history[i].friction *= share;
            history[i].stick_energy *= share;
            // The faces are numbered again with the released ones: the
            // old index names another face. A node (split or not) that
            // leaves contact in the step after a crack insertion (a
            // static run's re-solved step; an explicit run evaluates
            // before anything slips) books its spring's energy only, not
            // the half step's friction work (first order in the slip).
            history[i].face = numbers::invalid_unsigned_int;
            previous[i]     = parent.previous;
            fresh[i]        = parent.fresh;
          }
        old.erase(key);
      }
  }



  template <int dim>
  Tensor<1, dim>
  BodyContact<dim>::stretch_of(const History &h)
  {
    if (!h.in_contact || h.carried)
      return h.in_contact ? h.friction : Tensor<1, dim>();
    // stick_energy = |F|^2 / (2 k_t), so F / k_t = 2 stick_energy F / |F|^2.
    const double squared = h.friction.norm_square();
    return squared > 0 ? (2 * h.stick_energy / squared) * h.friction :
                         Tensor<1, dim>();
  }



  template <int dim>
  void
  BodyContact<dim>::carry_by_place(const std::vector<Node>    &old_nodes,
                                   const std::vector<Face>    &old_faces,
                                   const std::vector<History> &old_history)
  {
    // The places the old surface knows a stretch at: its nodes, and the
    // midpoints of its faces' edges and its faces' centres (the vertices
    // one refinement adds), each with its side and whether some node there
    // was in contact. A mean's side is that of its members (their
    // outward normals, unit(area_penalty)), not its face's normal: the
    // side faces of two stacked bodies (or of a crack's two sides) lie in
    // one plane with one normal, and an edge midpoint on their common
    // edge would tie between the bodies.
    struct Place
    {
      Point<dim>     x;
      Tensor<1, dim> side, stretch;
      bool           in_contact;
      /** An old node's own place (beats a mean at the same point). */
      bool node;
    };
    std::vector<Place> places;
    const auto         unit = [](const Tensor<1, dim> &v) {
      const double norm = v.norm();
      return norm > 0 ? v / norm : v;
    };
    const auto add_mean = [&](const std::vector<unsigned int> &members) {
      Place place{
        Point<dim>(), Tensor<1, dim>(), Tensor<1, dim>(), false, false};
      for (const unsigned int i : members)
        {
          place.side += unit(old_nodes[i].area_penalty);
          place.x += old_nodes[i].reference / double(members.size());
          place.stretch += stretch_of(old_history[i]) / double(members.size());
          place.in_contact = place.in_contact || old_history[i].in_contact;
        }
      place.side = unit(place.side);
      places.push_back(place);
    };
    for (unsigned int i = 0; i < old_nodes.size(); ++i)
      places.push_back({old_nodes[i].reference,
                        unit(old_nodes[i].area_penalty),
                        stretch_of(old_history[i]),
                        old_history[i].in_contact,
                        true});
    for (const Face &face : old_faces)
      {
        add_mean({face.nodes.begin(), face.nodes.end()});
        if constexpr (dim == 3)
          // The edges of a quadrilateral face: vertices 0-1, 2-3, 0-2, 1-3
          // in deal.II's numbering.
          for (const auto &[a, b] :
               {std::pair<unsigned int, unsigned int>{0, 1},
                {2, 3},
                {0, 2},
                {1, 3}})
            add_mean({face.nodes[a], face.nodes[b]});
      }
    const auto closer
      = [](const Place &a, const Place &b, const Tensor<1, dim> &side) {
          const double da = a.side * side, db = b.side * side;
          return da > db + 1e-12 || (da > db - 1e-12 && a.node && !b.node);
        };
    // Stable: places at one x keep the order above, on every rank.
    std::stable_sort(places.begin(),
                     places.end(),
                     [](const Place &a, const Place &b) {
                       return a.x[0] < b.x[0];
                     });
    // Each new node: the places within round-off of it, the closest side,
    // an old node before a mean.
    double size = 0;
    for (const Face &face : faces)
      size = std::max(size, face.depth);
    const double tolerance = 1e-9 * std::max(size, 1e-300);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const Point<dim> &x    = nodes[i].reference;
        const auto        side = unit(nodes[i].area_penalty);
        auto              it   = std::lower_bound(places.begin(),
                                   places.end(),
                                   x[0] - tolerance,
                                   [](const Place &p, const double value) {
                                     return p.x[0] < value;
                                   });
        const Place      *best = nullptr;
        for (; it != places.end() && it->x[0] <= x[0] + tolerance; ++it)
          if (it->x.distance(x) <= tolerance
              && (best == nullptr || closer(*it, *best, side)))
            best = &*it;
        // A place of another body (the other side of a released face)
        // is never this node's.
        if (best == nullptr || !best->in_contact || !(best->side * side > 0))
          continue;
        history[i].in_contact = true;
        history[i].carried    = true;
        history[i].friction   = best->stretch;
      }
  }



  template <int dim>
  void
  BodyContact<dim>::setup(const TiedCopyDoFs<dim> &dofs,
                          const FaceFilter        &released,
                          const FaceFilter        &paired,
                          const bool               mesh_change)
  {
    // A mesh change carries the history by place (carry_by_place()).
    const std::vector<Node> old_nodes
      = mesh_change ? nodes : std::vector<Node>();
    const std::vector<Face> old_faces
      = mesh_change ? faces : std::vector<Face>();
    const std::vector<History> old_history
      = mesh_change ? history : std::vector<History>();
    // The old history by node key, for the nodes of the new surface.
    struct Carried
    {
      History        history;
      Tensor<1, dim> previous;
      bool           fresh;
    };
    std::map<std::pair<unsigned int, unsigned int>, Carried> old;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      old[nodes[i].key] = {history[i], previous[i], fresh[i]};
    // The old node of each corner, with its place: the
    // parent of the copies a crack insertion split it into.
    struct Parent
    {
      std::pair<unsigned int, unsigned int> key;
      Point<dim>                            reference;
    };
    std::map<std::pair<unsigned int, unsigned int>, Parent> parent_of;
    for (const Node &node : nodes)
      for (const auto &corner : node.corners)
        parent_of[corner] = {node.key, node.reference};

    const auto                          &fe = dofs.get_fe();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    // Surface nodes by their first reduced dof, and faces by the dofs of
    // their vertices (renumbered once the nodes are sorted).
    std::map<types::global_dof_index, Node> found;
    struct RawFace
    {
      std::array<types::global_dof_index, n_face_vertices> dofs;
      double                                               sign, depth;
      bool                                                 exclude;
    };
    std::vector<RawFace> raw;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          const bool outer = cell->at_boundary(f);
          if (!outer && !(released && released(cell, f)))
            continue;
          dofs.get_dof_indices(cell, indices);
          RawFace                                 face;
          std::array<Point<dim>, n_face_vertices> vertices;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            {
              vertices[v]            = cell->face(f)->vertex(v);
              const double tolerance = 1e-10 * cell->diameter();
              bool         matched   = false;
              for (const unsigned int i : dofs.dofs_on_face(f))
                {
                  const auto [component, base]
                    = fe.system_to_component_index(i);
                  if (component != 0
                      || dofs.support_point(indices[i]).distance(vertices[v])
                           > tolerance)
                    continue;
                  matched      = true;
                  face.dofs[v] = indices[i];
                  const std::pair<unsigned int, unsigned int> key(
                    cell->active_cell_index(), base);
                  const auto [entry, first] = found.try_emplace(indices[i]);
                  Node &node                = entry->second;
                  if (first)
                    {
                      for (unsigned int d = 0; d < dim; ++d)
                        node.dofs[d]
                          = indices[fe.component_to_system_index(d, base)];
                      node.reference = dofs.support_point(indices[i]);
                      node.key       = key;
                    }
                  node.key = std::min(node.key, key);
                }
              AssertThrow(matched,
                          ExcMessage("contact: a face vertex without a "
                                     "support point (is the element Q1?)"));
            }
          // Orient the normal away from the cell.
          Point<dim> center;
          for (const auto &x : vertices)
            center += x / double(n_face_vertices);
          const Tensor<1, dim> n = normal(vertices, face_middle());
          face.sign              = n * (center - cell->center()) > 0 ? 1. : -1.;
          const double area      = face_measure(vertices);
          const double share     = 0.5 * penalty * area / n_face_vertices;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            {
              Node &node = found[face.dofs[v]];
              node.stiffness += share;
              node.area_penalty += share * face.sign * n;
            }
          // Half the cell's depth, and at most half the face's shortest
          // edge: then the point a depth behind the face moves by at most
          // twice as much as the vertices when the face turns.
          double shortest = std::numeric_limits<double>::max();
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            for (unsigned int w = v + 1; w < n_face_vertices; ++w)
              shortest = std::min(shortest, vertices[v].distance(vertices[w]));
          face.depth   = std::min(0.5 * cell->measure() / area, 0.5 * shortest);
          face.exclude = outer || (paired && paired(cell, f));
          raw.push_back(face);
        }

    // A node's key is its first copy over all its cells, not only those
    // with a surface face at it: a crack insertion that adds a surface
    // face elsewhere at the node does not change it, only a split does
    // (and then one of the two keeps it).
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        dofs.get_dof_indices(cell, indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          {
            const auto [component, base] = fe.system_to_component_index(i);
            if (component != 0)
              continue;
            const auto it = found.find(indices[i]);
            if (it == found.end())
              continue;
            const std::pair<unsigned int, unsigned int> corner(
              cell->active_cell_index(), base);
            it->second.key = std::min(it->second.key, corner);
            it->second.corners.push_back(corner);
          }
      }

    // Nodes in the order of their undeformed position (then key): the
    // evaluation order, the same on any partition.
    nodes.clear();
    for (auto &[dof, node] : found)
      nodes.push_back(node);
    std::sort(nodes.begin(), nodes.end(), [](const Node &a, const Node &b) {
      if (lexicographically_less(a.reference, b.reference))
        return true;
      if (lexicographically_less(b.reference, a.reference))
        return false;
      return a.key < b.key;
    });
    std::map<types::global_dof_index, unsigned int> node_of;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      node_of[nodes[i].dofs[0]] = i;
    faces.clear();
    for (const RawFace &r : raw)
      {
        Face face;
        for (unsigned int v = 0; v < n_face_vertices; ++v)
          face.nodes[v] = node_of.at(r.dofs[v]);
        face.sign               = r.sign;
        face.depth              = r.depth;
        face.exclude_coincident = r.exclude;
        faces.push_back(face);
      }

    // The candidates' margin: a fifth of the thinnest cell across a face,
    // twice the smallest depth (thin plies set it). Measured on the impact
    // plate with 41k surface faces: a margin of a twentieth of the mean
    // face size rebuilt the candidates 38 times in 5 us, at 36 ms each; a
    // fifth of it 10 times, but on coarse meshes its boxes reached across
    // several plies.
    double thinnest = std::numeric_limits<double>::max();
    for (const Face &face : faces)
      thinnest = std::min(thinnest, 2 * face.depth);
    margin           = faces.empty() ? 0. : 0.2 * thinnest;
    candidates_built = false;
    // The last surface's pairs and matrix couplings index its nodes.
    pairs.clear();
    coupled_start.clear();
    coupled.clear();
    constrained_dofs.clear();
    outdated         = false;
    pairs_factorized = false;
    history.assign(nodes.size(), History());
    previous.assign(nodes.size(), Tensor<1, dim>());
    positions.assign(nodes.size(), Point<dim>());
    fresh.assign(nodes.size(), true);
    if (mesh_change)
      carry_by_place(old_nodes, old_faces, old_history);
    else
      {
        inherit_history(old, parent_of);
        // The stick springs of nodes that are gone (split, or no longer on
        // the surface) release their energy: booked as dissipated, so that
        // the ledger stays closed.
        for (const auto &[key, entry] : old)
          dissipation += entry.history.stick_energy;
      }

    // What each rank sends, and the gathered order.
    const IndexSet &owned = dofs.locally_owned_dofs();
    owned_nodes.clear();
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (owned.is_element(nodes[i].dofs[0]))
        {
          for (unsigned int d = 1; d < dim; ++d)
            AssertThrow(owned.is_element(nodes[i].dofs[d]),
                        ExcMessage("a node's components are owned by one "
                                   "rank"));
          owned_nodes.push_back(i);
        }
    // Their entries in the owned part of a vector (the owned dofs are one
    // contiguous block per rank).
    owned_local.clear();
    for (const unsigned int i : owned_nodes)
      {
        std::array<unsigned int, dim> local;
        for (unsigned int d = 0; d < dim; ++d)
          local[d] = owned.index_within_set(nodes[i].dofs[d]);
        owned_local.push_back(local);
      }
    local_of_node.assign(nodes.size(), -1);
    for (std::size_t k = 0; k < owned_nodes.size(); ++k)
      local_of_node[owned_nodes[k]] = k;
    touching.assign(nodes.size(), false);
    collect_slaves();
    // The gathered order, and the counts and offsets of the positions'
    // gather in every step (the same from one step to the next).
    gathered_nodes             = concatenate_over_ranks(owned_nodes, comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    gather_sizes.clear();
    gather_offsets.clear();
    if (n_ranks > 1)
      {
        gather_sizes
          = Utilities::MPI::all_gather(comm, int(dim * owned_nodes.size()));
        gather_offsets.assign(n_ranks, 0);
        std::partial_sum(gather_sizes.begin(),
                         gather_sizes.end() - 1,
                         gather_offsets.begin() + 1);
      }
    AssertThrow(gathered_nodes.size() == nodes.size(),
                ExcMessage("contact: every surface node needs one owner"));
  }



  template <int dim>
  Point<dim - 1>
  BodyContact<dim>::face_middle()
  {
    Point<dim - 1> middle;
    for (unsigned int d = 0; d < dim - 1; ++d)
      middle[d] = 0.5;
    return middle;
  }



  template <int dim>
  void
  BodyContact<dim>::collect_slaves()
  {
    last_slaves.clear();
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (history[i].in_contact)
        last_slaves.push_back(i);
  }



  template <int dim>
  void
  BodyContact<dim>::gather(const Vector &u, std::vector<Tensor<1, dim>> &values)
  {
    values.resize(nodes.size());
    const double *owned_values = u.begin();
    if (gather_sizes.empty())
      {
        for (std::size_t k = 0; k < owned_nodes.size(); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            values[owned_nodes[k]][d] = owned_values[owned_local[k][d]];
        return;
      }
    // Buffers kept from step to step.
    std::vector<double> &mine = send_buffer, &all = receive_buffer;
    mine.clear();
    for (const auto &local : owned_local)
      for (unsigned int d = 0; d < dim; ++d)
        mine.push_back(owned_values[local[d]]);
    all.resize(dim * nodes.size());
    MPI_Allgatherv(mine.data(),
                   mine.size(),
                   MPI_DOUBLE,
                   all.data(),
                   gather_sizes.data(),
                   gather_offsets.data(),
                   MPI_DOUBLE,
                   comm);
    for (std::size_t k = 0; k < gathered_nodes.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        values[gathered_nodes[k]][d] = all[dim * k + d];
  }



  template <int dim>
  void
  BodyContact<dim>::gather_positions(const Vector &u)
  {
    gather(u, displacements);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      positions[i] = nodes[i].reference + displacements[i];
    if (deformed_areas)
      update_current_areas();
  }



  template <int dim>
  void
  BodyContact<dim>::update_current_areas()
  {
    // As setup() sums the undeformed ones, in the faces' order (the same
    // sums on every rank).
    for (Node &node : nodes)
      node.current_area = Tensor<1, dim>();
    for (const Face &face : faces)
      {
        std::array<Point<dim>, n_face_vertices> v;
        for (unsigned int a = 0; a < n_face_vertices; ++a)
          v[a] = positions[face.nodes[a]];
        const Tensor<1, dim> n = normal(v, face_middle());
        const double share = 0.5 * penalty * face_measure(v) / n_face_vertices;
        for (unsigned int a = 0; a < n_face_vertices; ++a)
          nodes[face.nodes[a]].current_area += share * face.sign * n;
      }
  }



  template <int dim>
  Tensor<1, dim>
  BodyContact<dim>::offset(const unsigned int    s,
                           const Face           &face,
                           const Point<dim - 1> &xi) const
  {
    // sum_a N_a (x_s - x_a), with each difference taken apart in the
    // reference positions and the displacements: a stiff penalty times
    // the round-off of coordinates far from the origin would otherwise
    // be a residual that Newton cannot reduce.
    const auto     N = shape_values(xi);
    Tensor<1, dim> r;
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      r += N[a]
           * ((nodes[s].reference - nodes[face.nodes[a]].reference)
              + (displacements[s] - displacements[face.nodes[a]]));
    return r;
  }



  template <int dim>
  void
  BodyContact<dim>::add_to_owned(double               *entries,
                                 const unsigned int    node,
                                 const Tensor<1, dim> &f) const
  {
    const int k = local_of_node[node];
    if (k >= 0)
      for (unsigned int d = 0; d < dim; ++d)
        entries[owned_local[k][d]] += f[d];
  }



  template <int dim>
  std::array<double, BodyContact<dim>::n_face_vertices>
  BodyContact<dim>::shape_values(const Point<dim - 1> &xi)
  {
    if constexpr (dim == 2)
      return {{1 - xi[0], xi[0]}};
    else
      return {{(1 - xi[0]) * (1 - xi[1]),
               xi[0] * (1 - xi[1]),
               (1 - xi[0]) * xi[1],
               xi[0] * xi[1]}};
  }



  template <int dim>
  Tensor<1, dim>
  BodyContact<dim>::normal(const std::array<Point<dim>, n_face_vertices> &v,
                           const Point<dim - 1> &xi) const
  {
    Tensor<1, dim> n;
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> t = v[1] - v[0];
        n[0]                   = t[1];
        n[1]                   = -t[0];
      }
    else
      {
        const Tensor<1, dim> d0
          = (v[1] - v[0]) * (1 - xi[1]) + (v[3] - v[2]) * xi[1];
        const Tensor<1, dim> d1
          = (v[2] - v[0]) * (1 - xi[0]) + (v[3] - v[1]) * xi[0];
        n = cross_product_3d(d0, d1);
      }
    return n / n.norm();
  }



  template <int dim>
  bool
  BodyContact<dim>::project(const std::array<Point<dim>, n_face_vertices> &v,
                            const Point<dim>                              &x,
                            Point<dim - 1>                                &xi,
                            Point<dim>  &on_face,
                            const double inside,
                            bool        *clamped) const
  {
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> t = v[1] - v[0];
        xi[0]                  = (x - v[0]) * t / t.norm_square();
      }
    else
      {
        // Newton on the two face coordinates of min |x(xi) - x|^2; the
        // bilinear face's curvature term keeps it quadratic on warped
        // faces, Gauss-Newton where that term spoils the Hessian.
        xi[0] = xi[1]              = 0.5;
        const Tensor<1, dim> twist = v[0] - v[1] - v[2] + v[3];
        for (unsigned int it = 0; it < 20; ++it)
          {
            const auto     N = shape_values(xi);
            Tensor<1, dim> r = -x;
            for (unsigned int a = 0; a < n_face_vertices; ++a)
              r += N[a] * v[a];
            const Tensor<1, dim> d0
              = (v[1] - v[0]) * (1 - xi[1]) + (v[3] - v[2]) * xi[1];
            const Tensor<1, dim> d1
              = (v[2] - v[0]) * (1 - xi[0]) + (v[3] - v[1]) * xi[0];
            const double g0 = r * d0, g1 = r * d1;
            const double h00 = d0 * d0, h11 = d1 * d1;
            double       h01 = d0 * d1 + r * twist;
            double       det = h00 * h11 - h01 * h01;
            if (!(det > 1e-12 * h00 * h11))
              {
                h01 = d0 * d1;
                det = h00 * h11 - h01 * h01;
              }
            const double s0 = (h11 * g0 - h01 * g1) / det;
            const double s1 = (h00 * g1 - h01 * g0) / det;
            xi[0] -= s0;
            xi[1] -= s1;
            if (std::abs(s0) + std::abs(s1) < 1e-13)
              break;
          }
      }
    std::array<bool, dim - 1> past_edge;
    for (unsigned int d = 0; d < dim - 1; ++d)
      {
        if (!(xi[d] > -inside && xi[d] < 1 + inside))
          return false;
        past_edge[d] = xi[d] < 0 || xi[d] > 1;
        // For the search's tie-break a face counts as passed only beyond
        // round-off: a node on the common edge of two faces (matching
        // meshes) is 1e-16 past one of them or the other from one iterate
        // to the next, and a face it "passed" would lose to a neighbour it
        // does not lie on (Newton then cycled between the two at a
        // residual of 1e-7 of the force). The geometry keeps the exact
        // rule, which the tangent differentiates.
        if (clamped && (xi[d] < -1e-10 || xi[d] > 1 + 1e-10))
          *clamped = true;
        xi[d] = std::clamp(xi[d], 0., 1.);
      }
    if constexpr (dim == 3)
      if (past_edge[0] != past_edge[1])
        {
          // Past one edge only: the closest point of that (straight) edge,
          // so that the other coordinate is a closest point's too (the
          // tangent differentiates that condition).
          const unsigned int along   = past_edge[0] ? 1 : 0;
          Point<dim - 1>     ends[2] = {xi, xi};
          ends[0][along]             = 0;
          ends[1][along]             = 1;
          Point<dim> end_points[2];
          for (unsigned int e = 0; e < 2; ++e)
            {
              const auto N = shape_values(ends[e]);
              for (unsigned int a = 0; a < n_face_vertices; ++a)
                end_points[e] += N[a] * v[a];
            }
          const Tensor<1, dim> edge = end_points[1] - end_points[0];
          xi[along]
            = std::clamp((x - end_points[0]) * edge / edge.norm_square(),
                         0.,
                         1.);
        }
    const auto N = shape_values(xi);
    on_face      = Point<dim>();
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      on_face += N[a] * v[a];
    return true;
  }



  template <int dim>
  bool
  BodyContact<dim>::excluded(const unsigned int s, const Face &face) const
  {
    std::array<Point<dim>, n_face_vertices> v;
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      v[a] = nodes[face.nodes[a]].reference;
    Point<dim - 1> xi;
    Point<dim>     on_face;
    if (!project(v, nodes[s].reference, xi, on_face, 1e-9))
      return false;
    const double round_off = 1e-9 * v[0].distance(v[n_face_vertices - 1]);
    const double gap
      = (nodes[s].reference - on_face) * (face.sign * normal(v, xi));
    return gap < -round_off
           || (face.exclude_coincident && std::abs(gap) <= round_off);
  }



  template <int dim>
  void
  BodyContact<dim>::update_candidates()
  {
    // Verlet's idea: the candidates hold while no node has moved by more
    // than a third of the margin since they were found. A node and a face
    // vertex have then moved by less than the margin relative to each
    // other, and the point a depth behind the face by less than twice the
    // margin: the face turns by at most the relative motion of two
    // vertices over its shortest edge, and the depth is at most half that
    // edge.
    double moved = 0;
    if (candidates_built)
      for (std::size_t i = 0; i < nodes.size(); ++i)
        moved
          = std::max(moved, (positions[i] - built_positions[i]).norm_square());
    if (candidates_built && moved < margin * margin / 9)
      return;
    const Clock::time_point start = Clock::now();
    ++n_rebuilds;
    built_positions  = positions;
    candidates_built = true;

    // A face's box holds its vertices, 2 % of its extent around them (the
    // projection's tolerance), the vertices moved by its depth against its
    // normal (where a node penetrating it can be) and the margin. The
    // grid's cells are as large as the mean box in each direction (thin
    // across the plies of a laminate), and each face is filed in every
    // cell its box touches, so a node meets only the faces near it.
    boxes.resize(faces.size());
    Tensor<1, dim> mean_extent;
    Point<dim>     origin;
    for (unsigned int d = 0; d < dim; ++d)
      origin[d] = std::numeric_limits<double>::max();
    const Point<dim - 1> middle = face_middle();
    for (std::size_t f = 0; f < faces.size(); ++f)
      {
        std::array<Point<dim>, n_face_vertices> v;
        for (unsigned int a = 0; a < n_face_vertices; ++a)
          v[a] = positions[faces[f].nodes[a]];
        const Tensor<1, dim> inward
          = -faces[f].depth * faces[f].sign * normal(v, middle);
        auto &[lo, hi] = boxes[f];
        lo = hi = v[0];
        for (const auto &x : v)
          for (unsigned int d = 0; d < dim; ++d)
            lo[d] = std::min({lo[d], x[d], x[d] + inward[d]}),
            hi[d] = std::max({hi[d], x[d], x[d] + inward[d]});
        const double grow = 0.02 * (hi - lo).norm() + 2 * margin;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] -= grow, hi[d] += grow;
            mean_extent[d] += (hi[d] - lo[d]) / faces.size();
            origin[d] = std::min(origin[d], lo[d]);
          }
      }
    const double floor    = 1e-6 * mean_extent.norm() + 1e-300;
    const auto   index_of = [&](const Point<dim> &x) {
      std::array<long, 3> index{{0, 0, 0}};
      for (unsigned int d = 0; d < dim; ++d)
        index[d]
          = std::floor((x[d] - origin[d]) / std::max(mean_extent[d], floor));
      return index;
    };
    grid.clear();
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        const auto lo = index_of(boxes[f].first),
                   hi = index_of(boxes[f].second);
        for (long i = lo[0]; i <= hi[0]; ++i)
          for (long j = lo[1]; j <= hi[1]; ++j)
            for (long k = lo[2]; k <= hi[2]; ++k)
              grid.emplace_back(grid_key({{i, j, k}}), f);
      }
    std::sort(grid.begin(), grid.end());

    // Each node's candidates: the faces in its grid cell whose box holds
    // it, without its own faces and those it is excluded from (the
    // exclusion depends on the undeformed laminate only).
    candidate_start.assign(1, 0);
    candidates.clear();
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        const Point<dim> &x   = positions[s];
        const auto        key = grid_key(index_of(x));
        for (auto it = std::lower_bound(grid.begin(),
                                        grid.end(),
                                        std::make_pair(key, 0u));
             it != grid.end() && it->first == key;
             ++it)
          {
            const Face &face = faces[it->second];
            if (std::find(face.nodes.begin(), face.nodes.end(), s)
                != face.nodes.end())
              continue;
            const auto &[lo, hi] = boxes[it->second];
            bool in_box          = true;
            for (unsigned int d = 0; d < dim; ++d)
              in_box = in_box && x[d] >= lo[d] && x[d] <= hi[d];
            if (in_box && !excluded(s, face))
              candidates.push_back(it->second);
          }
        candidate_start.push_back(candidates.size());
      }
    if (!coupled_start.empty())
      outdated = outdated || !candidates_coupled();
    rebuild_seconds += seconds_since(start);
  }



  template <int dim>
  void
  BodyContact<dim>::evaluate(const Vector &u, Vector &contact)
  {
    const Clock::time_point start = Clock::now();
    gather_positions(u);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (fresh[i])
        previous[i] = displacements[i], fresh[i] = false;

    const Clock::time_point search_start = Clock::now();
    update_candidates();
    // Narrow phase: each node against its candidate faces.
    pairs.clear();
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        const Point<dim> &x = positions[s];
        Pair              best{s, 0, Point<dim - 1>(), Tensor<1, dim>(), 0, {}};
        bool              found = false, best_clamped = false;
        for (unsigned int c = candidate_start[s]; c < candidate_start[s + 1];
             ++c)
          {
            const Face                             &face = faces[candidates[c]];
            std::array<Point<dim>, n_face_vertices> v;
            for (unsigned int a = 0; a < n_face_vertices; ++a)
              v[a] = positions[face.nodes[a]];
            Point<dim - 1> xi;
            Point<dim>     on_face;
            // Faces reach 2 % beyond their edges: a node that slides
            // over the edge of a face by a fraction of its size (as the
            // edges of two blocks of different lateral strain do) stays
            // in contact instead of dropping out and back in, which
            // would release and regain its penalty energy.
            bool clamped = false;
            if (!project(v, x, xi, on_face, 0.02, &clamped))
              continue;
            const Tensor<1, dim> n   = face.sign * normal(v, xi);
            const double         gap = offset(s, face, xi) * n;
            // Gaps of round-off (faces brought back to where they
            // touched) are not contact: their count would depend on the
            // order of sums, i.e. on the partition. Nor is a node whose
            // faces do not look at the face (a node that hangs at the
            // midpoint of an edge of the face's own cell lies half that
            // edge behind it, on a face at right angles to it).
            const Tensor<1, dim> &facing = facing_area(s);
            if (!(gap < -1e-13 * face.depth && gap > -face.depth)
                || !(facing * n < -1e-3 * facing.norm()))
              continue;
            // A face the node projects into beats one whose edge it has
            // passed (whose gap turns with the face and whose force is not
            // along the closest point's normal), then the least
            // penetration wins; the first one found keeps a tie.
            if (found
                && ((clamped && !best_clamped)
                    || (clamped == best_clamped && -gap >= -best.gap)))
              continue;
            best         = Pair{s, candidates[c], xi, n, gap, {}};
            best_clamped = clamped;
            found        = true;
          }
        if (found)
          pairs.push_back(best);
      }
    search_seconds += seconds_since(search_start);
    // Forces, friction and energies, in the nodes' order (the same sums
    // in the same order on every rank), straight into the owned entries.
    contact         = 0;
    double *entries = contact.begin();
    energy = normal_force = friction_force = penetration = 0;
    // Static runs evaluate trial states: the friction history moves from
    // the last converged state, and commit() keeps it.
    if (static_mode)
      trial_history = history;
    std::vector<History> &updated    = static_mode ? trial_history : history;
    double                dissipated = 0;
    for (Pair &pair : pairs)
      {
        const Face    &face = faces[pair.face];
        const auto     N    = shape_values(pair.xi);
        const double   k    = -(facing_area(pair.slave) * pair.n);
        const double   p    = -k * pair.gap;
        Tensor<1, dim> f    = p * pair.n;
        energy += 0.5 * k * pair.gap * pair.gap;
        normal_force += p;
        penetration     = std::max(penetration, -pair.gap);
        const History h = history[pair.slave];
        History       next;
        if (friction_coefficient > 0)
          {
            // The slip increment of the node relative to the face point,
            // from the displacements (a stiff stick spring times the
            // round-off of positions would be a residual floor).
            Tensor<1, dim> slip
              = displacements[pair.slave] - previous[pair.slave];
            for (unsigned int a = 0; a < n_face_vertices; ++a)
              slip
                -= N[a]
                   * (displacements[face.nodes[a]] - previous[face.nodes[a]]);
            slip -= (slip * pair.n) * pair.n;
            const double kt    = tangential_factor * k;
            const double limit = friction_coefficient * p;
            // A mesh change carried the spring's stretch: its force is
            // that of the node's new stiffness, within the new cone, and
            // its energy is where the dissipation starts from (what the
            // change takes from the springs is the change's, not friction's).
            Tensor<1, dim> old_force;
            double         stored = 0;
            if (h.in_contact)
              {
                old_force = h.friction - (h.friction * pair.n) * pair.n;
                if (h.carried)
                  {
                    old_force *= kt;
                    if (old_force.norm() > limit)
                      old_force *= limit / old_force.norm();
                  }
                stored = h.carried ? old_force.norm_square() / (2 * kt) :
                                     h.stick_energy;
              }
            Tensor<1, dim> trial = old_force - kt * slip;
            pair.trial           = trial;
            pair.kt              = kt;
            // On the cone within round-off (a node that slid, evaluated
            // again before it moves: the first iterate of a static step)
            // counts as sticking, so that the stick/slip decision and the
            // tangent do not depend on the order of sums.
            pair.slipping = trial.norm() > limit * (1 + 1e-10);
            if (pair.slipping)
              trial *= limit / trial.norm();
            // The work of the friction force less the change of the stick
            // spring's energy from what was stored (so that what a turning
            // face or a changed stiffness takes from the spring is booked
            // too): zero while the node sticks on a fixed face.
            const double stick = trial.norm_square() / (2 * kt);
            dissipated += -0.5 * (old_force + trial) * slip - (stick - stored);
            energy += stick;
            friction_force += trial.norm();
            next.friction     = trial;
            next.stick_energy = stick;
            f += trial;
          }
        next.in_contact     = true;
        next.face           = pair.face;
        next.xi             = pair.xi;
        updated[pair.slave] = next;
        add_to_owned(entries, pair.slave, f);
        for (unsigned int a = 0; a < n_face_vertices; ++a)
          add_to_owned(entries, face.nodes[a], -N[a] * f);
      }
    // The nodes that left contact lose their friction history (its
    // spring's energy and, as for a pair whose force falls to zero, the
    // mean of the old force and none along the step's slip on the face it
    // touched); touching is all false between the calls.
    for (const Pair &pair : pairs)
      touching[pair.slave] = true;
    for (const unsigned int s : last_slaves)
      if (!touching[s])
        {
          dissipated += history[s].stick_energy + leaving_work(s);
          updated[s] = History();
        }
    for (const Pair &pair : pairs)
      touching[pair.slave] = false;
    n_contact = pairs.size();
    if (static_mode)
      pending_dissipation = dissipated;
    else
      {
        dissipation += dissipated;
        last_slaves.clear();
        for (const Pair &pair : pairs)
          last_slaves.push_back(pair.slave);
        // The last displacements are needed for the slip increments only.
        if (friction_coefficient > 0)
          previous = displacements;
      }
    ++n_evaluations;
    evaluate_seconds += seconds_since(start);
  }



  template <int dim>
  double
  BodyContact<dim>::leaving_work(const unsigned int s) const
  {
    const History &h = history[s];
    if (friction_coefficient == 0 || !h.in_contact || h.carried
        || h.face == numbers::invalid_unsigned_int)
      return 0;
    const auto     N    = shape_values(h.xi);
    Tensor<1, dim> slip = displacements[s] - previous[s];
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      {
        const unsigned int v = faces[h.face].nodes[a];
        slip -= N[a] * (displacements[v] - previous[v]);
      }
    // The old force is tangential to the old face; it opposes the slip.
    return -0.5 * (h.friction * slip);
  }



  template <int dim>
  bool
  BodyContact<dim>::candidates_coupled() const
  {
    for (unsigned int s = 0; s < nodes.size(); ++s)
      for (unsigned int c = candidate_start[s]; c < candidate_start[s + 1]; ++c)
        if (!std::binary_search(coupled.begin() + coupled_start[s],
                                coupled.begin() + coupled_start[s + 1],
                                candidates[c]))
          return false;
    return true;
  }



  template <int dim>
  std::vector<types::global_dof_index>
  BodyContact<dim>::pair_dofs(const unsigned int slave,
                              const unsigned int face) const
  {
    std::vector<types::global_dof_index> dofs(nodes[slave].dofs.begin(),
                                              nodes[slave].dofs.end());
    for (const unsigned int a : faces[face].nodes)
      dofs.insert(dofs.end(), nodes[a].dofs.begin(), nodes[a].dofs.end());
    return dofs;
  }



  template <int dim>
  void
  BodyContact<dim>::add_couplings(const Vector                    &u,
                                  const AffineConstraints<double> &constraints,
                                  TrilinosWrappers::SparsityPattern &pattern)
  {
    // The parents of every surface dof that hangs or is supported (none),
    // from its owner: the same matrix on any partition.
    std::vector<double> mine;
    for (const unsigned int i : owned_nodes)
      for (const auto dof : nodes[i].dofs)
        {
          const auto *entries = constraints.get_constraint_entries(dof);
          if (entries == nullptr)
            continue;
          mine.push_back(dof);
          mine.push_back(entries->size());
          for (const auto &[parent, weight] : *entries)
            {
              mine.push_back(parent);
              mine.push_back(weight);
            }
        }
    const std::vector<double> all = concatenate_over_ranks(mine, comm);
    constrained_dofs.clear();
    for (std::size_t k = 0; k < all.size();)
      {
        auto &parents
          = constrained_dofs[static_cast<types::global_dof_index>(all[k])];
        const auto n = static_cast<std::size_t>(all[k + 1]);
        for (std::size_t j = 0; j < n; ++j)
          parents.emplace_back(static_cast<types::global_dof_index>(
                                 all[k + 2 + 2 * j]),
                               all[k + 3 + 2 * j]);
        k += 2 + 2 * n;
      }
    std::vector<std::pair<types::global_dof_index, double>> targets;
    const auto through = [&](const types::global_dof_index         dof,
                             std::vector<types::global_dof_index> &into) {
      matrix_targets(dof, targets);
      for (const auto &[target, weight] : targets)
        into.push_back(target);
    };
    std::vector<types::global_dof_index> rows, columns;
    gather_positions(u);
    candidates_built = false;
    update_candidates();
    coupled_start = candidate_start;
    coupled       = candidates;
    for (unsigned int s = 0; s < nodes.size(); ++s)
      std::sort(coupled.begin() + coupled_start[s],
                coupled.begin() + coupled_start[s + 1]);
    outdated = false;
    // Rows of the node and of the face's nodes, where this rank owns them.
    for (unsigned int s = 0; s < nodes.size(); ++s)
      for (unsigned int c = candidate_start[s]; c < candidate_start[s + 1]; ++c)
        {
          const auto                dofs = pair_dofs(s, candidates[c]);
          std::vector<unsigned int> members{s};
          members.insert(members.end(),
                         faces[candidates[c]].nodes.begin(),
                         faces[candidates[c]].nodes.end());
          columns.clear();
          for (const auto dof : dofs)
            through(dof, columns);
          std::sort(columns.begin(), columns.end());
          columns.erase(std::unique(columns.begin(), columns.end()),
                        columns.end());
          rows.clear();
          for (const unsigned int node : members)
            if (local_of_node[node] >= 0)
              for (const auto row : nodes[node].dofs)
                through(row, rows);
          for (const auto row : rows)
            pattern.add_entries(row, columns.begin(), columns.end());
        }
  }



  template <int dim>
  void
  BodyContact<dim>::commit()
  {
    history = trial_history;
    dissipation += pending_dissipation;
    pending_dissipation = 0;
    previous            = displacements;
    collect_slaves();
  }



  template <int dim>
  typename BodyContact<dim>::PairTangent
  BodyContact<dim>::pair_tangent(const Pair &pair) const
  {
    // The force f on the node (F_s = f) and -N_a f on the face's nodes
    // depend on u through the nodes, the closest point xi and the normal
    // n(xi): f_n = -k g n with k = -(A . n), and the friction's stick
    // force, measured in the tangent plane of n. All of them are
    // linearized here (the node-to-face contact's full tangent), so that
    // Newton converges quadratically however far the penalty lets the
    // bodies overlap.
    const Face           &face = faces[pair.face];
    const Point<dim - 1> &xi   = pair.xi;
    const Tensor<1, dim> &n    = pair.n;
    PairGradients         gradients;
    auto &[N, dN, dxi, dn, dk, dg] = gradients;
    N                              = shape_values(xi);
    std::array<Point<dim>, n_face_vertices> v;
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      v[a] = positions[face.nodes[a]];
    // dN_a/dxi_i and the face's tangents x_,i.
    std::array<Tensor<1, dim>, dim - 1> tangents;
    Tensor<1, dim>                      twist; // x_,01
    if constexpr (dim == 2)
      {
        dN[0][0] = -1, dN[1][0] = 1;
        tangents[0] = v[1] - v[0];
      }
    else
      {
        dN[0][0] = -(1 - xi[1]), dN[1][0] = 1 - xi[1];
        dN[2][0] = -xi[1], dN[3][0] = xi[1];
        dN[0][1] = -(1 - xi[0]), dN[1][1] = -xi[0];
        dN[2][1] = 1 - xi[0], dN[3][1] = xi[0];
        tangents[0] = (v[1] - v[0]) * (1 - xi[1]) + (v[3] - v[2]) * xi[1];
        tangents[1] = (v[2] - v[0]) * (1 - xi[0]) + (v[3] - v[1]) * xi[0];
        twist       = v[0] - v[1] - v[2] + v[3];
      }
    std::array<double, n_members> c{{1.}};
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      c[a + 1] = -N[a];
    const Tensor<1, dim> r = offset(pair.slave, face, xi);

    // dxi/du_J from the closest point's condition r . x_,i = 0 on the
    // coordinates that are free (a node past an edge has its coordinate
    // clamped to 0 or 1: fixed). sum_j (x_,i . x_,j - r . x_,ij) dxi_j
    // = sum_J (c_J x_,i + dN_J,i r) . du_J.
    {
      std::array<bool, dim - 1> free;
      for (unsigned int i = 0; i < dim - 1; ++i)
        free[i] = xi[i] > 0 && xi[i] < 1;
      Tensor<2, dim - 1> M;
      for (unsigned int i = 0; i < dim - 1; ++i)
        for (unsigned int j = 0; j < dim - 1; ++j)
          M[i][j] = tangents[i] * tangents[j] - (i != j ? r * twist : 0.);
      for (unsigned int i = 0; i < dim - 1; ++i)
        if (!free[i])
          for (unsigned int j = 0; j < dim - 1; ++j)
            M[i][j] = M[j][i] = (i == j);
      // Where the curvature term spoils the matrix, project() took
      // Gauss-Newton steps; so does the tangent (finite, if not exact, on a
      // strongly warped face pressed deep).
      if constexpr (dim == 3)
        if (!(determinant(M) > 1e-12 * M[0][0] * M[1][1]))
          M[0][1] = M[1][0]
            = free[0] && free[1] ? tangents[0] * tangents[1] : 0.;
      const Tensor<2, dim - 1> inverse = invert(M);
      for (unsigned int J = 0; J < n_members; ++J)
        {
          std::array<Tensor<1, dim>, dim - 1> rhs;
          for (unsigned int i = 0; i < dim - 1; ++i)
            if (free[i])
              rhs[i] = c[J] * tangents[i] + (J > 0 ? dN[J - 1][i] * r : 0 * r);
          for (unsigned int i = 0; i < dim - 1; ++i)
            for (unsigned int j = 0; j < dim - 1; ++j)
              dxi[J][i] += inverse[i][j] * rhs[j];
        }
    }

    // dn/du_J = sign (I - n n^T) dc/du_J / |c|, with c the face's normal
    // before scaling: R (v_1 - v_0) in 2D, x_,0 x x_,1 in 3D (which moves
    // with xi too).
    {
      const Tensor<2, dim> across
        = unit_symmetric_tensor<dim>() - outer_product(n, n);
      std::array<Tensor<2, dim>, n_members> dc;
      double                                length;
      if constexpr (dim == 2)
        {
          Tensor<2, dim> R;
          R[0][1] = 1, R[1][0] = -1;
          dc[1]  = -R;
          dc[2]  = R;
          length = tangents[0].norm();
        }
      else
        {
          const Tensor<1, dim> &d0 = tangents[0], &d1 = tangents[1];
          for (unsigned int a = 0; a < n_face_vertices; ++a)
            dc[a + 1]
              = -dN[a][0] * cross_matrix(d1) + dN[a][1] * cross_matrix(d0);
          const Tensor<1, dim> along_0 = cross_product_3d(d0, twist),
                               along_1 = cross_product_3d(twist, d1);
          for (unsigned int J = 0; J < n_members; ++J)
            dc[J] += outer_product(along_0, dxi[J][0])
                     + outer_product(along_1, dxi[J][1]);
          length = cross_product_3d(d0, d1).norm();
        }
      for (unsigned int J = 0; J < n_members; ++J)
        dn[J] = (face.sign / length) * across * dc[J];
    }

    // The normal force and its gradients: dg = c_J n + dn^T r (x_,i . n
    // = 0), dk = -dn^T A.
    const Tensor<1, dim>                 &A = facing_area(pair.slave);
    const double                          k = -(A * n), g = pair.gap;
    std::array<Tensor<2, dim>, n_members> B; // df/du_J
    for (unsigned int J = 0; J < n_members; ++J)
      {
        dk[J] = -(transpose(dn[J]) * A);
        dg[J] = c[J] * n + transpose(dn[J]) * r;
        B[J]  = -g * outer_product(n, dk[J]) - k * outer_product(n, dg[J])
               - (k * g) * dn[J];
      }
    Tensor<1, dim> f = -k * g * n;
    if (friction_coefficient > 0)
      f += add_friction_gradient(pair, gradients, B);

    // K_IJ = -(c_I df/du_J + f (x) dc_I/du_J), dc_a = -dN_a . dxi.
    PairTangent K;
    for (unsigned int I = 0; I < n_members; ++I)
      for (unsigned int J = 0; J < n_members; ++J)
        {
          K[I][J] = -c[I] * B[J];
          if (I > 0)
            for (unsigned int i = 0; i < dim - 1; ++i)
              K[I][J] += dN[I - 1][i] * outer_product(f, dxi[J][i]);
        }
    return K;
  }



  template <int dim>
  Tensor<1, dim>
  BodyContact<dim>::add_friction_gradient(
    const Pair                            &pair,
    const PairGradients                   &gradients,
    std::array<Tensor<2, dim>, n_members> &B) const
  {
    // As evaluate(): slip = P w with w the node's displacement increment
    // relative to the face point's, P = I - n n^T; the stick force
    // trial = P f_old - k_t slip, k_t = tangential_factor k; returned
    // onto the cone mu p if it slips.
    // References, not a structured binding: the lambda below captures dn.
    const auto           &N    = gradients.N;
    const auto           &dN   = gradients.dN;
    const auto           &dxi  = gradients.dxi;
    const auto           &dn   = gradients.dn;
    const auto           &dk   = gradients.dk;
    const auto           &dg   = gradients.dg;
    const Face           &face = faces[pair.face];
    const Tensor<1, dim> &n    = pair.n;
    const Tensor<2, dim> P = unit_symmetric_tensor<dim>() - outer_product(n, n);
    std::array<Tensor<1, dim>, n_face_vertices> increment;
    Tensor<1, dim> w = displacements[pair.slave] - previous[pair.slave];
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      {
        increment[a] = displacements[face.nodes[a]] - previous[face.nodes[a]];
        w -= N[a] * increment[a];
      }
    const History &h = history[pair.slave];
    // Static runs only: no mesh change has carried a stretch here.
    Assert(!h.carried, ExcInternalError());
    const Tensor<1, dim> old   = h.in_contact ? h.friction : Tensor<1, dim>();
    const Tensor<1, dim> slip  = P * w;
    const double         k     = -(facing_area(pair.slave) * n);
    const double         p     = -k * pair.gap;
    const double         size  = pair.trial.norm();
    const Tensor<1, dim> t     = size > 0 ? pair.trial / size : pair.trial;
    const double         limit = friction_coefficient * p;
    for (unsigned int J = 0; J < n_members; ++J)
      {
        // dw/du_J: the node's or the face point's increment, and the face
        // point moving along the face.
        Tensor<2, dim> dw
          = (J == 0 ? 1. : -N[J - 1]) * unit_symmetric_tensor<dim>();
        for (unsigned int a = 0; a < n_face_vertices; ++a)
          for (unsigned int i = 0; i < dim - 1; ++i)
            dw -= dN[a][i] * outer_product(increment[a], dxi[J][i]);
        // d(P x) = P dx - (n . x) dn - n (dn^T x).
        const auto turned = [&](const Tensor<1, dim> &x) {
          return -(n * x) * dn[J] - outer_product(n, transpose(dn[J]) * x);
        };
        const Tensor<2, dim> dslip = P * dw + turned(w);
        const Tensor<2, dim> dtrial
          = turned(old) - tangential_factor * outer_product(slip, dk[J])
            - pair.kt * dslip;
        if (!pair.slipping)
          B[J] += dtrial;
        else
          {
            const Tensor<1, dim> dlimit
              = -friction_coefficient * (pair.gap * dk[J] + k * dg[J]);
            B[J] += outer_product(t, dlimit)
                    + (limit / size)
                        * ((unit_symmetric_tensor<dim>() - outer_product(t, t))
                           * dtrial);
          }
      }
    return pair.slipping ? limit * t : pair.trial;
  }



  template <int dim>
  std::array<unsigned int, BodyContact<dim>::n_members>
  BodyContact<dim>::members_of(const Pair &pair) const
  {
    std::array<unsigned int, n_members> members{{pair.slave}};
    for (unsigned int a = 0; a < n_face_vertices; ++a)
      members[a + 1] = faces[pair.face].nodes[a];
    return members;
  }



  template <int dim>
  bool
  BodyContact<dim>::owns_a_member(const Pair &pair) const
  {
    for (const unsigned int node : members_of(pair))
      if (local_of_node[node] >= 0)
        return true;
    return false;
  }



  template <int dim>
  void
  BodyContact<dim>::matrix_targets(
    const types::global_dof_index                            dof,
    std::vector<std::pair<types::global_dof_index, double>> &into) const
  {
    // A supported dof has no parents and drops out: its row keeps the
    // bulk's diagonal, and the increments vanish there.
    into.clear();
    const auto constrained = constrained_dofs.find(dof);
    if (constrained != constrained_dofs.end())
      into = constrained->second;
    else
      into.emplace_back(dof, 1.);
  }



  template <int dim>
  void
  BodyContact<dim>::add_tangent(TrilinosWrappers::SparseMatrix &tangent) const
  {
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>
                                         targets(dim * n_members);
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    for (const Pair &pair : pairs)
      {
        // Every rank holds all pairs; each adds the rows it owns (through
        // the constraints), so that each row is added once.
        if (!owns_a_member(pair))
          continue;
        const auto        dofs    = pair_dofs(pair.slave, pair.face);
        const PairTangent K       = pair_tangent(pair);
        const auto        members = members_of(pair);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          matrix_targets(dofs[i], targets[i]);
        for (unsigned int I = 0; I < n_members; ++I)
          if (local_of_node[members[I]] >= 0)
            for (unsigned int d = 0; d < dim; ++d)
              for (const auto &[row, row_weight] : targets[dim * I + d])
                {
                  columns.clear();
                  values.clear();
                  for (unsigned int J = 0; J < n_members; ++J)
                    for (unsigned int e = 0; e < dim; ++e)
                      for (const auto &[column, weight] : targets[dim * J + e])
                        {
                          columns.push_back(column);
                          values.push_back(row_weight * weight * K[I][J][d][e]);
                        }
                  tangent.add(row,
                              columns.size(),
                              columns.data(),
                              values.data());
                }
      }
  }



  template <int dim>
  void
  BodyContact<dim>::add_tangent_product(const Vector &direction,
                                        Vector       &product)
  {
    gather(direction, gathered);
    double *entries = product.begin();
    for (const Pair &pair : pairs)
      {
        if (!owns_a_member(pair))
          continue;
        const PairTangent K       = pair_tangent(pair);
        const auto        members = members_of(pair);
        for (unsigned int I = 0; I < n_members; ++I)
          {
            Tensor<1, dim> row;
            for (unsigned int J = 0; J < n_members; ++J)
              row += K[I][J] * gathered[members[J]];
            add_to_owned(entries, members[I], row);
          }
      }
  }



  template <int dim>
  void
  BodyContact<dim>::add_penalty_rows(Vector &rows) const
  {
    const double tangential = friction_coefficient > 0 ? tangential_factor : 0;
    double      *entries    = rows.begin();
    for (std::size_t k = 0; k < owned_nodes.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        entries[owned_local[k][d]]
          += 4 * (1 + tangential) * nodes[owned_nodes[k]].stiffness;
  }



  template <int dim>
  std::vector<std::pair<std::string, double>>
  BodyContact<dim>::columns() const
  {
    return {{"body_contact_nodes", n_contact},
            {"body_contact_normal_force", normal_force},
            {"body_contact_friction_force", friction_force},
            {"body_contact_penetration", penetration}};
  }



  template <int dim>
  std::vector<double>
  BodyContact<dim>::state() const
  {
    // Layout 3: the face and point each node touched (for the friction
    // work of the step in which it leaves; layout 2 had none), the last
    // displacements (layout 1, without the entry, had positions;
    // restoring those through a difference would round the slip of the
    // next step).
    std::vector<double> values{dissipation, double(nodes.size()), 3.};
    for (std::size_t i = 0; i < nodes.size(); ++i)
      {
        // A mesh change is followed by an evaluation before any output
        // step's checkpoint, which turns the carried stretches into forces.
        AssertThrow(!history[i].carried,
                    ExcMessage(
                      "contact: a carried stick stretch in a checkpoint"));
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(history[i].friction[d]);
        values.push_back(history[i].stick_energy);
        values.push_back(history[i].in_contact ? 1 : 0);
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(previous[i][d]);
        values.push_back(history[i].face == numbers::invalid_unsigned_int ?
                           -1. :
                           double(history[i].face));
        for (unsigned int d = 0; d < dim - 1; ++d)
          values.push_back(history[i].xi[d]);
      }
    return values;
  }



  template <int dim>
  void
  BodyContact<dim>::set_state(const std::vector<double> &values)
  {
    const unsigned int layout = values.size() >= 3 ? values[2] : 0;
    const unsigned int stride = layout == 3 ? 3 * dim + 2 : 2 * dim + 2;
    AssertThrow(values.size() >= 3 && values[1] == nodes.size()
                  && (layout == 2 || layout == 3)
                  && values.size() == 3 + stride * nodes.size(),
                ExcMessage("the checkpoint's contact state does not match "
                           "the surface of this mesh ("
                           + std::to_string(nodes.size())
                           + " nodes) or was written by an older amfrac"));
    dissipation = values[0];
    for (std::size_t i = 0; i < nodes.size(); ++i)
      {
        const double *v = values.data() + 3 + stride * i;
        for (unsigned int d = 0; d < dim; ++d)
          history[i].friction[d] = v[d];
        history[i].stick_energy = v[dim];
        history[i].in_contact   = v[dim + 1] != 0;
        for (unsigned int d = 0; d < dim; ++d)
          previous[i][d] = v[dim + 2 + d];
        history[i].face = numbers::invalid_unsigned_int;
        if (layout == 3 && v[2 * dim + 2] >= 0)
          {
            AssertThrow(v[2 * dim + 2] < faces.size(),
                        ExcMessage("the checkpoint's contact state names a "
                                   "face this surface does not have"));
            history[i].face = static_cast<unsigned int>(v[2 * dim + 2]);
            for (unsigned int d = 0; d < dim - 1; ++d)
              history[i].xi[d] = v[2 * dim + 3 + d];
          }
        fresh[i] = false;
      }
    collect_slaves();
  }



  template class BodyContact<2>;
  template class BodyContact<3>;
} // namespace amfrac

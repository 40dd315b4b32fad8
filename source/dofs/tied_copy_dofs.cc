#include <algorithm>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_wedge_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <stdexcept>

namespace amfrac
{
  namespace
  {
    types::global_dof_index
    find_root(std::vector<types::global_dof_index> &parent,
              types::global_dof_index               i)
    {
      while (parent[i] != i)
        {
          parent[i] = parent[parent[i]]; // path halving
          i         = parent[i];
        }
      return i;
    }

    void
    unite(std::vector<types::global_dof_index> &parent,
          const types::global_dof_index         a,
          const types::global_dof_index         b)
    {
      const auto ra = find_root(parent, a), rb = find_root(parent, b);
      if (ra != rb)
        parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  } // namespace



  namespace
  {
    /** The discontinuous element whose copies the layer ties: Q on
     * Gauss-Lobatto nodes on hypercubes, P on wedges. */
    template <int dim>
    std::unique_ptr<FESystem<dim>>
    make_copy_element(const unsigned int degree, const ReferenceCell &shape)
    {
      if (shape.is_hyper_cube())
        return std::make_unique<FESystem<dim>>(
          FE_DGQArbitraryNodes<dim>(QGaussLobatto<1>(degree + 1)), dim);
      if (dim == 3 && shape == ReferenceCells::Wedge)
        return std::make_unique<FESystem<dim>>(FE_WedgeDGP<dim>(degree), dim);
      throw std::invalid_argument("TiedCopyDoFs: cells must be hypercubes "
                                  "or (3D) wedges");
    }
  } // namespace



  template <int dim>
  TiedCopyDoFs<dim>::TiedCopyDoFs(const Triangulation<dim> &triangulation,
                                  const unsigned int        degree,
                                  const ReferenceCell      &shape)
    : triangulation(triangulation)
    , shape(shape)
    , fe(make_copy_element<dim>(degree, shape))
    , dof_handler(triangulation)
    , face_dofs(shape.n_faces())
  {
    // A dof lies on reference face f if its support point lies in the
    // plane of the face (through its first vertex, along its normal).
    const auto &unit_points = fe->get_unit_support_points();
    for (unsigned int f = 0; f < shape.n_faces(); ++f)
      {
        const Point<dim> corner = shape.template vertex<dim>(
          shape.face_to_cell_vertices(f, 0, /*default orientation*/ 1));
        const Tensor<1, dim> normal
          = shape.template unit_normal_vectors<dim>(f);
        for (unsigned int i = 0; i < unit_points.size(); ++i)
          if (std::abs((unit_points[i] - corner) * normal) < 1e-12)
            face_dofs[f].push_back(i);
      }
  }



  namespace
  {
    /** Gauss on hypercubes, Witherden-Vincent (symmetric, positive
     * weights) on triangles, their product on wedges; @p n_through points
     * along the last axis (the thickness) of a 3D cell. */
    template <int dim>
    Quadrature<dim>
    gauss_rule(const ReferenceCell &shape,
               const unsigned int   n,
               const unsigned int   n_through)
    {
      if (shape.is_hyper_cube())
        {
          if constexpr (dim > 1)
            if (n_through != n)
              return Quadrature<dim>(QGauss<dim - 1>(n), QGauss<1>(n_through));
          return QGauss<dim>(n);
        }
      if (shape.is_simplex())
        return QWitherdenVincentSimplex<dim>(n);
      AssertThrow(dim == 3 && shape == ReferenceCells::Wedge,
                  ExcNotImplemented());
      const QWitherdenVincentSimplex<2> triangle(n);
      const QGauss<1>                   line(n_through);
      std::vector<Point<dim>>           points;
      std::vector<double>               weights;
      for (unsigned int k = 0; k < line.size(); ++k)
        for (unsigned int q = 0; q < triangle.size(); ++q)
          {
            Point<dim> p;
            p[0]       = triangle.point(q)[0];
            p[1]       = triangle.point(q)[1];
            p[dim - 1] = line.point(k)[0];
            points.push_back(p);
            weights.push_back(triangle.weight(q) * line.weight(k));
          }
      return Quadrature<dim>(points, weights);
    }
  } // namespace



  template <int dim>
  Quadrature<dim>
  TiedCopyDoFs<dim>::cell_quadrature(const unsigned int n_points_1d) const
  {
    return gauss_rule<dim>(shape, n_points_1d, n_points_1d);
  }



  template <int dim>
  Quadrature<dim>
  TiedCopyDoFs<dim>::cell_quadrature(const unsigned int n_points_1d,
                                     const unsigned int n_points_through) const
  {
    return gauss_rule<dim>(shape, n_points_1d, n_points_through);
  }



  template <int dim>
  hp::QCollection<dim - 1>
  TiedCopyDoFs<dim>::face_quadrature(const unsigned int n_points_1d) const
  {
    // One rule for faces that are all alike: MappingQ takes no more.
    if (shape.is_hyper_cube())
      return hp::QCollection<dim - 1>(QGauss<dim - 1>(n_points_1d));
    hp::QCollection<dim - 1> rules;
    for (unsigned int f = 0; f < shape.n_faces(); ++f)
      rules.push_back(gauss_rule<dim - 1>(shape.face_reference_cell(f),
                                          n_points_1d,
                                          n_points_1d));
    return rules;
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::distribute(const FaceFilter &released)
  {
    dof_handler.distribute_dofs(*fe);
    const unsigned int n_local = fe->n_dofs_per_cell();
    if (!mapping)
      {
        const auto ids    = dof_handler.get_triangulation().get_manifold_ids();
        const bool curved = std::any_of(ids.begin(), ids.end(), [](auto id) {
          return id != numbers::flat_manifold_id;
        });
        if (!shape.is_hyper_cube())
          {
            // P2 wedges on a hole (HoleEdgeManifold) get the isoparametric
            // map: MappingFE places its support points with the manifold.
            if constexpr (dim == 3)
              if (curved && fe->degree > 1)
                mapping = std::make_unique<MappingFE<dim>>(
                  FE_WedgeP<dim>(fe->degree));
            if (!mapping)
              mapping = get_linear_mapping().clone();
          }
        else
          mapping = curved && fe->degree > 1 ?
                      std::unique_ptr<Mapping<dim>>(
                        std::make_unique<MappingQ<dim>>(fe->degree)) :
                      std::make_unique<MappingQ1<dim>>();
      }

    // Real positions of all copies: copies are tied by position, so no
    // face-orientation logic is needed.
    copy_position.resize(dof_handler.n_dofs());
    FEValues<dim>                        fe_values(get_linear_mapping(),
                            *fe,
                            Quadrature<dim>(fe->get_unit_support_points()),
                            update_quadrature_points);
    std::vector<types::global_dof_index> local(n_local);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < n_local; ++i)
          copy_position[local[i]] = fe_values.quadrature_point(i);
      }

    parent.resize(dof_handler.n_dofs());
    for (types::global_dof_index i = 0; i < parent.size(); ++i)
      parent[i] = i;
    tie_faces(released);
    // A fine copy on a hanging face that sits on a node of the coarse
    // neighbour is that node (a union); the others interpolate the coarse
    // face (a constraint on the reduced numbering, built after numbering).
    hanging_ties.clear();
    hanging_copies.clear();
    for_each_hanging_copy(released, [&](const auto copy, const auto &weights) {
      if (weights.size() == 1)
        hanging_ties.emplace_back(copy, weights[0].first);
      else
        hanging_copies.emplace_back(copy, weights);
    });
    for (const auto &[fine, coarse] : hanging_ties)
      unite(parent, fine, coarse);
    index_copies(released);
    number_groups();
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::release(const std::vector<Face> &faces,
                             const FaceFilter        &released)
  {
    AssertThrow(released && !parent.empty()
                  && parent.size() == dof_handler.n_dofs()
                  && active_cells.size() == triangulation.n_active_cells(),
                ExcMessage("TiedCopyDoFs::release() needs a filter and the "
                           "mesh of the last distribute()"));
    // The groups of the copies on the new faces split (or not); all other
    // groups keep their copies.
    const unsigned int                   n_local = fe->n_dofs_per_cell();
    std::vector<types::global_dof_index> mine(n_local), theirs(n_local);
    std::vector<bool>                    affected(n_dofs(), false);
    for (const auto &[cell, f] : faces)
      {
        // A hanging face would change the hanging ties and constraints,
        // which release() keeps.
        AssertThrow(!cell->at_boundary(f) && cell->neighbor(f)->is_active()
                      && !cell->neighbor_is_coarser(f),
                    ExcMessage("TiedCopyDoFs::release() takes regular "
                               "interior faces only"));
        const auto neighbor = cell->neighbor(f);
        cell->get_dof_indices(mine);
        neighbor->get_dof_indices(theirs);
        for (const unsigned int i : face_dofs[f])
          affected[copy_to_reduced[mine[i]]] = true;
        for (const unsigned int i : face_dofs[cell->neighbor_of_neighbor(f)])
          affected[copy_to_reduced[theirs[i]]] = true;
        // Interface elements on the face couple the two cells.
        if (cell->is_locally_owned())
          relevant_copies.insert(relevant_copies.end(),
                                 theirs.begin(),
                                 theirs.end());
        if (neighbor->is_locally_owned())
          relevant_copies.insert(relevant_copies.end(),
                                 mine.begin(),
                                 mine.end());
      }
    std::vector<unsigned int> cells;
    for (types::global_dof_index c = 0; c < parent.size(); ++c)
      if (affected[copy_to_reduced[c]])
        {
          parent[c] = c;
          cells.push_back(copy_cell[c]);
        }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    // Tie the affected copies again across the faces that stay tied (from
    // both sides: a union is idempotent). A copy tied to an affected copy
    // was in its group, so it is affected too.
    for (const unsigned int index : cells)
      {
        const CellIterator &cell = active_cells[index];
        for (const unsigned int f : cell->face_indices())
          if (!cell->at_boundary(f) && !cell->neighbor_is_coarser(f)
              && !cell->neighbor(f)->has_children() && !released(cell, f))
            tie_face(cell, f, mine, theirs);
      }
    for (const auto &[fine, coarse] : hanging_ties)
      if (affected[copy_to_reduced[fine]])
        unite(parent, fine, coarse);
    number_groups();
  }



  template <int dim>
  template <typename Callback>
  void
  TiedCopyDoFs<dim>::for_each_hanging_copy(const FaceFilter &released,
                                           const Callback   &callback) const
  {
    const Mapping<dim>                  &mapping = get_linear_mapping();
    const unsigned int                   n_local = fe->n_dofs_per_cell();
    std::vector<types::global_dof_index> fine(n_local), coarse(n_local);
    HangingWeights                       weights;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          if (cell->at_boundary(f) || !cell->neighbor_is_coarser(f)
              || (released && released(cell, f)))
            continue;
          const auto neighbor = cell->neighbor(f);
          cell->get_dof_indices(fine);
          neighbor->get_dof_indices(coarse);
          for (const unsigned int i : face_dofs[f])
            {
              const unsigned int c = fe->system_to_component_index(i).first;
              const Point<dim>   unit
                = mapping.transform_real_to_unit_cell(neighbor,
                                                      copy_position[fine[i]]);
              weights.clear();
              for (unsigned int j = 0; j < n_local; ++j)
                if (fe->system_to_component_index(j).first == c)
                  {
                    const double w = fe->shape_value(j, unit);
                    if (std::abs(w) > 1e-10)
                      weights.emplace_back(coarse[j], w);
                  }
              if (weights.size() == 1)
                weights[0].second = 1;
              callback(fine[i], weights);
            }
        }
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::tie_face(const CellIterator                   &cell,
                              const unsigned int                    f,
                              std::vector<types::global_dof_index> &mine,
                              std::vector<types::global_dof_index> &theirs)
  {
    const auto         neighbor = cell->neighbor(f);
    const unsigned int nf       = cell->neighbor_of_neighbor(f);
    cell->get_dof_indices(mine);
    neighbor->get_dof_indices(theirs);
    const double tol = 1e-8 * cell->diameter();
    for (const unsigned int i : face_dofs[f])
      for (const unsigned int j : face_dofs[nf])
        if (fe->system_to_component_index(i).first
              == fe->system_to_component_index(j).first
            && copy_position[mine[i]].distance(copy_position[theirs[j]]) < tol)
          unite(parent, mine[i], theirs[j]);
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::tie_faces(const FaceFilter &released)
  {
    const unsigned int                   n_local = fe->n_dofs_per_cell();
    std::vector<types::global_dof_index> mine(n_local), theirs(n_local);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          if (cell->at_boundary(f))
            continue;
          // Hanging faces are tied by for_each_hanging_copy().
          if (cell->neighbor_is_coarser(f) || cell->neighbor(f)->has_children())
            continue;
          // Each conforming face once, from the cell with the lower index.
          if (cell->neighbor(f)->index() < cell->index()
              || (released && released(cell, f)))
            continue;
          tie_face(cell, f, mine, theirs);
        }
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::index_copies(const FaceFilter &released)
  {
    const MPI_Comm     comm    = triangulation.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int n_local = fe->n_dofs_per_cell();
    const unsigned int n_nodes = n_local / dim;

    // Cells rank by rank and, inside a cell, node by node: a group gets
    // its number at its first visit, so ranks own contiguous blocks and
    // the components of a node are consecutive.
    std::vector<std::vector<CellIterator>> cells_of_rank(n_ranks);
    active_cells.clear();
    copy_cell.resize(dof_handler.n_dofs());
    relevant_copies.clear();
    std::vector<types::global_dof_index> local(n_local);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cells_of_rank[n_ranks == 1 ? 0 : cell->subdomain_id()].push_back(cell);
        active_cells.push_back(cell);
        cell->get_dof_indices(local);
        for (const auto c : local)
          copy_cell[c] = cell->active_cell_index();
        if (!cell->is_locally_owned())
          continue;
        relevant_copies.insert(relevant_copies.end(),
                               local.begin(),
                               local.end());
        // Interface elements on a released face couple the cell with its
        // neighbour: this rank assembles into the neighbour's rows too.
        if (released)
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f) && !cell->neighbor(f)->has_children()
                && released(cell, f))
              {
                cell->neighbor(f)->get_dof_indices(local);
                relevant_copies.insert(relevant_copies.end(),
                                       local.begin(),
                                       local.end());
              }
      }
    visit_order.clear();
    rank_visits.assign(1, 0);
    for (unsigned int rank = 0; rank < n_ranks; ++rank)
      {
        for (const auto &cell : cells_of_rank[rank])
          {
            cell->get_dof_indices(local);
            for (unsigned int node = 0; node < n_nodes; ++node)
              for (unsigned int c = 0; c < dim; ++c)
                visit_order.push_back(
                  local[fe->component_to_system_index(c, node)]);
          }
        rank_visits.push_back(visit_order.size());
      }
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::number_groups()
  {
    const MPI_Comm     comm    = triangulation.get_communicator();
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const auto         invalid = numbers::invalid_dof_index;
    std::vector<types::global_dof_index> group_number(parent.size(), invalid);
    support_points.clear();
    components.clear();
    types::global_dof_index owned_begin = 0, owned_end = 0;
    for (unsigned int rank = 0; rank + 1 < rank_visits.size(); ++rank)
      {
        if (rank == my_rank)
          owned_begin = support_points.size();
        for (std::size_t v = rank_visits[rank]; v < rank_visits[rank + 1]; ++v)
          {
            const auto copy = visit_order[v];
            const auto root = find_root(parent, copy);
            if (group_number[root] != invalid)
              continue;
            group_number[root] = support_points.size();
            support_points.push_back(copy_position[copy]);
            // Every cell visits its nodes' dim components in turn.
            components.push_back(v % dim);
          }
        if (rank == my_rank)
          owned_end = support_points.size();
      }

    // Flat: every copy points at its root (release() resets groups).
    copy_to_reduced.resize(parent.size());
    for (types::global_dof_index c = 0; c < parent.size(); ++c)
      {
        parent[c]          = find_root(parent, c);
        copy_to_reduced[c] = group_number[parent[c]];
      }

    owned_dofs = IndexSet(n_dofs());
    owned_dofs.add_range(owned_begin, owned_end);
    std::vector<bool> relevant(n_dofs(), false);
    for (const auto c : relevant_copies)
      relevant[copy_to_reduced[c]] = true;
    for (auto i = owned_begin; i < owned_end; ++i)
      relevant[i] = true;

    hanging_constraints.clear();
    for (const auto &[copy, weights] : hanging_copies)
      {
        const auto line = copy_to_reduced[copy];
        if (hanging_constraints.is_constrained(line))
          continue;
        hanging_constraints.add_line(line);
        for (const auto &[coarse, weight] : weights)
          hanging_constraints.add_entry(line, copy_to_reduced[coarse], weight);
      }
    hanging_constraints.close();
    // The coarse dofs that a relevant hanging dof depends on are relevant
    // too: this rank writes into their rows.
    std::vector<types::global_dof_index> extra;
    for (const auto &line : hanging_constraints.get_lines())
      if (relevant[line.index])
        for (const auto &entry : line.entries)
          extra.push_back(entry.first);
    for (const auto i : extra)
      relevant[i] = true;
    std::vector<types::global_dof_index> indices;
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      if (relevant[i])
        indices.push_back(i);
    relevant_dofs = IndexSet(n_dofs());
    relevant_dofs.add_indices(indices.begin(), indices.end());
    relevant_dofs.compress();
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::get_dof_indices(
    const CellIterator                   &cell,
    std::vector<types::global_dof_index> &indices) const
  {
    cell->get_dof_indices(indices);
    for (auto &i : indices)
      i = copy_to_reduced[i];
  }



  template <int dim>
  std::vector<typename TiedCopyDoFs<dim>::CellIterator>
  TiedCopyDoFs<dim>::cells_with_owned_dofs() const
  {
    // One pass over the copies (the owned dofs are one range).
    std::vector<bool> has_owned(active_cells.size(), false);
    const auto        begin = owned_dofs.is_empty() ? 0 : *owned_dofs.begin();
    const auto        end   = begin + owned_dofs.n_elements();
    for (types::global_dof_index c = 0; c < copy_to_reduced.size(); ++c)
      if (copy_to_reduced[c] >= begin && copy_to_reduced[c] < end)
        has_owned[copy_cell[c]] = true;
    std::vector<CellIterator> cells;
    for (std::size_t i = 0; i < active_cells.size(); ++i)
      if (has_owned[i])
        cells.push_back(active_cells[i]);
    return cells;
  }



  template <int dim>
  std::size_t
  TiedCopyDoFs<dim>::memory_consumption() const
  {
    return dof_handler.memory_consumption()
           + hanging_constraints.memory_consumption()
           + copy_to_reduced.capacity() * sizeof(types::global_dof_index)
           + support_points.capacity() * sizeof(Point<dim>)
           + copy_position.capacity() * sizeof(Point<dim>)
           + (parent.capacity() + visit_order.capacity()
              + relevant_copies.capacity())
               * sizeof(types::global_dof_index)
           + copy_cell.capacity() * sizeof(unsigned int)
           + active_cells.capacity() * sizeof(CellIterator)
           + rank_visits.capacity() * sizeof(std::size_t)
           + hanging_ties.capacity() * 2 * sizeof(types::global_dof_index)
           + hanging_copies.capacity()
               * (sizeof(types::global_dof_index) + sizeof(HangingWeights))
           + components.capacity() + owned_dofs.memory_consumption()
           + relevant_dofs.memory_consumption();
  }

  template <int dim>
  std::vector<types::global_dof_index>
  TiedCopyDoFs<dim>::boundary_dofs(
    const types::boundary_id                                  boundary_id,
    const std::function<bool(const types::global_dof_index)> &select) const
  {
    std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
    std::vector<types::global_dof_index> found;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && cell->face(f)->boundary_id() == boundary_id)
          {
            get_dof_indices(cell, indices);
            for (const unsigned int i : face_dofs[f])
              found.push_back(indices[i]);
          }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    found.erase(std::remove_if(found.begin(),
                               found.end(),
                               [&](const auto dof) { return !select(dof); }),
                found.end());
    return found;
  }



  template <int dim>
  Vector<double>
  TiedCopyDoFs<dim>::replicate(const TrilinosWrappers::MPI::Vector &owned) const
  {
    Vector<double> local(n_dofs()), all(n_dofs());
    for (const auto i : owned_dofs)
      local[i] = owned[i];
    Utilities::MPI::sum(local, triangulation.get_communicator(), all);
    return all;
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::expand_all(const Vector<double> &replicated,
                                Vector<double>       &copies) const
  {
    copies.reinit(n_copies());
    for (types::global_dof_index c = 0; c < n_copies(); ++c)
      copies[c] = replicated[copy_to_reduced[c]];
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::gather(const Vector<double>          &copies,
                            TrilinosWrappers::MPI::Vector &reduced) const
  {
    const Vector<double>      sum = sums_over_copies(copies);
    std::vector<unsigned int> count(n_dofs(), 0);
    for (const auto r : copy_to_reduced)
      ++count[r];
    for (const auto i : owned_dofs)
      reduced[i] = sum[i] / count[i];
    reduced.compress(VectorOperation::insert);
  }



  template <int dim>
  Vector<double>
  TiedCopyDoFs<dim>::sums_over_copies(const Vector<double> &copies) const
  {
    Vector<double>                       sums(n_dofs());
    std::vector<types::global_dof_index> of_cell(fe->n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(of_cell);
        for (const auto copy : of_cell)
          sums[copy_to_reduced[copy]] += copies[copy];
      }
    return sums;
  }



  template class TiedCopyDoFs<2>;
  template class TiedCopyDoFs<3>;
} // namespace amfrac

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
  TiedCopyDoFs<dim>::distribute(const FaceFilter &released,
                                const bool        same_mesh)
  {
    // The copies of an unchanged mesh are numbered as before.
    if (!same_mesh || copy_position.size() != dof_handler.n_dofs()
        || copy_position.empty())
      {
        dof_handler.distribute_dofs(*fe);
        copy_position.clear();
      }
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
    if (copy_position.empty())
      {
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
      }

    std::vector<types::global_dof_index> parent(dof_handler.n_dofs());
    for (types::global_dof_index i = 0; i < parent.size(); ++i)
      parent[i] = i;
    tie_faces(released, copy_position, parent);
    // A fine copy on a hanging face that sits on a node of the coarse
    // neighbour is that node (a union); the others interpolate the coarse
    // face (a constraint on the reduced numbering, built after numbering).
    std::vector<std::pair<types::global_dof_index, HangingWeights>> hanging;
    for_each_hanging_copy(released,
                          copy_position,
                          [&](const auto copy, const auto &weights) {
                            if (weights.size() == 1)
                              unite(parent, copy, weights[0].first);
                            else
                              hanging.emplace_back(copy, weights);
                          });
    number_groups(parent, copy_position, released);

    hanging_constraints.clear();
    for (const auto &[copy, weights] : hanging)
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
      if (relevant_dofs.is_element(line.index))
        for (const auto &entry : line.entries)
          extra.push_back(entry.first);
    std::sort(extra.begin(), extra.end());
    extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
    relevant_dofs.add_indices(extra.begin(), extra.end());
    relevant_dofs.compress();
  }



  template <int dim>
  template <typename Callback>
  void
  TiedCopyDoFs<dim>::for_each_hanging_copy(
    const FaceFilter              &released,
    const std::vector<Point<dim>> &copy_position,
    const Callback                &callback) const
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
  TiedCopyDoFs<dim>::tie_faces(
    const FaceFilter                     &released,
    const std::vector<Point<dim>>        &copy_position,
    std::vector<types::global_dof_index> &parent) const
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
          const auto neighbor = cell->neighbor(f);
          // Each conforming face once, from the cell with the lower index.
          if (neighbor->index() < cell->index()
              || (released && released(cell, f)))
            continue;
          const unsigned int nf = cell->neighbor_of_neighbor(f);
          cell->get_dof_indices(mine);
          neighbor->get_dof_indices(theirs);
          const double tol = 1e-8 * cell->diameter();
          for (const unsigned int i : face_dofs[f])
            for (const unsigned int j : face_dofs[nf])
              if (fe->system_to_component_index(i).first
                    == fe->system_to_component_index(j).first
                  && copy_position[mine[i]].distance(copy_position[theirs[j]])
                       < tol)
                unite(parent, mine[i], theirs[j]);
        }
  }



  template <int dim>
  void
  TiedCopyDoFs<dim>::number_groups(std::vector<types::global_dof_index> &parent,
                                   const std::vector<Point<dim>> &copy_position,
                                   const FaceFilter              &released)
  {
    const MPI_Comm     comm    = triangulation.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_local = fe->n_dofs_per_cell();
    const unsigned int n_nodes = n_local / dim;

    // Visit the cells rank by rank and, inside a cell, node by node: a
    // group gets its number at its first visit, so ranks own contiguous
    // blocks and the components of a node are consecutive.
    std::vector<std::vector<CellIterator>> cells_of_rank(n_ranks);
    for (const auto &cell : dof_handler.active_cell_iterators())
      cells_of_rank[n_ranks == 1 ? 0 : cell->subdomain_id()].push_back(cell);

    const auto                           invalid = numbers::invalid_dof_index;
    std::vector<types::global_dof_index> group_number(parent.size(), invalid);
    std::vector<types::global_dof_index> local(n_local);
    support_points.clear();
    components.clear();
    types::global_dof_index owned_begin = 0, owned_end = 0;
    for (unsigned int rank = 0; rank < n_ranks; ++rank)
      {
        if (rank == my_rank)
          owned_begin = support_points.size();
        for (const auto &cell : cells_of_rank[rank])
          {
            cell->get_dof_indices(local);
            for (unsigned int node = 0; node < n_nodes; ++node)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const auto copy
                    = local[fe->component_to_system_index(c, node)];
                  const auto root = find_root(parent, copy);
                  if (group_number[root] != invalid)
                    continue;
                  group_number[root] = support_points.size();
                  support_points.push_back(copy_position[copy]);
                  components.push_back(c);
                }
          }
        if (rank == my_rank)
          owned_end = support_points.size();
      }

    copy_to_reduced.resize(parent.size());
    for (types::global_dof_index c = 0; c < parent.size(); ++c)
      copy_to_reduced[c] = group_number[find_root(parent, c)];

    owned_dofs = IndexSet(n_dofs());
    owned_dofs.add_range(owned_begin, owned_end);
    relevant_dofs = owned_dofs;
    std::vector<types::global_dof_index> relevant;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(local);
          for (const auto c : local)
            relevant.push_back(copy_to_reduced[c]);
          // Interface elements on a released face couple the cell with its
          // neighbour: this rank assembles into the neighbour's rows too.
          if (released)
            for (const unsigned int f : cell->face_indices())
              if (!cell->at_boundary(f) && !cell->neighbor(f)->has_children()
                  && released(cell, f))
                {
                  cell->neighbor(f)->get_dof_indices(local);
                  for (const auto c : local)
                    relevant.push_back(copy_to_reduced[c]);
                }
        }
    std::sort(relevant.begin(), relevant.end());
    relevant.erase(std::unique(relevant.begin(), relevant.end()),
                   relevant.end());
    relevant_dofs.add_indices(relevant.begin(), relevant.end());
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
    std::vector<CellIterator>            cells;
    std::vector<types::global_dof_index> local(fe->n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        if (std::any_of(local.begin(),
                        local.end(),
                        [&](const types::global_dof_index c) {
                          return owned_dofs.is_element(copy_to_reduced[c]);
                        }))
          cells.push_back(cell);
      }
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
    std::vector<double>       sum(n_dofs(), 0.);
    std::vector<unsigned int> count(n_dofs(), 0);
    for (types::global_dof_index c = 0; c < n_copies(); ++c)
      if (owned_dofs.is_element(copy_to_reduced[c]))
        {
          sum[copy_to_reduced[c]] += copies[c];
          ++count[copy_to_reduced[c]];
        }
    for (const auto i : owned_dofs)
      reduced[i] = sum[i] / count[i];
    reduced.compress(VectorOperation::insert);
  }



  template class TiedCopyDoFs<2>;
  template class TiedCopyDoFs<3>;
} // namespace amfrac

// Global remeshing of the cohesive interfaces: the history of the old
// mesh's interface points carried to the points of an unrelated new mesh
// by their positions on the interface surface (the seed's tau_1 for the
// interfaces, with a rule that never lowers damage).
#include <amfrac/base/point_order.h>
#include <amfrac/cohesive/interface_assembler.h>
#include <boost/geometry/index/rtree.hpp>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/rtree.h>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace amfrac
{
  namespace
  {
    namespace bgi = boost::geometry::index;

    /** Whether @p p lies in the planar face with vertices @p v (deal.II's
     * order: a triangle, or a quadrilateral as two triangles), to a
     * tolerance relative to the face's size. */
    template <int dim>
    bool
    in_face(const Point<dim> &p, const std::vector<Point<dim>> &v)
    {
      const auto in_triangle
        = [&](const Point<dim> &a, const Point<dim> &b, const Point<dim> &c) {
            const Tensor<1, dim> e1 = b - a, e2 = c - a, d = p - a;
            const double         g11 = e1 * e1, g12 = e1 * e2, g22 = e2 * e2;
            const double         det = g11 * g22 - g12 * g12;
            const double         r1 = d * e1, r2 = d * e2;
            const double         s         = (g22 * r1 - g12 * r2) / det;
            const double         t         = (g11 * r2 - g12 * r1) / det;
            const double         tolerance = 1e-10;
            const double         off       = (d - s * e1 - t * e2).norm();
            return s >= -tolerance && t >= -tolerance && s + t <= 1 + tolerance
                   && off <= tolerance * std::sqrt(g11 + g22);
          };
      if (v.size() == 3)
        return in_triangle(v[0], v[1], v[2]);
      return in_triangle(v[0], v[1], v[3]) || in_triangle(v[0], v[3], v[2]);
    }
  } // namespace



  template <int dim>
  typename CohesiveInterfaces<dim>::TransferReport
  CohesiveInterfaces<dim>::relocate(const Snapshot           &old,
                                    const Triangulation<dim> &mesh,
                                    const Vector             &solution,
                                    const MPI_Comm            comm)
  {
    AssertThrow(dim == 3, ExcNotImplemented());

    // The old points of each interface in a tree of their positions (all,
    // and those outside the pre-crack), and the energy each interface
    // dissipated. Every rank has all of them, in the same order.
    struct Source
    {
      const typename Snapshot::Face *face;
      unsigned int                   q;
      const Point<dim> &
      position() const
      {
        return face->points[q];
      }
      bool
      pre_crack() const
      {
        return face->pre_crack[q] != 0;
      }
    };
    using Entry = std::pair<Point<dim>, unsigned int>;
    const unsigned int              n_groups = data.interfaces.size() + 1;
    std::vector<Source>             sources;
    std::vector<std::vector<Entry>> all(n_groups), grown(n_groups);
    std::vector<double>             old_totals(3 * n_groups);
    for (const auto &face : old.faces)
      for (unsigned int q = 0; q < face.points.size(); ++q)
        {
          const Entry entry(face.points[q], sources.size());
          all[face.interface].push_back(entry);
          if (!face.pre_crack[q])
            grown[face.interface].push_back(entry);
          sources.push_back({&face, q});
          const auto densities = dissipated_densities(
            unpack(face.states.data() + q * state_size()));
          for (unsigned int k = 0; k < 3; ++k)
            old_totals[3 * face.interface + k] += face.JxW[q] * densities[k];
        }
    std::vector<RTree<Entry>> trees, grown_trees;
    for (unsigned int k = 0; k < n_groups; ++k)
      {
        trees.push_back(pack_rtree(all[k]));
        grown_trees.push_back(pack_rtree(grown[k]));
      }
    // The same verdict on every rank (a throw on some would leave the
    // others waiting in the collective calls below).
    unsigned int without_old = 0;
    for (const Element &element : elements)
      without_old += trees[element.interface].empty();
    AssertThrow(Utilities::MPI::sum(without_old, comm) == 0,
                ExcMessage("remeshing: an interface of the new mesh has no "
                           "point on the old one"));

    // The nearest of @p tree's points to x; equally near ones (within
    // round-off of @p size) are told apart by position, then by their
    // place in the snapshot, which is the same for any number of ranks.
    // All points that near are marked as taken (the nodal rule puts a
    // point of every face around an old node on it).
    std::vector<unsigned int> taken(sources.size(), 0); // 0/1 for MPI::max
    const auto                nearest
      = [&](const RTree<Entry> &tree, const Point<dim> &x, const double size) {
          std::vector<Entry> first;
          tree.query(bgi::nearest(x, 1), std::back_inserter(first));
          const double     reach = x.distance(first[0].first) + 1e-12 * size;
          BoundingBox<dim> ball({x, x});
          ball.extend(reach);
          std::vector<Entry> around;
          tree.query(bgi::intersects(ball), std::back_inserter(around));
          unsigned int best = first[0].second;
          for (const auto &[p, j] : around)
            if (x.distance(p) <= reach)
              {
                taken[j]            = 1;
                const Point<dim> &b = sources[best].position();
                if (lexicographically_less(p, b)
                    || (!lexicographically_less(b, p) && j < best))
                  best = j;
              }
          return best;
        };

    // Per new point, its sources: first the nearest old point, whose state
    // is the old field's (piecewise constant around the old points) at the
    // new point. The pre-crack is input, which setup() has seeded on the
    // new mesh exactly: a point outside it takes the nearest old point
    // outside it, so that the old mesh's coarser outline of the pre-crack
    // neither lengthens it nor heals a delamination grown from it.
    std::vector<std::vector<std::vector<unsigned int>>> from(elements.size());
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        const Element &element = elements[e];
        const double   size    = std::sqrt(
          std::accumulate(element.JxW.begin(), element.JxW.end(), 0.));
        for (unsigned int q = 0; q < element.points.size(); ++q)
          {
            const bool outside = !element.pre_crack[q]
                                 && !grown_trees[element.interface].empty();
            from[e].push_back(
              {nearest(outside ? grown_trees[element.interface] :
                                 trees[element.interface],
                       element.points[q],
                       size)});
          }
      }
    Utilities::MPI::max(taken, comm, taken);
    place_left_over(mesh, sources, taken, from, comm);

    TransferReport report;
    for (const auto &points : from)
      for (const auto &list : points)
        (list.size() == 1 ? report.injected : report.aggregated) += 1;

    // The most damaged source's state, the sources' mean densities.
    std::vector<std::vector<PointState>> carried(elements.size());
    std::vector<double>                  new_totals(3 * n_groups);
    for (unsigned int e = 0; e < elements.size(); ++e)
      for (unsigned int q = 0; q < elements[e].points.size(); ++q)
        {
          PointState            merged;
          double                worst = -1, weight = 0;
          std::array<double, 3> density{};
          // (from[e][q] is sorted: equally damaged sources, which have the
          // same state in practice, are taken in the snapshot's order.)
          for (const unsigned int j : from[e][q])
            {
              const Source    &source = sources[j];
              const PointState s
                = unpack(source.face->states.data() + source.q * state_size());
              const double w = source.face->JxW[source.q];
              const auto   d = dissipated_densities(s);
              for (unsigned int k = 0; k < 3; ++k)
                density[k] += w * d[k];
              weight += w;
              const double rank = (s.history.debonded ? 2. : 0.) + damage(s);
              if (rank > worst)
                {
                  worst  = rank;
                  merged = s;
                }
            }
          for (unsigned int k = 0; k < 3; ++k)
            {
              density[k] /= weight;
              new_totals[3 * elements[e].interface + k]
                += elements[e].JxW[q] * density[k];
            }
          merged.bond_work     = density[0];
          merged.friction_work = density[1];
          merged.viscous_work  = density[2];
          carried[e].push_back(merged);
        }

    // The dissipated energies exactly: the means above keep them only to
    // the difference of the two meshes' quadratures (a few per cent). A
    // total that changed by more than a factor 2 is round-off of the law
    // (bonded points' works less their stored energies, positive and
    // negative cancelling), which is left as the means give it.
    Utilities::MPI::sum(new_totals, comm, new_totals);
    for (unsigned int e = 0; e < elements.size(); ++e)
      for (auto &state : carried[e])
        {
          const unsigned int group = 3 * elements[e].interface;
          double            *works[3]
            = {&state.bond_work, &state.friction_work, &state.viscous_work};
          for (unsigned int k = 0; k < 3; ++k)
            {
              const double ratio
                = new_totals[group + k] != 0 ?
                    old_totals[group + k] / new_totals[group + k] :
                    0;
              if (ratio >= 0.5 && ratio <= 2)
                *works[k] *= ratio;
            }
        }

    finish_transfer(
      [&](Element &element) {
        element.converged = std::move(carried[&element - elements.data()]);
      },
      solution,
      comm,
      report);
    return report;
  }



  template <int dim>
  template <typename Source>
  void
  CohesiveInterfaces<dim>::place_left_over(
    const Triangulation<dim>                            &mesh,
    const std::vector<Source>                           &sources,
    const std::vector<unsigned int>                     &taken,
    std::vector<std::vector<std::vector<unsigned int>>> &from,
    const MPI_Comm                                       comm) const
  {
    // An old point nearest to no new point (where the new mesh is coarser)
    // joins the nearest point outside the pre-crack of the new face it
    // lies in, so that its damage is not lost. Not the pre-crack's: input.
    using Entry = std::pair<Point<dim>, unsigned int>;
    std::vector<std::vector<Entry>> left_over(data.interfaces.size() + 1);
    std::vector<unsigned int>       placed(sources.size(), 1);
    for (unsigned int j = 0; j < sources.size(); ++j)
      if (taken[j] == 0 && !sources[j].pre_crack())
        {
          left_over[sources[j].face->interface].emplace_back(
            sources[j].position(), j);
          placed[j] = 0;
        }
    std::vector<RTree<Entry>> trees;
    for (const auto &list : left_over)
      trees.push_back(pack_rtree(list));
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        const Element &element = elements[e];
        const auto     face
          = mesh.create_cell_iterator(element.cell)->face(element.face);
        std::vector<Point<dim>> vertices;
        for (const unsigned int v : face->vertex_indices())
          vertices.push_back(face->vertex(v));
        BoundingBox<dim> box(vertices);
        box.extend(1e-10 * face->diameter());
        std::vector<Entry> inside;
        trees[element.interface].query(bgi::intersects(box),
                                       std::back_inserter(inside));
        for (const auto &[p, j] : inside)
          if (in_face(p, vertices))
            if (const auto q = nearest_outside(element, p))
              {
                from[e][*q].push_back(j);
                placed[j] = 1;
              }
      }

    // One that lies in no new face (a curved boundary meshed twice
    // differently): the nearest new point outside the pre-crack of any
    // rank, the lowest rank among equally near ones.
    Utilities::MPI::max(placed, comm, placed);
    std::vector<unsigned int> unplaced;
    for (unsigned int j = 0; j < sources.size(); ++j)
      if (!placed[j])
        unplaced.push_back(j);
    std::vector<double>                                distance(unplaced.size(),
                                 std::numeric_limits<double>::max());
    std::vector<std::pair<unsigned int, unsigned int>> point(unplaced.size());
    for (unsigned int i = 0; i < unplaced.size(); ++i)
      for (unsigned int e = 0; e < elements.size(); ++e)
        if (elements[e].interface == sources[unplaced[i]].face->interface)
          if (const auto q
              = nearest_outside(elements[e], sources[unplaced[i]].position()))
            {
              const double d = sources[unplaced[i]].position().distance(
                elements[e].points[*q]);
              if (d < distance[i])
                distance[i] = d, point[i] = {e, *q};
            }
    std::vector<double> best(unplaced.size());
    Utilities::MPI::min(distance, comm, best);
    const unsigned int        rank = Utilities::MPI::this_mpi_process(comm);
    std::vector<unsigned int> owner(unplaced.size());
    for (unsigned int i = 0; i < unplaced.size(); ++i)
      owner[i] = distance[i] == best[i] ? rank : numbers::invalid_unsigned_int;
    Utilities::MPI::min(owner, comm, owner);
    for (unsigned int i = 0; i < unplaced.size(); ++i)
      if (owner[i] == rank && distance[i] < std::numeric_limits<double>::max())
        from[point[i].first][point[i].second].push_back(unplaced[i]);

    for (auto &points : from)
      for (auto &list : points)
        {
          std::sort(list.begin(), list.end());
          list.erase(std::unique(list.begin(), list.end()), list.end());
        }
  }



  template <int dim>
  std::optional<unsigned int>
  CohesiveInterfaces<dim>::nearest_outside(const Element    &element,
                                           const Point<dim> &p) const
  {
    std::optional<unsigned int> nearest;
    for (unsigned int q = 0; q < element.points.size(); ++q)
      if (!element.pre_crack[q]
          && (!nearest
              || p.distance(element.points[q])
                   < p.distance(element.points[*nearest])))
        nearest = q;
    return nearest;
  }

  template typename CohesiveInterfaces<2>::TransferReport
  CohesiveInterfaces<2>::relocate(const Snapshot &,
                                  const Triangulation<2> &,
                                  const Vector &,
                                  const MPI_Comm);
  template typename CohesiveInterfaces<3>::TransferReport
  CohesiveInterfaces<3>::relocate(const Snapshot &,
                                  const Triangulation<3> &,
                                  const Vector &,
                                  const MPI_Comm);
} // namespace amfrac

#pragma once

// Two orthotropic plies (+30 / -30 degrees) on 2 x 1 (x 1) cells each,
// the nodes on their interface duplicated: the small mesh of the unit tests
// of the total Lagrangian plies and of the interfaces that follow them.

#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/orthotropic.h>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>
#include <map>
#include <memory>
#include <vector>

namespace amfrac_test
{
  using namespace dealii;
  using namespace amfrac;

  /** The carbon/epoxy of the two plies (MPa). */
  inline ElasticConstants
  ply_material()
  {
    ElasticConstants c;
    c.E1 = 135000, c.E2 = c.E3 = 10000;
    c.G12 = c.G13 = 5000, c.G23 = 3500;
    c.nu12 = c.nu13 = 0.3, c.nu23 = 0.4;
    return c;
  }

  inline SymmetricTensor<4, 3>
  ply_stiffness(const double angle)
  {
    return rotate(stiffness_in_material_axes(ply_material()),
                  ply_rotation(angle));
  }

  /** A ply at @p angle of ply_stiffness()'s material with strengths,
   * Hoffman plasticity with hardening if @p plastic. */
  template <int dim>
  PlyProperties<dim>
  plastic_ply(const double angle, const bool plastic)
  {
    PlyProperties<dim> p;
    p.rotation = ply_rotation(angle);
    p.stiffness_3d
      = rotate(stiffness_in_material_axes(ply_material()), p.rotation);
    p.stiffness    = restrict_to_model<dim>(p.stiffness_3d);
    p.strengths.Xt = 1500, p.strengths.Xc = 1200;
    p.strengths.Yt = 50, p.strengths.Yc = 200;
    p.strengths.Zt = 45, p.strengths.Zc = 180;
    p.strengths.S12 = 70, p.strengths.S13 = 75, p.strengths.S23 = 40;
    p.density   = 1.6e-9;
    p.plastic   = plastic;
    p.hardening = 2;
    return p;
  }

  /** The 3D stiffness restricted to the (x, z) plane for dim = 2 (plane
   * strain of the cross-section), unchanged for dim = 3. */
  template <int dim>
  SymmetricTensor<4, dim> restrict(const SymmetricTensor<4, 3> &C)
  {
    SymmetricTensor<4, dim> r;
    const unsigned int      axis[3] = {0, dim == 2 ? 2u : 1u, 2};
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            r[i][j][k][l] = C[axis[i]][axis[j]][axis[k]][axis[l]];
    return r;
  }

  /** Two plies (+30 / -30 degrees, elastic, or @p given) on 2 x 1 (x 1)
   * cells each, the nodes on their interface duplicated. */
  template <int dim>
  struct TwoPlies
  {
    Triangulation<dim>                 tria;
    std::vector<PlyProperties<dim>>    plies;
    std::unique_ptr<TiedCopyDoFs<dim>> dofs;

    explicit TwoPlies(const unsigned int                     degree,
                      const std::vector<PlyProperties<dim>> &given = {})
      : plies(given)
    {
      std::vector<unsigned int> cells(dim, 1);
      cells[0]       = 2;
      cells[dim - 1] = 2;
      Point<dim> top;
      for (unsigned int d = 0; d < dim; ++d)
        top[d] = 1;
      top[0] = 2;
      GridGenerator::subdivided_hyper_rectangle(tria, cells, Point<dim>(), top);
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(cell->center()[dim - 1] > 0.5 ? 1 : 0);
      for (const double angle : {30., -30.})
        if (given.empty())
          {
            PlyProperties<dim> ply;
            ply.stiffness = restrict<dim>(ply_stiffness(angle));
            ply.density   = 1.6e-9;
            plies.push_back(ply);
          }
      dofs = std::make_unique<TiedCopyDoFs<dim>>(tria, degree);
      dofs->distribute([](const auto &cell, const unsigned int f) {
        return std::abs(cell->face(f)->center()[dim - 1] - 0.5) < 1e-12;
      });
    }
  };

  /** @p u with the locally relevant entries of @p dofs. */
  template <int dim>
  TrilinosWrappers::MPI::Vector
  ghosted(const TiedCopyDoFs<dim> &dofs, const TrilinosWrappers::MPI::Vector &u)
  {
    TrilinosWrappers::MPI::Vector relevant(dofs.locally_owned_dofs(),
                                           dofs.locally_relevant_dofs(),
                                           MPI_COMM_WORLD);
    relevant = u;
    return relevant;
  }

  /** A zero vector of @p dofs whose ghost entries can be added to. */
  template <int dim>
  TrilinosWrappers::MPI::Vector
  writable_ghosts(const TiedCopyDoFs<dim> &dofs)
  {
    TrilinosWrappers::MPI::Vector result;
    result.reinit(dofs.locally_owned_dofs(),
                  dofs.locally_relevant_dofs(),
                  MPI_COMM_WORLD,
                  true);
    return result;
  }

  /** The dofs of each node (one entry per component), and the ply of
   * the node (the interface's nodes are duplicated: one copy per ply). */
  template <int dim>
  std::map<std::array<types::global_dof_index, dim>, unsigned int>
  nodes(const TiedCopyDoFs<dim> &dofs)
  {
    std::map<std::array<types::global_dof_index, dim>, unsigned int> result;
    const auto                          &fe = dofs.get_fe();
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      {
        cell->get_dof_indices(local);
        std::map<unsigned int, std::array<types::global_dof_index, dim>> node;
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const auto [c, n] = fe.system_to_component_index(i);
            node[n][c]        = dofs.reduced_index(local[i]);
          }
        for (const auto &[n, indices] : node)
          result[indices] = cell->material_id();
      }
    return result;
  }

  /** A vector of nodal values @p value(X, ply). */
  template <int dim, typename Function>
  TrilinosWrappers::MPI::Vector
  nodal_vector(const TiedCopyDoFs<dim> &dofs, const Function &value)
  {
    TrilinosWrappers::MPI::Vector result(dofs.locally_owned_dofs(),
                                         MPI_COMM_WORLD);
    for (const auto &[indices, ply] : nodes(dofs))
      {
        const Point<dim>     X = dofs.support_point(indices[0]);
        const Tensor<1, dim> v = value(X, ply);
        for (unsigned int c = 0; c < dim; ++c)
          result(indices[c]) = v[c];
      }
    result.compress(VectorOperation::insert);
    return result;
  }

  /** The rotation by @p angle about y in 3D (in the x-z plane, as the 2D
   * cross-section). */
  template <int dim>
  Tensor<2, dim>
  rotation(const double angle)
  {
    Tensor<2, dim>     R = unit_symmetric_tensor<dim>();
    const unsigned int z = dim - 1;
    R[0][0]              = std::cos(angle);
    R[0][z]              = -std::sin(angle);
    R[z][0]              = std::sin(angle);
    R[z][z]              = std::cos(angle);
    return R;
  }
} // namespace amfrac_test

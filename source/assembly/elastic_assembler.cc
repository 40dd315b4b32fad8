#include <algorithm>
#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/assembly/shape_key.h>
#include <amfrac/base/first_failure.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace amfrac
{
  namespace
  {
    /** f(i) += values(k) for the owned entries i = indices[k] only. Summed
     * over TiedCopyDoFs::cells_with_owned_dofs() this gives every owned
     * entry the same sum, term by term, on any number of ranks (no
     * partial sums of other ranks are added in compress()). */
    void
    add_owned(const std::vector<types::global_dof_index> &indices,
              const dealii::Vector<double>               &values,
              TrilinosWrappers::MPI::Vector              &f)
    {
      // The owned dofs of the copy layer are one contiguous block.
      const auto [begin, end] = f.local_range();
      for (unsigned int k = 0; k < indices.size(); ++k)
        if (indices[k] >= begin && indices[k] < end)
          f(indices[k]) += values(k);
    }



    /** Adds to @p f the forces of the patch loads on @p face of @p cell at
     * time @p t: nodal forces per unit force, from prepare_patch(). */
    template <int dim, typename CellIterator>
    void
    add_patch_forces(const Loads<dim>       &loads,
                     const CellIterator     &cell,
                     const unsigned int      face,
                     const double            t,
                     dealii::Vector<double> &f)
    {
      for (const auto &patch : loads.patches)
        {
          const auto found
            = patch.unit_nodal_forces.find({cell->active_cell_index(), face});
          if (found == patch.unit_nodal_forces.end())
            continue;
          patch.force->set_time(t);
          f.add(patch.force->value(Point<dim>()), found->second);
        }
    }



    /** Rules fine enough to find where a patch edge crosses a face: 2 x 2
     * Gauss points on 16 x 16 sub-squares of a quadrilateral, 3 points on
     * 16 x 16 sub-triangles of a triangle (one rule for hypercube cells,
     * one per face of a wedge). */
    template <int dim>
    hp::QCollection<dim - 1>
    patch_face_rules(const ReferenceCell &shape)
    {
      const QIterated<dim - 1> squares(QGauss<1>(2), 16);
      if (shape.is_hyper_cube())
        return hp::QCollection<dim - 1>(squares);
      hp::QCollection<dim - 1> rules;
      if constexpr (dim == 3)
        for (unsigned int f = 0; f < shape.n_faces(); ++f)
          {
            if (shape.face_reference_cell(f) == ReferenceCells::Triangle)
              rules.push_back(QIteratedSimplex<2>(QGaussSimplex<2>(2), 16));
            else
              rules.push_back(squares);
          }
      else
        throw std::logic_error("patch loads: 2D cells are squares");
      return rules;
    }
  } // namespace


  /** FEValues objects and work arrays reused from cell to cell. */
  template <int dim>
  class ElasticAssembler<dim>::Scratch
  {
  public:
    /** Gauss rules with @p n_points points per direction on the cells
     * and faces of @p dofs (hexahedra or wedges). */
    Scratch(const TiedCopyDoFs<dim> &dofs, const unsigned int n_points)
      : fe_values(dofs.get_mapping(),
                  dofs.get_fe(),
                  dofs.cell_quadrature(n_points),
                  update_values | update_gradients | update_quadrature_points
                    | update_JxW_values)
      , face_values(dofs.get_mapping(),
                    dofs.get_fe(),
                    dofs.face_quadrature(n_points),
                    update_values | update_quadrature_points
                      | update_normal_vectors | update_JxW_values)
      , strains(dofs.get_fe().n_dofs_per_cell())
      , stresses(dofs.get_fe().n_dofs_per_cell())
    {}

    FEValues<dim>                        fe_values;
    FEFaceValues<dim>                    face_values;
    std::vector<SymmetricTensor<2, dim>> strains;
    std::vector<SymmetricTensor<2, dim>> stresses;
    const FEValuesExtractors::Vector     displacement{0};
  };



  /**
   * The element stiffness matrices of the mesh's cells, shared by the
   * cells of one shape (shape_key: ply, size and vertex offsets), each
   * computed once from the shape's first cell, the same cell on every rank
   * (so the matrices do not depend on the partition). On a structured
   * laminate a handful of matrices serve every cell: a static run
   * assembles its bulk matrices after every crack insertion, and K_e by
   * quadrature for every cell was 43 % of that set-up on the 3D bar of
   * doc/benchmarks section 11. A mesh whose cells mostly differ (a
   * distorted one) computes each cell's own, as before.
   */
  template <int dim>
  class ElasticAssembler<dim>::SharedStiffness
  {
  public:
    explicit SharedStiffness(const ElasticAssembler<dim> &assembler)
      : assembler(assembler)
      , scratch(assembler.dofs, assembler.quadrature_degree)
      , shapes(sort_into_shapes(
          assembler.dofs.copy_handler(),
          assembler.dofs.get_fe().degree > 1,
          assembler.dofs.copy_handler().get_triangulation().n_active_cells()
            / 4))
      , own(assembler.dofs.get_fe().n_dofs_per_cell(),
            assembler.dofs.get_fe().n_dofs_per_cell())
    {
      shared.resize(shapes.first_cell.size());
    }

    /** K_e of @p cell (valid until the next call). */
    const FullMatrix<double> &
    operator()(const typename TiedCopyDoFs<dim>::CellIterator &cell)
    {
      if (shared.empty())
        return compute(cell, own);
      const unsigned int shape
        = shapes.shape_of_cell[cell->active_cell_index()];
      FullMatrix<double> &K = shared[shape];
      if (K.m() == 0)
        {
          K.reinit(own.m(), own.n());
          compute(shapes.first_cell[shape], K);
        }
      return K;
    }

  private:
    const FullMatrix<double> &
    compute(const typename TiedCopyDoFs<dim>::CellIterator &cell,
            FullMatrix<double>                             &K)
    {
      scratch.fe_values.reinit(cell);
      assembler.cell_matrix(scratch, cell->material_id(), K);
      return K;
    }

    const ElasticAssembler<dim>    &assembler;
    Scratch                         scratch;
    const CellShapes<dim>           shapes;
    FullMatrix<double>              own;
    std::vector<FullMatrix<double>> shared;
  };



  template <int dim>
  ElasticAssembler<dim>::ElasticAssembler(
    const TiedCopyDoFs<dim>               &dofs,
    const std::vector<PlyProperties<dim>> &plies)
    : dofs(dofs)
    , plies(plies)
    , quadrature_degree(dofs.get_fe().degree + 1)
  {}



  template <int dim>
  void
  ElasticAssembler<dim>::reinit_matrix(
    const AffineConstraints<double> &constraints,
    Matrix                          &matrix) const
  {
    const MPI_Comm comm
      = dofs.copy_handler().get_triangulation().get_communicator();
    TrilinosWrappers::SparsityPattern pattern(dofs.locally_owned_dofs(),
                                              dofs.locally_owned_dofs(),
                                              dofs.locally_relevant_dofs(),
                                              comm);
    add_couplings(constraints, pattern);
    pattern.compress();
    matrix.reinit(pattern);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::add_couplings(
    const AffineConstraints<double>   &constraints,
    TrilinosWrappers::SparsityPattern &pattern) const
  {
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dofs.get_dof_indices(cell, indices);
          constraints.add_entries_local_to_global(indices, pattern, false);
        }
  }



  template <int dim>
  void
  ElasticAssembler<dim>::prepare_patch(PatchLoad<dim> &patch) const
  {
    const auto &fe = dofs.get_fe();
    // The patch edge cuts a face to within a 16th of its size (a 32nd on
    // quadrilaterals); the normalization below makes the total exact.
    FEFaceValues<dim>      fv(dofs.get_mapping(),
                         fe,
                         patch_face_rules<dim>(dofs.reference_cell()),
                         update_values | update_quadrature_points
                           | update_normal_vectors | update_JxW_values);
    dealii::Vector<double> f(fe.n_dofs_per_cell());
    double                 area = 0;
    patch.unit_nodal_forces.clear();
    // Every rank visits every cell of the replicated mesh, in mesh order:
    // a patch face of another rank's cell may load this rank's nodes
    // (assemble_load() keeps owned entries only), and the area is then
    // the same sum on any number of ranks.
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      for (const unsigned int face : cell->face_indices())
        {
          if (!cell->at_boundary(face)
              || cell->face(face)->boundary_id() != patch.boundary_id)
            continue;
          // Faces far from the patch (measured in the face plane: the
          // center's normal coordinate is ignored) are skipped.
          const auto geometry         = cell->face(face);
          Point<dim> in_plane         = geometry->center();
          in_plane[patch.normal_axis] = patch.center[patch.normal_axis];
          if (in_plane.distance(patch.center)
              > patch.reach() + geometry->diameter())
            continue;
          fv.reinit(cell, face);
          f             = 0;
          double inside = 0;
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              if (!patch.inside(fv.quadrature_point(q)))
                continue;
              inside += fv.JxW(q);
              const Tensor<1, dim> direction = patch.direction.norm() > 0 ?
                                                 patch.direction :
                                                 -fv.normal_vector(q);
              for (const unsigned int i : dofs.dofs_on_face(face))
                f(i) += fv.shape_value(i, q)
                        * direction[fe.system_to_component_index(i).first]
                        * fv.JxW(q);
            }
          if (inside > 0)
            {
              area += inside;
              patch.unit_nodal_forces[{cell->active_cell_index(), face}] = f;
            }
        }
    if (!(area > 0))
      throw InputError("Boundary conditions/Patch load/Center",
                       "the patch covers no part of its face");
    for (auto &[key, forces] : patch.unit_nodal_forces)
      forces /= area;
  }



  template <int dim>
  typename ElasticAssembler<dim>::CellList
  ElasticAssembler<dim>::loaded_cells(const Loads<dim> &loads) const
  {
    CellList cells;
    for (const auto &cell : dofs.cells_with_owned_dofs())
      {
        bool loaded = loads.body_force != nullptr;
        for (const unsigned int face : cell->face_indices())
          {
            if (!cell->at_boundary(face))
              continue;
            const auto id = cell->face(face)->boundary_id();
            loaded        = loaded || loads.tractions.count(id) > 0
                     || loads.pressures.count(id) > 0;
            // A patch loads only the faces it covers.
            for (const auto &patch : loads.patches)
              loaded = loaded
                       || patch.unit_nodal_forces.count(
                            {cell->active_cell_index(), face})
                            > 0;
          }
        if (loaded)
          cells.push_back(cell);
      }
    return cells;
  }



  template <int dim>
  void
  ElasticAssembler<dim>::assemble_load(const Loads<dim> &loads,
                                       const double      t,
                                       Vector           &f) const
  {
    assemble_load(loads, t, loaded_cells(loads), f);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::check_load_finite(const bool        finite,
                                           const Point<dim> &where,
                                           const double      t) const
  {
    const MPI_Comm comm
      = dofs.copy_handler().get_triangulation().get_communicator();
    std::string mine;
    if (!finite)
      {
        std::ostringstream message;
        message << "a load (Boundary conditions: Patch load, Traction, "
                   "Pressure or Body force) is not finite (NaN or inf) at t="
                << t << " near (" << where
                << "): look for an expression that is not defined there (a "
                   "sqrt or log of a negative number, a division by zero)";
        mine = message.str();
      }
    // Every rank throws the first rank's message (rank 0 prints it).
    throw_first_failure<NonFiniteValue>(comm, mine);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::assemble_load(const Loads<dim> &loads,
                                       const double      t,
                                       const CellList   &cells,
                                       Vector           &f) const
  {
    f                                      = 0;
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    dealii::Vector<double>               cell_f(n);
    std::vector<types::global_dof_index> indices(n);
    // Patch loads are stored nodal forces and need no FEValues, whose
    // set-up on wedges costs several force evaluations: an explicit run
    // assembles the load every step.
    std::optional<Scratch> scratch;
    if (loads.body_force || !loads.tractions.empty()
        || !loads.pressures.empty())
      scratch.emplace(dofs, quadrature_degree);
    // A load expression that is not defined at t (a sqrt of a negative
    // number) must stop the run with its name, on every rank together.
    bool       finite = true;
    Point<dim> where;
    for (const auto &cell : cells)
      {
        dofs.get_dof_indices(cell, indices);
        if (scratch)
          {
            if (loads.body_force)
              scratch->fe_values.reinit(cell);
            cell_load(*scratch, cell, loads, t, cell_f);
          }
        else
          {
            cell_f = 0;
            for (const unsigned int face : cell->face_indices())
              if (cell->at_boundary(face))
                add_patch_forces(loads, cell, face, t, cell_f);
          }
        if (std::all_of(cell_f.begin(), cell_f.end(), [](const double v) {
              return std::isfinite(v);
            }))
          add_owned(indices, cell_f, f);
        else if (finite)
          finite = false, where = cell->center();
      }
    f.compress(VectorOperation::add);
    check_load_finite(finite, where, t);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::cell_matrix(Scratch            &scratch,
                                     const unsigned int  ply,
                                     FullMatrix<double> &K) const
  {
    const auto        &C         = plies[ply].stiffness;
    const auto        &fe_values = scratch.fe_values;
    const unsigned int n         = K.m();
    K                            = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            scratch.strains[i]
              = fe_values[scratch.displacement].symmetric_gradient(i, q);
            scratch.stresses[i] = C * scratch.strains[i] * JxW;
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            K(i, j) += scratch.stresses[i] * scratch.strains[j];
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        K(i, j) = K(j, i);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::cell_load(
    Scratch                                        &scratch,
    const typename TiedCopyDoFs<dim>::CellIterator &cell,
    const Loads<dim>                               &loads,
    const double                                    t,
    dealii::Vector<double>                         &f) const
  {
    const auto &fe = dofs.get_fe();
    f              = 0;
    dealii::Vector<double> value(dim);
    if (loads.body_force)
      {
        loads.body_force->set_time(t);
        auto &fe_values = scratch.fe_values;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            loads.body_force->vector_value(fe_values.quadrature_point(q),
                                           value);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                f(i)
                  += fe_values.shape_value(i, q) * value(c) * fe_values.JxW(q);
              }
          }
      }
    for (const unsigned int face : cell->face_indices())
      {
        if (!cell->at_boundary(face)
            || !loads.on_face(cell->face(face)->boundary_id()))
          continue;
        const auto id = cell->face(face)->boundary_id();
        add_patch_forces(loads, cell, face, t, f);
        if (!loads.tractions.count(id) && !loads.pressures.count(id))
          continue;
        auto &fv = scratch.face_values;
        fv.reinit(cell, face);
        for (const unsigned int q : fv.quadrature_point_indices())
          {
            Tensor<1, dim> traction;
            if (loads.tractions.count(id))
              {
                loads.tractions.at(id)->set_time(t);
                loads.tractions.at(id)->vector_value(fv.quadrature_point(q),
                                                     value);
                for (unsigned int d = 0; d < dim; ++d)
                  traction[d] += value(d);
              }
            if (loads.pressures.count(id))
              {
                loads.pressures.at(id)->set_time(t);
                traction
                  -= loads.pressures.at(id)->value(fv.quadrature_point(q))
                     * fv.normal_vector(q);
              }
            for (const unsigned int i : dofs.dofs_on_face(face))
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                f(i) += fv.shape_value(i, q) * traction[c] * fv.JxW(q);
              }
          }
      }
  }



  template <int dim>
  void
  ElasticAssembler<dim>::assemble_matrix(
    const AffineConstraints<double> &constraints,
    Matrix                          &matrix) const
  {
    SharedStiffness                      stiffness(*this);
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    matrix = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dofs.get_dof_indices(cell, indices);
          constraints.distribute_local_to_global(stiffness(cell),
                                                 indices,
                                                 matrix);
        }
    matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::cell_geometric_matrix(Scratch           &scratch,
                                               const unsigned int ply,
                                               const dealii::Vector<double> &u,
                                               FullMatrix<double> &KG) const
  {
    const auto        &fe        = dofs.get_fe();
    const auto        &fe_values = scratch.fe_values;
    const unsigned int n         = KG.m();
    KG                           = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        SymmetricTensor<2, dim> strain;
        for (unsigned int i = 0; i < n; ++i)
          strain
            += u(i) * fe_values[scratch.displacement].symmetric_gradient(i, q);
        const SymmetricTensor<2, dim> stress
          = plies[ply].stiffness * strain * fe_values.JxW(q);
        // The primitive FESystem: shape i has one nonzero component, and
        // K_G couples only equal components.
        for (unsigned int i = 0; i < n; ++i)
          {
            const Tensor<1, dim> stress_grad_i
              = stress * fe_values.shape_grad(i, q);
            const unsigned int c_i = fe.system_to_component_index(i).first;
            for (unsigned int j = 0; j <= i; ++j)
              if (fe.system_to_component_index(j).first == c_i)
                KG(i, j) += stress_grad_i * fe_values.shape_grad(j, q);
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        KG(i, j) = KG(j, i);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::assemble_geometric_matrix(
    const Vector                    &relevant_solution,
    const AffineConstraints<double> &constraints,
    Matrix                          &matrix) const
  {
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    Scratch                              scratch(dofs, quadrature_degree);
    FullMatrix<double>                   KG(n, n);
    dealii::Vector<double>               u(n);
    std::vector<types::global_dof_index> indices(n);
    matrix = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          scratch.fe_values.reinit(cell);
          dofs.get_dof_indices(cell, indices);
          for (unsigned int i = 0; i < n; ++i)
            u(i) = relevant_solution(indices[i]);
          cell_geometric_matrix(scratch, cell->material_id(), u, KG);
          constraints.distribute_local_to_global(KG, indices, matrix);
        }
    matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::assemble_rhs(
    const Loads<dim>                &loads,
    const double                     t,
    const AffineConstraints<double> &constraints,
    Vector                          &rhs) const
  {
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    Scratch                              scratch(dofs, quadrature_degree);
    FullMatrix<double>                   K(n, n);
    dealii::Vector<double>               f(n);
    std::vector<types::global_dof_index> indices(n);
    rhs               = 0;
    bool       finite = true;
    Point<dim> where;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          scratch.fe_values.reinit(cell);
          dofs.get_dof_indices(cell, indices);
          cell_load(scratch, cell, loads, t, f);
          if (!std::all_of(f.begin(), f.end(), [](const double v) {
                return std::isfinite(v);
              }))
            {
              if (finite)
                finite = false, where = cell->center();
              f = 0;
            }
          const bool inhomogeneous
            = std::any_of(indices.begin(), indices.end(), [&](const auto i) {
                return constraints.is_inhomogeneously_constrained(i);
              });
          if (inhomogeneous)
            {
              cell_matrix(scratch, cell->material_id(), K);
              constraints.distribute_local_to_global(f, indices, rhs, K);
            }
          else
            constraints.distribute_local_to_global(f, indices, rhs);
        }
    rhs.compress(VectorOperation::add);
    check_load_finite(finite, where, t);
  }



  template <int dim>
  typename ElasticAssembler<dim>::Energies
  ElasticAssembler<dim>::compute_residual(const Loads<dim> &loads,
                                          const double      t,
                                          const Vector     &solution,
                                          Vector           &residual) const
  {
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    Scratch                              scratch(dofs, quadrature_degree);
    SharedStiffness                      stiffness(*this);
    dealii::Vector<double>               f(n), u(n), r(n);
    std::vector<types::global_dof_index> indices(n);
    Energies                             energies;
    residual = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          scratch.fe_values.reinit(cell);
          dofs.get_dof_indices(cell, indices);
          for (unsigned int i = 0; i < n; ++i)
            u(i) = solution(indices[i]);
          stiffness(cell).vmult(r, u);
          cell_load(scratch, cell, loads, t, f);
          energies.strain_energy += 0.5 * (r * u);
          energies.load_work += f * u;
          r -= f;
          residual.add(indices, r);
        }
    residual.compress(VectorOperation::add);
    const MPI_Comm comm
      = dofs.copy_handler().get_triangulation().get_communicator();
    energies.strain_energy = Utilities::MPI::sum(energies.strain_energy, comm);
    energies.load_work     = Utilities::MPI::sum(energies.load_work, comm);
    return energies;
  }

  namespace
  {
    /** The lumped mass of one element: the consistent mass integrated
     * with Gauss-Lobatto on the nodes (@p lobatto reinitialized on it). */
    template <int dim>
    void
    lobatto_lumped_mass(const FEValues<dim>    &lobatto,
                        const double            density,
                        dealii::Vector<double> &m)
    {
      m = 0;
      for (const unsigned int q : lobatto.quadrature_point_indices())
        for (unsigned int i = 0; i < m.size(); ++i)
          m(i) += density * lobatto.shape_value(i, q) * lobatto.JxW(q);
    }

    /** The rule on the element's nodes: Gauss-Lobatto on hypercubes; on a
     * linear wedge its six vertices with equal weights, which lumps the
     * mass as the row sum does (the quadratic wedge's lumped mass is not
     * positive: the parameters refuse explicit runs with it). */
    template <int dim>
    Quadrature<dim>
    nodal_rule(const TiedCopyDoFs<dim> &dofs)
    {
      const auto &shape = dofs.reference_cell();
      if (shape.is_hyper_cube())
        return QGaussLobatto<dim>(dofs.get_fe().degree + 1);
      AssertThrow(dofs.get_fe().degree == 1,
                  ExcMessage("lumped mass: only linear wedges"));
      const Quadrature<dim>   one_point = dofs.cell_quadrature(1);
      const double            volume    = one_point.weight(0);
      std::vector<Point<dim>> vertices;
      for (const unsigned int v : shape.vertex_indices())
        vertices.push_back(shape.template vertex<dim>(v));
      return Quadrature<dim>(vertices,
                             std::vector<double>(vertices.size(),
                                                 volume / vertices.size()));
    }

    template <int dim>
    FEValues<dim>
    lobatto_values(const TiedCopyDoFs<dim> &dofs)
    {
      return FEValues<dim>(dofs.get_mapping(),
                           dofs.get_fe(),
                           nodal_rule(dofs),
                           update_values | update_JxW_values);
    }
  } // namespace



  template <int dim>
  void
  ElasticAssembler<dim>::lumped_mass(Vector                 &mass,
                                     dealii::Vector<double> &copy_masses) const
  {
    const auto                          &fe = dofs.get_fe();
    dealii::Vector<double>               m(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> copies(fe.n_dofs_per_cell()),
      indices(fe.n_dofs_per_cell());
    // Every cell: after an insertion a rank may own a dof of a cell it
    // did not before.
    if (copy_masses.size() != dofs.n_copies())
      {
        copy_masses.reinit(dofs.n_copies());
        FEValues<dim> fe_values = lobatto_values(dofs);
        for (const auto &cell : dofs.copy_handler().active_cell_iterators())
          {
            fe_values.reinit(cell);
            lobatto_lumped_mass(fe_values,
                                plies[cell->material_id()].density,
                                m);
            cell->get_dof_indices(copies);
            for (unsigned int i = 0; i < copies.size(); ++i)
              copy_masses[copies[i]] = m(i);
          }
      }
    mass = 0;
    for (const auto &cell : dofs.cells_with_owned_dofs())
      {
        cell->get_dof_indices(copies);
        for (unsigned int i = 0; i < copies.size(); ++i)
          m(i) = copy_masses[copies[i]];
        dofs.get_dof_indices(cell, indices);
        add_owned(indices, m, mass);
      }
    mass.compress(VectorOperation::add);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::element_lumped_mass(
    const typename TiedCopyDoFs<dim>::CellIterator &cell,
    dealii::Vector<double>                         &mass) const
  {
    FEValues<dim> lobatto = lobatto_values(dofs);
    lobatto.reinit(cell);
    mass.reinit(dofs.get_fe().n_dofs_per_cell());
    lobatto_lumped_mass(lobatto, plies[cell->material_id()].density, mass);
  }



  template <int dim>
  void
  ElasticAssembler<dim>::element_stiffness(
    const typename TiedCopyDoFs<dim>::CellIterator &cell,
    FullMatrix<double>                             &K) const
  {
    Scratch scratch(dofs, quadrature_degree);
    scratch.fe_values.reinit(cell);
    K.reinit(dofs.get_fe().n_dofs_per_cell(), dofs.get_fe().n_dofs_per_cell());
    cell_matrix(scratch, cell->material_id(), K);
  }



  template <int dim>
  double
  ElasticAssembler<dim>::max_frequency_squared(
    const typename TiedCopyDoFs<dim>::CellIterator &cell) const
  {
    const auto        &fe = dofs.get_fe();
    const unsigned int n  = fe.n_dofs_per_cell();
    FullMatrix<double> K(n, n);
    element_stiffness(cell, K);
    FEValues<dim> lobatto = lobatto_values(dofs);
    lobatto.reinit(cell);
    dealii::Vector<double> m(n);
    lobatto_lumped_mass(lobatto, plies[cell->material_id()].density, m);
    // Largest eigenvalue of M^-1/2 K M^-1/2 (symmetric, positive
    // semi-definite): a dense eigenproblem of the element's size.
    LAPACKFullMatrix<double> A(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        A(i, j) = K(i, j) / std::sqrt(m(i) * m(j));
    // LAPACK fails on non-finite entries (an overflowing stiffness): the
    // caller reports an infinite frequency as a useless time step.
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (!std::isfinite(A(i, j)))
          return std::numeric_limits<double>::infinity();
    A.compute_eigenvalues();
    double largest = 0;
    for (unsigned int i = 0; i < n; ++i)
      largest = std::max(largest, A.eigenvalue(i).real());
    return largest;
  }



  template class ElasticAssembler<2>;
  template class ElasticAssembler<3>;
} // namespace amfrac

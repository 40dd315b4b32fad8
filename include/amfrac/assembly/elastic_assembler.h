#pragma once

#include <amfrac/assembly/loads.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/ply_table.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

namespace amfrac
{
  /**
   * Bulk (ply) small-strain elasticity on the tied-copy layer: stiffness,
   * load vector and the unconstrained residual K u - f (for reactions and
   * the energy balance), all in the reduced numbering.
   */
  template <int dim>
  class ElasticAssembler
  {
  public:
    using Matrix = TrilinosWrappers::SparseMatrix;
    using Vector = TrilinosWrappers::MPI::Vector;

    ElasticAssembler(const TiedCopyDoFs<dim>               &dofs,
                     const std::vector<PlyProperties<dim>> &plies);

    /** Add the cell couplings under @p constraints to @p pattern. */
    void
    add_couplings(const AffineConstraints<double>   &constraints,
                  TrilinosWrappers::SparsityPattern &pattern) const;

    /** Size @p matrix for the cell couplings under @p constraints. */
    void
    reinit_matrix(const AffineConstraints<double> &constraints,
                  Matrix                          &matrix) const;

    /** The condensed stiffness matrix. */
    void
    assemble_matrix(const AffineConstraints<double> &constraints,
                    Matrix                          &matrix) const;

    /** The condensed geometric (initial stress) stiffness K_G of the
     * stress of @p relevant_solution: K_G(i, j) = delta_{c_i c_j}
     * int grad(phi_i) . sigma grad(phi_j), the second variation of the
     * Green-Lagrange strain energy under a fixed stress. Linear buckling
     * solves (K + lambda K_G) v = 0 with it. */
    void
    assemble_geometric_matrix(const Vector &relevant_solution,
                              const AffineConstraints<double> &constraints,
                              Matrix                          &matrix) const;

    /** The condensed load vector at time @p t, including the effect of
     * inhomogeneous constraints (the cell stiffness is computed only on
     * cells that have such constraints). */
    void
    assemble_rhs(const Loads<dim>                &loads,
                 const double                     t,
                 const AffineConstraints<double> &constraints,
                 Vector                          &rhs) const;

    /** Compute @p patch.unit_nodal_forces: a unit total force spread
     * uniformly over the patch, integrated with a fine rule on each face
     * it touches, so that the total is exact whatever the mesh. Throws an
     * InputError if the patch covers no part of its face. */
    void
    prepare_patch(PatchLoad<dim> &patch) const;

    using CellList = std::vector<typename TiedCopyDoFs<dim>::CellIterator>;

    /** The locally owned cells that carry a load: all of them with a body
     * force, else those on loaded faces. */
    CellList
    loaded_cells(const Loads<dim> &loads) const;

    /** The load vector f(t) without constraints. */
    void
    assemble_load(const Loads<dim> &loads, const double t, Vector &f) const;

    /** The same, visiting only @p cells (from loaded_cells(): explicit
     * runs call this every step). */
    void
    assemble_load(const Loads<dim> &loads,
                  const double      t,
                  const CellList   &cells,
                  Vector           &f) const;

    struct Energies
    {
      double strain_energy = 0;
      double load_work     = 0;
    };

    /** residual = K u - f without constraints (its entries on supported
     * dofs are the reactions); returns strain energy and load work. */
    Energies
    compute_residual(const Loads<dim> &loads,
                     const double      t,
                     const Vector     &relevant_solution,
                     Vector           &residual) const;

    /** The stiffness matrix of one element (no constraints). */
    void
    element_stiffness(const typename TiedCopyDoFs<dim>::CellIterator &cell,
                      FullMatrix<double>                             &K) const;

    /** The lumped mass of every reduced dof: the consistent mass
     * integrated with the Gauss-Lobatto rule on the element's nodes,
     * which is diagonal and positive for Q1 and Q2 (a row sum with the
     * Gauss rule would give Q2 corner nodes negative mass). Keeps the
     * mass of every copy of every cell in
     * @p copy_masses (copy_handler() numbering); if it has one entry per
     * copy already (after crack insertion: the copies keep their masses,
     * only the groups change), the sums come from it without integrating
     * again, term by term as lumped_mass() adds them. */
    void
    lumped_mass(Vector &mass, dealii::Vector<double> &copy_masses) const;

    /** The same for the dofs of one element (in its local order). */
    void
    element_lumped_mass(const typename TiedCopyDoFs<dim>::CellIterator &cell,
                        dealii::Vector<double> &mass) const;

    /** omega_max^2 of one element alone, free, with its lumped mass: by
     * Irons' theorem the largest over the elements bounds the mesh's. */
    double
    max_frequency_squared(
      const typename TiedCopyDoFs<dim>::CellIterator &cell) const;

  private:
    /** Throw NonFiniteValue on every rank (the first failing rank's
     * message, naming @p where and @p t) unless every rank's load was
     * @p finite. Collective. */
    void
    check_load_finite(const bool        finite,
                      const Point<dim> &where,
                      const double      t) const;

    const TiedCopyDoFs<dim>               &dofs;
    const std::vector<PlyProperties<dim>> &plies;
    const unsigned int                     quadrature_degree;

    class Scratch;
    class SharedStiffness;

    void
    cell_matrix(Scratch            &scratch,
                const unsigned int  ply,
                FullMatrix<double> &K) const;

    /** K_G of one cell from its nodal displacements @p u (fe_values
     * reinitialized on the cell). */
    void
    cell_geometric_matrix(Scratch                      &scratch,
                          const unsigned int            ply,
                          const dealii::Vector<double> &u,
                          FullMatrix<double>           &KG) const;

    void
    cell_load(Scratch                                        &scratch,
              const typename TiedCopyDoFs<dim>::CellIterator &cell,
              const Loads<dim>                               &loads,
              const double                                    t,
              dealii::Vector<double>                         &f) const;
  };
} // namespace amfrac

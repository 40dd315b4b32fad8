#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/hoffman_plasticity.h>
#include <amfrac/material/ply_table.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <string>
#include <vector>

namespace amfrac
{
  /**
   * Hoffman plasticity of the plies whose material has Materials/
   * Plasticity = hoffman, on the static Newton path: the history
   * (plastic strain in material axes and the equivalent plastic strain
   * kappa) at the bulk quadrature points of the locally owned cells of
   * plastic plies, and what the plastic response changes in the elastic
   * bulk's residual and tangent.
   *
   * The Newton path keeps the elastic bulk matrix K (assembled once) and
   * adds a correction of the cells of plastic plies only:
   *
   *   R(u) = K u + int B^T (sigma(u) - C eps(u)),
   *   K_T  = K   + int B^T (C_ep - C) B,
   *
   * sigma(u) from the return mapping of the converged history, C_ep its
   * consistent tangent. A point that never yielded contributes exactly
   * nothing (and is skipped), so a Newton-path scene whose plies never
   * reach their strengths gives the elastic result bit for bit; elastic
   * plies are never visited.
   *
   * Every evaluation starts from the converged history (backward Euler
   * over the whole step), so Newton iterations and line searches may
   * evaluate any trial state; commit() makes the state of the converged
   * step the history.
   *
   * With finite strain (Kinematics = total Lagrangian), the same law acts
   * on the Green-Lagrange strain E = E_e + E_p (an additive split, for
   * small elastic and plastic strains under large rotations): the second
   * Piola-Kirchhoff stress S = C : (E - E_p) is returned to the Hoffman
   * surface in the ply axes of the reference configuration, which turn
   * with the material. The correction is then added to the total
   * Lagrangian bulk (S = C : E), with delta E_i = sym(F^T grad phi_i):
   *
   * @code
   *   R(u)_i += int (S - C E) : delta E_i
   *   K_T    += int delta E_i : (C_ep - C) : delta E_j
   *           + int grad phi_i . (S - C E) grad phi_j  (equal components)
   * @endcode
   *
   * The geometric (second) term belongs to every point that has yielded,
   * elastic now or not. The energy and the plastic work are those of S
   * and E; below, eps stands for E and B for delta E then.
   */
  template <int dim>
  class PlasticPlies
  {
  public:
    using Matrix = TrilinosWrappers::SparseMatrix;
    using Vector = TrilinosWrappers::MPI::Vector;
    using State  = HoffmanPlasticity::State;

    /** History components per point, in this order: the plastic strain
     * in material axes (Voigt 11, 22, 33, 23, 13, 12, engineering shear),
     * then kappa. */
    static constexpr unsigned int n_components = 7;

    /** With @p finite_strain, the law acts on the Green-Lagrange strain
     * and the correction is that of the total Lagrangian bulk. */
    PlasticPlies(const TiedCopyDoFs<dim>               &dofs,
                 const std::vector<PlyProperties<dim>> &plies,
                 const bool                             finite_strain = false);

    /** After the DoF layer changed: a virgin history on the new owned
     * cells of plastic plies (set_field() sets a transferred one). */
    void
    setup();

    /** Add int B^T (sigma - C eps) of @p relevant_u to @p force (ghost
     * entries writable; the caller compresses) and, with a @p tangent,
     * int B^T (C_ep - C) B condensed by @p constraints into it
     * (compressed here, collective then). Returns false if the return
     * mapping failed at some point of this rank (the step must be cut).
     * Without @p return_map the stress is C (eps - eps_p) of the history
     * as it is (the state a transfer to a new mesh left, which may lie
     * outside the yield surface), no tangent. */
    bool
    add_correction(const Vector                    &relevant_u,
                   const AffineConstraints<double> &constraints,
                   Vector                          &force,
                   Matrix                          *tangent,
                   const bool                       return_map = true);

    /** int B^T (C_ep - C) B @p relevant_direction at @p relevant_u, added
     * to @p product (ghost entries writable; the caller compresses). */
    void
    add_tangent_product(const Vector &relevant_u,
                        const Vector &relevant_direction,
                        Vector       &product) const;

    /** The state of @p relevant_u (the converged step) becomes the
     * history; returns the plastic work of the step from
     * @p relevant_previous, int (sigma_n + sigma_n+1) / 2 : d eps_p (the
     * trapezoidal rule of the external work, so that the balance closes
     * to the Newton tolerance), summed over the ranks. Collective. */
    double
    commit(const Vector &relevant_u, const Vector &relevant_previous);

    /** What the plastic strain changes in the stored elastic energy of
     * @p relevant_u: int eps_p : C : (eps_p / 2 - eps), so that
     * u.K u / 2 plus it is int (eps - eps_p) : C : (eps - eps_p) / 2
     * (with finite strain: E in place of eps, added to int E : C : E / 2
     * of the total Lagrangian bulk).
     * Summed over the ranks (collective). */
    double
    stored_energy_correction(const Vector &relevant_u) const;

    /** The tangent of the last add_correction() with a tangent had no
     * plastic point, nor had the one last factorized: a factorization of
     * the elastic tangent can be reused. */
    bool
    tangent_unchanged() const
    {
      return !last_tangent_plastic && !factorized_plastic;
    }

    /** The tangent of the last add_correction() was factorized. */
    void
    mark_factorized()
    {
      factorized_plastic = last_tangent_plastic;
    }

    /** Where the return mapping failed last (empty if it did not). */
    const std::string &
    failure() const
    {
      return last_failure;
    }

    /** Points of this rank that yielded in the last commit(). */
    unsigned int
    yielding_points() const
    {
      return n_yielding;
    }

    /** The history of every active cell (n_q * n_components values
     * each; zero on cells of elastic plies), the same on every rank
     * (collective): for the transfer to a new mesh. */
    std::vector<std::vector<double>>
    gather_field() const;

    /** Set the history of the owned cells of plastic plies from a field
     * in gather_field()'s layout (on the current mesh). */
    void
    set_field(const std::vector<std::vector<double>> &field);

    /** The history of the owned cells in the order of the locally owned
     * active cells (n_q * n_components values per cell), for a
     * checkpoint. */
    std::vector<double>
    owned_values() const;

    /** Set the history of @p cell (owned) from @p values (n_q *
     * n_components, owned_values()'s layout); nothing on cells of elastic
     * plies. */
    void
    set_cell_values(const typename TiedCopyDoFs<dim>::CellIterator &cell,
                    const double                                   *values);

    /** The number of quadrature points per cell. */
    unsigned int
    n_points() const
    {
      return quadrature.size();
    }

    /** The cell means of the plastic strain (laminate axes, 3D) and of
     * kappa on every active cell (zero elsewhere), the same on every
     * rank (collective): for the field output and the point values. */
    struct CellMeans
    {
      std::vector<SymmetricTensor<2, 3>> plastic_strain;
      std::vector<double>                kappa;
    };
    CellMeans
    cell_means() const;

    /** The largest kappa over all points (collective). */
    double
    max_kappa() const;

    /** The quadrature of the history (that of the bulk assembly). */
    const Quadrature<dim> &
    get_quadrature() const
    {
      return quadrature;
    }

  private:
    const TiedCopyDoFs<dim>               &dofs;
    const std::vector<PlyProperties<dim>> &plies;
    const Quadrature<dim>                  quadrature;
    const bool                             finite_strain;
    /** Per ply: its law (nullptr: elastic ply). */
    std::vector<std::unique_ptr<HoffmanPlasticity>> laws;
    /** Per ply: laminate to material axes of Voigt strains (engineering
     * shear). */
    std::vector<HoffmanPlasticity::Stiffness> strain_maps;
    /** Per active cell: the converged state of each point (empty unless
     * owned and plastic). */
    std::vector<std::vector<State>> history;
    /** Per active cell: some point of it has yielded (the cells the
     * stored energy and the output means have to visit). */
    std::vector<bool> yielded;
    bool              last_tangent_plastic = false;
    bool              factorized_plastic   = false;
    std::string       last_failure;
    unsigned int      n_yielding = 0;

    bool
    is_plastic(const typename TiedCopyDoFs<dim>::CellIterator &cell) const;

    /** For every owned cell of a plastic ply (with @p yielded_only, of
     * those where some point has yielded): @p visit gets the cell, its
     * local dof indices and its FEValues. */
    template <typename Visitor>
    void
    for_each_plastic_cell(const Visitor &visit,
                          const bool     yielded_only = false) const;

    /** Set yielded[] of the cell with active index @p c from its history. */
    void
    update_yielded(const std::size_t c);
  };
} // namespace amfrac

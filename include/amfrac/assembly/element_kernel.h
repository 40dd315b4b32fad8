#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace amfrac
{
  /**
   * f += K_e u_e over a set of elements whose stiffness matrices come from
   * a small table: elements of the same ply and the same shape (a
   * translated copy) share one matrix, which on the structured laminate
   * meshes leaves a handful of matrices for any number of elements. Plain
   * C++ without deal.II, so that this one translation unit can be compiled
   * with -O3 -march=native (Debian's deal.II is built without SIMD) and
   * the small dense products vectorize.
   */
  class ElementMatrixKernel
  {
  public:
    explicit ElementMatrixKernel(const unsigned int dofs_per_element);

    /** Add a symmetric element matrix (row major, n x n); returns its
     * index. */
    unsigned int
    add_matrix(const std::vector<double> &matrix);

    /** Forget the elements, keep the matrices (a new numbering). */
    void
    clear_elements();

    /** Add an element with matrix @p matrix and the local indices of its
     * dofs in the arrays apply() works on; its strain energy counts only
     * if @p counts (an element evaluated on several ranks counts on one). */
    void
    add_element(const unsigned int  matrix,
                const unsigned int *local_dofs,
                const bool          counts = true);

    /** f[i] += sum over elements of (K_e u_e)[i] (f is not zeroed), in the
     * order the elements were added; returns the strain energy
     * 1/2 u_e . K_e u_e of the elements that count. */
    double
    apply(const double *u, double *f) const;

    std::size_t
    n_elements() const
    {
      return element_matrix.size();
    }

    std::size_t
    n_matrices() const
    {
      return matrices.size() / (n * n);
    }

    std::size_t
    memory_consumption() const;

  private:
    unsigned int               n;
    std::vector<double>        matrices;
    std::vector<std::uint32_t> element_matrix;
    /** 1 if the element's energy counts, else 0. */
    std::vector<double>        energy_weight;
    std::vector<std::uint32_t> element_dofs;

    template <unsigned int N>
    double
    apply_fixed(const double *u, double *f) const;

    double
    apply_any(const double *u, double *f) const;
  };



  /** The length of gathered_columns_product()'s columns. */
  constexpr unsigned int column_length = 8;
  /** Zeros that pad a column of 6 (a symmetric tensor) to column_length. */
  constexpr unsigned int column_padding = column_length - 6;

  /**
   * y[r] = sum_i A[i column_length + r] u[local[i]] for r < column_length:
   * n columns of column_length entries (column major) times the entries
   * of u at n local indices. The columns are added as whole vectors, in
   * two accumulators (even and odd columns), which vectorizes across the
   * entries without -ffast-math (a row-major dot product stays a serial
   * chain of additions); each entry's sum has a fixed order, whatever the
   * vector width. Compiled with the element kernel's flags:
   * FaceHoffmanScreen's stresses at the face centres, every explicit step.
   */
  void
  gathered_columns_product(const double      *A,
                           const unsigned int n,
                           const int         *local,
                           const double      *u,
                           double            *y);
} // namespace amfrac

#include <amfrac/assembly/element_kernel.h>
#include <stdexcept>

namespace amfrac
{
  ElementMatrixKernel::ElementMatrixKernel(const unsigned int dofs_per_element)
    : n(dofs_per_element)
  {}



  unsigned int
  ElementMatrixKernel::add_matrix(const std::vector<double> &matrix)
  {
    if (matrix.size() != std::size_t(n) * n)
      throw std::logic_error("ElementMatrixKernel: matrix of wrong size");
    const unsigned int index = n_matrices();
    matrices.insert(matrices.end(), matrix.begin(), matrix.end());
    return index;
  }



  void
  ElementMatrixKernel::clear_elements()
  {
    element_matrix.clear();
    energy_weight.clear();
    element_dofs.clear();
  }



  void
  ElementMatrixKernel::add_element(const unsigned int  matrix,
                                   const unsigned int *local_dofs,
                                   const bool          counts)
  {
    element_matrix.push_back(matrix);
    energy_weight.push_back(counts ? 1. : 0.);
    element_dofs.insert(element_dofs.end(), local_dofs, local_dofs + n);
  }



  // The product is written column by column (K is symmetric, so columns
  // are rows): f_e += K(:, j) u_j has no horizontal reduction and
  // vectorizes over i with a compile-time length.
  template <unsigned int N>
  double
  ElementMatrixKernel::apply_fixed(const double *u, double *f) const
  {
    double              energy = 0;
    const std::size_t   n_el   = element_matrix.size();
    const double *const K0     = matrices.data();
    for (std::size_t e = 0; e < n_el; ++e)
      {
        const std::uint32_t *dofs = element_dofs.data() + e * N;
        const double        *K    = K0 + std::size_t(element_matrix[e]) * N * N;
        double               ue[N], fe[N] = {};
        for (unsigned int j = 0; j < N; ++j)
          ue[j] = u[dofs[j]];
        for (unsigned int j = 0; j < N; ++j)
          for (unsigned int i = 0; i < N; ++i)
            fe[i] += K[j * N + i] * ue[j];
        double work = 0;
        for (unsigned int i = 0; i < N; ++i)
          {
            work += ue[i] * fe[i];
            f[dofs[i]] += fe[i];
          }
        energy += energy_weight[e] * 0.5 * work;
      }
    return energy;
  }



  double
  ElementMatrixKernel::apply_any(const double *u, double *f) const
  {
    double              energy = 0;
    std::vector<double> ue(n), fe(n);
    for (std::size_t e = 0; e < element_matrix.size(); ++e)
      {
        const std::uint32_t *dofs = element_dofs.data() + e * n;
        const double        *K
          = matrices.data() + std::size_t(element_matrix[e]) * n * n;
        for (unsigned int j = 0; j < n; ++j)
          ue[j] = u[dofs[j]], fe[j] = 0;
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            fe[i] += K[j * n + i] * ue[j];
        for (unsigned int i = 0; i < n; ++i)
          {
            energy += energy_weight[e] * 0.5 * ue[i] * fe[i];
            f[dofs[i]] += fe[i];
          }
      }
    return energy;
  }



  double
  ElementMatrixKernel::apply(const double *u, double *f) const
  {
    switch (n)
      {
        case 8: // Q1 quadrilateral
          return apply_fixed<8>(u, f);
        case 18: // Q2 quadrilateral
          return apply_fixed<18>(u, f);
        case 24: // Q1 hexahedron
          return apply_fixed<24>(u, f);
        case 81: // Q2 hexahedron
          return apply_fixed<81>(u, f);
        default:
          return apply_any(u, f);
      }
  }



  namespace
  {
    template <unsigned int N>
    void
    gathered_columns_fixed(const double *A,
                           const int    *local,
                           const double *u,
                           double       *y)
    {
      // Two accumulators halve the chain of dependent additions.
      double       even[column_length] = {}, odd[column_length] = {};
      unsigned int i = 0;
      for (; i + 1 < N; i += 2)
        {
          const double  a = u[local[i]], b = u[local[i + 1]];
          const double *column = A + i * column_length;
          for (unsigned int r = 0; r < column_length; ++r)
            even[r] += column[r] * a;
          for (unsigned int r = 0; r < column_length; ++r)
            odd[r] += column[column_length + r] * b;
        }
      if (i < N)
        for (unsigned int r = 0; r < column_length; ++r)
          even[r] += A[i * column_length + r] * u[local[i]];
      for (unsigned int r = 0; r < column_length; ++r)
        y[r] = even[r] + odd[r];
    }
  } // namespace



  void
  gathered_columns_product(const double      *A,
                           const unsigned int n,
                           const int         *local,
                           const double      *u,
                           double            *y)
  {
    switch (n)
      {
        case 8:
          return gathered_columns_fixed<8>(A, local, u, y);
        case 18:
          return gathered_columns_fixed<18>(A, local, u, y);
        case 24:
          return gathered_columns_fixed<24>(A, local, u, y);
        case 81:
          return gathered_columns_fixed<81>(A, local, u, y);
        default:
          for (unsigned int r = 0; r < column_length; ++r)
            y[r] = 0;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int r = 0; r < column_length; ++r)
              y[r] += A[i * column_length + r] * u[local[i]];
      }
  }



  std::size_t
  ElementMatrixKernel::memory_consumption() const
  {
    return matrices.capacity() * sizeof(double)
           + (element_matrix.capacity() + element_dofs.capacity())
               * sizeof(std::uint32_t)
           + energy_weight.capacity() * sizeof(double);
  }
} // namespace amfrac

#pragma once

#include <deal.II/base/tensor.h>

namespace amfrac
{
  using namespace dealii;

  /** The cross product as a matrix: cross_matrix(a) v = a x v. */
  inline Tensor<2, 3>
  cross_matrix(const Tensor<1, 3> &a)
  {
    Tensor<2, 3> s;
    s[0][1] = -a[2], s[0][2] = a[1];
    s[1][0] = a[2], s[1][2] = -a[0];
    s[2][0] = -a[1], s[2][1] = a[0];
    return s;
  }
} // namespace amfrac

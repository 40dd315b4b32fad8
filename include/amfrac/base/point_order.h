#pragma once

#include <deal.II/base/point.h>

namespace amfrac
{
  /** Lexicographic order of positions (x, then y, then z): a strict weak
   * order for ordered containers of points, and a way to tell equally
   * near points apart by where they are, so that any number of ranks
   * makes the same choice. */
  template <int dim>
  bool
  lexicographically_less(const dealii::Point<dim> &a,
                         const dealii::Point<dim> &b)
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (a[d] != b[d])
        return a[d] < b[d];
    return false;
  }

  /** lexicographically_less() as the comparison of a std::map or std::set. */
  struct LexicographicLess
  {
    template <int dim>
    bool
    operator()(const dealii::Point<dim> &a, const dealii::Point<dim> &b) const
    {
      return lexicographically_less(a, b);
    }
  };
} // namespace amfrac

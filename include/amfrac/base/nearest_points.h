#pragma once

#include <algorithm>
#include <deal.II/base/point.h>
#include <vector>

namespace amfrac
{
  /**
   * For every point of @p a, the index of the nearest point of @p b (the
   * quadrature points of a face seen from its two cells: their orders
   * differ when the cells' face orientations do). @p largest_distance
   * gets the largest distance of a pair, for the caller to judge.
   */
  template <int dim>
  std::vector<unsigned int>
  nearest_points(const std::vector<dealii::Point<dim>> &a,
                 const std::vector<dealii::Point<dim>> &b,
                 double                                &largest_distance)
  {
    std::vector<unsigned int> match(a.size(), 0);
    largest_distance = 0;
    for (unsigned int q = 0; q < a.size(); ++q)
      {
        for (unsigned int r = 1; r < b.size(); ++r)
          if (a[q].distance(b[r]) < a[q].distance(b[match[q]]))
            match[q] = r;
        largest_distance
          = std::max(largest_distance, a[q].distance(b[match[q]]));
      }
    return match;
  }
} // namespace amfrac

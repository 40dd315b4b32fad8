#pragma once

#include <deal.II/base/function.h>
#include <memory>
#include <string>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /**
   * A FunctionParser of (x, y, [z,] t) with @p n_components components from
   * one expression (used for all components) or one per component. The
   * expressions are evaluated once here, so a malformed one fails at input
   * time with an InputError naming @p parameter. The function's time is
   * called @p time_name in the expressions.
   */
  template <int dim>
  std::shared_ptr<Function<dim>>
  make_expression_function(const std::vector<std::string> &expressions,
                           const unsigned int              n_components,
                           const std::string              &constants,
                           const std::string              &parameter,
                           const std::string              &time_name = "t");
} // namespace amfrac

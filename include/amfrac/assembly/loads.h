#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/types.h>
#include <map>
#include <memory>

namespace amfrac
{
  using namespace dealii;

  /** The applied loads of a scene, as functions of position and time. */
  template <int dim>
  struct Loads
  {
    /** Force per volume, dim components (nullptr: none). */
    std::shared_ptr<Function<dim>> body_force;
    /** Traction vectors (dim components) per boundary id. */
    std::map<types::boundary_id, std::shared_ptr<Function<dim>>> tractions;
    /** Scalar pressures (acting against the outward normal) per id. */
    std::map<types::boundary_id, std::shared_ptr<Function<dim>>> pressures;

    bool
    empty() const
    {
      return !body_force && tractions.empty() && pressures.empty();
    }

    bool
    on_face(const types::boundary_id id) const
    {
      return tractions.count(id) > 0 || pressures.count(id) > 0;
    }
  };
} // namespace amfrac

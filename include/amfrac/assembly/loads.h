#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>
#include <map>
#include <memory>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /** A total force F(t) spread uniformly over a circle or rectangle on one
   * boundary face. */
  template <int dim>
  struct PatchLoad
  {
    types::boundary_id boundary_id = 0;
    /** The face's normal axis; the patch is measured in the other axes. */
    unsigned int normal_axis = 0;
    Point<dim>   center;
    bool         circle = true;
    double       radius = 0;
    /** Half side lengths along the in-plane axes (rectangle). */
    std::array<double, 2> half_size{{0, 0}};
    /** Unit direction of the force; zero: the inward face normal. */
    Tensor<1, dim> direction;
    /** F(t), evaluated at the origin. */
    std::shared_ptr<Function<dim>> force;
    /** Nodal forces of a unit total force per (active cell index, face),
     * computed once by ElasticAssembler::prepare_patch. */
    std::map<std::pair<unsigned int, unsigned int>, dealii::Vector<double>>
      unit_nodal_forces;

    bool
    inside(const Point<dim> &p) const
    {
      double       r2 = 0;
      unsigned int k  = 0;
      for (unsigned int d = 0; d < dim; ++d)
        if (d != normal_axis)
          {
            const double offset = p[d] - center[d];
            if (!circle && std::abs(offset) > half_size[k])
              return false;
            r2 += offset * offset;
            ++k;
          }
      return !circle || r2 <= radius * radius;
    }

    /** Radius of a circle around the center that contains the patch. */
    double
    reach() const
    {
      return circle ? radius : std::hypot(half_size[0], half_size[1]);
    }
  };

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
    std::vector<PatchLoad<dim>>                                  patches;

    bool
    empty() const
    {
      return !body_force && tractions.empty() && pressures.empty()
             && patches.empty();
    }

    bool
    on_face(const types::boundary_id id) const
    {
      return tractions.count(id) > 0 || pressures.count(id) > 0
             || std::any_of(patches.begin(),
                            patches.end(),
                            [id](const auto &p) {
                              return p.boundary_id == id;
                            });
    }
  };
} // namespace amfrac

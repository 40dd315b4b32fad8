#pragma once

#include <amfrac/geometry/laminate.h>
#include <amfrac/material/orthotropic.h>
#include <amfrac/parameters/parameters.h>
#include <vector>

namespace amfrac
{
  /** What the bulk assembly and the postprocessing need of one ply. */
  template <int dim>
  struct PlyProperties
  {
    /** Stiffness in 3D laminate axes (x, y = width, z = thickness). */
    SymmetricTensor<4, 3> stiffness_3d;
    /** The same restricted to the model (plane strain in 2D). */
    SymmetricTensor<4, dim> stiffness;
    /** Columns: the ply's material axes in laminate axes. */
    Tensor<2, 3> rotation;
    Strengths    strengths;
    double       density;
  };

  /** One entry per ply (indexed by the cell's material id). */
  template <int dim>
  std::vector<PlyProperties<dim>>
  make_ply_table(const Laminate &laminate, const parameters::Materials &m);
} // namespace amfrac

namespace amfrac
{
  /** The stresses one strain produces in a ply, in every frame the
   * output needs. */
  struct PlyStress
  {
    /** In model axes (3x3; in 2D the out-of-plane plane-strain stress is
     * component zz). */
    SymmetricTensor<2, 3> model;
    /** In the ply's material axes 1, 2, 3. */
    SymmetricTensor<2, 3> material;
    double                hoffman;
  };

  template <int dim>
  PlyStress
  evaluate_ply_stress(const PlyProperties<dim>      &ply,
                      const SymmetricTensor<2, dim> &strain)
  {
    const SymmetricTensor<2, 3> laminate
      = ply.stiffness_3d * embed_in_3d<dim>(strain);
    PlyStress result;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = a; b < 3; ++b)
        result.model[a][b]
          = laminate[laminate_axis<dim>(a)][laminate_axis<dim>(b)];
    result.material = to_material_axes(laminate, ply.rotation);
    result.hoffman  = hoffman_index(result.material, ply.strengths);
    return result;
  }
} // namespace amfrac

#pragma once

#include <amfrac/geometry/laminate.h>
#include <amfrac/material/orthotropic.h>
#include <amfrac/parameters/parameters.h>
#include <limits>
#include <vector>

namespace amfrac
{
  /** One ply of a laminate homogenized through its thickness (the 2D
   * in-plane model): what recovering its stress from the common membrane
   * strain needs. */
  struct MembraneLayer
  {
    /** Plane-stress (reduced) stiffness Qbar in laminate axes x, y. */
    SymmetricTensor<4, 2> reduced_stiffness;
    Tensor<2, 3>          rotation;
    Strengths             strengths;
  };

  /** What the bulk assembly and the postprocessing need of one ply (of
   * the whole homogenized laminate in the 2D in-plane model). */
  template <int dim>
  struct PlyProperties
  {
    /** Stiffness in 3D laminate axes (x, y = width, z = thickness); the
     * thickness average for a homogenized laminate, where only the
     * membrane part below is used. */
    SymmetricTensor<4, 3> stiffness_3d;
    /** The model's stiffness: restricted to the (x, thickness) plane in
     * plane strain (2D cross-section), the membrane stiffness A/h in
     * plane stress (2D in-plane). */
    SymmetricTensor<4, dim> stiffness;
    /** Columns: the ply's material axes in laminate axes. */
    Tensor<2, 3> rotation;
    Strengths    strengths;
    double       density;
    /** Fracture energy of an inserted intra-ply crack [N/mm]. */
    double fracture_energy = 0;
    /** Hoffman plasticity of the ply's material (false: elastic), and its
     * isotropic hardening factor. */
    bool   plastic   = false;
    double hardening = 0;
    /** The plies of a homogenized laminate (2D in-plane model), bottom
     * first; empty otherwise. */
    std::vector<MembraneLayer> layers;
  };

  /**
   * One entry per ply (indexed by the cell's material id); a single entry
   * for the 2D in-plane model, the laminate homogenized by classical
   * lamination theory. Throws InputError if that laminate is not
   * symmetric (membrane-bending coupling B != 0).
   */
  template <int dim>
  std::vector<PlyProperties<dim>>
  make_ply_table(const Laminate &laminate, const parameters::Materials &m);

  /** The density of every ply of @p plies, by material id (the mass of
   * the explicit state transfers). */
  template <int dim>
  std::vector<double>
  ply_densities(const std::vector<PlyProperties<dim>> &plies)
  {
    std::vector<double> densities;
    for (const auto &ply : plies)
      densities.push_back(ply.density);
    return densities;
  }
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

  /** The homogenized laminate's stress: the membrane (thickness-average)
   * stress in model axes, and the material-axes stress and Hoffman index
   * of the ply with the largest index under the common strain. */
  template <int dim>
  PlyStress
  evaluate_membrane_stress(const PlyProperties<dim>      &laminate,
                           const SymmetricTensor<2, dim> &strain)
  {
    SymmetricTensor<2, 2> membrane_strain;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = a; b < 2; ++b)
        membrane_strain[a][b] = strain[a][b];
    const SymmetricTensor<2, dim> membrane_stress = laminate.stiffness * strain;
    PlyStress                     result;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b)
        result.model[a][b] = membrane_stress[a][b];
    result.hoffman = -std::numeric_limits<double>::max();
    for (const MembraneLayer &layer : laminate.layers)
      {
        const SymmetricTensor<2, 2> s2
          = layer.reduced_stiffness * membrane_strain;
        SymmetricTensor<2, 3> s3;
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = a; b < 2; ++b)
            s3[a][b] = s2[a][b];
        const SymmetricTensor<2, 3> material
          = to_material_axes(s3, layer.rotation);
        const double index = hoffman_index(material, layer.strengths);
        if (index > result.hoffman)
          {
            result.hoffman  = index;
            result.material = material;
          }
      }
    return result;
  }

  /** The stresses of the elastic strain @p elastic_strain (3D, laminate
   * axes) of a ply (not a homogenized laminate). */
  template <int dim>
  PlyStress
  evaluate_ply_stress_3d(const PlyProperties<dim>    &ply,
                         const SymmetricTensor<2, 3> &elastic_strain)
  {
    const SymmetricTensor<2, 3> laminate = ply.stiffness_3d * elastic_strain;
    PlyStress                   result;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = a; b < 3; ++b)
        result.model[a][b]
          = laminate[laminate_axis<dim>(a)][laminate_axis<dim>(b)];
    result.material = to_material_axes(laminate, ply.rotation);
    result.hoffman  = hoffman_index(result.material, ply.strengths);
    return result;
  }

  /** The stresses of a model strain in a ply, less the plastic strain
   * @p plastic (3D laminate axes; nullptr: none). */
  template <int dim>
  PlyStress
  evaluate_ply_stress(const PlyProperties<dim>      &ply,
                      const SymmetricTensor<2, dim> &strain,
                      const SymmetricTensor<2, 3>   *plastic = nullptr)
  {
    if (!ply.layers.empty())
      return evaluate_membrane_stress(ply, strain);
    SymmetricTensor<2, 3> elastic = embed_in_3d<dim>(strain);
    if (plastic)
      elastic -= *plastic;
    return evaluate_ply_stress_3d(ply, elastic);
  }
} // namespace amfrac

#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <string>

namespace amfrac
{
  using namespace dealii;

  /** Engineering constants of an orthotropic ply in its material axes
   * (1 = fibre, 2 = in-plane transverse, 3 = through the thickness).
   * Units: MPa for moduli, t/mm^3 for the density (N, mm, s system). */
  struct ElasticConstants
  {
    double E1 = 0, E2 = 0, E3 = 0;
    double G12 = 0, G13 = 0, G23 = 0;
    double nu12 = 0, nu13 = 0, nu23 = 0;
    double density = 0;
  };

  /** Strengths (positive magnitudes, MPa) for the Hoffman criterion. */
  struct Strengths
  {
    double Xt = 0, Xc = 0, Yt = 0, Yc = 0, Zt = 0, Zc = 0;
    double S12 = 0, S13 = 0, S23 = 0;
  };

  /** A named orthotropic material. */
  struct OrthotropicMaterial
  {
    std::string      name;
    ElasticConstants elastic;
    Strengths        strengths;
    /** Fracture energy of a crack inserted inside the ply [N/mm]. */
    double fracture_energy = 0.3;
    /** Hoffman plasticity (Materials/Plasticity = hoffman): the strengths
     * are the initial yield surface and grow by 1 + hardening x the
     * equivalent plastic strain; false: elastic up to any stress. */
    bool   plastic   = false;
    double hardening = 0;
  };

  /**
   * The stiffness tensor in material axes. Throws std::invalid_argument
   * (naming the offending constant) unless all moduli are positive and the
   * compliance matrix is positive definite.
   */
  SymmetricTensor<4, 3>
  stiffness_in_material_axes(const ElasticConstants &constants);

  /** Rotation whose columns are the material axes in laminate axes, for a
   * ply at @p angle_degrees about the laminate normal (axis 3 = z). */
  Tensor<2, 3>
  ply_rotation(const double angle_degrees);

  /** C'_{ijkl} = R_ia R_jb R_kc R_ld C_abcd. */
  SymmetricTensor<4, 3>
  rotate(const SymmetricTensor<4, 3> &C, const Tensor<2, 3> &R);

  /** Laminate-axes stress -> material-axes stress (R^T sigma R). */
  SymmetricTensor<2, 3>
  to_material_axes(const SymmetricTensor<2, 3> &stress, const Tensor<2, 3> &R);

  /**
   * The Hoffman (1967) failure index F of a material-axes stress; failure
   * at F = 1. Reference: ../shared/reference/README.md section 4.
   */
  double
  hoffman_index(const SymmetricTensor<2, 3> &stress_material_axes,
                const Strengths             &strengths);

  /**
   * hoffman_index() with its coefficients computed once, for the many
   * stresses of one material the crack check evaluates: a call costs a
   * few multiplications instead of nine divisions.
   */
  class HoffmanIndex
  {
  public:
    explicit HoffmanIndex(const Strengths &strengths);

    double
    operator()(const SymmetricTensor<2, 3> &s) const
    {
      const double components[6]
        = {s[0][0], s[1][1], s[2][2], s[1][2], s[0][2], s[0][1]};
      return (*this)(components);
    }

    /** The index of the stress with components @p s = (11, 22, 33, 23,
     * 13, 12). */
    double
    operator()(const double *s) const
    {
      const double s1 = s[0], s2 = s[1], s3 = s[2];
      return C1 * (s2 - s3) * (s2 - s3) + C2 * (s3 - s1) * (s3 - s1)
             + C3 * (s1 - s2) * (s1 - s2) + C4 * s1 + C5 * s2 + C6 * s3
             + s[3] * s[3] * shear23 + s[4] * s[4] * shear13
             + s[5] * s[5] * shear12;
    }

  private:
    double C1, C2, C3, C4, C5, C6;
    /** 1 / S_ij^2. */
    double shear23, shear13, shear12;
  };

  /**
   * Restrict a 3D laminate-axes tensor to the plane-strain model, whose
   * two axes are laminate x (0) and the thickness direction z (2); the
   * laminate width direction y is the out-of-plane axis.
   */
  template <int dim>
  SymmetricTensor<4, dim>
  restrict_to_model(const SymmetricTensor<4, 3> &C);

  /** The model-dimension part of a 3D laminate-axes tensor (the
   * counterpart of embed_in_3d()). */
  template <int dim>
  SymmetricTensor<2, dim>
  restrict_to_model(const SymmetricTensor<2, 3> &laminate);

  /** Embed a model-dimension strain into 3D laminate axes (plane strain:
   * zero strain components along the width direction). */
  template <int dim>
  SymmetricTensor<2, 3>
  embed_in_3d(const SymmetricTensor<2, dim> &strain);

  /** Axis of the 3D laminate frame (x, y = width, z = thickness) that
   * model axis @p a (0..2) maps to: identity in 3D; in 2D the model y is
   * the thickness and the out-of-plane model z is the laminate width. */
  template <int dim>
  constexpr unsigned int
  laminate_axis(const unsigned int a)
  {
    return dim == 3 ? a : (a == 0 ? 0 : (a == 1 ? 2 : 1));
  }

  /** Voigt order of symmetric 3x3 index pairs: 11, 22, 33, 23, 13, 12. */
  constexpr unsigned int voigt_pairs[6][2]
    = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

  /** Names of the Voigt pairs in model axes, for output columns. */
  constexpr const char *voigt_names[6] = {"xx", "yy", "zz", "yz", "xz", "xy"};
} // namespace amfrac

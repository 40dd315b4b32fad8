#include <amfrac/material/ply_table.h>
#include <amfrac/parameters/input_error.h>

namespace amfrac
{
  namespace
  {
    /** Plane-stress stiffness of a 3D laminate-axes stiffness: the
     * in-plane block of the compliance, inverted (sigma_zz = sigma_xz =
     * sigma_yz = 0). */
    SymmetricTensor<4, 2>
    reduced_stiffness(const SymmetricTensor<4, 3> &C)
    {
      const SymmetricTensor<4, 3> S = invert(C);
      SymmetricTensor<4, 2>       in_plane_compliance;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = k; l < 2; ++l)
              in_plane_compliance[i][j][k][l] = S[i][j][k][l];
      return invert(in_plane_compliance);
    }



    /**
     * Classical lamination theory: the membrane stiffness A/h of the
     * stacking as one homogenized material (the 2D in-plane model). The
     * model ignores bending, so it is refused unless the coupling matrix
     * B vanishes (a symmetric stacking).
     */
    template <int dim>
    PlyProperties<dim>
    homogenized_laminate(const std::vector<PlyProperties<dim>> &plies,
                         const Laminate                        &laminate)
    {
      const double          h = laminate.thickness();
      SymmetricTensor<4, 2> A, B;
      PlyProperties<dim>    result;
      result.density      = 0;
      result.stiffness_3d = 0;
      for (unsigned int p = 0; p < plies.size(); ++p)
        {
          const double t
            = laminate.ply_boundaries[p + 1] - laminate.ply_boundaries[p];
          const double z_mid
            = 0.5
                * (laminate.ply_boundaries[p + 1] + laminate.ply_boundaries[p])
              - 0.5 * h;
          const SymmetricTensor<4, 2> Q
            = reduced_stiffness(plies[p].stiffness_3d);
          A += t * Q;
          B += t * z_mid * Q;
          result.stiffness_3d += (t / h) * plies[p].stiffness_3d;
          result.density += (t / h) * plies[p].density;
          result.layers.push_back({Q, plies[p].rotation, plies[p].strengths});
        }
      if (B.norm() > 1e-10 * A.norm() * h)
        throw InputError("Geometry/Stacking sequence",
                         "Geometry/2D model = in-plane needs a symmetric "
                         "stacking sequence: this one couples membrane "
                         "and bending (|B| / (|A| h) = "
                           + number_text(B.norm() / (A.norm() * h))
                           + "), which a plane-stress model cannot carry");
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              result.stiffness[i][j][k][l] = A[i][j][k][l] / h;
      result.rotation  = Tensor<2, 3>(unit_symmetric_tensor<3>());
      result.strengths = plies.front().strengths;
      return result;
    }
  } // namespace



  template <int dim>
  std::vector<PlyProperties<dim>>
  make_ply_table(const Laminate &laminate, const parameters::Materials &m)
  {
    std::vector<PlyProperties<dim>> table;
    for (unsigned int p = 0; p < laminate.n_plies(); ++p)
      {
        const OrthotropicMaterial &material
          = m.materials[laminate.material_of_ply[p]];
        PlyProperties<dim> ply;
        ply.rotation = ply_rotation(laminate.plies[p].angle);
        ply.stiffness_3d
          = rotate(stiffness_in_material_axes(material.elastic), ply.rotation);
        ply.stiffness       = restrict_to_model<dim>(ply.stiffness_3d);
        ply.strengths       = material.strengths;
        ply.density         = material.elastic.density;
        ply.fracture_energy = material.fracture_energy;
        ply.plastic         = material.plastic;
        ply.hardening       = material.hardening;
        table.push_back(ply);
      }
    if (dim == 2 && laminate.in_plane)
      return {homogenized_laminate(table, laminate)};
    return table;
  }

  template std::vector<PlyProperties<2>>
  make_ply_table<2>(const Laminate &, const parameters::Materials &);
  template std::vector<PlyProperties<3>>
  make_ply_table<3>(const Laminate &, const parameters::Materials &);
} // namespace amfrac

#include <amfrac/material/orthotropic.h>
#include <amfrac/parameters/input_error.h>
#include <cmath>
#include <deal.II/lac/full_matrix.h>
#include <stdexcept>

namespace amfrac
{
  namespace
  {
    /** True if the symmetric matrix @p A admits a Cholesky factorization. */
    bool
    is_positive_definite(const FullMatrix<double> &A)
    {
      const unsigned int n = A.m();
      FullMatrix<double> L(n, n);
      for (unsigned int j = 0; j < n; ++j)
        {
          double d = A(j, j);
          for (unsigned int k = 0; k < j; ++k)
            d -= L(j, k) * L(j, k);
          if (!(d > 0))
            return false;
          L(j, j) = std::sqrt(d);
          for (unsigned int i = j + 1; i < n; ++i)
            {
              double s = A(i, j);
              for (unsigned int k = 0; k < j; ++k)
                s -= L(i, k) * L(j, k);
              L(i, j) = s / L(j, j);
            }
        }
      return true;
    }

    void
    require_positive(const double value, const char *name)
    {
      if (!(value > 0))
        throw std::invalid_argument(
          std::string(name) + " must be positive, got " + number_text(value));
    }
  } // namespace



  SymmetricTensor<4, 3>
  stiffness_in_material_axes(const ElasticConstants &c)
  {
    require_positive(c.E1, "E1");
    require_positive(c.E2, "E2");
    require_positive(c.E3, "E3");
    require_positive(c.G12, "G12");
    require_positive(c.G13, "G13");
    require_positive(c.G23, "G23");

    // Compliance in Voigt form with engineering shear strains.
    FullMatrix<double> S(6, 6);
    S(0, 0) = 1. / c.E1;
    S(1, 1) = 1. / c.E2;
    S(2, 2) = 1. / c.E3;
    S(0, 1) = S(1, 0) = -c.nu12 / c.E1;
    S(0, 2) = S(2, 0) = -c.nu13 / c.E1;
    S(1, 2) = S(2, 1) = -c.nu23 / c.E2;
    S(3, 3)           = 1. / c.G23;
    S(4, 4)           = 1. / c.G13;
    S(5, 5)           = 1. / c.G12;
    if (!is_positive_definite(S))
      throw std::invalid_argument(
        "the compliance matrix of these elastic constants is not positive "
        "definite (check the Poisson ratios nu12, nu13, nu23 against the "
        "moduli: nu_ij^2 < E_i/E_j is necessary)");

    FullMatrix<double> C(6, 6);
    C.invert(S);
    SymmetricTensor<4, 3> stiffness;
    for (unsigned int I = 0; I < 6; ++I)
      for (unsigned int J = 0; J < 6; ++J)
        stiffness[voigt_pairs[I][0]][voigt_pairs[I][1]][voigt_pairs[J][0]]
                 [voigt_pairs[J][1]]
          = C(I, J);
    return stiffness;
  }



  Tensor<2, 3>
  ply_rotation(const double angle_degrees)
  {
    const double theta = angle_degrees * M_PI / 180.;
    const double c = std::cos(theta), s = std::sin(theta);
    Tensor<2, 3> R;
    R[0][0] = c;
    R[0][1] = -s;
    R[1][0] = s;
    R[1][1] = c;
    R[2][2] = 1;
    return R;
  }



  SymmetricTensor<4, 3>
  rotate(const SymmetricTensor<4, 3> &C, const Tensor<2, 3> &R)
  {
    // Contract one index at a time: four passes of 3^5 operations instead
    // of one pass of 3^8.
    Tensor<4, 3> A = C, B;
    for (unsigned int pass = 0; pass < 4; ++pass)
      {
        B = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int l = 0; l < 3; ++l)
                for (unsigned int a = 0; a < 3; ++a)
                  B[i][j][k][l] += R[l][a] * A[a][i][j][k];
        // B[i][j][k][l] = sum_a R_la A_aijk: the new index moves to the
        // back, so four passes restore the original index order.
        A = B;
      }
    SymmetricTensor<4, 3> result;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = k; l < 3; ++l)
            result[i][j][k][l] = A[i][j][k][l];
    return result;
  }



  SymmetricTensor<2, 3>
  to_material_axes(const SymmetricTensor<2, 3> &stress, const Tensor<2, 3> &R)
  {
    return symmetrize(transpose(R) * Tensor<2, 3>(stress) * R);
  }



  HoffmanIndex::HoffmanIndex(const Strengths &f)
  {
    const double XX = 1. / (f.Xt * f.Xc), YY = 1. / (f.Yt * f.Yc),
                 ZZ = 1. / (f.Zt * f.Zc);
    C1              = 0.5 * (YY + ZZ - XX);
    C2              = 0.5 * (ZZ + XX - YY);
    C3              = 0.5 * (XX + YY - ZZ);
    C4              = 1. / f.Xt - 1. / f.Xc;
    C5              = 1. / f.Yt - 1. / f.Yc;
    C6              = 1. / f.Zt - 1. / f.Zc;
    shear23         = 1. / (f.S23 * f.S23);
    shear13         = 1. / (f.S13 * f.S13);
    shear12         = 1. / (f.S12 * f.S12);
  }



  double
  hoffman_index(const SymmetricTensor<2, 3> &s, const Strengths &f)
  {
    return HoffmanIndex(f)(s);
  }



  template <int dim>
  SymmetricTensor<4, dim>
  restrict_to_model(const SymmetricTensor<4, 3> &C)
  {
    SymmetricTensor<4, dim> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = k; l < dim; ++l)
            result[i][j][k][l]
              = C[laminate_axis<dim>(i)][laminate_axis<dim>(j)]
                 [laminate_axis<dim>(k)][laminate_axis<dim>(l)];
    return result;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  embed_in_3d(const SymmetricTensor<2, dim> &strain)
  {
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        result[laminate_axis<dim>(i)][laminate_axis<dim>(j)] = strain[i][j];
    return result;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  restrict_to_model(const SymmetricTensor<2, 3> &laminate)
  {
    SymmetricTensor<2, dim> model;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b)
        model[a][b] = laminate[laminate_axis<dim>(a)][laminate_axis<dim>(b)];
    return model;
  }

  template SymmetricTensor<2, 2>
  restrict_to_model<2>(const SymmetricTensor<2, 3> &);
  template SymmetricTensor<2, 3>
  restrict_to_model<3>(const SymmetricTensor<2, 3> &);
  template SymmetricTensor<4, 2>
  restrict_to_model<2>(const SymmetricTensor<4, 3> &);
  template SymmetricTensor<4, 3>
  restrict_to_model<3>(const SymmetricTensor<4, 3> &);
  template SymmetricTensor<2, 3>
  embed_in_3d<2>(const SymmetricTensor<2, 2> &);
  template SymmetricTensor<2, 3>
  embed_in_3d<3>(const SymmetricTensor<2, 3> &);
} // namespace amfrac

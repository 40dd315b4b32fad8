// The deformed mid-surface frame of an interface point and its first and
// second derivatives, written out by the chain rule through the two
// primitives it is made of: the normalization v / |v| and (in 3D) the
// cross product. unit/deformed_interface_frame checks every derivative
// against central differences.
#include <amfrac/base/cross_matrix.h>
#include <amfrac/cohesive/deformed_frame.h>
#include <deal.II/base/symmetric_tensor.h>

namespace amfrac
{
  namespace cohesive
  {
    namespace
    {
      /** d (v / |v|) / d v = (I - u u^T) / |v|, u = v / |v|. */
      template <int dim>
      Tensor<2, dim>
      normalization_jacobian(const Tensor<1, dim> &v)
      {
        const double         length = v.norm();
        const Tensor<1, dim> u      = v / length;
        return (unit_symmetric_tensor<dim>() - outer_product(u, u)) / length;
      }

      /** The Hessian of w . (v / |v|) with respect to v (w fixed). */
      template <int dim>
      Tensor<2, dim>
      normalization_hessian(const Tensor<1, dim> &v, const Tensor<1, dim> &w)
      {
        const double         length = v.norm();
        const Tensor<1, dim> u      = v / length;
        const Tensor<2, dim> I      = unit_symmetric_tensor<dim>();
        return -(outer_product(w, u) + outer_product(u, w)
                 + (w * u) * (I - 3 * outer_product(u, u)))
               / (length * length);
      }

      /** The quarter turn that takes the tangent to the normal in 2D. */
      Tensor<2, 2>
      quarter_turn()
      {
        Tensor<2, 2> Q;
        Q[0][1] = -1, Q[1][0] = 1;
        return Q;
      }

      /** In 3D: the derivatives of m = b1 x b2 with respect to b1, b2. */
      std::array<Tensor<2, 3>, 2>
      cross_jacobians(const std::array<Tensor<1, 3>, 2> &b)
      {
        return {{-cross_matrix(b[1]), cross_matrix(b[0])}};
      }
    } // namespace



    template <>
    DeformedFrame<2>::DeformedFrame(const Tangents &tangents)
      : b(tangents)
    {
      const Tensor<1, 2> t = b[0] / b[0].norm();
      frame[0]             = quarter_turn() * t;
      frame[1]             = t;
      const Tensor<2, 2> J = normalization_jacobian(b[0]);
      first[0][0]          = quarter_turn() * J;
      first[0][1]          = J;
    }



    template <>
    DeformedFrame<3>::DeformedFrame(const Tangents &tangents)
      : b(tangents)
    {
      const Tensor<1, 3> t1 = b[0] / b[0].norm();
      const Tensor<1, 3> m  = cross_product_3d(b[0], b[1]);
      const Tensor<1, 3> n  = m / m.norm();
      frame[0]              = n;
      frame[1]              = t1;
      frame[2]              = cross_product_3d(n, t1);
      const Tensor<2, 3> Jm = normalization_jacobian(m);
      const auto         M  = cross_jacobians(b);
      for (unsigned int a = 0; a < 2; ++a)
        {
          const Tensor<2, 3> dn = Jm * M[a];
          const Tensor<2, 3> dt1
            = a == 0 ? normalization_jacobian(b[0]) : Tensor<2, 3>();
          first[a][0] = dn;
          first[a][1] = dt1;
          // d (n x t1) = dn x t1 + n x dt1.
          first[a][2] = -cross_matrix(t1) * dn + cross_matrix(n) * dt1;
        }
    }



    template <int dim>
    Tensor<2, dim>
    DeformedFrame<dim>::gap_derivative(const unsigned int    a,
                                       const Tensor<1, dim> &v) const
    {
      Tensor<2, dim> result;
      for (unsigned int i = 0; i < dim; ++i)
        result[i] = v * first[a][i];
      return result;
    }



    template <int dim>
    Tensor<2, dim>
    DeformedFrame<dim>::traction_derivative(const unsigned int    a,
                                            const Tensor<1, dim> &w) const
    {
      Tensor<2, dim> result;
      for (unsigned int i = 0; i < dim; ++i)
        result += w[i] * first[a][i];
      return result;
    }



    template <>
    DeformedFrame<2>::Blocks
    DeformedFrame<2>::hessian(const Tensor<1, 2> &w,
                              const Tensor<1, 2> &v) const
    {
      // phi = w0 (Q t) . v + w1 t . v = t . (w0 Q^T v + w1 v).
      Blocks blocks;
      blocks[0][0] = normalization_hessian(
        b[0], w[0] * (transpose(quarter_turn()) * v) + w[1] * v);
      return blocks;
    }



    template <>
    DeformedFrame<3>::Blocks
    DeformedFrame<3>::hessian(const Tensor<1, 3> &w,
                              const Tensor<1, 3> &v) const
    {
      // phi = w0 n . v + w1 t1 . v + w2 (n x t1) . v: the weights on n and
      // on t1 (the last term is n . (t1 x v) = t1 . (v x n)), then the
      // second derivatives of n(m(b)), of t1(b1) and the mixed term of
      // (n x t1) . v.
      const Tensor<1, 3> &n   = frame[0];
      const Tensor<1, 3> &t1  = frame[1];
      const Tensor<1, 3>  wn  = w[0] * v + w[2] * cross_product_3d(t1, v);
      const Tensor<1, 3>  wt  = w[1] * v + w[2] * cross_product_3d(v, n);
      const Tensor<1, 3>  m   = cross_product_3d(b[0], b[1]);
      const Tensor<2, 3>  Hm  = normalization_hessian(m, wn);
      const Tensor<1, 3>  p   = normalization_jacobian(m) * wn;
      const auto          M   = cross_jacobians(b);
      const Tensor<2, 3>  mix = -w[2] * cross_matrix(v);
      Blocks              blocks;
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int c = 0; c < 2; ++c)
          blocks[a][c]
            = transpose(M[a]) * Hm * M[c]
              + transpose(first[a][0]) * mix * first[c][1]
              + transpose(first[a][1]) * transpose(mix) * first[c][0];
      // m is bilinear in (b1, b2): p . (db1 x db2).
      blocks[0][1] -= cross_matrix(p);
      blocks[1][0] += cross_matrix(p);
      blocks[0][0] += normalization_hessian(b[0], wt);
      return blocks;
    }



    template class DeformedFrame<2>;
    template class DeformedFrame<3>;
  } // namespace cohesive
} // namespace amfrac

#pragma once

#include <array>
#include <deal.II/base/tensor.h>

namespace amfrac
{
  namespace cohesive
  {
    using namespace dealii;

    /**
     * The local frame of an interface point on the deformed mid-surface
     * (total Lagrangian interfaces), and its first and second derivatives.
     *
     * The frame is a function of the convected tangents b_a = (I + grad
     * u_m) T_a of the mid-surface u_m = (u_lower + u_upper) / 2, where T_a
     * are the reference tangents (rows 1.. of the reference frame):
     *   2D: t = b / |b|, n = (-t_y, t_x);
     *   3D: t1 = b1 / |b1|, n = b1 x b2 / |b1 x b2|, t2 = n x t1.
     * At zero displacement it is the reference frame (normal, tangents),
     * and a rigid rotation Q of the mid-surface rotates it by Q: the gap
     * rows() [[u]] does not change under a rigid motion of both faces.
     */
    template <int dim>
    class DeformedFrame
    {
    public:
      using Tangents = std::array<Tensor<1, dim>, dim - 1>;
      /** Blocks of a matrix over (b_1, ..., b_{dim-1}). */
      using Blocks = std::array<std::array<Tensor<2, dim>, dim - 1>, dim - 1>;

      explicit DeformedFrame(const Tangents &b);

      /** Rows: the unit normal, then the unit tangents. */
      const Tensor<2, dim> &
      rows() const
      {
        return frame;
      }

      /** d rows()[i][j] / d b_a[m] as derivative(a)[i][j][m]. */
      const std::array<Tensor<2, dim>, dim> &
      derivative(const unsigned int a) const
      {
        return first[a];
      }

      /** The derivative of rows() @p v with respect to b_a:
       * [i][m] = sum_j v_j d rows()[i][j] / d b_a[m]. */
      Tensor<2, dim>
      gap_derivative(const unsigned int a, const Tensor<1, dim> &v) const;

      /** The derivative of transpose(rows()) @p w with respect to b_a:
       * [j][m] = sum_i w_i d rows()[i][j] / d b_a[m]. */
      Tensor<2, dim>
      traction_derivative(const unsigned int a, const Tensor<1, dim> &w) const;

      /** The Hessian of phi(b) = @p w . rows(b) @p v in blocks (a, c) over
       * (b_a, b_c): the second derivative of the work of a fixed local
       * traction w on a fixed global gap v. */
      Blocks
      hessian(const Tensor<1, dim> &w, const Tensor<1, dim> &v) const;

    private:
      Tangents                                             b;
      Tensor<2, dim>                                       frame;
      std::array<std::array<Tensor<2, dim>, dim>, dim - 1> first;
    };

    template <>
    DeformedFrame<2>::DeformedFrame(const Tangents &b);
    template <>
    DeformedFrame<3>::DeformedFrame(const Tangents &b);
    template <>
    DeformedFrame<2>::Blocks
    DeformedFrame<2>::hessian(const Tensor<1, 2> &w,
                              const Tensor<1, 2> &v) const;
    template <>
    DeformedFrame<3>::Blocks
    DeformedFrame<3>::hessian(const Tensor<1, 3> &w,
                              const Tensor<1, 3> &v) const;
  } // namespace cohesive
} // namespace amfrac

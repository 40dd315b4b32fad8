// Interface elements whose local frame follows the deformed mid-surface
// (total Lagrangian kinematics). The local gap of a point is
//   Delta = R(b) g,  g = [[u]],  b_a = T_a + grad(u_m) T_a,
// R the frame of the convected tangents b_a of the mid-surface u_m (see
// cohesive::DeformedFrame). With the traction T(Delta) of the law per
// reference area, the element force is int B^T T dA with
//   B_k = d Delta / d u_k = R e_c s_k + sum_a (dR/db_a g) e_c d_ak
// (s_k the gap's shape value, d_ak the mid-surface's derivative along T_a,
// c the component of dof k), and its derivative adds to B^T D B the
// derivative of the frame under the fixed traction:
//   s_k (dR^T T/db_a)[c_k][c_l] d_al + (k <-> l)
//   + d_ak d_bl d2(T . R g)/db_a db_b [c_k][c_l].
#include <amfrac/cohesive/interface_assembler.h>

namespace amfrac
{
  template <int dim>
  cohesive::DeformedFrame<dim>
  CohesiveInterfaces<dim>::deformed_kinematics(
    const Element                &element,
    const unsigned int            q,
    const dealii::Vector<double> &u,
    Tensor<1, dim>               &global_gap,
    std::vector<Tensor<1, dim>>  &B) const
  {
    const unsigned int                              n = element.dofs.size();
    typename cohesive::DeformedFrame<dim>::Tangents b;
    for (unsigned int a = 0; a + 1 < dim; ++a)
      b[a] = element.frame[q][a + 1];
    global_gap = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int c = element.component[k];
        global_gap[c] += element.shape(q, k) * u(k);
        for (unsigned int a = 0; a + 1 < dim; ++a)
          b[a][c] += element.tangent_shape[a](q, k) * u(k);
      }
    const cohesive::DeformedFrame<dim>  frame(b);
    std::array<Tensor<2, dim>, dim - 1> G;
    for (unsigned int a = 0; a + 1 < dim; ++a)
      G[a] = frame.gap_derivative(a, global_gap);
    const Tensor<2, dim> &R = frame.rows();
    B.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int c = element.component[k];
        for (unsigned int i = 0; i < dim; ++i)
          {
            B[k][i] = R[i][c] * element.shape(q, k);
            for (unsigned int a = 0; a + 1 < dim; ++a)
              B[k][i] += G[a][i][c] * element.tangent_shape[a](q, k);
          }
      }
    return frame;
  }



  template <int dim>
  void
  CohesiveInterfaces<dim>::deformed_element(
    const Element                &element,
    const dealii::Vector<double> &u,
    dealii::Vector<double>       &r,
    FullMatrix<double>           *K,
    std::vector<PointState>      *trial) const
  {
    const unsigned int          n = element.dofs.size();
    std::vector<Tensor<1, dim>> B, DB(n);
    Tensor<1, dim>              g;
    Tensor<2, dim>              D;
    for (unsigned int q = 0; q < element.JxW.size(); ++q)
      {
        const auto       frame = deformed_kinematics(element, q, u, g, B);
        const PointState state
          = evaluate(element.converged[q], frame.rows() * g, D);
        if (trial)
          (*trial)[q] = state;
        const double         JxW = element.JxW[q];
        const Tensor<1, dim> T   = state.traction + state.viscous;
        for (unsigned int k = 0; k < n; ++k)
          r(k) += JxW * (T * B[k]);
        if (!K)
          continue;
        std::array<Tensor<2, dim>, dim - 1> H;
        for (unsigned int a = 0; a + 1 < dim; ++a)
          H[a] = frame.traction_derivative(a, T);
        const auto Phi = frame.hessian(T, g);
        for (unsigned int l = 0; l < n; ++l)
          DB[l] = D * B[l];
        const auto &d = element.tangent_shape;
        for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int ck = element.component[k];
            const double       sk = element.shape(q, k);
            for (unsigned int l = 0; l < n; ++l)
              {
                const unsigned int cl    = element.component[l];
                const double       sl    = element.shape(q, l);
                double             value = B[k] * DB[l];
                for (unsigned int a = 0; a + 1 < dim; ++a)
                  {
                    value += sk * H[a][ck][cl] * d[a](q, l)
                             + sl * H[a][cl][ck] * d[a](q, k);
                    for (unsigned int c = 0; c + 1 < dim; ++c)
                      value += d[a](q, k) * d[c](q, l) * Phi[a][c][ck][cl];
                  }
                (*K)(k, l) += JxW * value;
              }
          }
      }
  }



  template class CohesiveInterfaces<2>;
  template class CohesiveInterfaces<3>;
} // namespace amfrac

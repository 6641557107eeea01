// Building blocks of the total Lagrangian kernels (solid_kernels.hpp).
#include <Eigen/LU>

#include "core/error.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

void b_nonlinear(const ShapeGrad& dNdX, const Mat3& F, BMatrix& B) {
  const int n = static_cast<int>(dNdX.rows());
  B.setZero(6, 3 * n);
  for (int a = 0; a < n; ++a) {
    const Real g0 = dNdX(a, 0), g1 = dNdX(a, 1), g2 = dNdX(a, 2);
    for (int k = 0; k < 3; ++k) {
      B(0, 3 * a + k) = F(k, 0) * g0;
      B(1, 3 * a + k) = F(k, 1) * g1;
      B(2, 3 * a + k) = F(k, 2) * g2;
      B(3, 3 * a + k) = F(k, 0) * g1 + F(k, 1) * g0;
      B(4, 3 * a + k) = F(k, 0) * g2 + F(k, 2) * g0;
      B(5, 3 * a + k) = F(k, 1) * g2 + F(k, 2) * g1;
    }
  }
}

void add_initial_stress_stiffness(const ShapeGrad& dNdX, const Mat3& S, Real dv, MatX& K) {
  const int n = static_cast<int>(dNdX.rows());
  const MatX G = dNdX * S * dNdX.transpose();  // n x n
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < 3; ++c) K(3 * a + c, 3 * b + c) += dv * G(a, b);
}

Mat3 deformation_gradient(const ShapeGrad& dNdX, const MatX3& u) {
  return Mat3::Identity() + u.transpose() * dNdX;  // F_ij = d_ij + du_i/dX_j
}

Mat3 tensor_from_voigt(const Vec6& s) {
  Mat3 t;
  t << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
  return t;
}

Vec6 voigt_from_tensor(const Mat3& t) {
  Vec6 v;
  v << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(0, 2), t(1, 2);
  return v;
}

void integrate_total_lagrangian(const std::vector<KernelPoint>& points, const MatX3& u,
                                bool want_tangent,
                                const TotalLagrangianMaterial& material, VecX& f, MatX& K,
                                MatX6& cauchy, MatX6& green_lagrange) {
  const int n = static_cast<int>(u.rows());
  const Index nip = static_cast<Index>(points.size());
  f.setZero(3 * n);
  if (want_tangent) K.setZero(3 * n, 3 * n);
  cauchy.resize(nip, 6);
  green_lagrange.resize(nip, 6);
  BMatrix B, Bm;
  for (Index k = 0; k < nip; ++k) {
    const KernelPoint& p = points[k];
    const Mat3 F = deformation_gradient(p.dNdX, u);
    const Real thermal = p.material.thermal_strain;
    const Mat3 Fm = mechanical_deformation_gradient(F, thermal);
    const Real J = F.determinant();
    if (!(J > 0) || !(Fm.determinant() > 0))
      throw SolverError("the element is inverted (det F <= 0)");
    const TotalLagrangianResponse r = material(k, F, Fm);
    const Mat3 S = tensor_from_voigt(r.stress);
    cauchy.row(k) = voigt_from_tensor(F * S * F.transpose() / J).transpose();
    green_lagrange.row(k) =
        voigt_from_tensor(0.5 * (F.transpose() * F - Mat3::Identity())).transpose();
    b_nonlinear(p.dNdX, F, B);
    f.noalias() += p.dv * (B.transpose() * r.stress);
    if (!want_tangent) continue;
    if (thermal != 0) {
      b_nonlinear(p.dNdX, Fm, Bm);  // the material responds to dE_m = B_NL(F_m) du
      K.noalias() += p.dv * (B.transpose() * r.tangent * Bm);
    } else {
      K.noalias() += p.dv * (B.transpose() * r.tangent * B);
    }
    add_initial_stress_stiffness(p.dNdX, S, p.dv, K);
  }
}

}  // namespace kontakt::element

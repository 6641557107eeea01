// C3D8R hourglass control: Flanagan & Belytschko (1981) orthogonal hourglass vectors with a
// stiffness-type coefficient. Scaling measured against ccx 2.20 (pure hourglass modes on
// boxes): k = 0.032 * E * sum_iI(B_iI^2) / V, with B_iI = integral of dN_I/dx_i over the element,
// independent of Poisson's ratio, for linear elasticity; for a *PLASTIC material ccx puts the
// current C_1111 of the material tangent in place of E (measured: lambda + 2 mu at rest, and
// following the xx entry under stretch in x or y, elastic or yielding).
#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {
namespace {

constexpr Real kHourglassScale = 0.032;

// Hourglass base vectors xi*eta, eta*zeta, zeta*xi, xi*eta*zeta at the 8 corners.
Eigen::Matrix<Real, 8, 4> hourglass_base() {
  Eigen::Matrix<Real, 8, 4> h;
  for (int a = 0; a < 8; ++a) {
    const Vec3 p = reference_node(Topology::Hex8, a);
    h.row(a) << p(0) * p(1), p(1) * p(2), p(2) * p(0), p(0) * p(1) * p(2);
  }
  return h;
}

}  // namespace

void mean_gradients(const MatX3& X, ShapeGrad& b, Real& volume) {
  KONTAKT_REQUIRE(X.rows() == 8, "C3D8R needs 8 nodes");
  b.setZero(8, 3);
  volume = 0;
  for (const auto& q : volume_rule(ElementType::C3D8)) {  // exact for the trilinear map
    const PointGeometry g = point_geometry(Topology::Hex8, X, q.xi);
    b += (q.weight * g.detJ) * g.dNdx;
    volume += q.weight * g.detJ;
  }
  b /= volume;
}

void hourglass_stiffness(const MatX3& X, Real modulus, MatX& Khg) {
  ShapeGrad bg;
  Real volume = 0;
  mean_gradients(X, bg, volume);
  const Eigen::Matrix<Real, 8, 3> b = bg;
  const Real sum_BB = volume * volume * b.squaredNorm();  // sum of (integral dN/dx)^2
  static const Eigen::Matrix<Real, 8, 4> h = hourglass_base();
  const Eigen::Matrix<Real, 8, 3> Xf = X;
  // gamma = (h - b (X^T h)) / 8: orthogonal to the linear field.
  const Eigen::Matrix<Real, 8, 4> gamma = (h - b * (Xf.transpose() * h)) / 8;
  const Real k = kHourglassScale * modulus * sum_BB / volume;
  const Eigen::Matrix<Real, 8, 8> G = k * gamma * gamma.transpose();
  Khg.setZero(24, 24);
  for (int a = 0; a < 8; ++a)
    for (int c = 0; c < 8; ++c)
      for (int d = 0; d < 3; ++d) Khg(3 * a + d, 3 * c + d) = G(a, c);
}

}  // namespace kontakt::element

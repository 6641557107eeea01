#include "material/hyperelastic.hpp"

#include <Eigen/LU>
#include <cmath>

#include "core/error.hpp"
#include "material/symmetric_voigt.hpp"

namespace kontakt::material {

HyperelasticResponse polynomial_hyperelastic(const HyperelasticPolynomial& p, const Mat3& C) {
  const Real det = C.determinant();
  if (!(det > 0)) throw SolverError("hyperelastic: det C <= 0 (inverted material)");
  const Real J = std::sqrt(det);
  const Mat3 Ci = C.inverse();
  const Real I1 = C.trace(), I2 = 0.5 * (I1 * I1 - (C * C).trace());

  // The invariants x = (I1, I2, J): their first and second derivatives with respect to C.
  const Vec6 one = voigt(Mat3::Identity());
  const std::array<Vec6, 3> dx = {one, I1 * one - voigt(C), 0.5 * J * voigt(Ci)};
  Mat6 sym_identity = Mat6::Zero();
  sym_identity.diagonal() << 1, 1, 1, 0.5, 0.5, 0.5;
  const std::array<Mat6, 3> ddx = {
      Mat6::Zero(), one * one.transpose() - sym_identity,
      0.25 * J * voigt(Ci) * voigt(Ci).transpose() + 0.5 * J * inverse_derivative(Ci)};

  // f1 = J^-2/3 I1 - 3 and f2 = J^-4/3 I2 - 3 with their gradients and Hessians in x.
  const Real j23 = std::pow(J, -2.0 / 3), j43 = j23 * j23;
  const Real f1 = j23 * I1 - 3, f2 = j43 * I2 - 3;
  const Vec3 g1(j23, 0, -2.0 / 3 * j23 / J * I1), g2(0, j43, -4.0 / 3 * j43 / J * I2);
  Mat3 h1 = Mat3::Zero(), h2 = Mat3::Zero();
  h1(0, 2) = h1(2, 0) = -2.0 / 3 * j23 / J;
  h1(2, 2) = 10.0 / 9 * j23 / (J * J) * I1;
  h2(1, 2) = h2(2, 1) = -4.0 / 3 * j43 / J;
  h2(2, 2) = 28.0 / 9 * j43 / (J * J) * I2;

  // U(f1, f2) of the deviatoric part: value, gradient and Hessian.
  Real U = 0, U1 = 0, U2 = 0, U11 = 0, U12 = 0, U22 = 0;
  const auto power = [](Real base, int n) { return n <= 0 ? 1.0 : std::pow(base, n); };
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j) {
      const Real c = p.c[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      if (c == 0 || i + j == 0) continue;
      U += c * power(f1, i) * power(f2, j);
      U1 += c * i * power(f1, i - 1) * power(f2, j);
      U2 += c * j * power(f1, i) * power(f2, j - 1);
      U11 += c * i * (i - 1) * power(f1, i - 2) * power(f2, j);
      U12 += c * i * j * power(f1, i - 1) * power(f2, j - 1);
      U22 += c * j * (j - 1) * power(f1, i) * power(f2, j - 2);
    }
  Vec3 W = U1 * g1 + U2 * g2;
  Mat3 H = U11 * g1 * g1.transpose() + U12 * (g1 * g2.transpose() + g2 * g1.transpose()) +
           U22 * g2 * g2.transpose() + U1 * h1 + U2 * h2;
  // The volumetric part sum (J - 1)^2k / D_k.
  for (int k = 1; k <= 3; ++k) {
    const Real d = p.d[static_cast<std::size_t>(k - 1)];
    if (d == 0) continue;
    U += power(J - 1, 2 * k) / d;
    W(2) += 2 * k * power(J - 1, 2 * k - 1) / d;
    H(2, 2) += 2 * k * (2 * k - 1) * power(J - 1, 2 * k - 2) / d;
  }

  // S = 2 dU/dC and dS/dE = 4 d2U/dC2 by the chain rule through x.
  HyperelasticResponse r;
  r.energy = U;
  for (int a = 0; a < 3; ++a) {
    r.stress += 2 * W(a) * dx[static_cast<std::size_t>(a)];
    r.tangent += 4 * W(a) * ddx[static_cast<std::size_t>(a)];
    for (int b = 0; b < 3; ++b)
      r.tangent += 4 * H(a, b) * dx[static_cast<std::size_t>(a)] *
                   dx[static_cast<std::size_t>(b)].transpose();
  }
  return r;
}

}  // namespace kontakt::material

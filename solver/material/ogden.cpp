#include "material/ogden.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/error.hpp"
#include "material/symmetric_voigt.hpp"

// Method: both potentials are U(x) of the scalars x = (T_1, T_2, T_3, J), T_i = sum_k c_k^p_i
// (p_i = alpha_i / 2) and J = sqrt(c1 c2 c3) of the eigenvalues c_k of C, so U is a symmetric
// function Phi(c). In the eigenbasis Q of C the spectral chain rule gives
//   S = 2 sum_k Phi_k q_k q_k^T,
//   Q^T dS Q = 2 [diag(sum_l Phi_kl M_ll) + theta_kl M_kl (k != l)],   M = Q^T dC Q,
// with theta_kl = (Phi_k - Phi_l) / (c_k - c_l) (Daleckii-Krein). Every x here has
// dx/dc_k = s(c) f(c_k) with s symmetric, so theta is a sum of divided differences of powers
// c^q, evaluated through expm1 of log(c_k / c_l): no cancellation for close eigenvalues and the
// exact limit (the second derivative) for coincident ones, where the eigenvectors are not unique
// but theta is constant over the coincident block, so any orthonormal Q gives the same S and
// tangent. Exact and perturbation-free, unlike the forward-differentiated eigenvalues, whose
// eigenvector derivatives are singular at C = I and in uniaxial states.

namespace kontakt::material {

namespace {

using Vec4 = Eigen::Matrix<Real, 4, 1>;
using Mat4 = Eigen::Matrix<Real, 4, 4>;

/// (a^q - b^q) / (a - b) for a, b > 0, and its limit q a^(q-1) at a = b.
Real power_divided_difference(Real a, Real b, Real q) {
  if (a == b) return q * std::pow(a, q - 1);
  const Real t = std::log1p((a - b) / b);  // log(a / b) without losing the digits of a - b
  return std::pow(b, q - 1) * std::expm1(q * t) / std::expm1(t);
}

/// A symmetric scalar function x(c) of the eigenvalues and what the spectral chain rule needs:
/// dx/dc_k, d2x/dc_k dc_l and the divided differences (dx/dc_k - dx/dc_l) / (c_k - c_l)
/// (k != l; the diagonal is unused).
struct SpectralScalar {
  Real value = 0;
  Vec3 gradient = Vec3::Zero();
  Mat3 hessian = Mat3::Zero();
  Mat3 divided_difference = Mat3::Zero();
};

/// T = sum_k c_k^p.
SpectralScalar power_sum(const Vec3& c, Real p) {
  SpectralScalar x;
  for (int k = 0; k < 3; ++k) {
    x.value += std::pow(c(k), p);
    x.gradient(k) = p * std::pow(c(k), p - 1);
    x.hessian(k, k) = p * (p - 1) * std::pow(c(k), p - 2);
    for (int l = 0; l < 3; ++l)
      if (l != k) x.divided_difference(k, l) = p * power_divided_difference(c(k), c(l), p - 1);
  }
  return x;
}

/// J = sqrt(c1 c2 c3): dJ/dc_k = J / (2 c_k).
SpectralScalar volume_ratio(const Vec3& c) {
  SpectralScalar x;
  x.value = std::sqrt(c.prod());
  const Real J = x.value;
  for (int k = 0; k < 3; ++k) {
    x.gradient(k) = J / (2 * c(k));
    for (int l = 0; l < 3; ++l) {
      x.hessian(k, l) = J / (4 * c(k) * c(l)) - (k == l ? J / (2 * c(k) * c(k)) : 0);
      if (l != k) x.divided_difference(k, l) = -J / (2 * c(k) * c(l));
    }
  }
  return x;
}

struct Principal {
  Vec3 c;  ///< eigenvalues of C (squared principal stretches)
  Mat3 Q;  ///< orthonormal eigenvectors, one a column
};

Principal principal(const Mat3& C) {
  // The iterative solver: its eigenvectors stay orthonormal for (nearly) equal eigenvalues.
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(C);
  if (eigen.info() != Eigen::Success) throw SolverError("hyperelastic: no eigenvalues of C");
  const Vec3 c = eigen.eigenvalues();
  for (int k = 0; k < 3; ++k)
    if (!(c(k) > 0)) throw SolverError("hyperelastic: C not positive definite (inverted material)");
  return {c, eigen.eigenvectors()};
}

/// S and dS/dE from U(x), its gradient dU and Hessian ddU in x = (T_1, T_2, T_3, J); entries
/// of unused terms are zero.
HyperelasticResponse spectral_response(const Principal& s, const std::array<SpectralScalar, 4>& x,
                                       Real U, const Vec4& dU, const Mat4& ddU) {
  Vec3 phi = Vec3::Zero();    // dU/dc_k
  Mat3 phi2 = Mat3::Zero();   // d2U/dc_k dc_l
  Mat3 theta = Mat3::Zero();  // (phi_k - phi_l) / (c_k - c_l)
  for (std::size_t a = 0; a < 4; ++a) {
    const Real dUa = dU(static_cast<Index>(a));
    phi += dUa * x[a].gradient;
    phi2 += dUa * x[a].hessian;
    theta += dUa * x[a].divided_difference;
    for (std::size_t b = 0; b < 4; ++b)
      phi2 += ddU(static_cast<Index>(a), static_cast<Index>(b)) * x[a].gradient *
              x[b].gradient.transpose();
  }
  HyperelasticResponse r;
  r.energy = U;
  r.stress = voigt(s.Q * (2 * phi).asDiagonal() * s.Q.transpose());
  // One column per unit engineering strain dE: dC = 2 dE.
  for (int col = 0; col < 6; ++col) {
    Mat3 dC = Mat3::Zero();
    dC(kVoigtI[col], kVoigtJ[col]) = dC(kVoigtJ[col], kVoigtI[col]) = 1;
    if (col < 3) dC *= 2;
    const Mat3 M = s.Q.transpose() * dC * s.Q;
    Mat3 dS = theta.cwiseProduct(M);
    dS.diagonal() = phi2 * M.diagonal();
    r.tangent.col(col) = voigt(s.Q * (2 * dS) * s.Q.transpose());
  }
  return r;
}

}  // namespace

HyperelasticResponse ogden_hyperelastic(const Ogden& p, const Mat3& C) {
  const Principal s = principal(C);
  std::array<SpectralScalar, 4> x;
  x[3] = volume_ratio(s.c);
  const Real J = x[3].value;
  Real U = 0;
  Vec4 dU = Vec4::Zero();
  Mat4 ddU = Mat4::Zero();
  // Term i: k J^m T_i - 3 k with k = 2 mu / alpha^2, m = -alpha / 3 (the isochoric stretches).
  for (int i = 0; i < p.n_terms; ++i) {
    const std::size_t t = static_cast<std::size_t>(i);
    x[t] = power_sum(s.c, p.alpha[t] / 2);
    const Real k = 2 * p.mu[t] / (p.alpha[t] * p.alpha[t]), m = -p.alpha[t] / 3;
    const Real w = k * std::pow(J, m), T = x[t].value;
    U += w * T - 3 * k;
    dU(i) = w;
    dU(3) += m * w / J * T;
    ddU(i, 3) = ddU(3, i) = m * w / J;
    ddU(3, 3) += m * (m - 1) * w / (J * J) * T;
  }
  for (int i = 1; i <= 3; ++i) {
    const Real d = p.d[static_cast<std::size_t>(i - 1)];
    if (d == 0) continue;
    U += std::pow(J - 1, 2 * i) / d;
    dU(3) += 2 * i * std::pow(J - 1, 2 * i - 1) / d;
    ddU(3, 3) += 2 * i * (2 * i - 1) * std::pow(J - 1, 2 * i - 2) / d;
  }
  return spectral_response(s, x, U, dU, ddU);
}

HyperelasticResponse hyperfoam(const Hyperfoam& p, const Mat3& C) {
  const Principal s = principal(C);
  std::array<SpectralScalar, 4> x;
  x[3] = volume_ratio(s.c);
  const Real J = x[3].value, log_J = std::log(J);
  Real U = 0;
  Vec4 dU = Vec4::Zero();
  Mat4 ddU = Mat4::Zero();
  // Term i: k [T_i - 3 + v(J)], k = 2 mu / alpha^2, v = (J^(-alpha beta) - 1) / beta.
  for (int i = 0; i < p.n_terms; ++i) {
    const std::size_t t = static_cast<std::size_t>(i);
    x[t] = power_sum(s.c, p.alpha[t] / 2);
    const Real alpha = p.alpha[t], beta = p.beta[t], k = 2 * p.mu[t] / (alpha * alpha);
    const Real v = beta == 0 ? -alpha * log_J : std::expm1(-alpha * beta * log_J) / beta;
    const Real power = std::pow(J, -alpha * beta);  // J^(-alpha beta)
    U += k * (x[t].value - 3 + v);
    dU(i) = k;
    dU(3) += k * -alpha * power / J;
    ddU(3, 3) += k * alpha * (alpha * beta + 1) * power / (J * J);
  }
  return spectral_response(s, x, U, dU, ddU);
}

}  // namespace kontakt::material

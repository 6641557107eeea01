#include "material/j2_finite_kinematic.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/AutoDiff>

#include "core/error.hpp"

namespace kontakt::material {

namespace {

using Dual = Eigen::AutoDiffScalar<Vec6>;  // derivatives with respect to E (engineering shear)
template <class S>
using M3 = Eigen::Matrix<S, 3, 3>;

template <class S>
M3<S> tensor(const Vec6& v) {
  M3<S> t;
  t << S(v[0]), S(v[3]), S(v[4]), S(v[3]), S(v[1]), S(v[5]), S(v[4]), S(v[5]), S(v[2]);
  return t;
}

template <class S>
Eigen::Matrix<S, 6, 1> voigt6(const M3<S>& t) {
  Eigen::Matrix<S, 6, 1> v;
  v << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(0, 2), t(1, 2);
  return v;
}

/// Everything of the point at C (any scalar) for the pieces ki (radius) and kk (kinematic) the
/// return ends on; `plastic` false: the elastic trial state.
template <class S>
struct PointResponse {
  Eigen::Matrix<S, 6, 1> stress;
  S f_trial, dg;
  M3<S> P_new, G_new;
};

template <class S>
PointResponse<S> respond(Real mu, Real bulk, const M3<S>& C, const M3<S>& P, const M3<S>& G,
                         Real alpha_n, Real radius_n, Real hk_n, const HardeningPiece& radius,
                         const HardeningPiece& kin, bool plastic) {
  using std::pow;
  using std::sqrt;
  const S det = C.determinant();
  const S J = sqrt(det);
  const M3<S> Ci = C.inverse();
  const S j23 = pow(J, -2.0 / 3.0);
  const M3<S> Pb = j23 * P, Gb = j23 * G;
  const S ie = (C * Pb).trace() / 3.0, ig = (C * Gb).trace() / 3.0;
  const M3<S> s = mu * (Pb - ie * Ci), b = Gb - ig * Ci;
  const M3<S> xi = s - b;
  const M3<S> xc = xi * C;
  const S norm = sqrt((xc * xc).trace());
  const Real r23 = std::sqrt(2.0 / 3.0);
  PointResponse<S> out;
  out.f_trial = norm - r23 * J * radius_n;
  const S pressure = 0.5 * bulk * (J * J - 1.0);
  if (!plastic) {
    out.stress = voigt6<S>(pressure * Ci + s);
    out.dg = S(0.0);
    out.P_new = P;
    out.G_new = G;
    return out;
  }
  const S m = mu * ie - ig;
  // The residual is linear in dg on the pieces: a - b dg = 0 with a = residual at dg = 0.
  const S a = norm - r23 * J * radius.at(alpha_n) - m * r23 * J * (kin.at(alpha_n) - hk_n) / mu;
  const S slope = (2.0 / 3.0) * J * radius.slope + m * (2.0 + (2.0 / 3.0) * J * kin.slope / mu);
  out.dg = a / slope;
  const S c = 2.0 * m * out.dg / norm;
  out.stress = voigt6<S>(pressure * Ci + s - c * xi);
  const S j23_inv = 1.0 / j23;
  out.P_new = P - (c / mu) * j23_inv * xi;
  out.G_new = G + (c / (3.0 * mu)) * J * kin.slope * j23_inv * xi;
  return out;
}

}  // namespace

J2FiniteKinematicResult j2_finite_kinematic(Real young, Real poisson,
                                            const HardeningTable& kinematic,
                                            const HardeningTable* cyclic,
                                            const J2KinematicState& committed, const Mat3& C) {
  check_elastic_constants(young, poisson);
  kinematic.validate();
  if (cyclic) cyclic->validate();
  if (!(C.determinant() > 0.0))
    throw SolverError("finite-strain J2: det C <= 0 (inverted material)");
  const Real mu = young / (2.0 * (1.0 + poisson));
  const Real bulk = young / (3.0 * (1.0 - 2.0 * poisson));
  const Real alpha_n = committed.equivalent_plastic_strain;
  const Real radius_n = cyclic ? cyclic->yield(alpha_n) : kinematic.points.front().first;
  const Real hk_n = kinematic.yield(alpha_n);
  const Mat3 P = Mat3::Identity() - 2.0 * tensor<Real>(committed.plastic_strain);
  const Mat3 G = tensor<Real>(committed.back_stress);

  std::size_t ki = cyclic ? cyclic->segment(alpha_n) : 0, kk = kinematic.segment(alpha_n);
  auto radius_piece = [&](std::size_t k) {
    return cyclic ? cyclic->piece(k) : HardeningPiece{radius_n, 0.0, 0.0};
  };
  const auto trial = respond<Real>(mu, bulk, C, P, G, alpha_n, radius_n, hk_n, {}, {}, false);
  const bool plastic = trial.f_trial > 1e-10 * radius_n * std::sqrt(C.determinant());
  if (plastic) {  // walk the pieces until the return ends on the ones it was solved on
    for (std::size_t it = 0;; ++it) {
      const HardeningPiece pr = radius_piece(ki), pk = kinematic.piece(kk);
      const auto r = respond<Real>(mu, bulk, C, P, G, alpha_n, radius_n, hk_n, pr, pk, true);
      if (!(r.dg > 0) || it > kinematic.points.size() + (cyclic ? cyclic->points.size() : 0) + 2)
        throw SolverError("finite-strain kinematic J2: the return mapping failed");
      const Real alpha = alpha_n + std::sqrt(2.0 / 3.0) * r.dg;
      const Real end = std::min(pr.end, pk.end);
      if (alpha <= end) break;
      if (pr.end <= pk.end) ++ki;
      if (pk.end <= pr.end) ++kk;
    }
  }
  // The same at C as a function of E, for the tangent.
  M3<Dual> Cd;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Cd(i, j) = Dual(C(i, j), Vec6::Zero());
  static constexpr int kI[6] = {0, 1, 2, 0, 0, 1}, kJ[6] = {0, 1, 2, 1, 2, 2};
  for (int q = 0; q < 6; ++q) {  // C = 1 + 2 E: dC_ii = 2 dE_ii, dC_ij = dC_ji = dgamma_ij
    Cd(kI[q], kJ[q]).derivatives()[q] += q < 3 ? 2.0 : 1.0;
    if (q >= 3) Cd(kJ[q], kI[q]).derivatives()[q] += 1.0;
  }
  const auto r = respond<Dual>(mu, bulk, Cd, P.cast<Dual>(), G.cast<Dual>(), alpha_n, radius_n,
                               hk_n, radius_piece(ki), kinematic.piece(kk), plastic);
  J2FiniteKinematicResult out;
  for (int i = 0; i < 6; ++i) {
    out.stress[i] = r.stress[i].value();
    out.tangent.row(i) = r.stress[i].derivatives().transpose();
  }
  out.state = committed;
  if (plastic) {
    M3<Real> Pn, Gn;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Pn(i, j) = r.P_new(i, j).value();
        Gn(i, j) = r.G_new(i, j).value();
      }
    out.delta_alpha = std::sqrt(2.0 / 3.0) * r.dg.value();
    out.state.plastic_strain = voigt6<Real>(0.5 * (Mat3::Identity() - Pn));
    out.state.back_stress = voigt6<Real>(Gn);
    out.state.equivalent_plastic_strain = alpha_n + out.delta_alpha;
    out.yielded = true;
  }
  return out;
}

}  // namespace kontakt::material

#include "material/j2_kinematic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"
#include "material/symmetric_voigt.hpp"

namespace kontakt::material {

J2KinematicResult j2_kinematic_return_map(Real young, Real poisson, const HardeningTable& kinematic,
                                          const HardeningTable* cyclic,
                                          const J2KinematicState& committed, const Vec6& strain,
                                          Real thermal_strain) {
  const Mat6 c_el = isotropic_elastic_stiffness(young, poisson);  // validates E, nu
  kinematic.validate();
  if (cyclic) cyclic->validate();
  const Real mu = young / (2.0 * (1.0 + poisson));
  const Real bulk = young / (3.0 * (1.0 - 2.0 * poisson));

  Vec6 eps_e = strain;
  eps_e.tail<3>() *= 0.5;
  eps_e.head<3>().array() -= thermal_strain;
  eps_e -= committed.plastic_strain;
  const Real volumetric = eps_e(0) + eps_e(1) + eps_e(2);
  const Vec6 s_trial = 2.0 * mu * deviator(eps_e);
  const Vec6 xi_trial = s_trial - committed.back_stress;  // relative stress
  const Real xi_norm = tensor_norm(xi_trial);
  const Real q_trial = std::sqrt(1.5) * xi_norm;

  const Real alpha_n = committed.equivalent_plastic_strain;
  const Real hk_n = kinematic.yield(alpha_n);
  const Real radius_n = cyclic ? cyclic->yield(alpha_n) : kinematic.points.front().first;

  J2KinematicResult out;
  out.state = committed;
  Vec6 pressure_part = Vec6::Zero();
  pressure_part.head<3>().setConstant(bulk * volumetric);

  const Real f_trial = q_trial - radius_n;
  if (!(f_trial > 1e-12 * std::max(radius_n, q_trial))) {
    out.stress = s_trial + pressure_part;
    out.tangent = c_el;
    return out;
  }

  // r(dg) = q_trial - 3 mu dg - [Hk(alpha_n + dg) - Hk(alpha_n)] - R(alpha_n + dg): piecewise
  // linear with the union of both tables' breakpoints. Newton steps are exact on a piece;
  // a step leaving the piece stops at the nearer breakpoint and the walk continues.
  std::size_t kk = kinematic.segment(alpha_n);
  std::size_t ki = cyclic ? cyclic->segment(alpha_n) : 0;
  auto radius_piece = [&](std::size_t k) {
    if (cyclic) return cyclic->piece(k);
    return HardeningPiece{radius_n, 0.0, 0.0};
  };
  const Real scale = std::max(q_trial, radius_n);
  const std::size_t max_iter = kinematic.points.size() + (cyclic ? cyclic->points.size() : 0) + 20;
  Real dg = 0.0;
  bool converged = false;
  for (std::size_t it = 0; it < max_iter; ++it) {
    const HardeningPiece pk = kinematic.piece(kk);
    const HardeningPiece pi = radius_piece(ki);
    const Real denom = 3.0 * mu + pk.slope + pi.slope;
    if (!(denom > 0.0))
      throw std::invalid_argument(
          "*PLASTIC: softening slope steeper than -3G makes the return mapping ill-posed");
    const Real a = alpha_n + dg;
    const Real r = q_trial - 3.0 * mu * dg - (pk.at(a) - hk_n) - pi.at(a);
    if (it > 0 && std::abs(r) <= 1e-13 * scale) {
      converged = true;
      break;
    }
    const Real next = dg + r / denom;
    const Real bk = pk.end, bi = pi.end;
    if (alpha_n + next > std::min(bk, bi)) {
      dg = std::min(bk, bi) - alpha_n;
      if (bk <= bi) ++kk;
      if (bi <= bk) ++ki;
      continue;
    }
    dg = next;
  }
  const HardeningPiece pk = kinematic.piece(kk);
  const HardeningPiece pi = radius_piece(ki);
  if (!converged) {
    const Real a = alpha_n + dg;
    const Real r = q_trial - 3.0 * mu * dg - (pk.at(a) - hk_n) - pi.at(a);
    if (!(std::abs(r) <= 1e-10 * scale) || !(dg >= 0.0))
      throw NonConvergence("J2 kinematic return mapping: local Newton iteration did not converge");
  }

  const Real alpha = alpha_n + dg;
  const Vec6 n = xi_trial / xi_norm;
  const Real h_total = pk.slope + pi.slope;
  const Real theta = 1.0 - 3.0 * mu * dg / q_trial;
  const Real theta_bar = 3.0 * mu / (3.0 * mu + h_total) - (1.0 - theta);

  out.stress = s_trial - std::sqrt(1.5) * 2.0 * mu * dg * n + pressure_part;
  out.state.plastic_strain = committed.plastic_strain + std::sqrt(1.5) * dg * n;
  out.state.equivalent_plastic_strain = alpha;
  out.state.back_stress = committed.back_stress + std::sqrt(2.0 / 3.0) * (pk.at(alpha) - hk_n) * n;
  out.yielded = true;
  out.delta_alpha = dg;

  Mat6 c = Mat6::Zero();
  c.topLeftCorner<3, 3>().setConstant(bulk - 2.0 * mu * theta / 3.0);
  for (int i = 0; i < 3; ++i) c(i, i) += 2.0 * mu * theta;
  for (int i = 3; i < 6; ++i) c(i, i) = mu * theta;
  c -= 2.0 * mu * theta_bar * (n * n.transpose());
  out.tangent = c;
  return out;
}

}  // namespace kontakt::material

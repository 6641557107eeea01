#include "nonlinear/convergence.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kontakt::nonlinear {

namespace {
/// Residuals below this absolute value count as zero (ccx).
constexpr Real kResidualFloor = 1e-6;
/// A value beyond this is a blow-up, checked for divergence at any iteration (ccx).
constexpr Real kBlowUp = 1e20;
}  // namespace

Convergence::Convergence(const SolutionControls& controls, Real previous_force_average)
    : c_(controls) {
  if (c_.fixed_force_average > 0)
    q_tilde_ = c_.fixed_force_average;
  else if (c_.initial_force_average > 0)
    q_tilde_ = c_.initial_force_average;
  else if (previous_force_average > 0)
    q_tilde_ = previous_force_average;
  else
    q_tilde_ = 0.01;
  last_q_bar_ = previous_force_average;
}

void Convergence::begin_increment() {
  q_tilde_trial_ = q_tilde_;
  trial_averaged_ = false;
}

Real Convergence::current_q_tilde(Real q_bar) const {
  if (c_.fixed_force_average > 0) return c_.fixed_force_average;
  // Only a q_bar above the zero-flux level enters the running time average.
  if (q_bar <= c_.zero_flux_ratio * q_tilde_) return q_tilde_;
  return (q_tilde_ * n_averaged_ + q_bar) / (n_averaged_ + 1);
}

Verdict Convergence::check(int iteration, const IterationMeasures& m) {
  Verdict v;
  const bool finite = std::isfinite(m.max_residual) && std::isfinite(m.max_correction) &&
                      std::isfinite(m.force_average);
  const Real r = finite && m.max_residual < kResidualFloor ? 0 : m.max_residual;
  const Real dc = m.max_correction;
  if (finite) {
    du_max_ = std::max(du_max_, dc);
    last_q_bar_ = m.force_average;
    q_tilde_trial_ = current_q_tilde(m.force_average);
    trial_averaged_ = m.force_average > c_.zero_flux_ratio * q_tilde_;
  }
  const Real q = q_tilde_trial_;
  const bool zero_flux = !(m.force_average > c_.zero_flux_ratio * q);
  const Real c1 = zero_flux ? c_.zero_flux_ratio
                            : (iteration <= c_.loose_residual_after ? c_.residual_tolerance
                                                                    : c_.loose_residual_tolerance);
  const Real c2 = zero_flux ? c_.zero_flux_correction_tolerance : c_.correction_tolerance;
  const Real r2 = std::min(r1_, r2_);
  v.residual_ratio = q > 0 ? r / q : 0;
  v.correction_ratio = du_max_ > 0 ? dc / du_max_ : 0;

  const bool small_correction = dc <= c2 * du_max_ || (r2 > 0 && r * dc / r2 < c2 * du_max_) ||
                                r <= c_.linear_residual_ratio * q || zero_flux || dc < 1e-8;
  if (finite && iteration > 1 && r <= c1 * q && !m.active_set_changed && small_correction) {
    v.kind = Verdict::Kind::Converged;
  } else if (!finite || r > kBlowUp ||
             (iteration >= c_.divergence_check_from && r1_ > r2 && r > r2 && r > c1 * q)) {
    v.kind = Verdict::Kind::Cutback;
    v.cutback_factor = c_.divergence_cutback;
    std::ostringstream why;
    if (!finite)
      why << "divergence: non-finite residual or correction in iteration " << iteration;
    else
      why << "divergence in iteration " << iteration << ": largest residual " << r
          << " grew over two iterations (" << r2 << ", " << r1_ << ")";
    v.reason = why.str();
  } else if (iteration >= c_.log_estimate_from) {
    // ccx's estimate of the iterations still needed at the current rate of convergence.
    const Real rate = r1_ > 0 ? r / r1_ : 1;
    const Real needed = rate < 1 && r > 0 ? std::ceil(iteration + std::log(c_.residual_tolerance * q / r) /
                                                                       std::log(rate))
                                          : iteration;
    if (iteration >= c_.max_iterations || needed > c_.max_iterations) {
      v.kind = Verdict::Kind::Cutback;
      v.cutback_factor = c_.slow_cutback;
      std::ostringstream why;
      why << "slow convergence in iteration " << iteration << ": residual ratio "
          << v.residual_ratio << ", about " << needed << " iterations needed, limit "
          << c_.max_iterations;
      v.reason = why.str();
    }
  }
  r2_ = r1_;
  r1_ = r;
  return v;
}

void Convergence::commit_increment() {
  if (trial_averaged_ && c_.fixed_force_average <= 0) {
    q_tilde_ = q_tilde_trial_;
    ++n_averaged_;
  }
  trial_averaged_ = false;
}

}  // namespace kontakt::nonlinear

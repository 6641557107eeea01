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

Convergence::Convergence(const model::SolutionControls& controls, Real previous_force_average)
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
  begin_increment();
}

void Convergence::set_contact_criteria(ContactCriteria criteria, Real delcon) {
  contact_ = criteria;
  delcon_ = delcon;
}

void Convergence::begin_increment(int contact_elements) {
  q_tilde_trial_ = q_tilde_;
  trial_averaged_ = false;
  divergence_from_ = c_.divergence_check_from;
  estimate_from_ = c_.log_estimate_from;
  max_iterations_ = c_.max_iterations;
  residuals_.clear();
  counts_.assign(1, contact_elements);
  changed_.clear();
}

bool Convergence::contact_changed(int before, int after) const {
  if (contact_ == ContactCriteria::None || before < 0 || after < 0) return false;
  if (contact_ == ContactCriteria::NodeToSurface) return before != after;
  return std::abs(after - before) > delcon_ * std::max(before, 1);
}

bool Convergence::surface_divergence(int iteration, Real r, Real c1q) const {
  const std::size_t i = residuals_.size() - 1;  // index of the current iteration
  if (iteration < divergence_from_ || r <= c1q || i < 2) return false;
  // I: the last two residuals both exceed the smallest mean of two consecutive residuals.
  Real min_mean = 1e300;
  for (std::size_t k = 1; k < i; ++k) min_mean = std::min(min_mean, 0.5 * (residuals_[k] + residuals_[k - 1]));
  if (!(residuals_[i] > min_mean && residuals_[i - 1] > min_mean)) return false;
  // II: the contact set has settled (no change in this and the previous iteration).
  if (!changed_[i] && !changed_[i - 1]) return true;
  // III: residuals and contact counts repeat with some period P.
  for (std::size_t P = 2; P <= 6 && 2 * P <= i + 1; ++P) {
    bool repeats = true;
    for (std::size_t j = i + 1 - P; j <= i && repeats; ++j) {
      const Real a = residuals_[j], b = residuals_[j - P];
      repeats = counts_[j + 1] == counts_[j + 1 - P] && std::abs(a - b) <= 0.02 * std::max(a, b);
    }
    if (repeats) return true;
  }
  return false;
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
  residuals_.push_back(r);
  counts_.push_back(m.contact_elements);
  const bool changed = contact_changed(counts_[counts_.size() - 2], m.contact_elements);
  changed_.push_back(changed);
  // ccx extends the clocks for node-to-face changes, which its frozen pairing confines to the
  // first 8 iterations; later changes (feet sliding off their faces) still block convergence
  // but no longer extend the iteration cap, so a chattering contact set ends in a cutback.
  if (changed && contact_ == ContactCriteria::NodeToSurface && iteration <= kRepairingIterations) {
    divergence_from_ = std::max(divergence_from_, iteration + 4);
    estimate_from_ = std::max(estimate_from_, iteration + 8);
    ++max_iterations_;
  }
  const bool surface = contact_ == ContactCriteria::SurfaceToSurface;
  const bool diverging =
      !finite || r > kBlowUp ||
      (surface ? surface_divergence(iteration, r, c1 * q)
               : iteration >= divergence_from_ && r1_ > r2 && r > r2 && r > c1 * q);
  // ccx always iterates twice; an iteration 1 that leaves only a round-off residual (the
  // linear case R_l) with an unchanged contact set has solved the increment already.
  const bool solved_at_once = iteration == 1 && r <= c_.linear_residual_ratio * q;
  if (finite && (iteration > 1 || solved_at_once) && r <= c1 * q && !changed && small_correction) {
    v.kind = Verdict::Kind::Converged;
  } else if (diverging) {
    v.kind = Verdict::Kind::Cutback;
    v.cutback_factor = c_.divergence_cutback;
    std::ostringstream why;
    if (!finite)
      why << "divergence: non-finite residual or correction in iteration " << iteration;
    else if (surface)
      why << "divergence in iteration " << iteration << ": largest residual " << r
          << " keeps above its best two-iteration mean with "
          << (changed ? "a repeating contact pattern" : "the contact set settled");
    else
      why << "divergence in iteration " << iteration << ": largest residual " << r
          << " grew over two iterations (" << r2 << ", " << r1_ << ")";
    v.reason = why.str();
  } else if (surface) {
    if (iteration >= max_iterations_) {
      v.kind = Verdict::Kind::Cutback;
      v.cutback_factor = c_.slow_cutback;
      v.reason = "no convergence within " + std::to_string(max_iterations_) +
                 " iterations (*CONTROLS, PARAMETERS=CONTACT itf2f)";
    }
  } else if (iteration >= estimate_from_) {
    // ccx's estimate of the iterations still needed at the current rate of convergence.
    const Real rate = r1_ > 0 ? r / r1_ : 1;
    const Real needed = rate < 1 && r > 0 ? std::ceil(iteration + std::log(c_.residual_tolerance * q / r) /
                                                                       std::log(rate))
                                          : iteration;
    if (iteration >= max_iterations_ || needed > max_iterations_) {
      v.kind = Verdict::Kind::Cutback;
      v.cutback_factor = c_.slow_cutback;
      std::ostringstream why;
      why << "slow convergence in iteration " << iteration << ": residual ratio "
          << v.residual_ratio << ", about " << needed << " iterations needed, limit "
          << max_iterations_;
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

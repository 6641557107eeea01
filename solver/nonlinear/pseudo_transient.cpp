#include "nonlinear/pseudo_transient.hpp"

#include <algorithm>
#include <limits>

namespace kontakt::nonlinear {

void PseudoTransient::start(Real held_energy) {
  active_ = true;
  shift_ = kFirstShift;
  residual_ = 0;
  steps_ = 0;
  best_residual_ = std::numeric_limits<Real>::infinity();
  steps_since_best_ = 0;
  held_energy_ = held_energy;
  dissipated_ = 0;
}

bool PseudoTransient::raise() {
  if (shift_ * kMaxChange > kMaxShift) return false;
  shift_ = std::max(shift_, kNewtonShift) * kMaxChange;
  return true;
}

void PseudoTransient::stepped(Real residual, Real dissipated) {
  ++steps_;
  dissipated_ += dissipated;
  if (residual < best_residual_) {
    best_residual_ = residual;
    steps_since_best_ = 0;
  } else {
    ++steps_since_best_;
  }
  const Real ratio = residual_ > 0 ? residual / residual_ : 1;  // the first step: no history
  shift_ = std::clamp(shift_ * std::clamp(ratio, 1 / kMaxChange, kMaxChange), 0.0, kMaxShift);
  residual_ = residual;
}

}  // namespace kontakt::nonlinear

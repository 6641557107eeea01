#include "nonlinear/increment_control.hpp"

#include <algorithm>
#include <sstream>

#include "core/error.hpp"

namespace kontakt::nonlinear {

namespace {
/// Relative tolerance under which the step end counts as reached.
constexpr Real kTimeTolerance = 1e-12;
}  // namespace

IncrementControl::IncrementControl(const StepTiming& timing, const model::SolutionControls& controls)
    : t_(timing), c_(controls) {
  // ccx: a minimum below 1e-6 of the step time (or none) becomes min(initial, 1e-6 * period).
  const Real floor = 1e-6 * t_.period;
  dt_min_ = t_.min_increment < floor ? std::min(t_.initial_increment, floor) : t_.min_increment;
  dt_max_ = t_.max_increment > 0 ? t_.max_increment : 1e30;
  dt_ = std::min(t_.initial_increment > 0 ? t_.initial_increment : t_.period, dt_max_);
  clip_to_step_end();
  // Points at or before the step start are passed already.
  while (next_point_ < t_.time_points.size() && t_.time_points[next_point_] <= 0) ++next_point_;
  clip_to_time_point();
  // ccx: the first increment's size, as a time point shortened it, is the reference.
  dt_ref_ = dt_;
  if (dt_ < dt_min_) {
    std::ostringstream msg;
    msg << "the first time point " << dt_ << " comes before the minimum increment " << dt_min_;
    throw NonConvergence(msg.str());
  }
}

bool IncrementControl::finished() const {
  return time_ >= t_.period * (1 - kTimeTolerance);
}

void IncrementControl::clip_to_step_end() {
  const Real remaining = t_.period - time_;
  // Take the rest in one go when less than a sliver of an increment would remain.
  if (dt_ >= remaining * (1 - kTimeTolerance)) dt_ = dt_ref_ = remaining;
}

void IncrementControl::clip_to_time_point() {
  at_time_point_ = false;
  if (t_.direct || next_point_ >= t_.time_points.size()) return;
  const Real point = t_.time_points[next_point_];
  if (point > t_.period * (1 + kTimeTolerance)) return;  // beyond this step
  // ccx: an increment ending short of the point by less than 1e-6 of the step goes on to it.
  if (time_ + dt_ < point - 1e-6 * t_.period) return;
  dt_ = point - time_;
  ++next_point_;
  at_time_point_ = true;
}

void IncrementControl::converged(int iterations) {
  time_ = at_time_point_ ? t_.time_points[next_point_ - 1] : time_ + dt_;
  ++n_increments_;
  n_cutbacks_ = 0;
  if (finished()) {
    time_ = t_.period;
    return;
  }
  if (n_increments_ >= t_.max_increments) {
    std::ostringstream msg;
    msg << "the step needs more than " << t_.max_increments
        << " increments (*STEP, INC=) at step time " << time_ << " of " << t_.period;
    throw NonConvergence(msg.str());
  }
  if (!t_.direct) {
    dt_ = dt_ref_;
    if (iterations > c_.slow_increment_iterations) {
      dt_ *= c_.slow_next_factor;
      previous_was_fast_ = false;
      if (dt_ < dt_min_) {
        std::ostringstream msg;
        msg << "slow convergence: the next increment " << dt_ << " is below the minimum "
            << dt_min_;
        throw NonConvergence(msg.str());
      }
    } else if (iterations <= c_.fast_increment_iterations) {
      if (previous_was_fast_) dt_ *= c_.growth_factor;  // two fast increments in a row
      previous_was_fast_ = true;
    } else {
      previous_was_fast_ = false;
    }
    dt_ = dt_ref_ = std::min(dt_, dt_max_);
  }
  clip_to_step_end();
  clip_to_time_point();
}

void IncrementControl::cut_back(Real factor, const std::string& reason) {
  std::ostringstream msg;
  msg << "increment " << increment_number() << " (step time " << time_ << ", size " << dt_
      << ") failed: " << reason;
  if (t_.direct) throw NonConvergence(msg.str() + "; DIRECT incrementation allows no cutback");
  ++n_cutbacks_;
  previous_was_fast_ = false;
  if (n_cutbacks_ > c_.max_cutbacks)
    throw NonConvergence(msg.str() + "; more than " + std::to_string(c_.max_cutbacks) +
                         " cutbacks (*CONTROLS I_A)");
  dt_ *= factor;
  dt_ref_ = dt_;
  // The retry no longer reaches the time point; a later increment is shortened to it again.
  if (at_time_point_) {
    at_time_point_ = false;
    --next_point_;
  }
  if (dt_ < dt_min_) {
    std::ostringstream tail;
    tail << "; the cut-back increment " << dt_ << " is below the minimum " << dt_min_;
    throw NonConvergence(msg.str() + tail.str());
  }
}

}  // namespace kontakt::nonlinear

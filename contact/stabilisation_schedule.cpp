#include "contact/stabilisation_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace kontakt::contact {

void StabilisationSchedule::engage() {
  factor_ = kFirstFactor;
  held_factor_ = 0;
  step_ = kLevelRatio;
  releasing_ = release_failed_ = last_release_tried_ = false;
  released_energy_ = 0;
}

void StabilisationSchedule::disengage() {
  factor_ = held_factor_ = 0;
  step_ = kLevelRatio;
  releasing_ = release_failed_ = last_release_tried_ = false;
  released_energy_ = 0;
}

StabilisationSchedule::Next StabilisationSchedule::converged(Real energy, Real share,
                                                             std::optional<Real> approach) {
  if (!engaged() || releasing_) return Next::Done;
  released_energy_ = energy;
  held_factor_ = factor_;
  if (share <= kNegligibleShare) return Next::Done;
  if (share <= kReleaseShare && !release_failed_) {
    releasing_ = true;
    return Next::Continue;
  }
  const Real ratio =
      approach ? std::clamp(*approach, kMinApproachRatio, kMaxApproachRatio) : step_;
  step_ = std::max(kLevelRatio, step_ * step_);
  if (factor_ * ratio >= kMinFactor) {
    factor_ *= ratio;
    return Next::Continue;
  }
  // The weakest level: one more release from here, since the contact set may have changed
  // while the springs weakened (a tilting point contact reached the node that holds it).
  if (share > kReleaseShare || last_release_tried_) return Next::GiveUp;
  last_release_tried_ = releasing_ = true;
  return Next::Continue;
}

StabilisationSchedule::Next StabilisationSchedule::failed() {
  if (releasing_) {
    if (last_release_tried_ || factor_ * step_ < kMinFactor) return Next::GiveUp;
    releasing_ = false;
    release_failed_ = true;
    factor_ *= step_;
    return Next::RestoreAndContinue;
  }
  if (held_factor_ == 0) return Next::GiveUp;  // the springs themselves do not converge
  const Real milder = std::sqrt(factor_ / held_factor_);
  if (milder > kMaxRetryRatio) return Next::GiveUp;
  step_ = milder;
  factor_ = held_factor_ * milder;
  return Next::RestoreAndContinue;
}

}  // namespace kontakt::contact

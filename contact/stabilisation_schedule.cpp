#include "contact/stabilisation_schedule.hpp"

#include <algorithm>

namespace kontakt::contact {

void StabilisationSchedule::engage() {
  factor_ = kFirstFactor;
  releasing_ = release_failed_ = false;
  released_energy_ = 0;
}

void StabilisationSchedule::disengage() {
  factor_ = 0;
  releasing_ = release_failed_ = false;
  released_energy_ = 0;
}

StabilisationSchedule::Next StabilisationSchedule::converged(Real energy, Real share,
                                                             std::optional<Real> approach) {
  if (!engaged() || releasing_) return Next::Done;
  released_energy_ = energy;
  if (share <= kNegligibleShare) return Next::Done;
  if (share <= kReleaseShare && !release_failed_) {
    releasing_ = true;
    return Next::Continue;
  }
  const Real ratio =
      approach ? std::clamp(*approach, kMinApproachRatio, kMaxApproachRatio) : kLevelRatio;
  if (factor_ * ratio < kMinFactor) return Next::GiveUp;
  factor_ *= ratio;
  return Next::Continue;
}

StabilisationSchedule::Next StabilisationSchedule::failed() {
  if (!releasing_ || factor_ * kLevelRatio < kMinFactor) return Next::GiveUp;
  releasing_ = false;
  release_failed_ = true;
  factor_ *= kLevelRatio;
  return Next::RestoreAndContinue;
}

}  // namespace kontakt::contact

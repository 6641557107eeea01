// The contact stabilisation's continuation: while nothing touches, the springs weaken just
// enough to land the bodies on contact; then they step down by 10 until contact carries the
// load and are released; a failed release goes back one level further down, a failed level is
// retried from the last converged one with half the step in log(factor), springs that carry a
// negligible share count as released, and the weakest level is released once more before the
// increment fails; what the release removed is reported.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/stabilisation_schedule.hpp"

using namespace kontakt;
using namespace kontakt::contact;
using Next = StabilisationSchedule::Next;
using S = StabilisationSchedule;

TEST(StabilisationSchedule, OffUntilEngaged) {
  S s;
  EXPECT_FALSE(s.engaged());
  EXPECT_EQ(s.factor(), 0);
  EXPECT_EQ(s.converged(1, 1, std::nullopt), Next::Done);  // unstabilised: just converged
  EXPECT_EQ(s.absorbed_energy(), 0);
}

TEST(StabilisationSchedule, LandsOnContactThenStepsDownUntilContactCarriesTheLoad) {
  S s;
  s.engage();
  EXPECT_DOUBLE_EQ(s.factor(), 1e-2);
  // Nothing touches: the ratio that lands the bodies on contact, within its bounds.
  EXPECT_EQ(s.converged(5.0, 1.0, 0.02), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 2e-4);
  EXPECT_EQ(s.converged(5.0, 1.0, 1e-6), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 2e-4 * S::kMinApproachRatio);
  EXPECT_EQ(s.converged(5.0, 1.0, 0.9), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 2e-7 * S::kMaxApproachRatio);
  // Touching: steps of 10 until contact carries 99 %, then the release.
  EXPECT_EQ(s.converged(2.0, 0.2, std::nullopt), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 1e-8);
  EXPECT_FALSE(s.releasing());
  EXPECT_EQ(s.converged(0.3, 0.005, std::nullopt), Next::Continue);
  EXPECT_TRUE(s.releasing());
  EXPECT_EQ(s.factor(), 0);
  EXPECT_EQ(s.converged(0, 0, std::nullopt), Next::Done);
  EXPECT_DOUBLE_EQ(s.absorbed_energy(), 0.3);  // what the springs held when released
}

TEST(StabilisationSchedule, AFailedReleaseGoesBackAndStepsDownToNegligibleSprings) {
  S s;
  s.engage();
  s.converged(1.0, 0.001, std::nullopt);  // released after the first level
  ASSERT_TRUE(s.releasing());
  EXPECT_EQ(s.failed(), Next::RestoreAndContinue);
  EXPECT_FALSE(s.releasing());
  EXPECT_DOUBLE_EQ(s.factor(), 1e-3);
  // No second release: the levels go on down until the springs' share is negligible.
  EXPECT_EQ(s.converged(0.1, 1e-4, std::nullopt), Next::Continue);
  EXPECT_FALSE(s.releasing());
  EXPECT_DOUBLE_EQ(s.factor(), 1e-4);
  EXPECT_EQ(s.converged(0.01, 0.5 * S::kNegligibleShare, std::nullopt), Next::Done);
  EXPECT_DOUBLE_EQ(s.absorbed_energy(), 0.01);
}

TEST(StabilisationSchedule, GivesUpWhenTheFirstLevelFailsOrTheSpringsGetTooWeak) {
  S s;
  s.engage();
  EXPECT_EQ(s.failed(), Next::GiveUp);  // the springs themselves do not converge
  s.engage();
  int levels = 0;
  while (s.converged(1, 1, std::nullopt) == Next::Continue) ++levels;
  EXPECT_EQ(levels, 7);  // 1e-2 ... 1e-9: weaker springs no longer hold a body numerically
  EXPECT_GE(s.factor(), S::kMinFactor);
}

TEST(StabilisationSchedule, TheWeakestLevelIsReleasedOnceMoreBeforeGivingUp) {
  S s;
  s.engage();
  s.converged(1, 0.001, std::nullopt);
  ASSERT_TRUE(s.releasing());
  ASSERT_EQ(s.failed(), Next::RestoreAndContinue);  // 1e-3, no release while stepping down
  int levels = 0;
  while (!s.releasing()) {
    ASSERT_EQ(s.converged(0.5, 5e-6, std::nullopt), Next::Continue);
    ++levels;
  }
  EXPECT_EQ(levels, 7);  // 1e-3 ... 1e-9 converged, then the release from 1e-9
  EXPECT_EQ(s.factor(), 0);
  EXPECT_EQ(s.failed(), Next::GiveUp);  // only once
  // The same release converging ends the increment with the weakest level's energy.
  s.engage();
  s.converged(1, 0.001, std::nullopt);
  s.failed();
  while (!s.releasing()) s.converged(0.25, 5e-6, std::nullopt);
  EXPECT_EQ(s.converged(0, 0, std::nullopt), Next::Done);
  EXPECT_DOUBLE_EQ(s.absorbed_energy(), 0.25);
  EXPECT_DOUBLE_EQ(s.held_factor(), 1e-9);
}

TEST(StabilisationSchedule, AFailedLevelIsRetriedWithHalfTheStepWhichThenGrowsBack) {
  S s;
  s.engage();
  EXPECT_EQ(s.converged(1, 0.5, std::nullopt), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 1e-3);
  // 1e-3 fails: back to 1e-2's solution, half the step in log (ratio sqrt(0.1)), and again.
  EXPECT_EQ(s.failed(), Next::RestoreAndContinue);
  EXPECT_DOUBLE_EQ(s.factor(), 1e-2 * std::sqrt(0.1));
  EXPECT_EQ(s.failed(), Next::RestoreAndContinue);
  EXPECT_DOUBLE_EQ(s.factor(), 1e-2 * std::pow(0.1, 0.25));
  // Converged levels square the ratio again, up to the factor of 10.
  const Real r = std::pow(0.1, 0.25);
  EXPECT_EQ(s.converged(1, 0.5, std::nullopt), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 1e-2 * r * r);
  EXPECT_EQ(s.converged(1, 0.5, std::nullopt), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 1e-2 * r * r * r * r);
  EXPECT_EQ(s.converged(1, 0.5, std::nullopt), Next::Continue);
  EXPECT_DOUBLE_EQ(s.factor(), 1e-2 * r * r * r * r * 0.1);
  // Retries stop once a level is within kMaxRetryRatio of the last converged one.
  int retries = 0;
  while (s.failed() == Next::RestoreAndContinue) ++retries;
  EXPECT_EQ(retries, 3);  // ratios 0.1^(1/2), 0.1^(1/4), 0.1^(1/8); 0.1^(1/16) > 0.8
}

TEST(StabilisationSchedule, AFailedReleaseStepsDownByTheCurrentStep) {
  S s;
  s.engage();
  s.converged(1, 0.5, std::nullopt);
  s.failed();  // 1e-3 failed: retried at 1e-2 * sqrt(0.1)
  const Real held = s.factor();
  s.converged(1, 0.001, std::nullopt);  // released
  ASSERT_TRUE(s.releasing());
  EXPECT_EQ(s.failed(), Next::RestoreAndContinue);
  EXPECT_DOUBLE_EQ(s.factor(), held * std::sqrt(0.1));  // the reduced step, not 10
}

TEST(StabilisationSchedule, EngagingAgainStartsOverAndDisengagingSwitchesOff) {
  S s;
  s.engage();
  s.converged(1, 1, std::nullopt);
  s.engage();
  EXPECT_DOUBLE_EQ(s.factor(), 1e-2);
  EXPECT_EQ(s.absorbed_energy(), 0);
  s.disengage();
  EXPECT_FALSE(s.engaged());
  EXPECT_EQ(s.factor(), 0);
}

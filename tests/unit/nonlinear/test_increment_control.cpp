#include <gtest/gtest.h>

#include "core/error.hpp"
#include "nonlinear/increment_control.hpp"

using namespace kontakt;
using namespace kontakt::nonlinear;

TEST(IncrementControl, GrowsAfterTwoFastIncrementsAndEndsExactlyAtTheStepEnd) {
  IncrementControl inc({.period = 1, .initial_increment = 0.1}, {});
  EXPECT_DOUBLE_EQ(inc.increment(), 0.1);
  inc.converged(3);  // fast, but the first one: keep
  EXPECT_DOUBLE_EQ(inc.increment(), 0.1);
  inc.converged(3);  // second fast in a row: * 1.5
  EXPECT_NEAR(inc.increment(), 0.15, 1e-15);
  inc.converged(3);
  EXPECT_NEAR(inc.increment(), 0.225, 1e-15);
  while (!inc.finished()) inc.converged(3);
  EXPECT_DOUBLE_EQ(inc.step_time(), 1.0);
}

TEST(IncrementControl, SlowIncrementShrinksTheNextAndMediumKeepsIt) {
  model::SolutionControls c;
  IncrementControl inc({.period = 1, .initial_increment = 0.2}, c);
  inc.converged(c.slow_increment_iterations + 1);
  EXPECT_NEAR(inc.increment(), 0.2 * c.slow_next_factor, 1e-15);
  inc.converged(c.fast_increment_iterations + 1);
  EXPECT_NEAR(inc.increment(), 0.15, 1e-15);
}

TEST(IncrementControl, MaximumIncrementAndStepEndLimitTheSize) {
  IncrementControl inc({.period = 1, .initial_increment = 0.4, .max_increment = 0.5}, {});
  inc.converged(2);
  inc.converged(2);  // would grow to 0.6: limited to 0.5, then to the 0.2 left
  EXPECT_NEAR(inc.increment(), 0.2, 1e-15);
  inc.converged(2);
  EXPECT_TRUE(inc.finished());
}

TEST(IncrementControl, CutbacksShrinkTheIncrementUntilTheLimit) {
  model::SolutionControls c;
  IncrementControl inc({.period = 1, .initial_increment = 1}, c);
  for (int k = 1; k <= c.max_cutbacks; ++k) {
    inc.cut_back(0.5, "test");
    EXPECT_EQ(inc.attempt(), k + 1);
  }
  EXPECT_NEAR(inc.increment(), std::pow(0.5, c.max_cutbacks), 1e-15);
  try {
    inc.cut_back(0.5, "diverged");
    FAIL() << "cutback limit not enforced";
  } catch (const NonConvergence& e) {
    EXPECT_NE(std::string(e.what()).find("diverged"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cutbacks"), std::string::npos);
  }
}

TEST(IncrementControl, IncrementBelowTheMinimumFails) {
  IncrementControl inc({.period = 1, .initial_increment = 0.1, .min_increment = 0.05}, {});
  inc.cut_back(0.75, "slow");
  EXPECT_THROW(inc.cut_back(0.25, "diverged"), NonConvergence);
}

TEST(IncrementControl, DefaultMinimumFollowsCcx) {
  IncrementControl a({.period = 2, .initial_increment = 0.1}, {});
  EXPECT_DOUBLE_EQ(a.min_increment(), 2e-6);
  IncrementControl b({.period = 2, .initial_increment = 1e-7}, {});
  EXPECT_DOUBLE_EQ(b.min_increment(), 1e-7);
  EXPECT_DOUBLE_EQ(b.max_increment(), 1e30);
}

TEST(IncrementControl, DirectKeepsTheSizeAndAllowsNoCutback) {
  IncrementControl inc({.period = 1, .initial_increment = 0.25, .direct = true}, {});
  inc.converged(2);
  inc.converged(2);
  EXPECT_DOUBLE_EQ(inc.increment(), 0.25);
  EXPECT_THROW(inc.cut_back(0.25, "diverged"), NonConvergence);
}

TEST(IncrementControl, IncrementCountLimitOfTheStep) {
  IncrementControl inc({.period = 1, .initial_increment = 0.1, .direct = true, .max_increments = 3}, {});
  inc.converged(2);
  inc.converged(2);
  EXPECT_THROW(inc.converged(2), NonConvergence);
}

// ccx 2.20 on the suite's beamnlptp (*STATIC 1, 1; time points .4, .6, .9; 3, 2, 2, 2
// iterations): increments 0.4, 0.2, 0.3, 0.1, output at the first three and the step end.
TEST(IncrementControl, TimePointsEndIncrementsAndTheUnclippedSizeGrows) {
  IncrementControl inc({.period = 1, .initial_increment = 1, .time_points = {0.4, 0.6, 0.9}}, {});
  EXPECT_DOUBLE_EQ(inc.increment(), 0.4);
  EXPECT_TRUE(inc.ends_at_time_point());
  inc.converged(3);  // first fast: the size goes back to the reference 0.4, cut to 0.6
  EXPECT_DOUBLE_EQ(inc.step_time(), 0.4);
  EXPECT_NEAR(inc.increment(), 0.2, 1e-15);
  EXPECT_TRUE(inc.ends_at_time_point());
  inc.converged(2);  // second fast: 0.4 * 1.5 = 0.6, to the step end 0.4, cut to 0.9
  EXPECT_DOUBLE_EQ(inc.step_time(), 0.6);
  EXPECT_NEAR(inc.increment(), 0.3, 1e-15);
  EXPECT_TRUE(inc.ends_at_time_point());
  inc.converged(2);
  EXPECT_DOUBLE_EQ(inc.step_time(), 0.9);
  EXPECT_NEAR(inc.increment(), 0.1, 1e-15);
  EXPECT_FALSE(inc.ends_at_time_point());
  inc.converged(2);
  EXPECT_TRUE(inc.finished());
}

TEST(IncrementControl, TimePointsDoNotShrinkTheReferenceSize) {
  // 0.3 fixed-size-ish increments (no growth: medium convergence); the point 0.4 shortens
  // one increment to 0.1, the next is 0.3 again.
  model::SolutionControls c;
  IncrementControl inc({.period = 1, .initial_increment = 0.3, .time_points = {0.4}}, c);
  EXPECT_FALSE(inc.ends_at_time_point());
  inc.converged(c.fast_increment_iterations + 1);
  EXPECT_NEAR(inc.increment(), 0.1, 1e-15);
  EXPECT_TRUE(inc.ends_at_time_point());
  inc.converged(c.fast_increment_iterations + 1);
  EXPECT_NEAR(inc.increment(), 0.3, 1e-15);
  EXPECT_FALSE(inc.ends_at_time_point());
}

TEST(IncrementControl, AnIncrementEndingJustShortOfATimePointIsStretchedToIt) {
  IncrementControl inc({.period = 1, .initial_increment = 0.5 - 5e-7, .time_points = {0.5}}, {});
  EXPECT_DOUBLE_EQ(inc.increment(), 0.5);
  EXPECT_TRUE(inc.ends_at_time_point());
  IncrementControl far({.period = 1, .initial_increment = 0.5 - 2e-6, .time_points = {0.5}}, {});
  EXPECT_DOUBLE_EQ(far.increment(), 0.5 - 2e-6);
  EXPECT_FALSE(far.ends_at_time_point());
}

TEST(IncrementControl, ACutBackIncrementAimsAtTheTimePointAgainLater) {
  IncrementControl inc({.period = 1, .initial_increment = 1, .time_points = {0.4}}, {});
  inc.cut_back(0.25, "diverged");  // 0.1, the point is not reached
  EXPECT_NEAR(inc.increment(), 0.1, 1e-15);
  EXPECT_FALSE(inc.ends_at_time_point());
  inc.converged(3);
  inc.converged(3);  // 0.1, then grown to 0.15 (0.2 ... 0.35)
  EXPECT_NEAR(inc.step_time(), 0.2, 1e-15);
  EXPECT_NEAR(inc.increment(), 0.15, 1e-15);
  inc.converged(3);  // 0.225 would pass 0.4
  EXPECT_NEAR(inc.increment(), 0.05, 1e-15);
  EXPECT_TRUE(inc.ends_at_time_point());
}

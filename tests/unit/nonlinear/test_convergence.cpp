#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "nonlinear/convergence.hpp"

using namespace kontakt;
using namespace kontakt::nonlinear;
using Kind = Verdict::Kind;

namespace {
IterationMeasures measures(Real q_bar, Real r_max, Real c_max, bool changed = false) {
  return {q_bar, r_max, c_max, changed};
}
}  // namespace

TEST(Convergence, LinearProblemConvergesInExactlyTwoIterations) {
  Convergence conv({}, 0);
  conv.begin_increment();
  // Iteration 1 of a linear problem already has a zero residual, but ccx always does two.
  EXPECT_EQ(conv.check(1, measures(100, 0, 1.0)).kind, Kind::Iterate);
  EXPECT_EQ(conv.check(2, measures(100, 5e-7, 1e-12)).kind, Kind::Converged);
}

TEST(Convergence, ResidualMustBeBelowTheToleranceTimesTheForceAverage) {
  Convergence conv({}, 0);
  conv.begin_increment();
  conv.check(1, measures(100, 50, 1.0));
  // q~ = 100 in the first increment: R_n * q~ = 0.5.
  EXPECT_EQ(conv.check(2, measures(100, 0.6, 1e-3)).kind, Kind::Iterate);
  const Verdict v = conv.check(3, measures(100, 0.4, 1e-3));
  EXPECT_EQ(v.kind, Kind::Converged);
  EXPECT_NEAR(v.residual_ratio, 0.004, 1e-15);
}

TEST(Convergence, LooseResidualToleranceAppliesAfterIterationIP) {
  SolutionControls c;
  Convergence conv(c, 0);
  conv.begin_increment();
  Real r = 1.9;
  // The first correction sets the step's largest change; later ones are 0.1 % of it.
  for (int i = 1; i <= c.loose_residual_after; ++i, r *= 0.999)
    EXPECT_NE(conv.check(i, measures(100, r, i == 1 ? 1.0 : 1e-3)).kind, Kind::Converged) << i;
  // R_p * q~ = 2 now admits the same residual level.
  EXPECT_EQ(conv.check(c.loose_residual_after + 1, measures(100, r, 1e-3)).kind, Kind::Converged);
}

TEST(Convergence, LargeCorrectionBlocksConvergence) {
  Convergence conv({}, 0);
  conv.begin_increment();
  conv.check(1, measures(100, 10, 1.0));
  // r small, but the correction is half of the largest change: C_n = 1 % is not met, and
  // r * c / r_{i-2} = 0.4 * 0.5 / 10 = 0.02 is not below C_n * du_max = 0.01 either.
  EXPECT_EQ(conv.check(2, measures(100, 0.4, 0.5)).kind, Kind::Iterate);
}

TEST(Convergence, ChangedActiveSetBlocksConvergence) {
  Convergence conv({}, 0);
  conv.begin_increment();
  conv.check(1, measures(100, 10, 1.0));
  EXPECT_EQ(conv.check(2, measures(100, 0, 1e-12, true)).kind, Kind::Iterate);
  EXPECT_EQ(conv.check(3, measures(100, 0, 1e-12, false)).kind, Kind::Converged);
}

TEST(Convergence, DivergenceIsCheckedFromIterationI0Only) {
  SolutionControls c;
  Convergence conv(c, 0);
  conv.begin_increment();
  EXPECT_EQ(conv.check(1, measures(100, 10, 1)).kind, Kind::Iterate);
  EXPECT_EQ(conv.check(2, measures(100, 5, 1)).kind, Kind::Iterate);
  EXPECT_EQ(conv.check(3, measures(100, 8, 1)).kind, Kind::Iterate);  // grows, but i < I_0
  const Verdict v = conv.check(4, measures(100, 12, 1));              // grew twice over r_{i-2}
  EXPECT_EQ(v.kind, Kind::Cutback);
  EXPECT_DOUBLE_EQ(v.cutback_factor, c.divergence_cutback);
  EXPECT_NE(v.reason.find("divergence"), std::string::npos);
}

TEST(Convergence, NonFiniteValuesAreDivergenceAtOnce) {
  Convergence conv({}, 0);
  conv.begin_increment();
  const Verdict v = conv.check(1, measures(100, std::numeric_limits<Real>::quiet_NaN(), 1));
  EXPECT_EQ(v.kind, Kind::Cutback);
  EXPECT_NE(v.reason.find("non-finite"), std::string::npos);
}

TEST(Convergence, SlowConvergenceIsCutBackByTheLogarithmicEstimate) {
  SolutionControls c;
  for (Real rate : {0.9, 0.99}) {
    Convergence conv(c, 0);
    conv.begin_increment();
    Real r = 2.0;
    for (int i = 1; i < c.log_estimate_from; ++i, r *= rate) conv.check(i, measures(100, r, 1));
    const Verdict v = conv.check(c.log_estimate_from, measures(100, r, 1));
    // At rate 0.9, ceil(8 + ln(0.5 / r) / ln 0.9) stays within I_C = 16; at 0.99 it does not.
    const Real needed =
        std::ceil(c.log_estimate_from + std::log(c.residual_tolerance * 100 / r) / std::log(rate));
    EXPECT_EQ(v.kind == Kind::Cutback, needed > c.max_iterations) << rate;
    if (v.kind == Kind::Cutback) {
      EXPECT_DOUBLE_EQ(v.cutback_factor, c.slow_cutback);
    }
  }
}

TEST(Convergence, IterationICIsTheLastOne) {
  SolutionControls c;
  Convergence conv(c, 0);
  conv.begin_increment();
  Real r = 100;
  Verdict v;
  for (int i = 1; i <= c.max_iterations; ++i, r *= 0.7) v = conv.check(i, measures(100, r, 1));
  EXPECT_EQ(v.kind, Kind::Cutback);
}

TEST(Convergence, ZeroFluxUsesItsOwnTolerances) {
  Convergence conv({}, 0);
  conv.begin_increment();
  conv.check(1, measures(0, 0, 1));
  EXPECT_EQ(conv.check(2, measures(0, 0, 0.5)).kind, Kind::Converged);
}

TEST(Convergence, ForceAverageIsTheMeanOverConvergedIncrements) {
  Convergence conv({}, 0);
  for (Real q_bar : {100.0, 300.0}) {
    conv.begin_increment();
    conv.check(1, measures(q_bar, 1e3, 1));
    EXPECT_EQ(conv.check(2, measures(q_bar, 0, 1e-12)).kind, Kind::Converged);
    conv.commit_increment();
  }
  EXPECT_DOUBLE_EQ(conv.force_reference(), 200.0);
  // A fixed q_u overrides the average; an unset one starts from the previous step's q_bar.
  SolutionControls fixed;
  fixed.fixed_force_average = 42;
  EXPECT_DOUBLE_EQ(Convergence(fixed, 7).force_reference(), 42.0);
  EXPECT_DOUBLE_EQ(Convergence({}, 7).force_reference(), 7.0);
  EXPECT_DOUBLE_EQ(Convergence({}, 0).force_reference(), 0.01);
}

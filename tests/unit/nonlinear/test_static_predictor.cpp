// ccx's static predictor: nothing to extrapolate before an increment of the step converged,
// then the last converged increment's velocity.
#include "nonlinear/static_predictor.hpp"

#include <gtest/gtest.h>

namespace kontakt::nonlinear {
namespace {

TEST(StaticPredictor, ExtrapolatesTheLastConvergedIncrementWithinAStep) {
  StaticPredictor p;
  VecX u(2), v(2);
  u << 1.0, -2.0;
  EXPECT_EQ(p.start(u, 0.5), u);  // first increment of the step: the converged state
  v << 1.5, -1.0;
  p.converged(u, v, 0.25);        // velocity (2, 4)
  VecX expected(2);
  expected << 1.5 + 0.1 * 2.0, -1.0 + 0.1 * 4.0;
  EXPECT_LT((p.start(v, 0.1) - expected).norm(), 1e-15);
  p.converged(v, v, 0.1);          // an increment that did not move: nothing to extrapolate
  EXPECT_EQ(p.start(v, 0.3), v);
}

}  // namespace
}  // namespace kontakt::nonlinear

// Pseudo-transient continuation's shift: it starts at kFirstShift, follows the residual
// (switched evolution relaxation) by at most kMaxChange per step, reads 0 (a Newton step) once
// below kNewtonShift, grows tenfold for an indefinite tangent up to kMaxShift, and the
// continuation ends after kMaxSteps, or after kMaxStall steps without a smaller residual; the
// damping energy of the steps adds up to the springs'.
#include <gtest/gtest.h>

#include "nonlinear/pseudo_transient.hpp"

using namespace kontakt;
using kontakt::nonlinear::PseudoTransient;
using P = PseudoTransient;

TEST(PseudoTransient, OffUntilStarted) {
  P p;
  EXPECT_FALSE(p.active());
  EXPECT_EQ(p.shift(), 0);
  p.start(0);
  EXPECT_TRUE(p.active());
  EXPECT_DOUBLE_EQ(p.shift(), P::kFirstShift);
  EXPECT_EQ(p.steps(), 0);
  p.stop();
  EXPECT_FALSE(p.active());
}

TEST(PseudoTransient, TheShiftFollowsTheResidual) {
  P p;
  p.start(0);
  p.stepped(8.0, 0.5);  // the first step sets the scale: no change
  EXPECT_DOUBLE_EQ(p.shift(), P::kFirstShift);
  p.stepped(4.0, 0.25);  // residual halved: shift halved
  EXPECT_DOUBLE_EQ(p.shift(), P::kFirstShift / 2);
  p.stepped(12.0, 0.0);  // tripled (a contact event): three times the damping
  EXPECT_DOUBLE_EQ(p.shift(), P::kFirstShift * 3 / 2);
  p.stepped(12e6, 0.0);  // at most kMaxChange per step, either way
  EXPECT_DOUBLE_EQ(p.shift(), P::kFirstShift * 15);
  p.stepped(12.0, 0.0);
  EXPECT_DOUBLE_EQ(p.shift(), P::kFirstShift * 1.5);
  EXPECT_DOUBLE_EQ(p.absorbed_energy(), 0.75);
  EXPECT_EQ(p.steps(), 5);
}

TEST(PseudoTransient, BecomesNewtonAsTheResidualVanishes) {
  P p;
  p.start(0);
  Real r = 1.0;
  p.stepped(r, 0);
  for (int i = 0; i < 9; ++i) p.stepped(r *= 0.1, 0);
  EXPECT_NEAR(p.shift(), P::kFirstShift * 1e-9, 1e-20);
  p.stepped(r *= 0.1, 0);
  p.stepped(r *= 0.1, 0);
  EXPECT_EQ(p.shift(), 0);  // 1e-13 < kNewtonShift
  // An indefinite tangent in the Newton phase gets a shift again.
  EXPECT_TRUE(p.raise());
  EXPECT_DOUBLE_EQ(p.shift(), P::kNewtonShift * P::kMaxChange);
}

TEST(PseudoTransient, RaisesForIndefiniteTangentsUpToTheLargestShift) {
  P p;
  p.start(0);
  int raised = 0;
  while (p.raise()) ++raised;
  EXPECT_LE(p.shift(), P::kMaxShift);
  EXPECT_GT(p.shift() * P::kMaxChange, P::kMaxShift);
  EXPECT_EQ(raised, 6);  // 1e-2 -> 1e4
}

TEST(PseudoTransient, EndsAfterItsSteps) {
  P p;
  p.start(0);
  Real residual = 1.0;
  for (int i = 0; i < P::kMaxSteps - 1; ++i) p.stepped(residual *= 0.99, 0);
  EXPECT_FALSE(p.exhausted());
  p.stepped(residual *= 0.99, 0);
  EXPECT_TRUE(p.exhausted());
  p.start(0.25);  // a new continuation starts afresh, from springs that held 0.25
  EXPECT_FALSE(p.exhausted());
  EXPECT_EQ(p.absorbed_energy(), 0.25);
  p.stepped(1.0, 0.5);
  EXPECT_EQ(p.absorbed_energy(), 0.75);
}

TEST(PseudoTransient, EndsWhenItsResidualStopsFallingButNotDuringASnap) {
  P p;
  p.start(0);
  p.stepped(1.0, 0);
  // A snap: the residual grows for kMaxStall - 1 steps, then falls below where it started.
  for (int i = 1; i < P::kMaxStall; ++i) p.stepped(1.0 + i, 0);
  EXPECT_FALSE(p.exhausted());
  p.stepped(0.5, 0);
  EXPECT_FALSE(p.exhausted());
  // Chattering just above its best: kMaxStall steps without a smaller residual end it.
  for (int i = 1; i < P::kMaxStall; ++i) p.stepped(i % 2 ? 0.6 : 0.5, 0);
  EXPECT_FALSE(p.exhausted());
  p.stepped(0.5, 0);
  EXPECT_TRUE(p.exhausted());
  EXPECT_LT(p.steps(), P::kMaxSteps);
  p.start(0);
  EXPECT_FALSE(p.exhausted());
}

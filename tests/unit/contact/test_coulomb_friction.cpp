// The Coulomb point kernel: the radial return's forces and states, and its derivatives by
// central finite differences and by the Taylor test (second-order remainder) in stick, in slip,
// near the transition, and for tied contact.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include "contact/coulomb_friction.hpp"

using namespace kontakt;
using namespace kontakt::contact;

namespace {

const Vec3 kNormal = Vec3(0.3, -0.2, 1).normalized();
constexpr Real kArea = 0.5;

TangentialResponse at(const CoulombLaw& law, const FrictionState& start, const Vec3& s, Real fn) {
  return coulomb_response(law, start, s, kNormal, kArea, fn);
}

/// Largest error of the analytic derivatives of F_T against central differences, relative
/// to the largest derivative.
Real fd_error(const CoulombLaw& law, const FrictionState& start, const Vec3& s, Real fn) {
  const TangentialResponse r = at(law, start, s, fn);
  const Real h = 1e-7 * std::max(s.norm(), 1e-3);
  Mat3 fd_s;
  for (int c = 0; c < 3; ++c) {
    Vec3 sp = s, sm = s;
    sp(c) += h;
    sm(c) -= h;
    fd_s.col(c) = (at(law, start, sp, fn).force - at(law, start, sm, fn).force) / (2 * h);
  }
  const Real hn = 1e-7 * fn;
  const Vec3 fd_n = (at(law, start, s, fn + hn).force - at(law, start, s, fn - hn).force) / (2 * hn);
  const Real scale = std::max(r.d_force_d_s.cwiseAbs().maxCoeff(), 1.0);
  return std::max((fd_s - r.d_force_d_s).cwiseAbs().maxCoeff(),
                  (fd_n - r.d_force_d_normal).cwiseAbs().maxCoeff()) / scale;
}

/// Observed order of the Taylor remainder |F(s + e d) - F(s) - e dF/ds d| as e halves.
Real taylor_order(const CoulombLaw& law, const FrictionState& start, const Vec3& s, Real fn) {
  const TangentialResponse r = at(law, start, s, fn);
  const Vec3 d = Vec3(0.7, -0.4, 0.2) * 1e-4;
  auto remainder = [&](Real e) {
    const Real dn = 0.3 * fn * e;
    return (at(law, start, s + e * d, fn + dn).force - r.force - e * r.d_force_d_s * d -
            dn * r.d_force_d_normal).norm();
  };
  return std::log2(remainder(0.02) / remainder(0.01));
}

}  // namespace

TEST(CoulombFriction, SticksElasticallyBelowTheLimit) {
  const CoulombLaw law{.mu = 0.3, .stick_slope = 1000};
  const Vec3 s(1e-4, 2e-4, 5e-4);  // partly normal: only the tangential part counts
  const TangentialResponse r = at(law, {}, s, 10);
  const Vec3 tangential = s - s.dot(kNormal) * kNormal;
  EXPECT_FALSE(r.slipping);
  EXPECT_LT((r.force - 1000 * kArea * tangential).norm(), 1e-12);
  EXPECT_LT(std::abs(r.force.dot(kNormal)), 1e-12);
  EXPECT_EQ(r.state.slip, Vec3::Zero());
  EXPECT_LT(fd_error(law, {}, s, 10), 1e-6);
}

TEST(CoulombFriction, SlipsOnTheConeAndAccumulatesTheExcess) {
  const CoulombLaw law{.mu = 0.3, .stick_slope = 1000};
  const Vec3 s(0.05, -0.02, 0);
  const Real fn = 10;
  const TangentialResponse r = at(law, {}, s, fn);
  ASSERT_TRUE(r.slipping);
  EXPECT_NEAR(r.force.norm(), 0.3 * fn, 1e-12);
  // The elastic part left is exactly what the cone allows.
  EXPECT_NEAR((1000 * kArea * (r.state.tangential - r.state.slip)).norm(), 0.3 * fn, 1e-9);
  EXPECT_LT(r.force.cross(r.state.slip).norm(), 1e-9 * r.force.norm() * r.state.slip.norm());
  EXPECT_LT(fd_error(law, {}, s, fn), 1e-6);
  EXPECT_GT(taylor_order(law, {}, s, fn), 1.9);
  // The slip tangent is unsymmetric once the normal force enters: dF_T/dF_N = mu xi.
  EXPECT_LT((r.d_force_d_normal - 0.3 * r.force / r.force.norm()).norm(), 1e-12);
}

TEST(CoulombFriction, TangentsHoldOnBothSidesOfTheTransition) {
  const CoulombLaw law{.mu = 0.2, .stick_slope = 500};
  const Real fn = 4;
  const Vec3 dir = (Vec3(1, 1, 0) - Vec3(1, 1, 0).dot(kNormal) * kNormal).normalized();
  const Real onset = 0.2 * fn / (500 * kArea);  // |t| where the cone is reached
  for (Real f : {0.999, 1.001}) {
    const Vec3 s = f * onset * dir;
    EXPECT_EQ(at(law, {}, s, fn).slipping, f > 1) << f;
    EXPECT_LT(fd_error(law, {}, s, fn), 1e-5) << f;
  }
}

TEST(CoulombFriction, StartsFromTheCommittedStateAndReversesElastically) {
  // After slipping by +x, a reversal first unloads elastically: the force changes sign only
  // after twice the elastic range (the hysteresis loop of fricloop).
  const CoulombLaw law{.mu = 0.2, .stick_slope = 1000};
  const Vec3 n = Vec3::UnitZ();
  const Real fn = 5, onset = 0.2 * fn / (1000 * kArea);
  const TangentialResponse loaded =
      coulomb_response(law, {}, Vec3(10 * onset, 0, 0), n, kArea, fn);
  ASSERT_TRUE(loaded.slipping);
  const TangentialResponse back =
      coulomb_response(law, loaded.state, Vec3(-onset, 0, 0), n, kArea, fn);
  EXPECT_FALSE(back.slipping);
  EXPECT_NEAR(back.force.x(), 0, 1e-12);
  const TangentialResponse reversed =
      coulomb_response(law, loaded.state, Vec3(-3 * onset, 0, 0), n, kArea, fn);
  EXPECT_TRUE(reversed.slipping);
  EXPECT_NEAR(reversed.force.x(), -0.2 * fn, 1e-12);
}

TEST(CoulombFriction, AnOpenPointCarriesNoShearAndRelaxes) {
  const CoulombLaw law{.mu = 0.2, .stick_slope = 1000};
  const FrictionState start{.tangential = Vec3(1e-3, 0, 0), .slip = Vec3(0.5e-3, 0, 0)};
  const TangentialResponse r = coulomb_response(law, start, Vec3(2e-3, 0, 0), Vec3::UnitZ(),
                                                kArea, 0);
  EXPECT_EQ(r.force, Vec3::Zero());
  EXPECT_EQ(r.d_force_d_s, Mat3::Zero());
  EXPECT_EQ(r.state.slip, r.state.tangential);  // no elastic stretch left to snap back
  EXPECT_NEAR(r.state.tangential.x(), 3e-3, 1e-15);
}

TEST(CoulombFriction, ATouchingPointNotYetStretchedSticksWithoutForce) {
  // ccx's rule: a zero trial force sticks. Bodies that touch without pressure (the first
  // iteration of a body held only by friction) get the stick stiffness, no force.
  const CoulombLaw law{.mu = 0.2, .stick_slope = 1000};
  const FrictionState start{.tangential = Vec3(1e-3, 0, 0), .slip = Vec3(1e-3, 0, 0)};
  const Mat3 P = Mat3::Identity() - kNormal * kNormal.transpose();
  for (Real fn : {0.0, -5.0}) {
    const TangentialResponse r = at(law, start, Vec3::Zero(), fn);  // as it starts
    EXPECT_EQ(r.force, Vec3::Zero()) << fn;
    EXPECT_FALSE(r.slipping) << fn;
    EXPECT_LT((r.d_force_d_s - 1000 * kArea * P).cwiseAbs().maxCoeff(), 1e-9) << fn;
    EXPECT_EQ(r.state.slip, r.state.tangential) << fn;
  }
  // Once stretched it carries nothing and relaxes (AnOpenPointCarriesNoShearAndRelaxes).
  EXPECT_EQ(at(law, start, Vec3(1e-4, 0, 0), 0).d_force_d_s, Mat3::Zero());
}

TEST(CoulombFriction, AStateFromAnEarlierNormalActsInTheCurrentTangentPlane) {
  // The committed state was tangent to the normal of the last increment; the normal has turned
  // since (a curved, deforming master). Stick and slip forces stay tangential, and the slip
  // force is mu F_N in full.
  const CoulombLaw law{.mu = 0.3, .stick_slope = 1000};
  const Vec3 old_normal = Vec3(0.1, 0, 1).normalized();
  const Vec3 t = Vec3(1, 0, 0) - Vec3(1, 0, 0).dot(old_normal) * old_normal;
  const Real fn = 10;
  for (Real size : {1e-4, 1e-2}) {  // stick, slip
    const FrictionState start{.tangential = size * t, .slip = Vec3::Zero()};
    const TangentialResponse r =
        coulomb_response(law, start, Vec3::Zero(), Vec3::UnitZ(), kArea, fn);
    EXPECT_NEAR(r.force.z(), 0, 1e-14) << size;
    if (r.slipping) EXPECT_NEAR(r.force.norm(), 0.3 * fn, 1e-12);
    else EXPECT_NEAR(r.force.x(), 1000 * kArea * size * t.x(), 1e-12);
  }
  EXPECT_TRUE(coulomb_response(law, {.tangential = 1e-2 * t}, Vec3::Zero(), Vec3::UnitZ(), kArea,
                               fn).slipping);
}

TEST(CoulombFriction, TiedContactAlwaysSticksEvenInTension) {
  const CoulombLaw tied{.mu = std::numeric_limits<Real>::infinity(), .stick_slope = 1e6};
  for (Real fn : {-50.0, 0.0, 50.0}) {
    const TangentialResponse r = at(tied, {}, Vec3(0.1, 0.2, 0), fn);
    EXPECT_FALSE(r.slipping) << fn;
    EXPECT_LT((r.d_force_d_s - 1e6 * kArea * (Mat3::Identity() - kNormal * kNormal.transpose()))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-6)
        << fn;
  }
}

// Tests for the kinematic / combined hardening J2 kernel (solver/material/j2_kinematic).
#include "material/j2_kinematic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <vector>

// A namespace of its own: the helpers' names recur in the other material tests.
namespace kontakt::material::test_j2_kinematic {
namespace {

constexpr Real kE = 200000.0;
constexpr Real kNu = 0.3;
constexpr Real kSy = 250.0;
const Real kG = kE / (2 * (1 + kNu));

Vec6 v6(Real a, Real b, Real c, Real d, Real e, Real f) {
  Vec6 v;
  v << a, b, c, d, e, f;
  return v;
}

HardeningTable multi_table() {
  return HardeningTable{{{250.0, 0.0}, {300.0, 0.002}, {320.0, 0.006}, {400.0, 0.010}, {410.0, 0.03}}};
}
HardeningTable cyclic_table() {  // breakpoints different from multi_table's
  return HardeningTable{{{250.0, 0.0}, {270.0, 0.003}, {300.0, 0.008}}};
}

J2KinematicResult kin(const HardeningTable& k, const HardeningTable* cyc, const J2KinematicState& s,
                      const Vec6& eps) {
  return j2_kinematic_return_map(kE, kNu, k, cyc, s, eps);
}

Real rel_err(const Mat6& a, const Mat6& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

Mat6 fd_tangent(const HardeningTable& k, const HardeningTable* cyc, const J2KinematicState& s,
                const Vec6& eps, Real h) {
  Mat6 d;
  for (int j = 0; j < 6; ++j) {
    Vec6 p = eps, m = eps;
    p(j) += h;
    m(j) -= h;
    d.col(j) = (kin(k, cyc, s, p).stress - kin(k, cyc, s, m).stress) / (2.0 * h);
  }
  return d;
}

/// eps_xx prescribed, all other stresses zero, Newton with the consistent tangent.
J2KinematicResult uniaxial(const HardeningTable& k, const HardeningTable* cyc, const J2KinematicState& s,
                           Vec6& eps) {
  J2KinematicResult r;
  for (int it = 0; it < 50; ++it) {
    r = kin(k, cyc, s, eps);
    const Eigen::Matrix<Real, 5, 1> res = r.stress.tail<5>();
    if (res.norm() < 1e-13 * kSy) return r;
    const Eigen::Matrix<Real, 5, 5> kt = r.tangent.bottomRightCorner<5, 5>();
    eps.tail<5>() -= kt.partialPivLu().solve(res);
  }
  ADD_FAILURE() << "uniaxial driver did not converge";
  return r;
}

TEST(J2Kinematic, ElasticStepBelowYield) {
  const Vec6 eps = v6(4e-4, -1e-4, 2e-4, 3e-4, -2e-4, 1e-4);
  const J2KinematicResult r = kin(multi_table(), nullptr, J2KinematicState{}, eps);
  const Mat6 c = isotropic_elastic_stiffness(kE, kNu);
  EXPECT_FALSE(r.yielded);
  EXPECT_LT((r.stress - c * eps).norm(), 1e-12 * (c * eps).norm());
  EXPECT_LT(rel_err(r.tangent, c), 1e-15);
  EXPECT_EQ(r.state.back_stress, Vec6::Zero());
}

TEST(J2Kinematic, ProportionalLoadingMatchesIsotropicCurve) {
  // Under radial loading from the virgin state the back stress is collinear with the
  // flow direction, so KINEMATIC and ISOTROPIC give the same response for the same table.
  const HardeningTable t = multi_table();
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  J2KinematicState ks;
  J2State is;
  for (int step = 1; step <= 12; ++step) {
    const Vec6 eps = 3e-3 * step * dir;
    const J2KinematicResult rk = kin(t, nullptr, ks, eps);
    const J2Result ri = j2_return_map(kE, kNu, t, is, eps);
    ASSERT_EQ(rk.yielded, ri.yielded) << step;
    EXPECT_LT((rk.stress - ri.stress).norm(), 1e-9 * kSy) << step;
    EXPECT_NEAR(rk.state.equivalent_plastic_strain, ri.state.equivalent_plastic_strain, 1e-14) << step;
    // (The tangents differ: a non-radial perturbation sees a surface centred at beta.)
    const Real alpha = rk.state.equivalent_plastic_strain;
    EXPECT_NEAR(von_mises(rk.state.back_stress), t.yield(alpha) - t.yield(0), 1e-9) << step;
    ks = rk.state;
    is = ri.state;
  }
  EXPECT_GT(ks.equivalent_plastic_strain, 0.03);  // reached the constant tail
}

TEST(J2Kinematic, UniaxialCycleShowsBauschingerEffect) {
  // Linear kinematic hardening, closed form for a tension / compression cycle.
  const Real h = 20000.0;
  const HardeningTable t{{{kSy, 0.0}, {kSy + 10 * h, 10.0}}};
  const Real h_eff = kE * h / (kE + h);
  const Real eps_y = kSy / kE;
  const Real eps_max = 5e-3;
  const Real s_max = kSy + h_eff * (eps_max - eps_y);
  const Real eps_rev = eps_max - 2 * kSy / kE;  // reverse yield at s_max - 2 sy
  J2KinematicState state;
  Vec6 eps = Vec6::Zero();
  std::vector<Real> path;
  for (int i = 1; i <= 50; ++i) path.push_back(eps_max * i / 50.0);
  for (int i = 1; i <= 80; ++i) path.push_back(eps_max - 2 * eps_max * i / 80.0);
  bool reverse_plastic = false;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Real e = path[i];
    eps(0) = e;
    const J2KinematicResult r = uniaxial(t, nullptr, state, eps);
    Real expected;
    if (i < 50) {
      expected = e <= eps_y ? kE * e : kSy + h_eff * (e - eps_y);
    } else {
      expected = e >= eps_rev ? s_max - kE * (eps_max - e) : s_max - 2 * kSy - h_eff * (eps_rev - e);
      reverse_plastic = reverse_plastic || e < eps_rev;
    }
    EXPECT_NEAR(r.stress(0), expected, 1e-10 * std::abs(expected) + 1e-9) << "point " << i << " eps " << e;
    // The elastic range stays 2 sy wide: |sigma - beta|_vm = sy whenever yielding.
    if (r.yielded) {
      EXPECT_NEAR(von_mises(r.stress - r.state.back_stress), kSy, 1e-9);
    }
    state = r.state;
  }
  EXPECT_TRUE(reverse_plastic);
  // Isotropic hardening on the same path would reverse-yield only at -s_max.
  EXPECT_LT(s_max - 2 * kSy, 0.0);
  EXPECT_GT(s_max - 2 * kSy, -s_max);
}

TEST(J2Kinematic, ReturnLandsOnShiftedSurfaceForNonProportionalPaths) {
  const HardeningTable k = multi_table();
  const HardeningTable cyc = cyclic_table();
  for (const HardeningTable* c : {static_cast<const HardeningTable*>(nullptr), &cyc}) {
    J2KinematicState state;
    Vec6 eps = Vec6::Zero();
    const std::array<Vec6, 4> incs = {v6(2e-3, -5e-4, 0, 1e-3, 0, 0), v6(-1e-3, 2e-3, 0, 0, 1.5e-3, 0),
                                      v6(0, 0, 2.5e-3, -2e-3, 0, 1e-3), v6(-3e-3, 1e-3, -2e-3, 0, -1e-3, 2e-3)};
    int n_plastic = 0;
    for (int step = 0; step < 24; ++step) {
      eps += incs[step % 4];
      const J2KinematicResult r = kin(k, c, state, eps);
      const Real alpha = r.state.equivalent_plastic_strain;
      const Real radius = c ? c->yield(alpha) : k.points.front().first;
      const Real f = von_mises(r.stress - r.state.back_stress);
      if (r.yielded) {
        ++n_plastic;
        EXPECT_NEAR(f, radius, 1e-12 * radius) << "step " << step;
        // Back-stress increment has von Mises magnitude Hk(alpha) - Hk(alpha_n).
        const Real dbeta = von_mises(r.state.back_stress - state.back_stress);
        EXPECT_NEAR(dbeta, k.yield(alpha) - k.yield(state.equivalent_plastic_strain), 1e-9);
      } else {
        EXPECT_LE(f, radius * (1 + 1e-12));
      }
      const Vec6& b = r.state.back_stress;
      const Vec6& ep = r.state.plastic_strain;
      EXPECT_LT(std::abs(b(0) + b(1) + b(2)), 1e-12 * kSy);
      EXPECT_LT(std::abs(ep(0) + ep(1) + ep(2)), 1e-15 * (1 + ep.norm()));
      state = r.state;
    }
    EXPECT_GE(n_plastic, 10);
  }
}

/// Reference delta-alpha by bisection for the combined model.
Real bisect(const HardeningTable& k, const HardeningTable* c, Real q_trial, Real alpha_n) {
  Real lo = 0, hi = q_trial / (3 * kG);
  auto r = [&](Real dg) {
    const Real a = alpha_n + dg;
    return q_trial - 3 * kG * dg - (k.yield(a) - k.yield(alpha_n)) - (c ? c->yield(a) : k.points[0].first);
  };
  for (int i = 0; i < 200; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (r(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(J2Kinematic, CombinedCrossesBothTablesInOneIncrement) {
  const HardeningTable k = multi_table();
  const HardeningTable cyc = cyclic_table();
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  for (Real s : {1.6e-3, 4e-3, 9e-3, 2e-2, 6e-2}) {
    for (const HardeningTable* c : {static_cast<const HardeningTable*>(nullptr), &cyc}) {
      const J2KinematicResult r = kin(k, c, J2KinematicState{}, s * dir);
      ASSERT_TRUE(r.yielded);
      const Real alpha = r.state.equivalent_plastic_strain;
      const Real q_trial = von_mises(r.stress - r.state.back_stress) + von_mises(r.state.back_stress) + 3 * kG * alpha;
      EXPECT_NEAR(alpha, bisect(k, c, q_trial, 0.0), 1e-12 * (alpha + 1e-3)) << s;
      // Monotonic radial loading: sigma_vm = R(alpha) + Hk(alpha) - Hk(0).
      const Real radius = c ? c->yield(alpha) : k.points[0].first;
      EXPECT_NEAR(von_mises(r.stress), radius + k.yield(alpha) - k.yield(0), 1e-9) << s;
    }
  }
}

TEST(J2Kinematic, ConsistentTangentMatchesFiniteDifferences) {
  const HardeningTable k = multi_table();
  const HardeningTable cyc = cyclic_table();
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  const Vec6 side = v6(0, 1.5e-3, 0, 0, 2e-3, 0);
  const Real h = 1e-8;
  for (const HardeningTable* c : {static_cast<const HardeningTable*>(nullptr), &cyc}) {
    const J2KinematicResult pre = kin(k, c, J2KinematicState{}, 3.5e-3 * dir);
    ASSERT_TRUE(pre.yielded);
    struct Case {
      const char* name;
      J2KinematicState s;
      Vec6 eps;
      bool yielded;
    };
    const std::array<Case, 4> cases = {Case{"virgin plastic", J2KinematicState{}, 8e-3 * dir, true},
                                       Case{"reloading with back stress", pre.state, 3.5e-3 * dir + side, true},
                                       Case{"elastic unloading", pre.state, 2.5e-3 * dir, false},
                                       Case{"reverse plastic", pre.state, -1e-3 * dir, true}};
    for (const Case& cs : cases) {
      const J2KinematicResult r = kin(k, c, cs.s, cs.eps);
      ASSERT_EQ(r.yielded, cs.yielded) << cs.name;
      const Mat6 fd = fd_tangent(k, c, cs.s, cs.eps, h);
      EXPECT_LE(rel_err(r.tangent, fd), 1e-6) << cs.name << (c ? " combined" : " kinematic");
      if (cs.yielded) {
        EXPECT_GT(rel_err(isotropic_elastic_stiffness(kE, kNu), fd), 1e-2) << cs.name;
      }
    }
  }
}

TEST(J2Kinematic, UnloadingIsElasticAndKeepsInternalVariables) {
  const HardeningTable k = multi_table();
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  const J2KinematicResult loaded = kin(k, nullptr, J2KinematicState{}, 5e-3 * dir);
  ASSERT_TRUE(loaded.yielded);
  EXPECT_FALSE(kin(k, nullptr, loaded.state, 5e-3 * dir).yielded);
  const J2KinematicResult r = kin(k, nullptr, loaded.state, 4.5e-3 * dir);
  EXPECT_FALSE(r.yielded);
  EXPECT_EQ(r.state.equivalent_plastic_strain, loaded.state.equivalent_plastic_strain);
  EXPECT_EQ(r.state.back_stress, loaded.state.back_stress);
  EXPECT_EQ(r.state.plastic_strain, loaded.state.plastic_strain);
}

}  // namespace
}  // namespace kontakt::material::test_j2_kinematic

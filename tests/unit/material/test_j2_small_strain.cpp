// Tests for the small-strain J2 radial-return kernel (solver/material/j2_small_strain).
#include "material/j2_small_strain.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

// A namespace of its own: the helpers' names recur in the other material tests.
namespace kontakt::material::test_j2_small_strain {
namespace {

constexpr Real kE = 200000.0;
constexpr Real kNu = 0.3;
constexpr Real kSy = 250.0;

HardeningTable linear_table(Real sy, Real h) {
  // Linear hardening up to a large plastic strain, so the constant tail is never hit.
  return HardeningTable{{{sy, 0.0}, {sy + h * 10.0, 10.0}}};
}

HardeningTable multi_table() {
  // Decreasing and increasing slopes, so segment crossing is exercised both ways.
  return HardeningTable{{{250.0, 0.0}, {300.0, 0.002}, {320.0, 0.006}, {400.0, 0.010}, {410.0, 0.03}}};
}

Vec6 v6(Real a, Real b, Real c, Real d, Real e, Real f) {
  Vec6 v;
  v << a, b, c, d, e, f;
  return v;
}

/// Central finite-difference d(stress)/d(strain) of the return map at a fixed committed state.
Mat6 fd_tangent(const HardeningTable& t, const J2State& committed, const Vec6& strain, Real h) {
  Mat6 d;
  for (int j = 0; j < 6; ++j) {
    Vec6 p = strain, m = strain;
    p(j) += h;
    m(j) -= h;
    d.col(j) = (j2_return_map(kE, kNu, t, committed, p).stress -
                j2_return_map(kE, kNu, t, committed, m).stress) /
               (2.0 * h);
  }
  return d;
}

Real rel_err(const Mat6& a, const Mat6& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

/// Mixed single-point problem: strain components in `fixed` are prescribed, the others are
/// solved so that their stress equals `target`, by Newton with the returned tangent (or a
/// supplied replacement). Returns the converged result; `residuals` gets the history.
struct MixedSolve {
  std::vector<int> free;  // indices whose stress is prescribed
  Vec6 target = Vec6::Zero();
  bool use_elastic_tangent = false;
  int max_iter = 50;
  Real tol = 1e-13;

  J2Result run(const HardeningTable& t, const J2State& committed, Vec6& strain,
               std::vector<Real>* residuals = nullptr) const {
    const int nf = static_cast<int>(free.size());
    const Mat6 ce = isotropic_elastic_stiffness(kE, kNu);
    J2Result r;
    for (int it = 0; it < max_iter; ++it) {
      r = j2_return_map(kE, kNu, t, committed, strain);
      Eigen::VectorXd res(nf);
      Eigen::MatrixXd k(nf, nf);
      const Mat6& c = use_elastic_tangent ? ce : r.tangent;
      for (int a = 0; a < nf; ++a) {
        res(a) = r.stress(free[a]) - target(free[a]);
        for (int b = 0; b < nf; ++b) k(a, b) = c(free[a], free[b]);
      }
      const Real norm = res.norm() / kSy;
      if (residuals) residuals->push_back(norm);
      if (norm < tol) return r;
      const Eigen::VectorXd dx = k.partialPivLu().solve(-res);
      for (int a = 0; a < nf; ++a) strain(free[a]) += dx(a);
    }
    return r;
  }
};

// ---------------------------------------------------------------- hardening table

TEST(HardeningTable, InterpolatesAndStaysConstantBeyondLastRow) {
  const HardeningTable t = multi_table();
  EXPECT_DOUBLE_EQ(t.yield(0.0), 250.0);
  EXPECT_DOUBLE_EQ(t.yield(0.001), 275.0);
  EXPECT_DOUBLE_EQ(t.yield(0.002), 300.0);
  EXPECT_DOUBLE_EQ(t.yield(0.004), 310.0);
  EXPECT_DOUBLE_EQ(t.slope(0.001), 25000.0);
  EXPECT_DOUBLE_EQ(t.slope(0.002), 5000.0);  // right derivative at a breakpoint
  EXPECT_DOUBLE_EQ(t.yield(0.03), 410.0);
  EXPECT_DOUBLE_EQ(t.yield(5.0), 410.0);  // ccx plinterpol: last stress, slope 0
  EXPECT_DOUBLE_EQ(t.slope(5.0), 0.0);
  const HardeningTable perfect{{{kSy, 0.0}}};
  EXPECT_DOUBLE_EQ(perfect.yield(0.3), kSy);
  EXPECT_DOUBLE_EQ(perfect.slope(0.3), 0.0);
}

TEST(HardeningTable, ValidateRejectsBadTables) {
  EXPECT_THROW(HardeningTable{}.validate(), std::invalid_argument);
  EXPECT_THROW((HardeningTable{{{250.0, 0.001}}}.validate()), std::invalid_argument);
  EXPECT_THROW((HardeningTable{{{250.0, 0.0}, {260.0, 0.0}}}.validate()), std::invalid_argument);
  EXPECT_THROW((HardeningTable{{{250.0, 0.0}, {260.0, 0.2}, {270.0, 0.1}}}.validate()),
               std::invalid_argument);
  EXPECT_THROW((HardeningTable{{{-1.0, 0.0}}}.validate()), std::invalid_argument);
  EXPECT_NO_THROW(multi_table().validate());
  EXPECT_THROW(j2_return_map(kE, kNu, HardeningTable{}, J2State{}, Vec6::Zero()), std::invalid_argument);
  EXPECT_THROW(j2_return_map(kE, 0.5, multi_table(), J2State{}, Vec6::Zero()), std::invalid_argument);
}

// ---------------------------------------------------------------- elastic regime

TEST(J2SmallStrain, ElasticStepBelowYieldGivesElasticStressAndTangent) {
  const Vec6 eps = v6(4e-4, -1e-4, 2e-4, 3e-4, -2e-4, 1e-4);  // engineering shear
  const J2Result r = j2_return_map(kE, kNu, linear_table(kSy, 1000.0), J2State{}, eps);
  const Mat6 c = isotropic_elastic_stiffness(kE, kNu);
  ASSERT_FALSE(r.yielded);
  EXPECT_LT(von_mises(r.stress), kSy);
  EXPECT_LT((r.stress - c * eps).norm(), 1e-12 * (c * eps).norm());
  EXPECT_LT(rel_err(r.tangent, c), 1e-15);
  EXPECT_EQ(r.state.equivalent_plastic_strain, 0.0);
  EXPECT_EQ(r.state.plastic_strain, Vec6::Zero());
  // Hand value: G = E/2.6, so tau_xy = G * gamma_xy.
  EXPECT_NEAR(r.stress(3), kE / 2.6 * 3e-4, 1e-12);
}

TEST(J2SmallStrain, ThermalStrainIsSubtracted) {
  const Real eth = 1.5e-3;  // well beyond yield strain if it were mechanical
  const Vec6 free_expansion = v6(eth, eth, eth, 0, 0, 0);
  const J2Result r = j2_return_map(kE, kNu, linear_table(kSy, 1000.0), J2State{}, free_expansion, eth);
  EXPECT_FALSE(r.yielded);
  EXPECT_LT(r.stress.norm(), 1e-10);
  // Shifting mechanical and thermal strain by the same isotropic amount changes nothing.
  const Vec6 eps = v6(3e-3, -1e-3, 5e-4, 2e-3, 0, -1e-3);
  const J2Result a = j2_return_map(kE, kNu, multi_table(), J2State{}, eps);
  const J2Result b = j2_return_map(kE, kNu, multi_table(), J2State{}, eps + free_expansion, eth);
  ASSERT_TRUE(a.yielded);
  EXPECT_LT((a.stress - b.stress).norm(), 1e-9);
  EXPECT_NEAR(a.state.equivalent_plastic_strain, b.state.equivalent_plastic_strain, 1e-14);
}

// ---------------------------------------------------------------- uniaxial closed form

TEST(J2SmallStrain, UniaxialStressPathMatchesLinearHardeningClosedForm) {
  const Real h = 20000.0;
  const HardeningTable t = linear_table(kSy, h);
  const Real eps_y = kSy / kE;
  const Real h_eff = kE * h / (kE + h);
  MixedSolve solve;
  solve.free = {1, 2, 3, 4, 5};
  J2State state;
  Vec6 eps = Vec6::Zero();
  int n_plastic = 0;
  for (int step = 1; step <= 40; ++step) {
    const Real exx = 0.00013 * step;  // first plastic step crosses yield inside the increment
    eps(0) = exx;
    const J2Result r = solve.run(t, state, eps);
    const Real expected = exx <= eps_y ? kE * exx : kSy + h_eff * (exx - eps_y);
    EXPECT_NEAR(r.stress(0), expected, 1e-10 * expected) << "step " << step;
    EXPECT_LT(r.stress.tail<5>().cwiseAbs().maxCoeff(), 1e-10 * kSy);
    if (exx > eps_y) {
      ++n_plastic;
      ASSERT_TRUE(r.yielded);
      const Real ep = (expected - kSy) / h;  // uniaxial: alpha = eps_p_xx
      EXPECT_NEAR(r.state.equivalent_plastic_strain, ep, 1e-10 * ep);
      EXPECT_NEAR(r.state.plastic_strain(0), ep, 1e-10 * ep);
      EXPECT_NEAR(r.state.plastic_strain(1), -0.5 * ep, 1e-10 * ep);
      EXPECT_NEAR(r.state.plastic_strain(2), -0.5 * ep, 1e-10 * ep);
    }
    state = r.state;  // commit
  }
  EXPECT_GT(n_plastic, 30);
}

// ---------------------------------------------------------------- perfect plasticity

TEST(J2SmallStrain, PerfectlyPlasticStaysOnYieldStress) {
  const HardeningTable t{{{kSy, 0.0}}};
  J2State state;
  Vec6 eps = Vec6::Zero();
  const std::array<Vec6, 3> dirs = {v6(1, -0.3, -0.3, 0, 0, 0), v6(0.2, 0.5, -0.7, 1.5, 0, 0),
                                    v6(-0.4, 0.1, 0.2, -0.5, 1.0, 0.8)};
  int n_plastic = 0;
  for (int step = 0; step < 60; ++step) {
    eps += 4e-4 * dirs[step / 20];
    const J2Result r = j2_return_map(kE, kNu, t, state, eps);
    if (r.yielded) {
      ++n_plastic;
      EXPECT_NEAR(von_mises(r.stress), kSy, 1e-12 * kSy) << "step " << step;
      EXPECT_GT(r.state.equivalent_plastic_strain, state.equivalent_plastic_strain);
    } else {
      EXPECT_LE(von_mises(r.stress), kSy * (1 + 1e-12));
    }
    state = r.state;
  }
  EXPECT_GT(n_plastic, 40);
}

// ---------------------------------------------------------------- segment crossing

/// Reference delta-alpha by bisection on q_trial - 3G dg - yield(alpha_n + dg) = 0.
Real bisect_dalpha(const HardeningTable& t, Real q_trial, Real alpha_n) {
  const Real g = kE / (2 * (1 + kNu));
  Real lo = 0, hi = q_trial / (3 * g);
  for (int i = 0; i < 200; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (q_trial - 3 * g * mid - t.yield(alpha_n + mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(J2SmallStrain, MultiSegmentTableCrossedInOneIncrement) {
  const HardeningTable t = multi_table();
  const Real g = kE / (2 * (1 + kNu));
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  // Increment sizes chosen to end in segment 0, 1, 2, 3 and the constant tail.
  const std::array<Real, 5> expected_segment = {0, 1, 2, 3, 4};
  const std::array<Real, 5> scale = {1.6e-3, 3.5e-3, 8e-3, 1.4e-2, 5e-2};
  for (int i = 0; i < 5; ++i) {
    const Vec6 eps = scale[i] * dir;
    const J2Result r = j2_return_map(kE, kNu, t, J2State{}, eps);
    ASSERT_TRUE(r.yielded);
    const Real alpha = r.state.equivalent_plastic_strain;
    EXPECT_EQ(static_cast<Real>(t.segment(alpha)), expected_segment[i]) << "case " << i;
    const Real q_trial = von_mises(r.stress) + 3 * g * alpha;
    EXPECT_NEAR(alpha, bisect_dalpha(t, q_trial, 0.0), 1e-12 * (alpha + 1e-3));
    EXPECT_NEAR(von_mises(r.stress), t.yield(alpha), 1e-11 * t.yield(alpha));
  }
  // Same from a committed plastic state sitting inside segment 1, ending in segment 3:
  // the walk must start in the committed state's segment, not at the table start.
  const J2Result first = j2_return_map(kE, kNu, t, J2State{}, 3.5e-3 * dir);
  ASSERT_EQ(t.segment(first.state.equivalent_plastic_strain), 1u);
  const J2Result second = j2_return_map(kE, kNu, t, first.state, 1.4e-2 * dir);
  ASSERT_TRUE(second.yielded);
  EXPECT_EQ(t.segment(second.state.equivalent_plastic_strain), 3u);
  EXPECT_NEAR(von_mises(second.stress), t.yield(second.state.equivalent_plastic_strain), 1e-11 * 400);
}

// ---------------------------------------------------------------- consistent tangent

TEST(J2SmallStrain, ConsistentTangentMatchesFiniteDifferencesInAllRegimes) {
  const HardeningTable lin = linear_table(kSy, 15000.0);
  const HardeningTable multi = multi_table();
  const HardeningTable perfect{{{kSy, 0.0}}};
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  const Real h = 1e-8;

  struct Case {
    const char* name;
    const HardeningTable* table;
    J2State committed;
    Vec6 strain;
    bool yielded;
  };
  std::vector<Case> cases;
  cases.push_back({"elastic", &lin, J2State{}, 5e-4 * dir, false});
  cases.push_back({"plastic linear", &lin, J2State{}, 3e-3 * dir, true});
  cases.push_back({"plastic perfect", &perfect, J2State{}, 3e-3 * dir, true});
  cases.push_back({"plastic segment 2", &multi, J2State{}, 8e-3 * dir, true});
  {  // plastic loading from a committed plastic state in another direction
    const J2Result pre = j2_return_map(kE, kNu, multi, J2State{}, 3.5e-3 * dir);
    cases.push_back({"plastic reloading", &multi, pre.state,
                     3.5e-3 * dir + v6(0, 1.5e-3, 0, 0, 2e-3, 0), true});
    // elastic unloading from the plastic state
    cases.push_back({"elastic unloading", &multi, pre.state, 2.5e-3 * dir, false});
  }
  for (const Case& c : cases) {
    const J2Result r = j2_return_map(kE, kNu, *c.table, c.committed, c.strain);
    ASSERT_EQ(r.yielded, c.yielded) << c.name;
    const Mat6 fd = fd_tangent(*c.table, c.committed, c.strain, h);
    EXPECT_LE(rel_err(r.tangent, fd), 1e-6) << c.name;
    EXPECT_LT((r.tangent - r.tangent.transpose()).cwiseAbs().maxCoeff(), 1e-9 * kE) << c.name;
    if (c.yielded) {  // and the tangent is really not the elastic one
      EXPECT_GT(rel_err(isotropic_elastic_stiffness(kE, kNu), fd), 1e-2) << c.name;
    }
  }
}

// ---------------------------------------------------------------- return properties

TEST(J2SmallStrain, ReturnLandsOnYieldSurfaceAndPlasticFlowIsIsochoric) {
  const HardeningTable t = multi_table();
  J2State state;
  Vec6 eps = Vec6::Zero();
  // A non-proportional path with random-ish increments.
  const std::array<Vec6, 4> incs = {v6(2e-3, -5e-4, 0, 1e-3, 0, 0), v6(-1e-3, 2e-3, 0, 0, 1.5e-3, 0),
                                    v6(0, 0, 2.5e-3, -2e-3, 0, 1e-3), v6(1e-3, 1e-3, -2e-3, 0, -1e-3, 2e-3)};
  int n_plastic = 0;
  for (int step = 0; step < 24; ++step) {
    eps += incs[step % 4];
    const J2Result r = j2_return_map(kE, kNu, t, state, eps);
    if (r.yielded) {
      ++n_plastic;
      const Real alpha = r.state.equivalent_plastic_strain;
      EXPECT_NEAR(von_mises(r.stress), t.yield(alpha), 1e-12 * t.yield(alpha)) << "step " << step;
      // Increment of equivalent plastic strain = sqrt(2/3)|d eps_p|.
      const Vec6 dep = r.state.plastic_strain - state.plastic_strain;
      const Real dep_norm = std::sqrt(dep.head<3>().squaredNorm() + 2 * dep.tail<3>().squaredNorm());
      EXPECT_NEAR(std::sqrt(2.0 / 3.0) * dep_norm, r.delta_alpha, 1e-12 * r.delta_alpha);
    }
    const Vec6& ep = r.state.plastic_strain;
    EXPECT_LE(std::abs(ep(0) + ep(1) + ep(2)), 1e-15 * (1.0 + ep.norm()) + 1e-17) << "step " << step;
    state = r.state;
  }
  EXPECT_GE(n_plastic, 10);
}

TEST(J2SmallStrain, UnloadingAfterYieldingIsElastic) {
  const HardeningTable t = multi_table();
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  const Vec6 eps1 = 5e-3 * dir;
  const J2Result loaded = j2_return_map(kE, kNu, t, J2State{}, eps1);
  ASSERT_TRUE(loaded.yielded);
  const Mat6 c = isotropic_elastic_stiffness(kE, kNu);
  // Re-evaluating at the converged strain is elastic (point is on, not outside, the surface).
  EXPECT_FALSE(j2_return_map(kE, kNu, t, loaded.state, eps1).yielded);
  for (Real f : {0.9, 0.7, 0.55}) {  // reverse yielding starts near f = 0.47
    const Vec6 eps = f * eps1;
    const J2Result r = j2_return_map(kE, kNu, t, loaded.state, eps);
    EXPECT_FALSE(r.yielded) << f;
    EXPECT_EQ(r.state.equivalent_plastic_strain, loaded.state.equivalent_plastic_strain);
    EXPECT_EQ(r.state.plastic_strain, loaded.state.plastic_strain);
    Vec6 ep_eng = loaded.state.plastic_strain;
    ep_eng.tail<3>() *= 2.0;
    EXPECT_LT((r.stress - c * (eps - ep_eng)).norm(), 1e-9 * kSy) << f;
    EXPECT_LT((r.stress - (loaded.stress - c * (eps1 - eps))).norm(), 1e-9 * kSy) << f;
    EXPECT_LT(rel_err(r.tangent, c), 1e-15);
  }
  // Reversed loading re-yields (isotropic hardening: at the expanded yield stress).
  const J2Result rev = j2_return_map(kE, kNu, t, loaded.state, -2e-3 * dir);
  ASSERT_TRUE(rev.yielded);
  EXPECT_NEAR(von_mises(rev.stress), t.yield(rev.state.equivalent_plastic_strain), 1e-9);
  EXPECT_GT(rev.state.equivalent_plastic_strain, loaded.state.equivalent_plastic_strain);
}

// ---------------------------------------------------------------- Newton / Taylor

/// Observed convergence orders log(r_{k+1}/r_k) / log(r_k/r_{k-1}) for residuals in the
/// asymptotic range (above round-off).
std::vector<Real> orders(const std::vector<Real>& r) {
  std::vector<Real> out;
  for (std::size_t k = 1; k + 1 < r.size(); ++k)
    if (r[k + 1] > 1e-13 && r[k] < 1e-2) out.push_back(std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]));
  return out;
}

TEST(J2SmallStrain, TaylorRemainderAndNewtonConvergeQuadratically) {
  const HardeningTable t = linear_table(kSy, 15000.0);
  // Committed plastic state.
  const Vec6 dir = v6(1.0, -0.2, -0.5, 0.6, 0.3, -0.4);
  const J2State committed = j2_return_map(kE, kNu, t, J2State{}, 2e-3 * dir).state;

  // (a) Taylor test of the tangent: |s(e + t d) - s(e) - t C d| = O(t^2).
  const Vec6 e0 = 4e-3 * dir;
  const J2Result r0 = j2_return_map(kE, kNu, t, committed, e0);
  ASSERT_TRUE(r0.yielded);
  const Vec6 d = v6(0.3, 0.8, -0.2, -0.5, 0.9, 0.1) * 1e-3;
  std::vector<Real> rem;
  for (Real s = 1.0; s > 1e-3; s *= 0.5) {
    const J2Result rs = j2_return_map(kE, kNu, t, committed, e0 + s * d);
    ASSERT_TRUE(rs.yielded);
    rem.push_back((rs.stress - r0.stress - s * r0.tangent * d).norm());
  }
  for (std::size_t k = 1; k < rem.size(); ++k) {
    if (rem[k] < 1e-9) break;  // round-off floor
    EXPECT_NEAR(std::log2(rem[k - 1] / rem[k]), 2.0, 0.1) << "halving " << k;
  }

  // (b) Newton on the mixed problem: eps_xx prescribed, sigma_xy = 80, the other stresses 0.
  MixedSolve solve;
  solve.free = {1, 2, 3, 4, 5};
  solve.target(3) = 80.0;
  Vec6 eps = Vec6::Zero();
  eps(0) = 4e-3;
  std::vector<Real> res;
  const J2Result r = solve.run(t, committed, eps, &res);
  ASSERT_LT(res.back(), 1e-13);
  ASSERT_TRUE(r.yielded);
  EXPECT_LE(res.size(), 8u);
  EXPECT_NEAR(r.stress(3), 80.0, 1e-10);
  const std::vector<Real> q = orders(res);
  ASSERT_FALSE(q.empty());
  EXPECT_GT(q.back(), 1.8);
  for (std::size_t k = 2; k < res.size(); ++k)
    if (res[k] > 1e-13) {
      EXPECT_LT(res[k], 10.0 * res[k - 1] * res[k - 1]) << "iteration " << k;
    }

  // Negative control: the same iteration with the elastic tangent is only linear, so the
  // checks above would fail for a non-consistent tangent.
  MixedSolve elastic = solve;
  elastic.use_elastic_tangent = true;
  Vec6 eps_e = Vec6::Zero();
  eps_e(0) = 4e-3;
  std::vector<Real> res_e;
  elastic.run(t, committed, eps_e, &res_e);
  EXPECT_GT(res_e.size(), res.size() + 3);
  const std::vector<Real> qe = orders(res_e);
  ASSERT_FALSE(qe.empty());
  EXPECT_LT(qe.back(), 1.3);
}

}  // namespace
}  // namespace kontakt::material::test_j2_small_strain

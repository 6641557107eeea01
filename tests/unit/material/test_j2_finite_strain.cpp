// Tests for the finite-strain J2 model (solver/material/j2_finite_strain): ccx's answers on a
// homogeneous path, the small-strain limit, consistency of the return, and finite-difference
// checks of the consistent tangent (elastic, plastic loading across table rows, perfectly
// plastic, elastic unloading).
#include "material/j2_finite_strain.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "core/error.hpp"

// A namespace of its own: the helpers' names recur in the other material tests.
namespace kontakt::material::test_j2_finite_strain {
namespace {

constexpr Real kE = 210000.0;
constexpr Real kNu = 0.3;

HardeningTable three_rows() { return HardeningTable{{{800.0, 0.0}, {1000.0, 0.05}, {1200.0, 0.2}}}; }

Mat3 right_cauchy_green(const Mat3& F) { return F.transpose() * F; }

/// Cauchy stress F S F^T / det F as a 3 x 3 tensor.
Mat3 cauchy(const Mat3& F, const Vec6& S) {
  Mat3 s;
  s << S[0], S[3], S[4], S[3], S[1], S[5], S[4], S[5], S[2];
  return F * s * F.transpose() / F.determinant();
}

/// Von Mises stress of the Cauchy stress belonging to S at C (invariants of tau = F S F^T).
Real cauchy_von_mises(const Mat3& C, const Vec6& S) {
  Mat3 s;
  s << S[0], S[3], S[4], S[3], S[1], S[5], S[4], S[5], S[2];
  const Mat3 SC = s * C;
  const Real dev2 = (SC * SC).trace() - SC.trace() * SC.trace() / 3.0;
  return std::sqrt(1.5 * dev2) / std::sqrt(C.determinant());
}

/// C after a change of the engineering Green-Lagrange strain component j by h.
Mat3 perturbed(const Mat3& C, int j, Real h) {
  static constexpr int kI[6] = {0, 1, 2, 0, 0, 1}, kJ[6] = {0, 1, 2, 1, 2, 2};
  Mat3 c = C;
  if (j < 3) {
    c(j, j) += 2 * h;
  } else {
    c(kI[j], kJ[j]) += h;
    c(kJ[j], kI[j]) += h;
  }
  return c;
}

Mat6 fd_tangent(const HardeningTable& t, const J2State& s, const Mat3& C, Real h = 1e-7) {
  Mat6 d;
  for (int j = 0; j < 6; ++j)
    d.col(j) = (j2_finite_strain(kE, kNu, t, s, perturbed(C, j, h)).stress -
                j2_finite_strain(kE, kNu, t, s, perturbed(C, j, -h)).stress) /
               (2 * h);
  return d;
}

Real rel_err(const Mat6& a, const Mat6& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// Walks the deformation gradient linearly from F0 to F1 in n steps, committing every step.
J2FiniteResult walk(const HardeningTable& t, J2State& state, const Mat3& F0, const Mat3& F1, int n) {
  J2FiniteResult r;
  for (int k = 1; k <= n; ++k) {
    const Mat3 F = F0 + (F1 - F0) * (static_cast<Real>(k) / n);
    r = j2_finite_strain(kE, kNu, t, state, right_cauchy_green(F));
    state = r.state;
  }
  return r;
}

TEST(J2FiniteStrain, ReproducesCcxOnAHomogeneousPath) {
  // Reference: ccx 2.20, one C3D8 with every node prescribed on u = (F - 1) X, three steps of
  // 10 DIRECT increments each (simple shear, then a general F, then back towards 1), *PLASTIC
  // with three rows; Cauchy stresses and PEEQ as printed in its .dat file.
  Mat3 F1, F2, F3;
  F1 << 1, 0.3, 0, 0, 1, 0, 0, 0, 1;
  F2 << 1.1, 0.3, 0.05, 0.02, 0.95, 0, 0, 0.1, 1.02;
  F3 << 1.0, 0.1, 0.05, 0.02, 1.0, 0, 0, 0.1, 1.0;
  const Real ccx[3][7] = {{20.52564, -10.26282, -10.26282, 668.2532, 0, 0, 0.1683935},
                          {10736.42, 9616.933, 10195.6, -47.1603, 160.2255, 372.3826, 0.2725868},
                          {-743.9777, 77.9916, -332.4634, -557.5635, 13.33596, 6.048477, 0.4024182}};
  J2State state;
  Mat3 previous = Mat3::Identity();
  const Mat3 targets[3] = {F1, F2, F3};
  for (int s = 0; s < 3; ++s) {
    const J2FiniteResult r = walk(three_rows(), state, previous, targets[s], 10);
    previous = targets[s];
    const Mat3 sigma = cauchy(targets[s], r.stress);
    const Real ours[6] = {sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1), sigma(0, 2), sigma(1, 2)};
    Real scale = 0;
    for (int c = 0; c < 6; ++c) scale = std::max(scale, std::abs(ccx[s][c]));
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(ours[c], ccx[s][c], 1e-6 * scale) << "step " << s << " comp " << c;
    EXPECT_NEAR(r.state.equivalent_plastic_strain, ccx[s][6], 1e-6 * ccx[s][6]) << "step " << s;
  }
}

TEST(J2FiniteStrain, ElasticResponseIsSimosNeoHookeanEnergy) {
  // Uniaxial stretch 1.5 with the lateral stretch ccx finds for E = 100, nu = 0.3 (a stress-free
  // side): Cauchy sigma_xx = 42.404 printed by ccx 2.20.
  const Real lateral = 1 - 0.1115936;
  Mat3 F = Mat3::Identity();
  F(0, 0) = 1.5;
  F(1, 1) = F(2, 2) = lateral;
  const HardeningTable never{{{1e9, 0.0}}};
  const J2FiniteResult r = j2_finite_strain(100.0, 0.3, never, J2State{}, right_cauchy_green(F));
  const Mat3 sigma = cauchy(F, r.stress);
  EXPECT_FALSE(r.yielded);
  EXPECT_NEAR(sigma(0, 0), 42.404, 1e-3);
  EXPECT_NEAR(sigma(1, 1), 0.0, 2e-4);
}

TEST(J2FiniteStrain, SmallStrainsGiveTheSmallStrainModel) {
  // Strains of 1e-4 beyond a yield strain of 5e-5: the two models agree to O(strain).
  const HardeningTable t{{{10.0, 0.0}, {30.0, 0.001}}};
  Vec6 eps;  // engineering shear
  eps << 2e-4, -5e-5, -7e-5, 1.2e-4, -4e-5, 3e-5;
  Mat3 H;
  H << eps[0], eps[3] / 2, eps[4] / 2, eps[3] / 2, eps[1], eps[5] / 2, eps[4] / 2, eps[5] / 2, eps[2];
  const J2FiniteResult fin = j2_finite_strain(1e5, kNu, t, J2State{}, right_cauchy_green(Mat3::Identity() + H));
  const J2Result sml = j2_return_map(1e5, kNu, t, J2State{}, eps);
  ASSERT_TRUE(fin.yielded && sml.yielded);
  EXPECT_LT((fin.stress - sml.stress).cwiseAbs().maxCoeff(), 1e-3 * sml.stress.cwiseAbs().maxCoeff());
  EXPECT_NEAR(fin.state.equivalent_plastic_strain, sml.state.equivalent_plastic_strain,
              1e-3 * sml.state.equivalent_plastic_strain);
  EXPECT_LT((fin.state.plastic_strain - sml.state.plastic_strain).cwiseAbs().maxCoeff(),
            1e-3 * sml.state.plastic_strain.cwiseAbs().maxCoeff());
  EXPECT_LT(rel_err(fin.tangent, sml.tangent), 1e-3);
}

TEST(J2FiniteStrain, ReturnLandsOnTheYieldSurfaceAndStaysThere) {
  Mat3 F;
  F << 1.08, 0.12, 0.0, -0.03, 0.97, 0.05, 0.02, 0.0, 0.99;
  const J2FiniteResult r = j2_finite_strain(kE, kNu, three_rows(), J2State{}, right_cauchy_green(F));
  ASSERT_TRUE(r.yielded);
  const Real alpha = r.state.equivalent_plastic_strain;
  EXPECT_NEAR(cauchy_von_mises(right_cauchy_green(F), r.stress), three_rows().yield(alpha), 1e-8 * 1000);
  // The returned state re-evaluated at the same deformation flows no further.
  const J2FiniteResult again = j2_finite_strain(kE, kNu, three_rows(), r.state, right_cauchy_green(F));
  EXPECT_FALSE(again.yielded);
  EXPECT_LT((again.stress - r.stress).cwiseAbs().maxCoeff(), 1e-8 * r.stress.cwiseAbs().maxCoeff());
}

TEST(J2FiniteStrain, TangentMatchesFiniteDifferencesElastic) {
  Mat3 F;
  F << 1.2, 0.15, -0.05, 0.1, 0.9, 0.07, 0.0, -0.12, 1.05;
  const HardeningTable never{{{1e9, 0.0}}};
  const J2FiniteResult r = j2_finite_strain(kE, kNu, never, J2State{}, right_cauchy_green(F));
  ASSERT_FALSE(r.yielded);
  EXPECT_LT(rel_err(r.tangent, fd_tangent(never, J2State{}, right_cauchy_green(F))), 1e-7);
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-9 * r.tangent.norm());  // hyperelastic
}

TEST(J2FiniteStrain, TangentMatchesFiniteDifferencesPlasticLoading) {
  // From the virgin state into the first row, from a plastic state across a table row, and
  // perfectly plastic; each from a prestrained, plastically deformed state.
  const HardeningTable perfect{{{800.0, 0.0}}};
  Mat3 Fpre;
  Fpre << 1.05, 0.08, 0.0, 0.0, 0.98, 0.03, 0.01, 0.0, 0.99;
  Mat3 F;
  F << 1.08, 0.12, 0.0, -0.03, 0.97, 0.05, 0.02, 0.0, 0.99;
  for (const HardeningTable& t : {three_rows(), perfect}) {
    const J2FiniteResult virgin = j2_finite_strain(kE, kNu, t, J2State{}, right_cauchy_green(F));
    ASSERT_TRUE(virgin.yielded);
    EXPECT_LT(rel_err(virgin.tangent, fd_tangent(t, J2State{}, right_cauchy_green(F))), 1e-6);
    J2State s;
    walk(t, s, Mat3::Identity(), Fpre, 5);
    ASSERT_GT(s.equivalent_plastic_strain, 0.0);
    const J2FiniteResult r = j2_finite_strain(kE, kNu, t, s, right_cauchy_green(F));
    ASSERT_TRUE(r.yielded);
    EXPECT_LT(rel_err(r.tangent, fd_tangent(t, s, right_cauchy_green(F))), 1e-6);
  }
  // A step long enough to leave the first row of the table (alpha beyond 0.05).
  Mat3 Flong = Mat3::Identity();
  Flong(0, 1) = 0.25;
  const J2FiniteResult cross = j2_finite_strain(kE, kNu, three_rows(), J2State{}, right_cauchy_green(Flong));
  ASSERT_GT(cross.state.equivalent_plastic_strain, 0.05);
  EXPECT_LT(rel_err(cross.tangent, fd_tangent(three_rows(), J2State{}, right_cauchy_green(Flong))), 1e-6);
}

TEST(J2FiniteStrain, TangentMatchesFiniteDifferencesElasticUnloading) {
  Mat3 Fpre;
  Fpre << 1.05, 0.08, 0.0, 0.0, 0.98, 0.03, 0.01, 0.0, 0.99;
  J2State s;
  const J2FiniteResult loaded = walk(three_rows(), s, Mat3::Identity(), Fpre, 5);
  Mat3 back = Fpre;
  back(0, 1) -= 0.004;  // reverse the shear a little: elastic unloading
  const J2FiniteResult r = j2_finite_strain(kE, kNu, three_rows(), s, right_cauchy_green(back));
  ASSERT_FALSE(r.yielded);
  EXPECT_LT(cauchy_von_mises(right_cauchy_green(back), r.stress),
            cauchy_von_mises(right_cauchy_green(Fpre), loaded.stress));
  EXPECT_EQ(r.state.equivalent_plastic_strain, s.equivalent_plastic_strain);
  EXPECT_LT(rel_err(r.tangent, fd_tangent(three_rows(), s, right_cauchy_green(back))), 1e-7);
}

TEST(J2FiniteStrain, KirchhoffTangentDropsOnlyTheVolumeCouplingOfTheYield) {
  Mat3 F;
  F << 1.08, 0.12, 0.0, -0.03, 0.97, 0.05, 0.02, 0.0, 0.99;
  const Mat3 C = right_cauchy_green(F);
  const J2FiniteResult r = j2_finite_strain(kE, kNu, three_rows(), J2State{}, C);
  ASSERT_TRUE(r.yielded);
  // The difference is rank one: the deviatoric stress (pulled back) times d(ln J).
  const Real bulk = kE / (3 * (1 - 2 * kNu));
  const Real J = std::sqrt(C.determinant());
  const Mat3 Ci = C.inverse();
  Vec6 Ci_v;
  Ci_v << Ci(0, 0), Ci(1, 1), Ci(2, 2), Ci(0, 1), Ci(0, 2), Ci(1, 2);
  const Vec6 dlnJ = Ci_v;  // d(ln J)/dE in engineering shear: C^-1 with tensor components
  const Vec6 s_dev = r.stress - 0.5 * bulk * (J * J - 1) * Ci_v;
  const Mat6 diff = r.tangent - r.kirchhoff_tangent;
  const Real scale = diff.norm();
  ASSERT_GT(scale, 1e-6 * r.tangent.norm());
  const Real weight = (s_dev.transpose() * diff * dlnJ)(0, 0) / (s_dev.squaredNorm() * dlnJ.squaredNorm());
  const Mat6 rank_one = weight * s_dev * dlnJ.transpose();
  EXPECT_LT((diff - rank_one).norm(), 1e-8 * scale);
  // Nearly symmetric, and equal to the exact tangent where the point stays elastic.
  EXPECT_LT((r.kirchhoff_tangent - r.kirchhoff_tangent.transpose()).norm(), 1e-3 * r.kirchhoff_tangent.norm());
  const J2FiniteResult e = j2_finite_strain(kE, kNu, HardeningTable{{{1e9, 0.0}}}, J2State{}, C);
  EXPECT_EQ(e.tangent, e.kirchhoff_tangent);
}

TEST(J2FiniteStrain, RejectsAnInvertedDeformation) {
  Mat3 C = Mat3::Identity();
  C(2, 2) = -1;
  EXPECT_THROW(j2_finite_strain(kE, kNu, three_rows(), J2State{}, C), SolverError);
}

}  // namespace
}  // namespace kontakt::material::test_j2_finite_strain

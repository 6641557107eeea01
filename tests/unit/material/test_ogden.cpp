// Tests for the Ogden and hyperfoam potentials (solver/material/ogden): stress against the energy
// and tangent against the stress by central differences, and a Taylor test, at a general C, at
// C = I and at C with two and with three equal eigenvalues; Ogden with alpha = 2 against
// Neo-Hooke; the small-strain limits; continuity where eigenvalues nearly coincide.
#include "material/ogden.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "material/hyperelastic_potential.hpp"
#include "material/j2_small_strain.hpp"

namespace kontakt::material {
namespace {

Ogden ogden_one_term() {  // beamog's constants, with a compressibility
  Ogden p;
  p.mu = {3.488, 0, 0};
  p.alpha = {2.163, 0, 0};
  p.d = {0.0286697, 0, 0};
  return p;
}

Ogden ogden_three_terms() {  // a negative alpha and all three D_k
  Ogden p;
  p.n_terms = 3;
  p.mu = {1.5, 0.4, 0.05};
  p.alpha = {2.5, -2.0, 5.0};
  p.d = {0.05, 0.2, 0.5};
  return p;
}

Hyperfoam hyperfoam_two_terms() {  // beamhf's constants: nu = 0, beta = 0
  Hyperfoam p;
  p.n_terms = 2;
  p.mu = {0.164861, 2.302e-5, 0};
  p.alpha = {8.88413, -4.81798, 0};
  return p;
}

Hyperfoam hyperfoam_three_terms() {
  Hyperfoam p;
  p.n_terms = 3;
  p.mu = {0.5, 0.2, 0.1};
  p.alpha = {3.0, -2.0, 1.5};
  p.beta = {0.25, 1.0 / 3, -0.1};  // nu = 1/6, 0.2, -1/8
  return p;
}

/// C = 1 + 2E of a Green-Lagrange strain with engineering shear.
Mat3 right_cauchy_green(const Vec6& e) {
  Mat3 E;
  E << e(0), e(3) / 2, e(4) / 2, e(3) / 2, e(1), e(5) / 2, e(4) / 2, e(5) / 2, e(2);
  return Mat3::Identity() + 2 * E;
}

/// The engineering Green-Lagrange strain of C.
Vec6 strain(const Mat3& C) {
  const Mat3 E = 0.5 * (C - Mat3::Identity());
  Vec6 e;
  e << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(0, 2), 2 * E(1, 2);
  return e;
}

/// C with eigenvalues c in a general (not the global) frame.
Mat3 rotated(const Vec3& c) {
  const Mat3 R = Eigen::AngleAxisd(0.9, Vec3(1, -2, 3).normalized()).toRotationMatrix();
  return R * c.asDiagonal() * R.transpose();
}

enum class State { General, AtRest, TwoEqual, ThreeEqual };

Vec6 strain_at(State state) {
  switch (state) {
    case State::General: {
      Vec6 e;
      e << 0.12, -0.05, 0.07, 0.09, -0.06, 0.04;
      return e;
    }
    case State::AtRest:
      return Vec6::Zero();
    case State::TwoEqual:  // uniaxial with lateral contraction, J != 1
      return strain(rotated(Vec3(1.3 * 1.3, 0.9, 0.9)));
    case State::ThreeEqual:  // pure dilatation
      return strain(rotated(Vec3(1.2, 1.2, 1.2)));
  }
  return Vec6::Zero();
}

struct Case {
  HyperelasticPotential potential;
  State state;
};

HyperelasticResponse at(const HyperelasticPotential& p, const Vec6& e) {
  return hyperelastic_response(p, right_cauchy_green(e));
}

class OgdenAndHyperfoam : public ::testing::TestWithParam<Case> {};

TEST_P(OgdenAndHyperfoam, StressIsTheDerivativeOfTheEnergy) {
  const Vec6 e = strain_at(GetParam().state);
  const HyperelasticPotential& p = GetParam().potential;
  const Real h = 1e-6;
  Vec6 fd;
  for (int b = 0; b < 6; ++b) {
    Vec6 plus = e, minus = e;
    plus(b) += h;
    minus(b) -= h;
    fd(b) = (at(p, plus).energy - at(p, minus).energy) / (2 * h);
  }
  const HyperelasticResponse r = at(p, e);
  // At rest S = 0: the energy's differences measure only round-off there.
  EXPECT_LT((fd - r.stress).norm(), 1e-7 * std::max(r.stress.norm(), r.tangent.norm() * 1e-2));
}

TEST_P(OgdenAndHyperfoam, TangentIsTheDerivativeOfTheStressAndConvergesQuadratically) {
  const Vec6 e = strain_at(GetParam().state);
  const HyperelasticPotential& p = GetParam().potential;
  const HyperelasticResponse r = at(p, e);
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-12 * r.tangent.norm());
  const Real h = 1e-6;
  Mat6 fd;
  for (int b = 0; b < 6; ++b) {
    Vec6 plus = e, minus = e;
    plus(b) += h;
    minus(b) -= h;
    fd.col(b) = (at(p, plus).stress - at(p, minus).stress) / (2 * h);
  }
  EXPECT_LT((fd - r.tangent).norm(), 1e-8 * r.tangent.norm());
  // Taylor: |S(e + t d) - S(e) - t D d| falls as t^2.
  Vec6 d;
  d << 0.3, -0.2, 0.5, 0.4, 0.1, -0.6;
  std::vector<Real> errors;
  for (Real t : {1e-2, 5e-3, 2.5e-3})
    errors.push_back((at(p, e + t * d).stress - r.stress - t * r.tangent * d).norm());
  for (std::size_t k = 1; k < errors.size(); ++k)
    EXPECT_GT(std::log(errors[k - 1] / errors[k]) / std::log(2.0), 1.9);
}

INSTANTIATE_TEST_SUITE_P(
    States, OgdenAndHyperfoam,
    ::testing::Values(Case{ogden_one_term(), State::General}, Case{ogden_one_term(), State::AtRest},
                      Case{ogden_one_term(), State::TwoEqual},
                      Case{ogden_one_term(), State::ThreeEqual},
                      Case{ogden_three_terms(), State::General},
                      Case{ogden_three_terms(), State::AtRest},
                      Case{ogden_three_terms(), State::TwoEqual},
                      Case{ogden_three_terms(), State::ThreeEqual},
                      Case{hyperfoam_two_terms(), State::General},
                      Case{hyperfoam_two_terms(), State::AtRest},
                      Case{hyperfoam_two_terms(), State::TwoEqual},
                      Case{hyperfoam_two_terms(), State::ThreeEqual},
                      Case{hyperfoam_three_terms(), State::General},
                      Case{hyperfoam_three_terms(), State::AtRest},
                      Case{hyperfoam_three_terms(), State::TwoEqual},
                      Case{hyperfoam_three_terms(), State::ThreeEqual}));

TEST(Ogden, AlphaTwoIsNeoHookeWithC10HalfOfMu) {
  Ogden ogden;
  ogden.mu = {3.85, 0, 0};
  ogden.alpha = {2, 0, 0};
  ogden.d = {0.026, 0, 0};
  HyperelasticPolynomial neo_hooke;
  neo_hooke.c[1][0] = 3.85 / 2;
  neo_hooke.d[0] = 0.026;
  for (State state : {State::General, State::AtRest, State::TwoEqual, State::ThreeEqual}) {
    const Mat3 C = right_cauchy_green(strain_at(state));
    const HyperelasticResponse o = ogden_hyperelastic(ogden, C);
    const HyperelasticResponse n = polynomial_hyperelastic(neo_hooke, C);
    EXPECT_NEAR(o.energy, n.energy, 1e-12);
    EXPECT_LT((o.stress - n.stress).norm(), 1e-12 * std::max(1.0, n.stress.norm()));
    EXPECT_LT((o.tangent - n.tangent).norm(), 1e-12 * n.tangent.norm());
  }
}

/// The isotropic stiffness of shear modulus mu and bulk modulus K.
Mat6 isotropic(Real mu, Real K) {
  return isotropic_elastic_stiffness(9 * K * mu / (3 * K + mu),
                                     (3 * K - 2 * mu) / (2 * (3 * K + mu)));
}

TEST(OgdenAndHyperfoamLimit, AtRestTheTangentIsLinearElasticity) {
  // Ogden: mu = sum mu_i, K = 2 / D1. Hyperfoam: mu = sum mu_i, K = sum 2 mu_i (1/3 + beta_i).
  const Ogden o = ogden_three_terms();
  const HyperelasticResponse ro = ogden_hyperelastic(o, Mat3::Identity());
  EXPECT_LT(ro.stress.norm(), 1e-14);
  EXPECT_LT(std::abs(ro.energy), 1e-14);
  const Mat6 Do = isotropic(1.5 + 0.4 + 0.05, 2 / 0.05);
  EXPECT_LT((ro.tangent - Do).norm(), 1e-12 * Do.norm());
  const Hyperfoam f = hyperfoam_three_terms();
  const HyperelasticResponse rf = hyperfoam(f, Mat3::Identity());
  EXPECT_LT(rf.stress.norm(), 1e-14);
  Real K = 0;
  for (std::size_t i = 0; i < 3; ++i) K += 2 * f.mu[i] * (1.0 / 3 + f.beta[i]);
  const Mat6 Df = isotropic(0.5 + 0.2 + 0.1, K);
  EXPECT_LT((rf.tangent - Df).norm(), 1e-12 * Df.norm());
}

TEST(OgdenAndHyperfoamLimit, NearlyCoincidentEigenvaluesJoinTheCoincidentOnes) {
  // The divided differences may lose no digits as two eigenvalues approach each other.
  const Mat3 coincident = rotated(Vec3(1.44, 0.9, 0.9));
  for (Real gap : {1e-4, 1e-8, 1e-12}) {
    const Mat3 C = rotated(Vec3(1.44, 0.9, 0.9 * (1 + gap)));
    for (const HyperelasticPotential& p :
         {HyperelasticPotential{ogden_three_terms()}, HyperelasticPotential{hyperfoam_three_terms()}}) {
      const HyperelasticResponse near = hyperelastic_response(p, C);
      const HyperelasticResponse joined = hyperelastic_response(p, coincident);
      EXPECT_LT((near.tangent - joined.tangent).norm(), (10 * gap + 1e-13) * joined.tangent.norm());
    }
  }
}

TEST(HyperfoamLimit, BetaZeroIsTheLimitOfSmallBeta) {
  Hyperfoam zero = hyperfoam_two_terms(), small = zero;
  small.beta = {1e-9, 1e-9, 0};
  const Mat3 C = right_cauchy_green(strain_at(State::General));
  const HyperelasticResponse a = hyperfoam(zero, C), b = hyperfoam(small, C);
  EXPECT_LT((a.stress - b.stress).norm(), 1e-7 * a.stress.norm());
  EXPECT_LT((a.tangent - b.tangent).norm(), 1e-7 * a.tangent.norm());
}

TEST(HyperfoamLimit, UniaxialStressOfOneTermWithNuZeroHasNoLateralStress) {
  // nu = 0: sigma_k J = 2 mu / alpha (l_k^alpha - 1), so a stretch along x alone is uniaxial.
  Hyperfoam p;
  p.mu = {0.7, 0, 0};
  p.alpha = {4.0, 0, 0};
  Mat3 C = Mat3::Identity();
  C(0, 0) = 1.2 * 1.2;
  const Vec6 S = hyperfoam(p, C).stress;
  EXPECT_NEAR(S(1), 0, 1e-15);
  EXPECT_NEAR(S(2), 0, 1e-15);
  // S_xx = tau_x / l^2 = 2 mu / alpha (l^alpha - 1) / l^2.
  EXPECT_NEAR(S(0), 2 * 0.7 / 4.0 * (std::pow(1.2, 4.0) - 1) / (1.2 * 1.2), 1e-14);
}

TEST(OgdenAndHyperfoam, AnInvertedMaterialIsASolverError) {
  Mat3 C = Mat3::Identity();
  C(2, 2) = -0.1;
  EXPECT_THROW(ogden_hyperelastic(ogden_one_term(), C), SolverError);
  EXPECT_THROW(hyperfoam(hyperfoam_two_terms(), C), SolverError);
}

}  // namespace
}  // namespace kontakt::material

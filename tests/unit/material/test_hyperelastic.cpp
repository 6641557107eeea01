// Tests for the polynomial hyperelastic potential (solver/material/hyperelastic): stress against
// the energy and tangent against the stress by central differences, a Taylor test, and the
// small-strain limit.
#include "material/hyperelastic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "material/j2_small_strain.hpp"

namespace kontakt::material {
namespace {

HyperelasticPolynomial neo_hooke() {
  HyperelasticPolynomial p;
  p.c[1][0] = 1.92505;
  p.d[0] = 0.026;
  return p;
}

HyperelasticPolynomial third_order() {
  HyperelasticPolynomial p;
  p.c[1][0] = 0.8;
  p.c[0][1] = 0.2;
  p.c[2][0] = -0.05;
  p.c[1][1] = 0.03;
  p.c[0][2] = 0.02;
  p.c[3][0] = 0.004;
  p.c[2][1] = -0.002;
  p.c[1][2] = 0.001;
  p.c[0][3] = 0.003;
  p.d = {0.05, 0.2, 0.5};
  return p;
}

/// C = 1 + 2E of a Green-Lagrange strain with engineering shear.
Mat3 right_cauchy_green(const Vec6& e) {
  Mat3 E;
  E << e(0), e(3) / 2, e(4) / 2, e(3) / 2, e(1), e(5) / 2, e(4) / 2, e(5) / 2, e(2);
  return Mat3::Identity() + 2 * E;
}

HyperelasticResponse at(const HyperelasticPolynomial& p, const Vec6& e) {
  return polynomial_hyperelastic(p, right_cauchy_green(e));
}

Vec6 finite_strain() {
  Vec6 e;
  e << 0.12, -0.05, 0.07, 0.09, -0.06, 0.04;
  return e;
}

class Hyperelastic : public ::testing::TestWithParam<int> {
 protected:
  HyperelasticPolynomial material() const { return GetParam() == 0 ? neo_hooke() : third_order(); }
};

TEST_P(Hyperelastic, StressIsTheDerivativeOfTheEnergy) {
  const Vec6 e = finite_strain();
  const Real h = 1e-6;
  Vec6 fd;
  for (int b = 0; b < 6; ++b) {
    Vec6 p = e, m = e;
    p(b) += h;
    m(b) -= h;
    fd(b) = (at(material(), p).energy - at(material(), m).energy) / (2 * h);
  }
  const Vec6 S = at(material(), e).stress;
  EXPECT_LT((fd - S).norm(), 1e-7 * S.norm());
}

TEST_P(Hyperelastic, TangentIsTheDerivativeOfTheStressAndConvergesQuadratically) {
  const Vec6 e = finite_strain();
  const HyperelasticResponse r = at(material(), e);
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-10 * r.tangent.norm());
  const Real h = 1e-6;
  Mat6 fd;
  for (int b = 0; b < 6; ++b) {
    Vec6 p = e, m = e;
    p(b) += h;
    m(b) -= h;
    fd.col(b) = (at(material(), p).stress - at(material(), m).stress) / (2 * h);
  }
  EXPECT_LT((fd - r.tangent).norm(), 1e-7 * r.tangent.norm());
  // Taylor: |S(e + t d) - S(e) - t D d| falls as t^2.
  Vec6 d;
  d << 0.3, -0.2, 0.5, 0.4, 0.1, -0.6;
  std::vector<Real> errors;
  for (Real t : {1e-2, 5e-3, 2.5e-3})
    errors.push_back((at(material(), e + t * d).stress - r.stress - t * r.tangent * d).norm());
  for (std::size_t k = 1; k < errors.size(); ++k)
    EXPECT_GT(std::log(errors[k - 1] / errors[k]) / std::log(2.0), 1.9);
}

INSTANTIATE_TEST_SUITE_P(NeoHookeAndThirdOrder, Hyperelastic, ::testing::Values(0, 1));

TEST(HyperelasticLimit, AtRestTheTangentIsLinearElasticity) {
  // mu = 2 (C10 + C01), bulk modulus K = 2 / D1: the small-strain isotropic stiffness.
  HyperelasticPolynomial p;
  p.c[1][0] = 0.7;
  p.c[0][1] = 0.3;
  p.d[0] = 0.1;
  const HyperelasticResponse r = polynomial_hyperelastic(p, Mat3::Identity());
  EXPECT_LT(r.stress.norm(), 1e-14);
  EXPECT_LT(std::abs(r.energy), 1e-14);
  const Real mu = 2 * (0.7 + 0.3), K = 2 / 0.1;
  const Real young = 9 * K * mu / (3 * K + mu), poisson = (3 * K - 2 * mu) / (2 * (3 * K + mu));
  EXPECT_LT((r.tangent - isotropic_elastic_stiffness(young, poisson)).norm(), 1e-10 * r.tangent.norm());
}

TEST(HyperelasticLimit, IsochoricStretchOfNeoHookeMatchesTheClosedForm) {
  // Isochoric uniaxial stretch l (C = diag(l^2, 1/l, 1/l), J = 1): the Cauchy stress
  // sigma = F S F^T has sigma_xx - sigma_yy = 2 C10 (l^2 - 1/l).
  const Real l = 1.3, C10 = 1.92505;
  HyperelasticPolynomial p = neo_hooke();
  Mat3 C = Mat3::Zero();
  C.diagonal() << l * l, 1 / l, 1 / l;
  const Vec6 S = polynomial_hyperelastic(p, C).stress;
  const Real sigma_xx = l * l * S(0), sigma_yy = S(1) / l;  // sigma = F S F^T, J = 1
  EXPECT_NEAR(sigma_xx - sigma_yy, 2 * C10 * (l * l - 1 / l), 1e-12);
}

}  // namespace
}  // namespace kontakt::material

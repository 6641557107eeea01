// Tests for orthotropic / anisotropic elasticity and its frame rotation
// (solver/material/anisotropic_elastic).
#include "material/anisotropic_elastic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "material/j2_small_strain.hpp"

namespace kontakt::material {
namespace {

// An orthotropic material by engineering constants (nu_ij / E_i = nu_ji / E_j).
constexpr Real kE1 = 150000, kE2 = 60000, kE3 = 30000, kNu12 = 0.25, kNu13 = 0.3, kNu23 = 0.35;
constexpr Real kG12 = 20000, kG13 = 15000, kG23 = 10000;

Mat6 engineering_stiffness() {
  return anisotropic_stiffness(
      from_engineering({kE1, kE2, kE3, kNu12, kNu13, kNu23, kG12, kG13, kG23}));
}

Mat3 rotation(const Vec3& axis, Real degrees) {
  return Eigen::AngleAxis<Real>(degrees * M_PI / 180, axis.normalized()).toRotationMatrix();
}

TEST(materialAnisotropic, TwentyOneConstantsFillTheUpperTriangleColumnByColumn) {
  AnisotropicConstants d{};
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = static_cast<Real>(i + 1);
  const Mat6 D = anisotropic_stiffness(d);
  EXPECT_EQ(D, D.transpose());
  EXPECT_EQ(D(0, 0), 1);   // D1111
  EXPECT_EQ(D(0, 1), 2);   // D1122
  EXPECT_EQ(D(2, 2), 6);   // D3333
  EXPECT_EQ(D(0, 3), 7);   // D1112
  EXPECT_EQ(D(3, 3), 10);  // D1212
  EXPECT_EQ(D(3, 4), 14);  // D1213
  EXPECT_EQ(D(0, 5), 16);  // D1123
  EXPECT_EQ(D(5, 5), 21);  // D2323
}

TEST(materialAnisotropic, IsotropicConstantsGiveTheIsotropicStiffness) {
  // The manual's isotropic material as ORTHO: D1111 = lambda + 2 mu, D1122 = lambda, D1212 = mu.
  const Real E = 210000, nu = 0.3, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
             mu = E / (2 * (1 + nu));
  const Mat6 D = anisotropic_stiffness(from_orthotropic(
      {lambda + 2 * mu, lambda, lambda + 2 * mu, lambda, lambda, lambda + 2 * mu, mu, mu, mu}));
  EXPECT_LT((D - isotropic_elastic_stiffness(E, nu)).norm(), 1e-9 * D.norm());
  EXPECT_LT((anisotropic_stiffness(from_engineering({E, E, E, nu, nu, nu, mu, mu, mu})) - D).norm(),
            1e-9 * D.norm());
}

TEST(materialAnisotropic, EngineeringConstantsInvertTheCompliance) {
  // A uniaxial stress along each axis strains as the engineering constants say.
  const Mat6 D = engineering_stiffness();
  EXPECT_TRUE(is_positive_definite(D));
  Vec6 strain;
  strain << 1 / kE1, -kNu12 / kE1, -kNu13 / kE1, 0, 0, 0;
  Vec6 expected = Vec6::Zero();
  expected(0) = 1;
  EXPECT_LT((D * strain - expected).norm(), 1e-12);
  strain << -kNu13 / kE1, -kNu23 / kE2, 1 / kE3, 0, 0, 0;  // nu31 / E3 = nu13 / E1
  expected.setZero();
  expected(2) = 1;
  EXPECT_LT((D * strain - expected).norm(), 1e-12);
  EXPECT_EQ(D(3, 3), kG12);
  EXPECT_EQ(D(4, 4), kG13);
  EXPECT_EQ(D(5, 5), kG23);
}

TEST(materialAnisotropic, BadConstantsAreRefused) {
  EXPECT_THROW(from_engineering({0, 1, 1, .3, .3, .3, 1, 1, 1}), std::invalid_argument);
  EXPECT_THROW(from_engineering({1, 1, 1, .3, .3, .3, 1, 1, -1}), std::invalid_argument);
  // nu12 = 2 with E1 = E2: the compliance is indefinite, so is the stiffness.
  EXPECT_FALSE(is_positive_definite(
      anisotropic_stiffness(from_engineering({1, 1, 1, 2, .3, .3, 1, 1, 1}))));
  // A coupling larger than the geometric mean of its diagonal terms.
  EXPECT_FALSE(is_positive_definite(anisotropic_stiffness(from_orthotropic({1, 5, 1, 0, 0, 1, 1, 1, 1}))));
  EXPECT_FALSE(is_positive_definite(anisotropic_stiffness(from_orthotropic({1, 0, 1, 0, 0, 1, 1, 1, 0}))));
}

TEST(materialAnisotropic, RotatedOrthotropicBlockMatchesTheClosedForm) {
  // A uniaxial stress sigma along global x of an orthotropic material whose axis 1 is turned by
  // theta about z: eps_xx = sigma (c^4/E1 + (1/G12 - 2 nu12/E1) s^2 c^2 + s^4/E2).
  for (const Real theta : {0., 25., 60., 90.}) {
    const Real c = std::cos(theta * M_PI / 180), s = std::sin(theta * M_PI / 180);
    const Mat6 D = rotate_stiffness(engineering_stiffness(), rotation(Vec3::UnitZ(), theta));
    Vec6 stress = Vec6::Zero();
    stress(0) = 100;
    const Vec6 strain = D.ldlt().solve(stress);
    const Real closed = 100 * (std::pow(c, 4) / kE1 + (1 / kG12 - 2 * kNu12 / kE1) * s * s * c * c +
                               std::pow(s, 4) / kE2);
    EXPECT_NEAR(strain(0), closed, 1e-12 * std::abs(closed)) << theta;
  }
}

TEST(materialAnisotropic, RotationKeepsTheEnergyAndTheStressInTheFrame) {
  const Mat3 R = rotation(Vec3(1, 2, 3), 40);
  AnisotropicConstants d{};
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = 1000 + 37.0 * static_cast<Real>(i % 7);
  const Mat6 local = anisotropic_stiffness(d) + 50000 * Mat6::Identity();
  const Mat6 global = rotate_stiffness(local, R);
  EXPECT_LT((global - global.transpose()).norm(), 1e-9 * global.norm());
  EXPECT_TRUE(is_positive_definite(global));
  Vec6 e;
  e << 1e-3, -2e-4, 5e-4, 3e-4, -7e-4, 2e-4;  // global, engineering shear
  // The stress of the global strain, seen in the frame, is the local law on the local strain.
  Vec6 tensor = e;
  tensor.tail<3>() *= 0.5;
  Vec6 local_strain = stress_to_local(tensor, R);  // a symmetric tensor rotates alike
  local_strain.tail<3>() *= 2;
  EXPECT_LT((stress_to_local(global * e, R) - local * local_strain).norm(),
            1e-10 * (local * local_strain).norm());
  EXPECT_NEAR(e.dot(global * e), local_strain.dot(local * local_strain), 1e-12 * e.dot(global * e));
  // Turning by 90 degrees about z swaps axes 1 and 2.
  const Mat6 turned = rotate_stiffness(local, rotation(Vec3::UnitZ(), 90));
  EXPECT_NEAR(turned(0, 0), local(1, 1), 1e-9 * local(1, 1));
  EXPECT_NEAR(turned(5, 5), local(4, 4), 1e-9 * local(4, 4));
}

}  // namespace
}  // namespace kontakt::material

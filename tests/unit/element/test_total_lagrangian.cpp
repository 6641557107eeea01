// Total Lagrangian kernels: consistency with the linear kernels, tangent by finite differences
// and a Taylor test, objectivity, and the closed-form uniaxial St. Venant-Kirchhoff answer.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "element/total_lagrangian.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

const ElementType kNlgeomTypes[] = {ElementType::C3D4,  ElementType::C3D6,  ElementType::C3D8,
                                    ElementType::C3D8R, ElementType::C3D10, ElementType::C3D15,
                                    ElementType::C3D20, ElementType::C3D20R};

class TotalLagrangian : public ::testing::TestWithParam<ElementType> {
 protected:
  ElementType type() const { return GetParam(); }
  MatX3 X() const { return test::distorted_coordinates(volume_topology(type())); }
  /// A moderately large, smooth displacement field (strains of about 10 %).
  MatX3 displacement(Real scale = 1) const {
    const MatX3 x = X();
    MatX3 u(x.rows(), 3);
    for (Index a = 0; a < x.rows(); ++a)
      u.row(a) << 0.08 * x(a, 1) + 0.05 * x(a, 0) * x(a, 2), -0.06 * x(a, 2) + 0.03 * x(a, 0),
          0.1 * x(a, 0) - 0.04 * x(a, 1) * x(a, 1);
    return scale * u;
  }
  LinearElastic mat() const { return {1000.0, 0.3, 0.0}; }
};

TEST_P(TotalLagrangian, TangentAtRestIsTheLinearStiffness) {
  MatX K;
  linear_stiffness(type(), X(), mat(), K);
  NlgeomResult r;
  nlgeom_element(type(), X(), mat(), MatX3::Zero(X().rows(), 3), VecX(), true, r);
  EXPECT_LT((r.tangent - K).norm(), 1e-10 * K.norm());
  EXPECT_LT(r.internal_force.norm(), 1e-12);
}

TEST_P(TotalLagrangian, TangentMatchesCentralDifferencesAndConvergesQuadratically) {
  const MatX3 x = X(), u = displacement();
  NlgeomResult r;
  nlgeom_element(type(), x, mat(), u, VecX(), true, r);
  const Index n = 3 * x.rows();
  MatX K_fd(n, n);
  const Real h = 1e-6;
  for (Index j = 0; j < n; ++j) {
    MatX3 up = u, um = u;
    up(j / 3, j % 3) += h;
    um(j / 3, j % 3) -= h;
    NlgeomResult rp, rm;
    nlgeom_element(type(), x, mat(), up, VecX(), false, rp);
    nlgeom_element(type(), x, mat(), um, VecX(), false, rm);
    K_fd.col(j) = (rp.internal_force - rm.internal_force) / (2 * h);
  }
  EXPECT_LT((K_fd - r.tangent).norm(), 1e-6 * r.tangent.norm());
  // Taylor test: the remainder f(u + t d) - f(u) - t K d shrinks like t^2.
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> dist(-1, 1);
  MatX3 d(x.rows(), 3);
  for (Index k = 0; k < d.size(); ++k) d.data()[k] = 0.05 * dist(rng);
  const VecX dv = Eigen::Map<const VecX>(d.data(), d.size());
  Real previous = 0;
  for (Real t : {1.0, 0.5, 0.25}) {
    NlgeomResult rt;
    nlgeom_element(type(), x, mat(), u + t * d, VecX(), false, rt);
    const Real rem = (rt.internal_force - r.internal_force - t * r.tangent * dv).norm();
    if (previous > 0) {
      EXPECT_GT(std::log2(previous / rem), 1.9);
    }
    previous = rem;
  }
}

TEST_P(TotalLagrangian, RigidRotationIsStressFree) {
  const MatX3 x = X();
  const Mat3 R = Eigen::AngleAxisd(M_PI / 3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  MatX3 u(x.rows(), 3);
  for (Index a = 0; a < x.rows(); ++a) u.row(a) = (R * x.row(a).transpose() - x.row(a).transpose()).transpose();
  NlgeomResult r;
  nlgeom_element(type(), x, mat(), u, VecX(), false, r);
  if (type() != ElementType::C3D8R) {  // C3D8R's hourglass term is small-strain by design
    EXPECT_LT(r.internal_force.norm(), 1e-9 * mat().young);
    EXPECT_LT(r.cauchy.cwiseAbs().maxCoeff(), 1e-9 * mat().young);
  }
  EXPECT_LT(r.green_lagrange.cwiseAbs().maxCoeff(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, TotalLagrangian, ::testing::ValuesIn(kNlgeomTypes),
                         [](const auto& info) { return std::string(traits(info.param).name); });

TEST(TotalLagrangianCube, UniaxialStretchGivesTheClosedFormCauchyStress) {
  const MatX3 X = test::reference_coordinates(Topology::Hex8) * 0.5 + MatX3::Constant(8, 3, 0.5);
  const Real stretch = 1.4, nu = 0.3, E11 = (stretch * stretch - 1) / 2, E22 = -nu * E11;
  const Real lateral = std::sqrt(1 + 2 * E22);
  MatX3 u(8, 3);
  for (int a = 0; a < 8; ++a)
    u.row(a) << (stretch - 1) * X(a, 0), (lateral - 1) * X(a, 1), (lateral - 1) * X(a, 2);
  NlgeomResult r;
  nlgeom_element(ElementType::C3D8, X, {1000.0, nu, 0.0}, u, VecX(), false, r);
  const Real S11 = 1000 * E11, J = stretch * lateral * lateral;
  for (Index k = 0; k < 8; ++k) {
    EXPECT_NEAR(r.cauchy(k, 0), stretch * stretch * S11 / J, 1e-9 * S11);
    EXPECT_NEAR(r.cauchy(k, 1), 0.0, 1e-9 * S11);
    EXPECT_NEAR(r.green_lagrange(k, 0), E11, 1e-12);
  }
}

TEST(TotalLagrangianCube, IncompatibleModesAreRefusedUnderNlgeom) {
  NlgeomResult r;
  EXPECT_THROW(nlgeom_element(ElementType::C3D8I, test::reference_coordinates(Topology::Hex8),
                              {1000.0, 0.3, 0.0}, MatX3::Zero(8, 3), VecX(), true, r),
               SolverError);
}

}  // namespace
}  // namespace kontakt::element

// SPRINGA and GAPUNI kernels (analysis/connector): forces against the closed forms, tangents
// against central differences of the forces, forces against differences of the energy.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/connector.hpp"

using namespace kontakt;
using analysis::connector_response;
using Vec6 = Eigen::Matrix<Real, 6, 1>;

namespace {

model::Connector linear_spring(Real k) {
  model::Connector c;
  c.kind = model::Connector::Kind::Spring;
  c.stiffness = k;
  return c;
}

model::Connector curve_spring() {
  model::Connector c;
  c.kind = model::Connector::Kind::Spring;
  c.curve = {{-0.5, -20.0}, {0.0, 0.0}, {1.0, 10.0}, {20.0, 100.0}};
  return c;
}

model::Connector gap(Real clearance) {
  model::Connector c;
  c.kind = model::Connector::Kind::Gap;
  c.clearance = clearance;
  c.direction = Vec3(1, 2, 2) / 3.0;
  c.stiffness = 1e6;
  c.tension = 1.0;
  return c;
}

const Vec3 X1(0.1, -0.2, 0.3), X2(1.3, 0.4, -0.5);

analysis::ConnectorResponse at(const model::Connector& c, const Vec6& u, bool nlgeom) {
  return connector_response(c, X1, X2, u.head<3>(), u.tail<3>(), nlgeom);
}

/// The tangent is the derivative of the force, the force the derivative of the energy.
void expect_consistent(const model::Connector& c, const Vec6& u, bool nlgeom) {
  const auto r = at(c, u, nlgeom);
  const Real h = 1e-7;
  for (int j = 0; j < 6; ++j) {
    Vec6 up = u, um = u;
    up[j] += h;
    um[j] -= h;
    const auto rp = at(c, up, nlgeom), rm = at(c, um, nlgeom);
    const Vec6 column = (rp.force - rm.force) / (2 * h);
    EXPECT_NEAR((r.stiffness.col(j) - column).norm(), 0, 1e-5 * (1 + column.norm())) << "dof " << j;
    EXPECT_NEAR(r.force[j], (rp.energy - rm.energy) / (2 * h), 1e-5 * (1 + std::abs(r.force[j])))
        << "dof " << j;
  }
  EXPECT_NEAR((r.stiffness - r.stiffness.transpose()).norm(), 0, 1e-12 * (1 + r.stiffness.norm()));
}

}  // namespace

TEST(Connector, LinearSpringPullsAlongItsCurrentAxisUnderNlgeom) {
  const model::Connector c = linear_spring(10);
  Vec6 u;
  u << 0.05, 0.1, -0.2, 0.4, -0.3, 0.25;
  const auto r = at(c, u, true);
  const Vec3 d = X2 + u.tail<3>() - X1 - u.head<3>();
  const Real elongation = d.norm() - (X2 - X1).norm();
  EXPECT_NEAR((r.force.tail<3>() - 10 * elongation * d.normalized()).norm(), 0, 1e-13);
  EXPECT_NEAR((r.force.head<3>() + r.force.tail<3>()).norm(), 0, 1e-13);
  expect_consistent(c, u, true);
  expect_consistent(c, u, false);
}

TEST(Connector, SpringCurveIsPiecewiseLinearAndConstantBeyondItsEnds) {
  const model::Connector c = curve_spring();
  const Vec3 axis = (X2 - X1).normalized();
  for (const auto& [elongation, force] :
       {std::pair{0.5, 5.0}, std::pair{10.5, 55.0}, std::pair{25.0, 100.0}, std::pair{-0.25, -10.0},
        std::pair{-0.9, -20.0}}) {
    Vec6 u = Vec6::Zero();
    u.tail<3>() = elongation * axis;
    EXPECT_NEAR(at(c, u, true).force.tail<3>().dot(axis), force, 1e-12) << elongation;
    expect_consistent(c, u, true);
  }
  Vec6 beyond = Vec6::Zero();
  beyond.tail<3>() = 25.0 * axis;
  const auto r = at(c, beyond, false);
  EXPECT_NEAR(r.stiffness.norm(), 0, 1e-15);  // constant force: no axial slope
}

TEST(Connector, GapCarriesItsPenaltyForceOnlyOnceItsClearanceIsUsedUp) {
  const model::Connector c = gap(0.01);
  const Vec3& n = c.direction;
  Vec6 open = Vec6::Zero();
  open.tail<3>() = -0.005 * n;  // half the clearance used
  // Open, the gap carries no more than ccx's tensile force at infinite opening.
  EXPECT_NEAR(at(c, open, true).force.tail<3>().norm(), c.tension, 1e-3 * c.tension);
  Vec6 closed = Vec6::Zero();
  closed.tail<3>() = -0.012 * n;  // overclosed by 0.002
  const auto r = at(c, closed, true);
  EXPECT_NEAR(r.force.tail<3>().dot(n), -1e6 * 0.002, 2.0);  // pushes node 2 back along n
  EXPECT_NEAR((r.force.tail<3>() - r.force.tail<3>().dot(n) * n).norm(), 0, 1e-9);
  expect_consistent(c, closed, true);
  expect_consistent(c, open, false);
}

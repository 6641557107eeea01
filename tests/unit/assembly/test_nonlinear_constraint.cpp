#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "assembly/dof_map.hpp"
#include "assembly/nonlinear_constraint.hpp"
#include "test_model_fixture.hpp"

using namespace kontakt;
using assembly::constraint_dofs;
using assembly::constraint_value;
using Kind = model::NonlinearConstraint::Kind;

namespace {

/// Two bricks in a row (12 nodes) and two extra nodes, 12 and 13, no element uses.
model::Model bricks_with_extra_nodes() {
  model::Model m = fixtures::brick_row(2);
  m.mesh.coords.conservativeResize(14, 3);
  m.mesh.coords.row(12) << 2.5, 0.5, 0.5;
  m.mesh.coords.row(13) << 0.3, 0.2, 1.0;  // a MEANROT axis
  m.mesh.node_ids.push_back(13);
  m.mesh.node_ids.push_back(14);
  return m;
}

model::NonlinearConstraint constraint(Kind kind, std::vector<int> nodes, int component,
                                      int pivot = 0) {
  return {.kind = kind,
          .nodes = std::move(nodes),
          .component = component,
          .pivot = pivot,
          .where = {"deck.inp", 7},
          .keyword = "*MPC"};
}

/// A DIST from node 5 (1, 1, 0) to node 0 (0, 0, 0) of at most 1.5, solved for 5's x.
model::NonlinearConstraint distance_5_0() {
  model::NonlinearConstraint c = constraint(Kind::Distance, {5, 0}, 0);
  c.distance = 1.5;
  return c;
}

/// One of every kind, on the nodes of bricks_with_extra_nodes().
std::vector<model::NonlinearConstraint> every_kind() {
  return {constraint(Kind::Rigid, {8, 12, 13}, 1), constraint(Kind::Plane, {9, 0, 1, 2}, 0),
          constraint(Kind::Straight, {10, 0, 4}, 1, 0),
          constraint(Kind::MeanRotation, {8, 9, 10, 11, 13}, 2), distance_5_0()};
}

/// An *EQUATION of the deck on `line` (built member by member: GCC 12 misreads the aggregate
/// temporary's string as uninitialised once this file is compiled with others, a unity build).
model::Equation equation(std::vector<model::EquationTerm> terms, int line) {
  model::Equation e;
  e.terms = std::move(terms);
  e.where.file = "deck.inp";
  e.where.line = line;
  return e;
}

VecX random_displacements(int n_nodes, Real size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> d(-size, size);
  VecX u(3 * n_nodes);
  for (Index i = 0; i < u.size(); ++i) u[i] = d(rng);
  return u;
}

}  // namespace

TEST(Rotation, IsOrthogonalKeepsItsAxisAndMatchesTheAngleAxisForm) {
  for (const Vec3& theta : {Vec3(0.3, -1.2, 0.7), Vec3(1e-5, 2e-5, -1e-5), Vec3(0, 0, 2.5)}) {
    Mat3 R;
    for (int c = 0; c < 3; ++c) R.col(c) = assembly::rotate(theta, Vec3::Unit(c));
    EXPECT_NEAR((R.transpose() * R - Mat3::Identity()).norm(), 0, 1e-14);
    EXPECT_NEAR((R * theta - theta).norm(), 0, 1e-14 * theta.norm());
    const Mat3 expected = Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix();
    EXPECT_NEAR((R - expected).norm(), 0, 1e-14);
  }
  // Both sides of the series' switch at |theta|^2 = 1e-8 agree.
  const Vec3 v(0.4, -0.9, 1.3), axis = Vec3(1, 2, -2).normalized();
  const Vec3 below = assembly::rotate(axis * 0.99999e-4, v),
             above = assembly::rotate(axis * 1.00001e-4, v);
  EXPECT_NEAR((below - above).norm(), 2e-9 * axis.cross(v).norm(), 1e-15);
}

TEST(NonlinearConstraint, GradientMatchesCentralDifferencesForEveryKind) {
  const model::Model m = bricks_with_extra_nodes();
  for (const auto& c : every_kind()) {
    for (unsigned seed : {3u, 11u}) {
      const VecX u = random_displacements(14, 0.2, seed);
      VecX gradient;
      constraint_value(c, m.mesh.coords, u, &gradient);
      const auto dofs = constraint_dofs(c);
      ASSERT_EQ(gradient.size(), static_cast<Index>(dofs.size()));
      for (std::size_t q = 0; q < dofs.size(); ++q) {
        const int d = 3 * dofs[q].node + dofs[q].component;
        const Real h = 1e-6;
        VecX up = u, um = u;
        up[d] += h;
        um[d] -= h;
        const Real fd =
            (constraint_value(c, m.mesh.coords, up) - constraint_value(c, m.mesh.coords, um)) /
            (2 * h);
        EXPECT_NEAR(gradient[static_cast<Index>(q)], fd, 1e-7 * (1 + std::abs(fd)))
            << "kind " << static_cast<int>(c.kind) << " dof " << q;
      }
      // Taylor: the remainder of the linear model falls with the square of the step.
      const VecX du = random_displacements(14, 1, seed + 100);
      VecX dq(static_cast<Index>(dofs.size()));
      for (std::size_t q = 0; q < dofs.size(); ++q)
        dq[static_cast<Index>(q)] = du[3 * dofs[q].node + dofs[q].component];
      auto restricted = [&](Real t) {
        VecX v = u;
        for (const auto& cd : dofs)
          v[3 * cd.node + cd.component] += t * du[3 * cd.node + cd.component];
        return constraint_value(c, m.mesh.coords, v);
      };
      const Real g0 = restricted(0), slope = gradient.dot(dq);
      const Real r1 = std::abs(restricted(1e-3) - g0 - 1e-3 * slope);
      const Real r2 = std::abs(restricted(5e-4) - g0 - 5e-4 * slope);
      if (r1 > 1e-13) {
        EXPECT_NEAR(r1 / r2, 4, 0.2) << "kind " << static_cast<int>(c.kind);
      }
    }
  }
}

TEST(NonlinearConstraint, RigidBodyMovesTheNodeWithTheRotatedArm) {
  const model::Model m = bricks_with_extra_nodes();
  VecX u = VecX::Zero(3 * 14);
  const Vec3 theta(0.2, -0.4, 0.9), shift(0.1, 0.3, -0.2);
  u.segment<3>(3 * 13) = theta;  // the rotation node's dofs
  u.segment<3>(3 * 12) = shift;  // the reference node
  const Vec3 arm = m.mesh.coords.row(5).transpose() - m.mesh.coords.row(12).transpose();
  u.segment<3>(3 * 5) = shift + assembly::rotate(theta, arm) - arm;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(constraint_value(constraint(Kind::Rigid, {5, 12, 13}, c), m.mesh.coords, u), 0,
                1e-15);
  u[3 * 5 + 2] += 1e-3;
  EXPECT_NEAR(constraint_value(constraint(Kind::Rigid, {5, 12, 13}, 2), m.mesh.coords, u), 1e-3,
              1e-15);
}

TEST(NonlinearConstraint, MeanRotationOfARigidlyTurnedSetIsItsAngle) {
  model::Model m = bricks_with_extra_nodes();
  m.mesh.coords.row(13) << 1, 0, 0;  // the axis: x, through the end face's centre
  VecX u = VecX::Zero(3 * 14);
  const Real angle = 0.6;
  const Vec3 centre(2, 0.5, 0.5);
  for (int node : {8, 9, 10, 11}) {
    const Vec3 r = m.mesh.coords.row(node).transpose() - centre;
    u.segment<3>(3 * node) = Eigen::AngleAxisd(angle, Vec3::UnitX()) * r - r + Vec3(0.1, -0.2, 0.3);
  }
  u[3 * 13] = angle;
  EXPECT_NEAR(
      constraint_value(constraint(Kind::MeanRotation, {8, 9, 10, 11, 13}, 1), m.mesh.coords, u), 0,
      1e-14);
}

TEST(DofMap, RelinearisedConstraintsHoldExactlyAndTheirRowsAreTheDerivatives) {
  model::Model m = bricks_with_extra_nodes();
  for (int c = 0; c < 3; ++c)  // the far end face rides on a rigid body
    for (int node : {8, 9, 10, 11})
      m.nonlinear_constraints.push_back(constraint(Kind::Rigid, {node, 12, 13}, c));
  m.nonlinear_constraints.push_back(constraint(Kind::Straight, {6, 1, 2}, 0, 2));
  m.nonlinear_constraints.push_back(constraint(Kind::Plane, {7, 0, 1, 2}, 0));
  m.nonlinear_constraints.push_back(distance_5_0());  // quadratic in its dependent dof
  // Equations that follow the constraints (as the copies of a 2D node on a rigid body do),
  // one through the other: 3y = 0.5 8x + 0.25 2y, then 4z = 2 3y - 9z + 1.5 6x.
  m.equations.push_back(equation({{3, 1, 1.0}, {8, 0, -0.5}, {2, 1, -0.25}}, 9));
  m.equations.push_back(equation({{4, 2, 1.0}, {3, 1, -2.0}, {9, 2, 1.0}, {6, 0, -1.5}}, 10));
  assembly::DofMap dofs(m, {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}});
  ASSERT_TRUE(dofs.has_nonlinear_constraints());
  VecX u = random_displacements(14, 0.3, 5);
  u.segment<3>(3 * 13) << 0.4, -0.8, 1.1;
  dofs.relinearise(u);
  for (const auto& c : m.nonlinear_constraints)
    EXPECT_NEAR(constraint_value(c, m.mesh.coords, u), 0, 1e-13);
  EXPECT_NEAR(u[3 * 3 + 1], 0.5 * u[3 * 8] + 0.25 * u[3 * 2 + 1], 1e-15);
  EXPECT_NEAR(u[3 * 4 + 2], 2 * u[3 * 3 + 1] - u[3 * 9 + 2] + 1.5 * u[3 * 6], 1e-15);
  // expand() of the unknowns of u gives u back.
  VecX x(dofs.n_equations()), g(dofs.n_prescribed());
  for (int eq = 0; eq < dofs.n_equations(); ++eq) x[eq] = u[dofs.equation_dof(eq)];
  for (int k = 0; k < dofs.n_prescribed(); ++k) g[k] = u[dofs.prescribed_dof(k)];
  EXPECT_NEAR((dofs.expand(x, g) - u).cwiseAbs().maxCoeff(), 0, 1e-14);
  // T = du/dx: the solved dependent dofs' derivatives by central differences.
  std::mt19937 rng(17);
  for (int trial = 0; trial < 6; ++trial) {
    const int eq = std::uniform_int_distribution<int>(0, dofs.n_equations() - 1)(rng);
    const Real h = 1e-6;
    auto solved = [&](Real step) {
      VecX xs = x;
      xs[eq] += step;
      VecX us = dofs.expand(xs, g);
      assembly::DofMap copy = dofs;
      copy.relinearise(us);
      return us;
    };
    const VecX fd = (solved(h) - solved(-h)) / (2 * h);
    for (int d = 0; d < dofs.n_dofs(); ++d) {
      Real t = 0;
      for (auto term = dofs.terms_begin(d); term != dofs.terms_end(d); ++term)
        if (!term->is_prescribed && term->index == eq) t += term->coef;
      EXPECT_NEAR(t, fd[d], 1e-7) << "dof " << d << " unknown " << eq;
    }
  }
  // The rigid nodes keep their distances to each other.
  auto x_of = [&](int node) -> Vec3 {
    return m.mesh.coords.row(node).transpose() + u.segment<3>(3 * node);
  };
  EXPECT_NEAR((x_of(8) - x_of(10)).norm(), std::sqrt(2.0), 1e-13);
}

TEST(DofMap, ConstraintForcesReachOnlyNodesWithoutElements) {
  model::Model m = bricks_with_extra_nodes();
  m.nonlinear_constraints.push_back(constraint(Kind::Rigid, {8, 12, 13}, 1));
  const assembly::DofMap dofs(m, {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}});
  MatX3 f = MatX3::Zero(14, 3);
  f(8, 1) = 2.0;  // node 9 (at 2, 0, 0) pushed in y, the reference node at (2.5, 0.5, 0.5)
  dofs.add_constraint_forces(f);
  EXPECT_DOUBLE_EQ(f(8, 1), 2.0);
  EXPECT_NEAR(f(12, 1), 2.0, 1e-15);  // the force on the body
  EXPECT_NEAR((f.row(13).transpose() - Vec3(-0.5, -0.5, -0.5).cross(Vec3(0, 2, 0))).norm(), 0,
              1e-15);
}

TEST(DofMap, RefusesChainedAndPrescribedNonlinearConstraints) {
  model::Model m = bricks_with_extra_nodes();
  m.nonlinear_constraints.push_back(constraint(Kind::Rigid, {8, 12, 13}, 0));
  EXPECT_THROW(assembly::DofMap(m, {{8, 0, 0.1}}), InputError);  // its dependent dof prescribed
  m.nonlinear_constraints.push_back(
      constraint(Kind::Straight, {9, 8, 4}, 1, 0));  // 8x is dependent
  try {
    assembly::DofMap dofs(m, {});
    FAIL() << "chained constraints accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be chained"), std::string::npos) << e.what();
  }
}

TEST(DofMap, ANonlinearConstraintNotInForceLeavesItsDofsAlone) {
  // A DIST whose nodes are not linked: node 5 moves freely, nothing is solved for it.
  model::Model m = bricks_with_extra_nodes();
  m.nonlinear_constraints.push_back(distance_5_0());
  const assembly::DofMap linked(m, {{0, 0, 0}}), free(m, {{0, 0, 0}}, {}, {0});
  EXPECT_TRUE(linked.has_nonlinear_constraints());
  EXPECT_FALSE(linked.is_free(3 * 5));
  EXPECT_FALSE(free.has_nonlinear_constraints());
  EXPECT_TRUE(free.is_free(3 * 5));
  VecX u = VecX::Zero(3 * 14);
  u[3 * 5] = 0.7;  // 1.97 apart: beyond the distance, which only a linked DIST pulls back
  VecX v = u;
  assembly::DofMap(free).relinearise(v);
  EXPECT_EQ(v[3 * 5], 0.7);
  assembly::DofMap(linked).relinearise(u);
  EXPECT_NEAR((m.mesh.coords.row(5).transpose() + u.segment<3>(15)).norm(), 1.5, 1e-14);
}

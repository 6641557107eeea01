#include <gtest/gtest.h>

#include <Eigen/Geometry>  // cross, determinant
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

#include "model/local_frame.hpp"

using namespace kontakt;
using model::Transform;

namespace {

Transform transform(Transform::Kind kind, Vec3 a, Vec3 b) {
  Transform t;
  t.kind = kind;
  t.a = a;
  t.b = b;
  return t;
}

void expect_rotation(const Mat3& r) {
  EXPECT_LT((r.transpose() * r - Mat3::Identity()).norm(), 1e-14);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-14);  // right-handed
}

std::string error_of(const Transform& t, const Vec3& x) {
  try {
    model::local_frame(t, x);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(LocalFrame, RectangularAxesFromThePointsAndIndependentOfTheNode) {
  // The manual's example: a on global y, b on global z: x' = y, y' = z, z' = x.
  const Transform t = transform(Transform::Kind::Rectangular, {0, 1, 0}, {0, 0, 1});
  const Mat3 r = model::local_frame(t, {5, -3, 2});
  expect_rotation(r);
  EXPECT_LT((r.col(0) - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((r.col(1) - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((r.col(2) - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((model::local_frame(t, {0, 0, 0}) - r).norm(), 1e-15);
  // b need not be orthogonal to a: only the x'-y' plane it spans counts.
  const Mat3 skew = model::local_frame(
      transform(Transform::Kind::Rectangular, {2, 2, 0}, {0, 7, 0}), Vec3::Zero());
  expect_rotation(skew);
  EXPECT_LT((skew.col(0) - Vec3(1, 1, 0) / std::sqrt(2.0)).norm(), 1e-15);
  EXPECT_LT((skew.col(2) - Vec3(0, 0, 1)).norm(), 1e-15);
}

TEST(LocalFrame, CylindricalRadialTangentialAxial) {
  // Axis along global z through (1, 1, 0): a node at (3, 1, 4) is radial along +x.
  const Transform t = transform(Transform::Kind::Cylindrical, {1, 1, 0}, {1, 1, 2});
  const Mat3 r = model::local_frame(t, {3, 1, 4});
  expect_rotation(r);
  EXPECT_LT((r.col(0) - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((r.col(1) - Vec3(0, 1, 0)).norm(), 1e-15);  // tangential, right-handed about z'
  EXPECT_LT((r.col(2) - Vec3(0, 0, 1)).norm(), 1e-15);
  // A tilted axis: the radial axis is orthogonal to it and points at the node.
  const Transform tilted = transform(Transform::Kind::Cylindrical, {0, 0, 0}, {1, 1, 1});
  const Vec3 x(2, -1, 0.5);
  const Mat3 q = model::local_frame(tilted, x);
  expect_rotation(q);
  EXPECT_NEAR(q.col(0).dot(Vec3(1, 1, 1)), 0, 1e-15);
  EXPECT_GT(q.col(0).dot(x), 0);
  EXPECT_NEAR(q.col(0).cross(x).dot(Vec3(1, 1, 1)), 0, 1e-14);  // x in the radial plane
  // Reversing the axis (b to a) flips z' and y', keeps x'.
  const Mat3 flipped = model::local_frame(
      transform(Transform::Kind::Cylindrical, {1, 1, 1}, {0, 0, 0}), x);
  EXPECT_LT((flipped.col(0) - q.col(0)).norm(), 1e-14);
  EXPECT_LT((flipped.col(2) + q.col(2)).norm(), 1e-14);
}

TEST(LocalFrame, NodesOnTheCylinderAxisGetCcxsFrame) {
  // Measured with ccx 2.20 (a node on the axis loaded along its local x' and y'): y' is global
  // z projected normal to the axis, global y for an axis along z; x' = y' x z'.
  using K = Transform::Kind;
  struct Case {
    Vec3 axis, x_local, y_local;
  };
  const Real s = 1 / std::sqrt(2.0);
  const Vec3 e = Vec3(1, 2, 3).normalized();
  const Vec3 y5 = (Vec3::UnitZ() - e.z() * e).normalized();
  const Case cases[] = {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                        {{1, 1, 0}, {-s, s, 0}, {0, 0, 1}},
                        {{1, 2, 3}, y5.cross(e), y5}};
  for (const Case& c : cases) {
    const Transform t = transform(K::Cylindrical, {0, 0, 1}, Vec3(0, 0, 1) + c.axis);
    const Vec3 node(0, 0, 1);
    EXPECT_TRUE(model::on_cylinder_axis(t, node));
    const Mat3 r = model::local_frame(t, node);
    expect_rotation(r);
    EXPECT_LT((r.col(0) - c.x_local).norm(), 1e-14) << c.axis.transpose();
    EXPECT_LT((r.col(1) - c.y_local).norm(), 1e-14) << c.axis.transpose();
  }
  const Transform z = transform(K::Cylindrical, {0, 0, 0}, {0, 0, 1});
  EXPECT_TRUE(model::on_cylinder_axis(z, {1e-14, 0, 3}));
  EXPECT_FALSE(model::on_cylinder_axis(z, {1e-6, 0, 3}));
  EXPECT_FALSE(model::on_cylinder_axis(transform(K::Rectangular, {1, 0, 0}, {0, 1, 0}), {0, 0, 0}));
}

TEST(LocalFrame, DegenerateDefinitionsAreErrors) {
  using K = Transform::Kind;
  EXPECT_NE(error_of(transform(K::Cylindrical, {1, 2, 3}, {1, 2, 3}), {5, 5, 5})
                .find("coincide"),
            std::string::npos);
  EXPECT_NE(error_of(transform(K::Rectangular, {0, 0, 0}, {0, 1, 0}), {5, 5, 5})
                .find("is the origin"),
            std::string::npos);
  EXPECT_NE(error_of(transform(K::Rectangular, {1, 0, 0}, {-3, 0, 0}), {5, 5, 5})
                .find("lies on the local x' axis"),
            std::string::npos);
  EXPECT_NE(error_of(transform(K::Rectangular, {1, 0, 0}, {0, 0, 0}), {5, 5, 5})
                .find("lies on the local x' axis"),
            std::string::npos);
}

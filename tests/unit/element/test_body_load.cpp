// Body forces of *DLOAD GRAV and CENTRIF: resultants against closed forms.
#include <gtest/gtest.h>

#include "element/body_load.hpp"
#include "element/solid_linear.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

using test::kAllTypes;

/// An affine map of the reference element (constant Jacobian): every rule integrates the
/// linear acceleration fields exactly, so the resultants have closed forms.
MatX3 sheared_block(ElementType type) {
  MatX3 X = test::reference_coordinates(volume_topology(type));
  Mat3 A;
  A << 1.3, 0.2, 0.1, -0.1, 0.9, 0.15, 0.05, -0.2, 1.1;
  return (X * A.transpose()).rowwise() + Vec3(4.0, -1.0, 2.5).transpose();
}

Vec3 resultant(const VecX& f) {
  Vec3 r = Vec3::Zero();
  for (Index a = 0; a < f.size() / 3; ++a) r += f.segment<3>(3 * a);
  return r;
}

TEST(BodyLoad, GravityResultantIsWeight) {
  const BodyAcceleration g{.kind = BodyAcceleration::Kind::Gravity, .magnitude = 9810,
                           .direction = Vec3(0, 0.6, -0.8)};
  for (ElementType type : kAllTypes) {
    SCOPED_TRACE(traits(type).name);
    const MatX3 X = test::distorted_coordinates(volume_topology(type));
    VecX f;
    body_load(type, X, MatX3::Zero(X.rows(), 3), 7.8e-9, g, f);
    const Real mass = 7.8e-9 * ip_volumes(type, X).sum();
    EXPECT_LT((resultant(f) - mass * 9810 * g.direction).norm(), 1e-12 * mass * 9810);
  }
}

TEST(BodyLoad, CentrifugalResultantActsAtTheCentreOfMass) {
  const Vec3 axis = Vec3(1, 2, 2) / 3;
  const BodyAcceleration spin{.kind = BodyAcceleration::Kind::Centrifugal, .magnitude = 1e6,
                              .point = Vec3(0.5, -2, 1), .direction = axis};
  for (ElementType type : kAllTypes) {
    SCOPED_TRACE(traits(type).name);
    const MatX3 X = sheared_block(type);
    VecX f;
    body_load(type, X, MatX3::Zero(X.rows(), 3), 2.0, spin, f);
    // Affine element: the centre of mass is the mean of the reference element's nodes mapped.
    const Vec3 centre = X.colwise().mean().transpose();
    const Real mass = 2.0 * ip_volumes(type, X).sum();
    const Vec3 off_axis = (Mat3::Identity() - axis * axis.transpose()) * (centre - spin.point);
    EXPECT_LT((resultant(f) - mass * 1e6 * off_axis).norm(), 1e-10 * (mass * 1e6 * off_axis).norm());
    EXPECT_NEAR(resultant(f).dot(axis), 0, 1e-9 * resultant(f).norm());
  }
}

TEST(BodyLoad, CentrifugalForceFollowsTheMass) {
  // Moving the whole element by d changes every point's acceleration by omega^2 d_perp.
  const Vec3 axis(0, 0.6, 0.8), d(0.3, -0.2, 0.5);
  const BodyAcceleration spin{.kind = BodyAcceleration::Kind::Centrifugal, .magnitude = 3e4,
                              .point = Vec3(-1, 0.5, 0), .direction = axis};
  for (ElementType type : kAllTypes) {
    SCOPED_TRACE(traits(type).name);
    const MatX3 X = test::distorted_coordinates(volume_topology(type));
    VecX f0, f1;
    body_load(type, X, MatX3::Zero(X.rows(), 3), 1.5, spin, f0);
    body_load(type, X, d.transpose().replicate(X.rows(), 1), 1.5, spin, f1);
    const Real mass = 1.5 * ip_volumes(type, X).sum();
    const Vec3 expected = mass * 3e4 * (Mat3::Identity() - axis * axis.transpose()) * d;
    EXPECT_LT((resultant(f1) - resultant(f0) - expected).norm(), 1e-10 * expected.norm());
  }
}

TEST(BodyLoad, GravityDoesNotDependOnTheDisplacement) {
  const BodyAcceleration g{.kind = BodyAcceleration::Kind::Gravity, .magnitude = 2,
                           .direction = Vec3::UnitX()};
  const MatX3 X = test::distorted_coordinates(Topology::Hex20);
  VecX f0, f1;
  body_load(ElementType::C3D20, X, MatX3::Zero(20, 3), 3, g, f0);
  body_load(ElementType::C3D20, X, MatX3::Constant(20, 3, 0.3), 3, g, f1);
  EXPECT_EQ(f0, f1);
}

}  // namespace
}  // namespace kontakt::element

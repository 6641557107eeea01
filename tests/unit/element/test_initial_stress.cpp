// Nodal forces of an initial stress (*INITIAL CONDITIONS, TYPE=STRESS): the same integral of
// B^T sigma as the elastic internal force, point by point in ccx's order, and a uniform field
// that is self-equilibrated (zero resultant, face tractions as forces).
#include <gtest/gtest.h>

#include "element/initial_stress.hpp"
#include "element/quadrature.hpp"
#include "core/error.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

using test::distorted_coordinates;
using test::kAllTypes;
using test::reference_coordinates;
using test::smooth_displacement;
using test::test_material;

TEST(InitialStress, PointwiseStressGivesTheElasticInternalForce) {
  // A stress field varying from point to point (the elastic stress of a smooth displacement
  // on a distorted element) must give exactly recover's internal force: a wrong point order,
  // weight or Jacobian would not. C3D8R adds hourglass forces there, C3D8I is refused.
  for (ElementType type : kAllTypes) {
    if (type == ElementType::C3D8R || type == ElementType::C3D8I) continue;
    SCOPED_TRACE(std::string(traits(type).name));
    const MatX3 X = distorted_coordinates(volume_topology(type));
    IpResults r;
    recover(type, X, test_material(), smooth_displacement(X, 1e-3), VecX(), r);
    VecX f;
    initial_stress_force(type, X, r.stress, f);
    EXPECT_LT((f - r.internal_force).norm(), 1e-10 * r.internal_force.norm());
  }
}

TEST(InitialStress, UniformStressIsSelfEquilibratedWithFaceTractions) {
  // sigma_xx = 7, sigma_xy = 3 on the reference cube [-1,1]^3: no resultant; the nodes of the
  // face x = +1 carry the traction sigma n times the face area 4.
  for (ElementType type : {ElementType::C3D8, ElementType::C3D8R, ElementType::C3D20,
                           ElementType::C3D20R}) {
    SCOPED_TRACE(std::string(traits(type).name));
    const MatX3 X = reference_coordinates(volume_topology(type));
    MatX sigma0 = MatX::Zero(static_cast<Index>(volume_rule(type).size()), 6);
    sigma0.col(0).setConstant(7);
    sigma0.col(3).setConstant(3);
    VecX f;
    initial_stress_force(type, X, sigma0, f);
    Vec3 total = Vec3::Zero(), face = Vec3::Zero();
    for (Index a = 0; a < X.rows(); ++a) {
      total += f.segment<3>(3 * a);
      if (X(a, 0) > 0.5) face += f.segment<3>(3 * a);
    }
    EXPECT_LT(total.norm(), 1e-12);
    // The internal force balances the traction the rest of the body would apply: sigma n A.
    EXPECT_NEAR(face(0), 7 * 4, 1e-12);
    EXPECT_NEAR(face(1), 3 * 4, 1e-12);
    EXPECT_NEAR(face(2), 0, 1e-12);
  }
}

TEST(InitialStress, RefusesMismatchedPointsAndC3D8I) {
  const MatX3 X = reference_coordinates(Topology::Hex8);
  VecX f;
  EXPECT_THROW(initial_stress_force(ElementType::C3D8, X, MatX::Zero(7, 6), f), SolverError);
  EXPECT_THROW(initial_stress_force(ElementType::C3D8I, X, MatX::Zero(8, 6), f), SolverError);
}

}  // namespace
}  // namespace kontakt::element

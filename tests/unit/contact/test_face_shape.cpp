#include <gtest/gtest.h>

#include "contact/face_shape.hpp"
#include "contact_test_util.hpp"

using namespace kontakt;
using namespace kontakt::contact;
using element::Topology;

TEST(FaceShape, MatchesElementShapeFunctionsAndPartitionOfUnity) {
  for (Topology topo : fixtures::kFaceTopologies) {
    for (const Vec2& xi : {Vec2(0.1, 0.2), Vec2(-0.3, 0.6), Vec2(0.25, 0.25)}) {
      FaceShape s;
      face_shape(topo, xi, s);
      element::ShapeVec N;
      element::ShapeGrad dN;
      element::shape_functions(topo, Vec3(xi(0), xi(1), 0), N, dN);
      EXPECT_NEAR(s.N.sum(), 1, 1e-14);
      EXPECT_NEAR(s.dN.col(0).sum(), 0, 1e-14);
      EXPECT_NEAR(s.d2N.col(2).sum(), 0, 1e-14);
      for (int i = 0; i < s.N.size(); ++i) {
        EXPECT_NEAR(s.N(i), N(i), 1e-14);
        EXPECT_NEAR(s.dN(i, 0), dN(i, 0), 1e-14);
        EXPECT_NEAR(s.dN(i, 1), dN(i, 1), 1e-14);
      }
    }
  }
}

TEST(FaceShape, KroneckerAtNodes) {
  for (Topology topo : fixtures::kFaceTopologies) {
    const int n = element::node_count(topo);
    for (int i = 0; i < n; ++i) {
      FaceShape s;
      face_shape(topo, fixtures::reference_face_node(topo, i), s);
      for (int j = 0; j < n; ++j) EXPECT_NEAR(s.N(j), i == j ? 1 : 0, 1e-14);
    }
  }
}

TEST(FaceShape, SecondDerivativesMatchFiniteDifferences) {
  const Real h = 1e-6;
  for (Topology topo : fixtures::kFaceTopologies) {
    const Vec2 xi(0.21, 0.33);
    FaceShape s, sp, sm;
    face_shape(topo, xi, s);
    for (int dir = 0; dir < 2; ++dir) {
      const Vec2 e = dir == 0 ? Vec2(h, 0) : Vec2(0, h);
      face_shape(topo, xi + e, sp);
      face_shape(topo, xi - e, sm);
      for (int i = 0; i < s.N.size(); ++i) {
        EXPECT_NEAR((sp.N(i) - sm.N(i)) / (2 * h), s.dN(i, dir), 1e-8);
        const Real d2_same = (sp.dN(i, dir) - sm.dN(i, dir)) / (2 * h);
        const Real d2_mixed = (sp.dN(i, 1 - dir) - sm.dN(i, 1 - dir)) / (2 * h);
        EXPECT_NEAR(d2_same, s.d2N(i, dir), 1e-7);
        EXPECT_NEAR(d2_mixed, s.d2N(i, 2), 1e-7);
      }
    }
  }
}

TEST(FaceShape, InsideAndClamp) {
  EXPECT_TRUE(inside_reference_face(Topology::Quad4, Vec2(1.0005, 0), 1e-3));
  EXPECT_FALSE(inside_reference_face(Topology::Quad4, Vec2(1.01, 0), 1e-3));
  EXPECT_TRUE(inside_reference_face(Topology::Tri3, Vec2(0.5, 0.5), 0));
  EXPECT_FALSE(inside_reference_face(Topology::Tri6, Vec2(0.6, 0.5), 1e-3));
  EXPECT_TRUE(clamp_to_reference_face(Topology::Quad8, Vec2(2, -3)).isApprox(Vec2(1, -1)));
  EXPECT_TRUE(clamp_to_reference_face(Topology::Tri3, Vec2(1, 1)).isApprox(Vec2(0.5, 0.5)));
  EXPECT_TRUE(clamp_to_reference_face(Topology::Tri3, Vec2(-1, 0.3)).isApprox(Vec2(0, 0.3)));
}

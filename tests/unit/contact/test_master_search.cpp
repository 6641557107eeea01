// The narrow phase's choice of master face, and the faces a point on an edge or a vertex of a
// faceted master surface projects into at one distance.
#include <gtest/gtest.h>

#include <algorithm>

#include "contact/master_search.hpp"

using namespace kontakt;
using namespace kontakt::contact;

namespace {

/// A quadrilateral face through four corners (counter-clockwise seen from outside).
FaceGeometry quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  FaceGeometry f;
  f.topo = element::Topology::Quad4;
  f.x.resize(4, 3);
  f.x << a.transpose(), b.transpose(), c.transpose(), d.transpose();
  return f;
}

/// A roof: two faces meeting at the ridge x = 0 (z = 0), falling by `slope` per unit of |x|.
std::vector<FaceGeometry> roof(Real slope) {
  return {quad({-1, 0, -slope}, {0, 0, 0}, {0, 1, 0}, {-1, 1, -slope}),
          quad({0, 0, 0}, {1, 0, -slope}, {1, 1, -slope}, {0, 1, 0})};
}

/// A four-sided dome with its apex at the origin, z = -slope (|x| + |y|).
std::vector<FaceGeometry> dome(Real slope) {
  std::vector<FaceGeometry> faces;
  for (const Real sx : {1.0, -1.0})
    for (const Real sy : {1.0, -1.0}) {
      const auto at = [&](Real x, Real y) { return Vec3(sx * x, sy * y, -slope * (x + y)); };
      FaceGeometry f = quad(at(0, 0), at(1, 0), at(1, 1), at(0, 1));
      if (sx * sy < 0) f.x.colwise().reverseInPlace();  // a mirror image turns the order
      faces.push_back(f);
    }
  return faces;
}

std::vector<const FaceGeometry*> pointers(const std::vector<FaceGeometry>& faces) {
  std::vector<const FaceGeometry*> p;
  for (const auto& f : faces) p.push_back(&f);
  return p;
}

std::vector<int> candidates_of(const std::vector<MasterFoot>& feet) {
  std::vector<int> c;
  for (const auto& f : feet) c.push_back(f.candidate);
  std::sort(c.begin(), c.end());
  return c;
}

}  // namespace

TEST(MasterSearch, APointUnderARidgeProjectsIntoBothFacesAtOneDistance) {
  const std::vector<FaceGeometry> faces = roof(0.2);
  const auto c = pointers(faces);
  // Below the ridge (a penetrating slave node) and on it (a node of a conforming mesh).
  for (const Vec3& p : {Vec3(0, 0.5, -0.01), Vec3(0, 0.3, 0)}) {
    const std::vector<MasterFoot> feet = find_tied_masters(p, c);
    EXPECT_EQ(candidates_of(feet), (std::vector<int>{0, 1}));
    ASSERT_EQ(feet.size(), 2u);
    EXPECT_NEAR(feet[0].foot.gap, feet[1].foot.gap, 1e-15);
    EXPECT_NEAR(feet[0].foot.normal.x(), -feet[1].foot.normal.x(), 1e-15);
    EXPECT_EQ(find_master(p, c).candidate, feet[0].candidate);
  }
  // Off the bisector by more than the tie tolerance: the nearer face only.
  const std::vector<MasterFoot> right = find_tied_masters(Vec3(1e-3, 0.5, -0.01), c);
  EXPECT_EQ(candidates_of(right), std::vector<int>{1});
  const std::vector<MasterFoot> left = find_tied_masters(Vec3(-1e-3, 0.5, -0.01), c);
  EXPECT_EQ(candidates_of(left), std::vector<int>{0});
}

TEST(MasterSearch, CoplanarFacesGiveOneFoot) {
  // Over the edge between two faces of one plane either face gives the same foot and force.
  const std::vector<FaceGeometry> faces = roof(0);
  EXPECT_EQ(find_tied_masters(Vec3(0, 0.5, -0.01), pointers(faces)).size(), 1u);
}

TEST(MasterSearch, APointUnderAVertexProjectsIntoEveryFaceThere) {
  const std::vector<FaceGeometry> faces = dome(0.15);
  const std::vector<MasterFoot> feet = find_tied_masters(Vec3(0, 0, -0.02), pointers(faces));
  EXPECT_EQ(candidates_of(feet), (std::vector<int>{0, 1, 2, 3}));
  Vec3 sum = Vec3::Zero();
  for (const auto& f : feet) sum += f.foot.normal;
  EXPECT_LT(sum.head<2>().norm(), 1e-14);  // their normals average to the dome's axis
}

TEST(MasterSearch, APointBeyondEveryFaceHasNoFoot) {
  const std::vector<FaceGeometry> faces = roof(0.2);
  EXPECT_TRUE(find_tied_masters(Vec3(3, 0.5, 0), pointers(faces)).empty());
  EXPECT_EQ(find_master(Vec3(3, 0.5, 0), pointers(faces)).candidate, -1);
}

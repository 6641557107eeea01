#include <gtest/gtest.h>

#include "contact/closest_point.hpp"
#include "contact_test_util.hpp"

using namespace kontakt;
using namespace kontakt::contact;
using element::Topology;

namespace {
/// Brute-force closest point over a fine grid of the reference face, for comparison.
Real sampled_min_distance(const FaceGeometry& f, const Vec3& p) {
  Real best = 1e300;
  const int n = 400;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      Vec2 xi = is_triangle(f.topo) ? Vec2(Real(i) / n, Real(j) / n)
                                    : Vec2(-1 + 2.0 * i / n, -1 + 2.0 * j / n);
      if (!inside_reference_face(f.topo, xi, 0)) continue;
      best = std::min(best, (p - surface_point(f, xi).x).norm());
    }
  return best;
}
}  // namespace

TEST(ClosestPoint, CurvedFacesOrthogonalAndNearest) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (Topology topo : fixtures::kFaceTopologies) {
    for (int k = 0; k < 6; ++k) {
      const FaceGeometry f = fixtures::curved_face(topo, 1.0, 0.25, 0.08, rng);
      const Vec2 target = is_triangle(topo) ? Vec2(0.15 + 0.3 * (u(rng) + 1) / 2, 0.1 + 0.3 * (u(rng) + 1) / 2)
                                            : Vec2(0.8 * u(rng), 0.8 * u(rng));
      const SurfacePoint sp = surface_point(f, target);
      const Real offset = 0.05 * u(rng);
      const Vec3 p = sp.x + offset * sp.normal;
      const ClosestPoint cp = project_onto_face(f, p, face_centre(topo));
      ASSERT_TRUE(cp.converged);
      const SurfacePoint at = surface_point(f, cp.xi);
      EXPECT_LT(std::abs((p - at.x).dot(at.a1)), 1e-10);
      EXPECT_LT(std::abs((p - at.x).dot(at.a2)), 1e-10);
      EXPECT_NEAR(cp.gap, offset, 1e-9 + 0.02 * std::abs(offset));  // curved: foot moves a little
      EXPECT_LE(std::abs(cp.gap), sampled_min_distance(f, p) + 1e-9);
    }
  }
}

TEST(ClosestPoint, PointsOffTheFaceProjectOutside) {
  std::mt19937 rng(2);
  const FaceGeometry f = fixtures::curved_face(Topology::Quad4, 1.0, 0.0, 0.0, rng);
  const SurfacePoint sp = surface_point(f, Vec2(1.5, 0.2));  // on the extended plane
  const ClosestPoint cp = project_onto_face(f, sp.x + 0.01 * sp.normal, Vec2::Zero());
  ASSERT_TRUE(cp.converged);
  EXPECT_NEAR(cp.xi(0), 1.5, 1e-10);
  EXPECT_FALSE(inside_reference_face(f.topo, cp.xi, 1e-3));
  EXPECT_NEAR(cp.gap, 0.01, 1e-12);
}

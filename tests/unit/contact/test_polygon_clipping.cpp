#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "contact/polygon_clipping.hpp"

using namespace kontakt;
using namespace kontakt::contact;

namespace {

Polygon2 square(Real x0, Real y0, Real size) {
  return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

/// A random convex polygon: sorted angles on a circle, counter-clockwise.
Polygon2 random_convex(std::mt19937& rng, int n) {
  std::uniform_real_distribution<Real> angle(0, 2 * M_PI), offset(-0.5, 0.5), radius(0.3, 1.2);
  std::vector<Real> t(n);
  for (auto& v : t) v = angle(rng);
  std::sort(t.begin(), t.end());
  const Vec2 c(offset(rng), offset(rng));
  const Real r = radius(rng);
  Polygon2 p;
  for (Real v : t) p.push_back(c + r * Vec2(std::cos(v), std::sin(v)));
  return p;
}

bool inside_convex(const Polygon2& poly, const Vec2& q) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 e = poly[(i + 1) % poly.size()] - poly[i], w = q - poly[i];
    if (e.x() * w.y() - e.y() * w.x() < 0) return false;
  }
  return true;
}

}  // namespace

TEST(PolygonClipping, OverlapOfOffsetSquaresIsExact) {
  const Polygon2 overlap = clip_against_convex(square(0, 0, 1), square(0.25, 0.6, 1));
  EXPECT_NEAR(signed_area(overlap), 0.75 * 0.4, 1e-15);
  EXPECT_TRUE(clip_against_convex(square(0, 0, 1), square(2, 2, 1)).empty());
  const Polygon2 inner = square(0.2, 0.3, 0.1);  // fully inside: itself
  EXPECT_NEAR(signed_area(clip_against_convex(inner, square(0, 0, 1))), 0.01, 1e-15);
}

TEST(PolygonClipping, RandomPairsAgreeBothWaysAndWithSampling) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-2, 2);
  for (int trial = 0; trial < 2000; ++trial) {
    const Polygon2 a = random_convex(rng, 3 + trial % 6), b = random_convex(rng, 3 + trial % 5);
    const Real ab = std::abs(signed_area(clip_against_convex(a, b)));
    const Real ba = std::abs(signed_area(clip_against_convex(b, a)));
    ASSERT_NEAR(ab, ba, 1e-12) << trial;  // the intersection does not depend on the order
    ASSERT_LE(ab, std::min(signed_area(a), signed_area(b)) + 1e-12);
    if (trial % 100 == 0) {  // an independent estimate by sampling the bounding square
      int hits = 0;
      const int n = 200000;
      for (int k = 0; k < n; ++k) {
        const Vec2 q(u(rng), u(rng));
        hits += inside_convex(a, q) && inside_convex(b, q);
      }
      EXPECT_NEAR(ab, 16.0 * hits / n, 0.02) << trial;
    }
  }
}

TEST(PolygonClipping, FanTrianglesCoverTheConvexPolygon) {
  std::mt19937 rng(3);
  for (int n = 3; n <= 9; ++n) {
    const Polygon2 p = random_convex(rng, n);
    Real sum = 0;
    for (const auto& t : fan_triangulate(p)) {
      const Real area = 0.5 * ((t.b - t.a).x() * (t.c - t.a).y() - (t.b - t.a).y() * (t.c - t.a).x());
      EXPECT_GT(area, 0);  // counter-clockwise, non-degenerate
      sum += area;
    }
    EXPECT_NEAR(sum, signed_area(p), 1e-13);
    EXPECT_EQ(fan_triangulate(p).size(), n == 3 ? 1u : static_cast<std::size_t>(n));
  }
}

TEST(PolygonClipping, ProjectionKeepsInPlaneDistances) {
  const Vec3 n = Vec3(1, 2, 2).normalized();
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  const Vec3 o(0.3, -1, 2);
  const std::vector<Vec3> pts = {o + 2 * e1, o + 3 * e2 + 0.7 * n, o - e1 + e2};
  const Polygon2 p = project_to_plane(pts, o, e1, e2);
  EXPECT_NEAR((p[0] - Vec2(2, 0)).norm(), 0, 1e-14);
  EXPECT_NEAR((p[1] - Vec2(0, 3)).norm(), 0, 1e-14);  // the normal offset is dropped
  EXPECT_NEAR((p[2] - Vec2(-1, 1)).norm(), 0, 1e-14);
}

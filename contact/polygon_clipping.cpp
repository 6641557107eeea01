#include "contact/polygon_clipping.hpp"

#include <cmath>

namespace kontakt::contact {

namespace {

/// Positive when p lies left of the directed edge a -> b (inside for a counter-clockwise clip).
Real side(const Vec2& a, const Vec2& b, const Vec2& p) { return cross2(b - a, p - a); }

}  // namespace

Real signed_area(const Polygon2& polygon) {
  Real twice = 0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i)
    twice += cross2(polygon[i], polygon[(i + 1) % n]);
  return 0.5 * twice;
}

Polygon2 clip_against_convex(const Polygon2& subject, const Polygon2& clip, Real min_area) {
  Polygon2 out = subject;
  for (std::size_t e = 0, m = clip.size(); e < m && !out.empty(); ++e) {
    const Vec2& a = clip[e];
    const Vec2& b = clip[(e + 1) % m];
    Polygon2 in = std::move(out);
    out.clear();
    for (std::size_t i = 0, n = in.size(); i < n; ++i) {
      const Vec2& p = in[i];
      const Vec2& q = in[(i + 1) % n];
      const Real sp = side(a, b, p), sq = side(a, b, q);
      if (sp >= 0) out.push_back(p);
      // The edge p -> q crosses the clip line: keep the crossing point.
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
  }
  if (out.size() < 3 || std::abs(signed_area(out)) <= min_area) return {};
  return out;
}

std::vector<Triangle2> fan_triangulate(const Polygon2& convex) {
  if (convex.size() < 3) return {};
  if (convex.size() == 3) return {{convex[0], convex[1], convex[2]}};
  Vec2 centre = Vec2::Zero();
  for (const Vec2& p : convex) centre += p;
  centre /= static_cast<Real>(convex.size());
  std::vector<Triangle2> triangles;
  triangles.reserve(convex.size());
  for (std::size_t i = 0, n = convex.size(); i < n; ++i)
    triangles.push_back({centre, convex[i], convex[(i + 1) % n]});
  return triangles;
}

Polygon2 project_to_plane(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& e1,
                          const Vec3& e2) {
  Polygon2 out;
  out.reserve(points.size());
  for (const Vec3& p : points) out.emplace_back((p - origin).dot(e1), (p - origin).dot(e2));
  return out;
}

}  // namespace kontakt::contact

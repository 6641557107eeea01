#include "contact/state_transfer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "contact/contact_extrapolation.hpp"
#include "contact/polygon_clipping.hpp"

namespace kontakt::contact {

namespace {

using element::Topology;
using Triangle = std::array<int, 3>;

/// Whether p lies strictly inside the circumcircle of the counter-clockwise triangle abc.
bool in_circumcircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& p) {
  const Vec2 da = a - p, db = b - p, dc = c - p;
  const Real det = (da.squaredNorm() * cross2(db, dc) - db.squaredNorm() * cross2(da, dc) +
                    dc.squaredNorm() * cross2(da, db));
  return det > 0;
}

/// Barycentric coordinates of p in the triangle abc.
Vec3 barycentric(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& p) {
  const Real area = cross2(b - a, c - a);
  const Real l1 = cross2(b - p, c - p) / area, l2 = cross2(c - p, a - p) / area;
  return {l1, l2, 1 - l1 - l2};
}

/// The point of segment ab nearest to p, as the weight of b.
Real segment_weight(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 d = b - a;
  return std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
}

}  // namespace

StateVector pack(const FrictionState& s) {
  StateVector v;
  v << s.tangential, s.slip;
  return v;
}

FrictionState unpack(const StateVector& v) { return {v.head<3>(), v.tail<3>()}; }

std::vector<Triangle> delaunay(const std::vector<Vec2>& points) {
  const int n = static_cast<int>(points.size());
  if (n < 3) return {};
  Vec2 lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec2 centre = 0.5 * (lo + hi);
  const Real size = std::max((hi - lo).maxCoeff(), 1e-12);
  // An enclosing triangle (vertices n, n + 1, n + 2) far enough outside that removing it
  // leaves the convex hull (thesis 4.3.1: a near one leaves concave boundaries).
  const Real far = 1e5 * size;
  std::vector<Vec2> p = points;
  p.push_back(centre + Vec2(-far, -far));
  p.push_back(centre + Vec2(far, -far));
  p.push_back(centre + Vec2(0, far));
  std::vector<Triangle> tris{{n, n + 1, n + 2}};
  for (int i = 0; i < n; ++i) {
    bool duplicate = false;
    for (int j = 0; j < i && !duplicate; ++j) duplicate = (p[i] - p[j]).norm() < 1e-12;
    if (duplicate) continue;
    // Remove the triangles whose circumcircle holds the point; re-fan the cavity's boundary.
    std::vector<std::array<int, 2>> edges;
    std::vector<Triangle> kept;
    for (const Triangle& t : tris) {
      if (!in_circumcircle(p[t[0]], p[t[1]], p[t[2]], p[i])) {
        kept.push_back(t);
        continue;
      }
      for (int e = 0; e < 3; ++e) {
        const std::array<int, 2> edge{t[e], t[(e + 1) % 3]};
        auto twin = std::find_if(edges.begin(), edges.end(), [&](const auto& f) {
          return f[0] == edge[1] && f[1] == edge[0];
        });
        if (twin != edges.end())
          edges.erase(twin);  // shared by two removed triangles: interior to the cavity
        else
          edges.push_back(edge);
      }
    }
    for (const auto& e : edges) kept.push_back({e[0], e[1], i});  // counter-clockwise
    tris = std::move(kept);
  }
  std::vector<Triangle> out;
  for (const Triangle& t : tris)
    if (t[0] < n && t[1] < n && t[2] < n) out.push_back(t);
  return out;
}

MatX interpolate_on_triangulation(const std::vector<Vec2>& points, const MatX& values,
                                  const std::vector<Vec2>& targets) {
  const std::vector<Triangle> tris = delaunay(points);
  MatX out(static_cast<Index>(targets.size()), values.cols());
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const Vec2& q = targets[k];
    // Inside a triangle: its barycentric weights; else the nearest boundary point of the
    // triangle whose most negative weight is least negative.
    Real best_worst = -std::numeric_limits<Real>::infinity();
    Vec3 best_weights = Vec3::Zero();
    const Triangle* best = nullptr;
    for (const Triangle& t : tris) {
      const Vec3 w = barycentric(points[t[0]], points[t[1]], points[t[2]], q);
      if (w.minCoeff() > best_worst) {
        best_worst = w.minCoeff();
        best_weights = w;
        best = &t;
      }
      if (best_worst >= -1e-12) break;
    }
    if (!best) {  // fewer than three distinct points: the nearest one
      std::size_t nearest = 0;
      for (std::size_t i = 1; i < points.size(); ++i)
        if ((points[i] - q).norm() < (points[nearest] - q).norm()) nearest = i;
      out.row(static_cast<Index>(k)) = values.row(static_cast<Index>(nearest));
      continue;
    }
    const Triangle& t = *best;
    if (best_worst < -1e-12) {  // outside: onto the nearest edge of that triangle
      Real nearest = std::numeric_limits<Real>::infinity();
      for (int e = 0; e < 3; ++e) {
        const Vec2 &a = points[t[e]], &b = points[t[(e + 1) % 3]];
        const Real s = segment_weight(a, b, q);
        const Real d = (a + s * (b - a) - q).norm();
        if (d < nearest) {
          nearest = d;
          best_weights.setZero();
          best_weights(e) = 1 - s;
          best_weights((e + 1) % 3) = s;
        }
      }
    }
    out.row(static_cast<Index>(k)) = best_weights(0) * values.row(t[0]) +
                                     best_weights(1) * values.row(t[1]) +
                                     best_weights(2) * values.row(t[2]);
  }
  return out;
}

std::vector<Vec2> corner_coordinates(Topology face) {
  if (face == Topology::Tri3 || face == Topology::Tri6) return {{0, 0}, {1, 0}, {0, 1}};
  return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
}

MatX corner_states(Topology face, const std::vector<Vec2>& old_xi, const MatX& old_states) {
  // The fit itself, not clamped to the points' range as for output: a linear state field must
  // move exactly.
  return fit_corner_values(face, extrapolation_method(face, static_cast<int>(old_xi.size())),
                           old_xi, old_states);
}

MatX transfer_states(Topology face, const std::vector<Vec2>& old_xi, const MatX& old_states,
                     const MatX& corners, const std::vector<Vec2>& new_xi) {
  if (old_xi.empty()) return MatX::Zero(static_cast<Index>(new_xi.size()), old_states.cols());
  std::vector<Vec2> points = corner_coordinates(face);
  MatX values(static_cast<Index>(points.size() + old_xi.size()), old_states.cols());
  values.topRows(corners.rows()) = corners;
  values.bottomRows(old_states.rows()) = old_states;
  points.insert(points.end(), old_xi.begin(), old_xi.end());
  return interpolate_on_triangulation(points, values, new_xi);
}

}  // namespace kontakt::contact

#include "contact/slave_points.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "contact/polygon_clipping.hpp"
#include "contact/triangle_rules.hpp"

namespace kontakt::contact {

using element::ElementType;
using element::Topology;

std::vector<SlavePointSeed> gauss_points(ElementType type, Topology topo) {
  std::vector<SlavePointSeed> pts;
  if (is_triangle(topo)) {
    const bool three = type == ElementType::C3D10 || type == ElementType::C3D15;
    if (!three) return {{Vec2(1.0 / 3, 1.0 / 3), 0.5, -1}};
    for (const Vec2& xi : {Vec2(1.0 / 6, 1.0 / 6), Vec2(2.0 / 3, 1.0 / 6), Vec2(1.0 / 6, 2.0 / 3)})
      pts.push_back({xi, 1.0 / 6, -1});
    return pts;
  }
  const int n = type == ElementType::C3D8R ? 1
                : (type == ElementType::C3D20 || type == ElementType::C3D15) ? 3
                                                                              : 2;
  static const Real k2 = 1 / std::sqrt(3.0), k3 = std::sqrt(0.6);
  const std::vector<std::pair<Real, Real>> line =
      n == 1   ? std::vector<std::pair<Real, Real>>{{0, 2}}
      : n == 2 ? std::vector<std::pair<Real, Real>>{{-k2, 1}, {k2, 1}}
               : std::vector<std::pair<Real, Real>>{{-k3, 5.0 / 9}, {0, 8.0 / 9}, {k3, 5.0 / 9}};
  for (const auto& [eta, we] : line)
    for (const auto& [xi, wx] : line) pts.push_back({Vec2(xi, eta), wx * we, -1});
  return pts;
}

namespace {

/// Convex pieces of a face as local node lists (quadratic faces: corner triangles and the
/// central triangle or quad between the midside nodes, as ccx cuts them).
const std::vector<std::vector<int>>& face_pieces(Topology topo) {
  static const std::vector<std::vector<int>> tri3{{0, 1, 2}}, quad4{{0, 1, 2, 3}},
      tri6{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}},
      quad8{{0, 4, 7}, {4, 1, 5}, {5, 2, 6}, {6, 3, 7}, {4, 5, 6, 7}};
  switch (topo) {
    case Topology::Tri3: return tri3;
    case Topology::Tri6: return tri6;
    case Topology::Quad8: return quad8;
    default: return quad4;
  }
}

bool is_convex_ccw(const Polygon2& p) {
  for (std::size_t i = 0, n = p.size(); i < n; ++i)
    if (cross2(p[(i + 1) % n] - p[i], p[(i + 2) % n] - p[(i + 1) % n]) <= 0) return false;
  return true;
}

/// The face's pieces projected into the plane, counter-clockwise; a non-convex quadrilateral
/// piece (a strongly distorted face) is split into two triangles.
std::vector<Polygon2> planar_pieces(const FaceGeometry& face, const Vec3& origin, const Vec3& e1,
                                    const Vec3& e2) {
  std::vector<Polygon2> out;
  for (const auto& piece : face_pieces(face.topo)) {
    std::vector<Vec3> pts;
    for (int i : piece) pts.push_back(face.x.row(i).transpose());
    Polygon2 p = project_to_plane(pts, origin, e1, e2);
    if (signed_area(p) < 0) std::reverse(p.begin(), p.end());
    if (p.size() == 4 && !is_convex_ccw(p)) {
      // Split along the diagonal that keeps both triangles positive.
      Polygon2 a{p[0], p[1], p[2]}, b{p[0], p[2], p[3]};
      if (signed_area(a) <= 0 || signed_area(b) <= 0) {
        a = {p[1], p[2], p[3]};
        b = {p[1], p[3], p[0]};
      }
      out.push_back(a);
      out.push_back(b);
      continue;
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

bool invert_plane_projection(const FaceGeometry& face, const Vec3& origin, const Vec3& e1,
                             const Vec3& e2, const Vec2& q, Vec2& xi) {
  for (int it = 0; it < 30; ++it) {
    const SurfacePoint sp = surface_point(face, xi);
    const Vec2 r = q - Vec2((sp.x - origin).dot(e1), (sp.x - origin).dot(e2));
    Eigen::Matrix2d J;
    J << e1.dot(sp.a1), e1.dot(sp.a2), e2.dot(sp.a1), e2.dot(sp.a2);
    const Vec2 step = J.partialPivLu().solve(r);
    if (!step.allFinite()) return false;
    xi += step;
    if (step.norm() < 1e-13) return true;
  }
  return false;
}

std::vector<SlavePointSeed> gauss_cut_points(const FaceGeometry& slave,
                                             const std::vector<FaceGeometry>& masters,
                                             int rule_points) {
  std::vector<SlavePointSeed> pts;
  const SurfacePoint centre = surface_point(slave, face_centre(slave.topo));
  const Vec3 n = centre.normal;
  const Vec3 e1 = centre.a1.normalized(), e2 = n.cross(e1);
  const std::vector<Polygon2> slave_pieces = planar_pieces(slave, centre.x, e1, e2);
  Real slave_planar_area = 0;
  for (const auto& p : slave_pieces) slave_planar_area += signed_area(p);
  const Real min_area = 1e-10 * slave_planar_area;
  const auto rule = triangle_rule(rule_points);

  for (std::size_t m = 0; m < masters.size(); ++m) {
    const SurfacePoint mc = surface_point(masters[m], face_centre(masters[m].topo));
    if (mc.normal.dot(n) > kOpposingCosine) continue;
    for (const Polygon2& mp : planar_pieces(masters[m], centre.x, e1, e2)) {
      for (const Polygon2& sp : slave_pieces) {
        const Polygon2 overlap = clip_against_convex(mp, sp, min_area);
        for (const Triangle2& t : fan_triangulate(overlap)) {
          const Real tri_area = 0.5 * cross2(t.b - t.a, t.c - t.a);
          if (tri_area <= min_area) continue;
          for (const TrianglePoint& rp : rule) {
            const Vec2 q = rp.l1 * t.a + rp.l2 * t.b + rp.l3 * t.c;
            Vec2 xi = face_centre(slave.topo);
            if (!invert_plane_projection(slave, centre.x, e1, e2, q, xi)) continue;
            // Planar area over the cosine of the face's inclination = area on the face.
            const SurfacePoint at = surface_point(slave, xi);
            const Real cosine = std::abs(at.normal.dot(n));
            if (cosine < 1e-6) continue;
            const Real area = tri_area * rp.weight / cosine;
            pts.push_back({xi, area / at.jacobian, static_cast<int>(m)});
          }
        }
      }
    }
  }
  return pts;
}

}  // namespace kontakt::contact

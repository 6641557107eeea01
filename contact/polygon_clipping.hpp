// Planar polygon geometry for Gauss-Cut contact integration (thesis §4.3): the slave face and a
// master face are projected into a common plane, the master polygon is clipped against the slave
// polygon, and the overlap is triangulated for the triangle rules. Pure functions.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace kontakt::contact {

/// Vertices in order; counter-clockwise for positive area.
using Polygon2 = std::vector<Vec2>;

struct Triangle2 {
  Vec2 a, b, c;
};

/// z component of the cross product of two in-plane vectors (twice the signed triangle area).
inline Real cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Signed area (positive for counter-clockwise vertex order).
Real signed_area(const Polygon2& polygon);

/// Intersection of `subject` (any simple polygon) with the convex, counter-clockwise `clip`
/// polygon (Sutherland-Hodgman). Empty when they do not overlap; degenerate slivers with area
/// below `min_area` are dropped.
Polygon2 clip_against_convex(const Polygon2& subject, const Polygon2& clip, Real min_area = 0);

/// Fan triangulation around the vertex centroid (a triangle is returned as it is), as the
/// Gauss-Cut scheme does; the triangles cover a convex polygon exactly.
std::vector<Triangle2> fan_triangulate(const Polygon2& convex);

/// In-plane coordinates of 3-D points in the plane through `origin` spanned by the orthonormal
/// `e1`, `e2` (the component along the normal is dropped).
Polygon2 project_to_plane(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& e1,
                          const Vec3& e2);

}  // namespace kontakt::contact

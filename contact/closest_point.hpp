// Closest-point projection of a point onto a contact face (linear or quadratic, in its current
// configuration): Newton on the orthogonality conditions (x_p - x(xi)) . x,alpha = 0 with the
// curvature term, Gauss-Newton steps where that Hessian is not positive definite, and
// backtracking so the distance never grows. Quadratic faces are used as they are.
#pragma once

#include "contact/face_shape.hpp"

namespace kontakt::contact {

struct FaceGeometry {
  element::Topology topo = element::Topology::Quad4;
  FaceCoords x;             ///< current nodal coordinates
};

/// Surface point x(xi), tangents x,xi and x,eta, unit normal (right-hand rule on the tangents:
/// out of the element for element faces) and the surface Jacobian |x,xi x x,eta|.
struct SurfacePoint {
  Vec3 x, a1, a2, normal;
  Real jacobian = 0;
};
SurfacePoint surface_point(const FaceGeometry& face, const Vec2& xi);

struct ClosestPoint {
  Vec2 xi = Vec2::Zero();   ///< natural coordinates of the foot point (may lie outside the face)
  Vec3 x = Vec3::Zero();    ///< foot point
  Vec3 normal = Vec3::Zero();
  Real gap = 0;             ///< (p - x) . normal: negative when p is behind the face
  bool converged = false;
};

/// Projects `p` onto the (extended) surface of `face`, starting from `start`. The foot point
/// may lie outside the reference face; the caller decides with inside_reference_face().
ClosestPoint project_onto_face(const FaceGeometry& face, const Vec3& p, const Vec2& start);

}  // namespace kontakt::contact

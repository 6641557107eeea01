#include "contact/closest_point.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace kontakt::contact {

SurfacePoint surface_point(const FaceGeometry& face, const Vec2& xi) {
  FaceShape s;
  face_shape(face.topo, xi, s);
  SurfacePoint sp;
  sp.x = face.x.transpose() * s.N;
  sp.a1 = face.x.transpose() * s.dN.col(0);
  sp.a2 = face.x.transpose() * s.dN.col(1);
  const Vec3 m = sp.a1.cross(sp.a2);
  sp.jacobian = m.norm();
  sp.normal = sp.jacobian > 0 ? Vec3(m / sp.jacobian) : Vec3::Zero();
  return sp;
}

namespace {
/// Natural coordinates are kept within this box: far outside a quadratic face the extended
/// surface folds over, and such points are off the face anyway.
constexpr Real kXiBound = 3;
constexpr int kMaxIterations = 30;
}  // namespace

ClosestPoint project_onto_face(const FaceGeometry& face, const Vec3& p, const Vec2& start) {
  FaceShape s;
  Vec2 xi = start;
  auto distance2 = [&](const Vec2& z) {
    face_shape(face.topo, z, s);
    return (p - face.x.transpose() * s.N).squaredNorm();
  };
  Real d2 = distance2(xi);
  ClosestPoint cp;
  bool polishing = false;
  for (int it = 0; it < kMaxIterations; ++it) {
    face_shape(face.topo, xi, s);
    const Vec3 x = face.x.transpose() * s.N;
    const Vec3 a1 = face.x.transpose() * s.dN.col(0), a2 = face.x.transpose() * s.dN.col(1);
    const Vec3 x11 = face.x.transpose() * s.d2N.col(0), x22 = face.x.transpose() * s.d2N.col(1),
               x12 = face.x.transpose() * s.d2N.col(2);
    const Vec3 r = p - x;
    const Vec2 rhs(r.dot(a1), r.dot(a2));
    Eigen::Matrix2d metric;
    metric << a1.dot(a1), a1.dot(a2), a1.dot(a2), a2.dot(a2);
    Eigen::Matrix2d H = metric;
    H(0, 0) -= r.dot(x11);
    H(1, 1) -= r.dot(x22);
    H(0, 1) -= r.dot(x12);
    H(1, 0) = H(0, 1);
    // Full Newton where the distance function is convex, Gauss-Newton otherwise.
    const bool convex = H(0, 0) > 0 && H.determinant() > 1e-12 * metric.determinant();
    Vec2 step = (convex ? H : metric).ldlt().solve(rhs);
    if (!step.allFinite()) break;
    // Backtrack until the distance does not grow (and xi stays in the box).
    Real t = 1;
    Vec2 trial = xi + step;
    Real d2_trial = 0;
    for (int k = 0; k < 30; ++k) {
      trial = (xi + t * step).cwiseMax(-kXiBound).cwiseMin(kXiBound);
      d2_trial = distance2(trial);
      if (d2_trial <= d2 * (1 + 1e-14) + 1e-300) break;
      t *= 0.5;
    }
    const Real moved = (trial - xi).norm();
    xi = trial;
    d2 = d2_trial;
    // Once the steps are small, one more (quadratically converging) step reaches round-off, so
    // the foot point does not depend on where the iteration started.
    if (polishing) {
      cp.converged = true;
      break;
    }
    polishing = moved < 1e-9 * (1 + xi.norm());
  }
  const SurfacePoint sp = surface_point(face, xi);
  cp.xi = xi;
  cp.x = sp.x;
  cp.normal = sp.normal;
  cp.gap = (p - sp.x).dot(sp.normal);
  // At a bound of the box the orthogonality conditions may not hold; not a usable projection.
  if ((xi.cwiseAbs().array() >= kXiBound).any()) cp.converged = false;
  return cp;
}

}  // namespace kontakt::contact

#include "model/local_frame.hpp"

#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>  // cross products

#include "element/quadrature.hpp"
#include "element/shape_functions.hpp"

namespace kontakt::model {

namespace {

/// Relative size below which a direction counts as zero (points given to ~12 digits).
constexpr Real kDegenerate = 1e-10;

Mat3 columns(const Vec3& e1, const Vec3& e2, const Vec3& e3) {
  Mat3 r;
  r.col(0) = e1;
  r.col(1) = e2;
  r.col(2) = e3;
  return r;
}

/// The part of `v` normal to the unit vector `e`.
Vec3 normal_part(const Vec3& v, const Vec3& e) { return v - v.dot(e) * e; }

/// Radial part of x - a, and the scale it is judged against.
std::pair<Vec3, Real> radial(const Transform& t, const Vec3& x) {
  const Vec3 axis = t.b - t.a;
  const Vec3 off_axis = x - t.a;
  return {normal_part(off_axis, axis.normalized()), off_axis.norm() + axis.norm()};
}

}  // namespace

bool on_cylinder_axis(const Transform& t, const Vec3& x) {
  if (t.kind != Transform::Kind::Cylindrical || t.a == t.b) return false;
  const auto [r, scale] = radial(t, x);
  return r.norm() <= kDegenerate * scale;
}

Mat3 local_frame(const Transform& t, const Vec3& x) {
  if (t.kind == Transform::Kind::Rectangular) {
    if (t.a.norm() == 0)
      throw std::invalid_argument("point a (on the local x' axis) is the origin");
    const Vec3 e1 = t.a.normalized();
    const Vec3 normal = t.a.cross(t.b);
    if (normal.norm() <= kDegenerate * t.a.norm() * t.b.norm() || t.b.norm() == 0)
      throw std::invalid_argument("point b lies on the local x' axis (through the origin and a)");
    const Vec3 e3 = normal.normalized();
    return columns(e1, e3.cross(e1), e3);
  }
  const Vec3 axis = t.b - t.a;
  if (axis.norm() == 0) throw std::invalid_argument("points a and b of the axis coincide");
  const Vec3 e3 = axis.normalized();
  if (on_cylinder_axis(t, x)) {  // ccx's choice (see the header)
    Vec3 e2 = normal_part(Vec3::UnitZ(), e3);
    if (e2.norm() <= kDegenerate) e2 = normal_part(Vec3::UnitY(), e3);
    e2.normalize();
    return columns(e2.cross(e3), e2, e3);
  }
  const Vec3 e1 = radial(t, x).first.normalized();
  return columns(e1, e3.cross(e1), e3);
}

std::vector<Mat3> point_frames(const Orientation& orientation, element::ElementType type,
                               const MatX3& X) {
  std::vector<Mat3> frames;
  const element::Topology topo = element::volume_topology(type);
  for (const element::QuadraturePoint& q : element::volume_rule(type)) {
    element::ShapeVec N;
    element::ShapeGrad dN;
    element::shape_functions(topo, q.xi, N, dN);
    frames.push_back(local_frame(orientation.frame, X.transpose() * N));
  }
  return frames;
}

}  // namespace kontakt::model

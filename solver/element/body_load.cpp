#include "element/body_load.hpp"

#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

namespace {
Mat3 off_axis_projector(const Vec3& axis) { return Mat3::Identity() - axis * axis.transpose(); }
}  // namespace

Vec3 acceleration_at(const BodyAcceleration& b, const Vec3& x) {
  if (b.kind == BodyAcceleration::Kind::Gravity) return b.magnitude * b.direction;
  return b.magnitude * off_axis_projector(b.direction) * (x - b.point);
}

void body_load(ElementType type, const MatX3& X, const MatX3& u, Real density,
               const BodyAcceleration& b, VecX& f) {
  KONTAKT_REQUIRE(u.rows() == X.rows(), "body_load: wrong number of nodal displacements");
  f.setZero(3 * X.rows());
  const MatX3 x = X + u;
  for (const auto& q : volume_rule(type)) {
    const PointGeometry g = rule_point_geometry(type, X, q.xi);
    const Vec3 acc = acceleration_at(b, x.transpose() * g.N);
    const Real mass = density * q.weight * g.detJ;
    for (Index a = 0; a < X.rows(); ++a) f.segment<3>(3 * a) += (mass * g.N(a)) * acc;
  }
}

}  // namespace kontakt::element

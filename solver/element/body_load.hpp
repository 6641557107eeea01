// Body forces per unit mass (*DLOAD GRAV and CENTRIF): the acceleration field and the element's
// consistent nodal forces.
#pragma once

#include "core/types.hpp"
#include "element/element_type.hpp"

namespace kontakt::element {

/// An acceleration field b(x) acting on the mass: gravity b = magnitude * direction; a rotation
/// about the axis through `point` along `direction` (unit) with magnitude = omega^2 gives
/// b = omega^2 (x - point)_perp, the distance vector from the axis.
struct BodyAcceleration {
  enum class Kind { Gravity, Centrifugal };
  Kind kind = Kind::Gravity;
  Real magnitude = 0;
  Vec3 point = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();
};

Vec3 acceleration_at(const BodyAcceleration& b, const Vec3& x);

/// Consistent nodal forces (3n) f_a = integral(N_a rho b(x) dV0) over the reference volume of
/// the element (nodes X, n x 3, the element's own rule, as ccx integrates them), with b at the
/// points' current positions x = N * (X + u): u = 0 for small strain; under NLGEOM the mass
/// moves with the body and so does its centrifugal force.
void body_load(ElementType type, const MatX3& X, const MatX3& u, Real density,
               const BodyAcceleration& b, VecX& f);

}  // namespace kontakt::element

// Local nodal coordinate systems of *TRANSFORM (ccx): *BOUNDARY, *CLOAD, *EQUATION terms and
// *NODE PRINT output of a transformed node are in its local system.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"
#include "element/element_type.hpp"

namespace kontakt::model {

/// A *TRANSFORM data line. Rectangular: `a` lies on the local x' axis, `b` in the x'-y' plane
/// (off the x' axis), right-handed. Cylindrical: `a` and `b` lie on the axis; x' radial,
/// z' from a to b, y' tangential (right-handed).
struct Transform {
  enum class Kind { Rectangular, Cylindrical };
  Kind kind = Kind::Rectangular;
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();
};

/// The local axes at a node at `x` as the columns of an orthonormal matrix (global
/// components): u_global = R u_local. Throws std::invalid_argument naming the reason for a
/// degenerate definition (a at the origin, b on the x' axis, a = b).
///
/// A node on a cylinder's axis has no radial direction; ccx 2.20 accepts it (metalforming has
/// one) and, as measured with five axes, takes y' along global z projected onto the plane
/// normal to the axis (global y when the axis is along z) and x' = y' x z'. Kontakt does the
/// same; the reader warns (on_cylinder_axis).
Mat3 local_frame(const Transform& transform, const Vec3& x);

/// True when `x` lies on the axis of a cylindrical transform.
bool on_cylinder_axis(const Transform& transform, const Vec3& x);

/// An *ORIENTATION: a named material frame of the same definition (ccx), for the elements of
/// a *SOLID SECTION.
struct Orientation {
  std::string name;
  Transform frame;
};

/// The orientation's frame at each integration point of an element of `type` with nodal
/// coordinates X (ccx evaluates a cylindrical frame at the point, so it varies in the element).
std::vector<Mat3> point_frames(const Orientation& orientation, element::ElementType type,
                               const MatX3& X);

}  // namespace kontakt::model

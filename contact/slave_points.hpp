// Integration points of a slave face for one increment (thesis sections 4.2 and 4.3).
//   Gauss:     the slave face's own Gauss rule (quad 1/4/9, triangle 1/3 points, by element type).
//   Gauss-Cut: the slave face and each opposing master face are projected into the slave face's
//              mean plane, cut into convex pieces, the master pieces clipped against the slave
//              pieces, the overlaps fan-triangulated and a 1/3/7/12-point rule put in each
//              triangle. Each point knows the master face it came from.
// A point's slave area is ref_weight * |J_slave(xi)|, so it follows the slave face's stretch.
#pragma once

#include <vector>

#include "contact/closest_point.hpp"
#include "element/element_type.hpp"

namespace kontakt::contact {

struct SlavePointSeed {
  Vec2 xi = Vec2::Zero();   ///< natural coordinates in the slave face
  Real ref_weight = 0;      ///< area = ref_weight * |J_slave(xi)|
  int master = -1;          ///< Gauss-Cut: index of the master face it came from; Gauss: -1
};

/// The Gauss points of a slave face of an element of type `type`.
std::vector<SlavePointSeed> gauss_points(element::ElementType type, element::Topology topo);

/// Points of the Gauss-Cut scheme with `rule_points` per triangle against `masters`. Master
/// faces whose normal is not roughly opposite to the slave's (cosine above
/// kOpposingCosine) are skipped. Overlap slivers below `1e-10` of the slave area are dropped.
std::vector<SlavePointSeed> gauss_cut_points(const FaceGeometry& slave,
                                             const std::vector<FaceGeometry>& masters,
                                             int rule_points);

/// Master faces count as opposing when their normals make more than 135 degrees (as ccx).
inline constexpr Real kOpposingCosine = -0.7;

/// Natural coordinates of the point of `face` whose projection into the plane (origin, e1, e2)
/// is `q`: Newton from `start`. Returns false when it does not converge.
bool invert_plane_projection(const FaceGeometry& face, const Vec3& origin, const Vec3& e1,
                             const Vec3& e2, const Vec2& q, Vec2& xi);

}  // namespace kontakt::contact

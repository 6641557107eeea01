// Integration rules in ccx's point order, and rules for the 2-D faces.
#pragma once

#include <span>

#include "core/types.hpp"
#include "element/element_type.hpp"
#include "element/shape_functions.hpp"

namespace kontakt::element {

struct QuadraturePoint {
  Vec3 xi;       ///< natural coordinates (third is 0 for face rules)
  Real weight;   ///< weights sum to the reference measure
};

/// The element's integration rule, points in ccx output order:
/// bricks xi fastest, then eta, then zeta from (-,-,-); C3D10: (a,a,a),(b,a,a),(a,b,a),(a,a,b);
/// C3D6: centroid at zeta = -1/sqrt3, +1/sqrt3; C3D15: in-plane (1/6,1/6),(2/3,1/6),(1/6,2/3)
/// fastest, zeta = -sqrt(3/5), 0, +sqrt(3/5) outermost.
std::span<const QuadraturePoint> volume_rule(ElementType type);

/// Rule used for pressure on a face topology: 7-point (degree 5) triangle, 3x3 Gauss quad.
std::span<const QuadraturePoint> face_rule(Topology face);

/// Measure of the reference domain: 8 (hex), 1/6 (tet), 1 (wedge), 1/2 (tri), 4 (quad).
Real reference_measure(Topology topo);

}  // namespace kontakt::element

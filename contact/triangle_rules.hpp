// Symmetric Gauss rules on triangles used by the Gauss-Cut schemes (1, 3, 7 and 12 points per
// triangle; polynomial degrees 1, 2, 5 and 6). Points in area coordinates; weights sum to 1 so
// that the integral over a triangle is its area times the weighted sum.
#pragma once

#include <span>

#include "core/types.hpp"

namespace kontakt::contact {

struct TrianglePoint {
  Real l1, l2, l3;  ///< area coordinates, l1 + l2 + l3 = 1
  Real weight;      ///< fraction of the triangle's area
};

/// The rule with `n_points` in {1, 3, 7, 12}; throws SolverError for other counts.
std::span<const TrianglePoint> triangle_rule(int n_points);

/// Polynomial degree the rule integrates exactly.
int triangle_rule_degree(int n_points);

}  // namespace kontakt::contact

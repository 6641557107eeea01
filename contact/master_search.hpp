// Narrow phase of the contact search: the master face a slave point belongs to, among the
// candidates the broad phase found. A point pairs with the face whose (extended) surface it
// projects into, preferring the nearest such face; points that project outside every candidate
// face lie beyond the master surface and get no contact.
#pragma once

#include <span>
#include <vector>

#include "contact/aabb_tree.hpp"
#include "contact/closest_point.hpp"

namespace kontakt::contact {

struct MasterFoot {
  int candidate = -1;       ///< index into the candidate list; -1 when outside the master surface
  ClosestPoint foot;
};

/// Natural-coordinate tolerance of the "inside the face" test. The first pass is tight; the
/// second widens it so a point at a convex edge of the master surface (whose projections fall
/// just outside both faces) still finds the nearer face.
inline constexpr Real kInsideTolerance = 1e-3;
inline constexpr Real kEdgeTolerance = 0.05;

/// Every face of `faces` as a candidate list.
std::vector<const FaceGeometry*> as_candidates(const std::vector<FaceGeometry>& faces);

/// The nearest candidate `p` projects into. Candidates are visited by the distance from `p`
/// to their bounding boxes, and the search stops at the first box farther than the best foot
/// found (a foot lies in its face's box): only the faces near the point are projected on.
MasterFoot find_master(const Vec3& p, std::span<const FaceGeometry* const> candidates);

/// Feet at one distance: within this fraction of the nearest face's size.
inline constexpr Real kTieTolerance = 1e-6;

/// The nearest foot (as find_master) and the feet on every other candidate `p` projects into at
/// the same distance, one per plane: a point on the bisector of an edge or a vertex of a
/// faceted master surface. Which of those faces find_master picks is a matter of order, and
/// picking one tilts the force by half the angle between the faces: over a conforming mesh of a
/// curved surface every node tilts the same way (two rings pressed together turned 1e-5 against
/// each other). Empty when p projects into no candidate.
std::vector<MasterFoot> find_tied_masters(const Vec3& p,
                                          std::span<const FaceGeometry* const> candidates);

}  // namespace kontakt::contact

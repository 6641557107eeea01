// Moving the friction state of a slave face's integration points to the points of the next
// increment (thesis section 4.3.1): the old points and the face's corners are Delaunay-
// triangulated in the face's natural coordinates, and each new point takes the linear
// interpolation in its triangle. The corners' values are the old points' fitted and evaluated
// at the corners (thesis 4.3.3, contact_extrapolation) and averaged over the faces that share the
// corner node, so that neighbouring faces agree at their common edge. A face without old
// points passes nothing on: its new points start without state. Pure functions.
#pragma once

#include <vector>

#include "contact/coulomb_friction.hpp"
#include "element/shape_functions.hpp"

namespace kontakt::contact {

/// A field carried by a point: `state` packed as a vector (FrictionState: 6 components).
using StateVector = Eigen::Matrix<Real, 6, 1>;
StateVector pack(const FrictionState& s);
FrictionState unpack(const StateVector& v);

/// Triangles (indices into `points`) of the Delaunay triangulation of distinct 2D points
/// (Bowyer-Watson from an enclosing triangle); points closer than 1e-12 to an earlier one are
/// left out (their indices appear in no triangle).
std::vector<std::array<int, 3>> delaunay(const std::vector<Vec2>& points);

/// The values at `targets` interpolated linearly over the Delaunay triangulation of `points`
/// (one row of `values` per point). A target outside every triangle takes the value of the
/// nearest point on the triangulation's boundary.
MatX interpolate_on_triangulation(const std::vector<Vec2>& points, const MatX& values,
                                  const std::vector<Vec2>& targets);

/// The natural coordinates of a face topology's corners (ccx order).
std::vector<Vec2> corner_coordinates(element::Topology face);

/// The old points' states extrapolated to the face's corners (one row per corner): the fit of
/// thesis table 2, unclamped, so that a linear field moves exactly.
MatX corner_states(element::Topology face, const std::vector<Vec2>& old_xi, const MatX& old_states);

/// The states of the new points (one row each) from the old points' (one row each) and the
/// corners' (one row per corner, already averaged over the faces at each corner node).
MatX transfer_states(element::Topology face, const std::vector<Vec2>& old_xi,
                     const MatX& old_states, const MatX& corners,
                     const std::vector<Vec2>& new_xi);

}  // namespace kontakt::contact

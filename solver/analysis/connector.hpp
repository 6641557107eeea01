// SPRINGA springs, GAPUNI gaps and T3D2 trusses (model::Connector): the force each exerts on
// its two nodes and its tangent, as ccx 2.20 defines them (manual: SPRINGA, GAPUNI, T3D2,
// *SPRING, *GAP).
#pragma once

#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

/// An axial member's force along its axis at some elongation (final minus initial length), the
/// force's slope against the elongation and the energy stored from zero elongation.
struct AxialForce {
  Real force = 0, slope = 0, energy = 0;
};

struct ConnectorResponse {
  Eigen::Matrix<Real, 6, 1> force = Eigen::Matrix<Real, 6, 1>::Zero();  ///< internal, nodes 1, 2
  Eigen::Matrix<Real, 6, 6> stiffness = Eigen::Matrix<Real, 6, 6>::Zero();
  Real energy = 0;
};

/// The response at nodal displacements u1, u2 of nodes at X1, X2. A spring or a truss follows
/// the line between its nodes under NLGEOM (force F(l - L) along it, tangent
/// F' n n^T + F / l (I - n n^T)) and keeps its initial direction otherwise, a truss with the law
/// of analysis/truss; a gap acts along its fixed direction with ccx's node-to-face linear law on
/// the overclosure -(clearance + n . (u2 - u1)).
ConnectorResponse connector_response(const model::Connector& c, const Vec3& X1, const Vec3& X2,
                                     const Vec3& u1, const Vec3& u2, bool nlgeom);

}  // namespace kontakt::analysis

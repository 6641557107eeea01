// SPRINGA springs and GAPUNI gaps (model::Connector): the force each exerts on its two nodes
// and its tangent, as ccx 2.20 defines them (manual: SPRINGA, GAPUNI, *SPRING, *GAP).
#pragma once

#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

struct ConnectorResponse {
  Eigen::Matrix<Real, 6, 1> force = Eigen::Matrix<Real, 6, 1>::Zero();  ///< internal, nodes 1, 2
  Eigen::Matrix<Real, 6, 6> stiffness = Eigen::Matrix<Real, 6, 6>::Zero();
  Real energy = 0;
};

/// The response at nodal displacements u1, u2 of nodes at X1, X2. A spring follows the line
/// between its nodes under NLGEOM (force F(l - L) along it, tangent F' n n^T + F / l (I - n n^T))
/// and keeps its initial direction otherwise; a gap acts along its fixed direction with ccx's
/// node-to-face linear law on the overclosure -(clearance + n . (u2 - u1)).
ConnectorResponse connector_response(const model::Connector& c, const Vec3& X1, const Vec3& X2,
                                     const Vec3& u1, const Vec3& u2, bool nlgeom);

}  // namespace kontakt::analysis

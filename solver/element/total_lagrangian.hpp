// Geometrically nonlinear (total Lagrangian) solid kernels with St. Venant-Kirchhoff elasticity:
// second Piola-Kirchhoff S = D : (E - alpha dT I) with the Green-Lagrange strain E = (F^T F - I)/2,
// which is what ccx does for *ELASTIC under NLGEOM. Pure functions of nodal data; node-major DOFs.
#pragma once

#include "core/types.hpp"
#include "element/element_type.hpp"
#include "element/solid_linear.hpp"

namespace kontakt::element {

struct NlgeomResult {
  VecX internal_force;   ///< 3n: integral of B_NL^T S over the reference volume
  MatX tangent;          ///< 3n x 3n: material + geometric stiffness (when requested)
  MatX6 cauchy;          ///< n_ip x 6: sigma = F S F^T / det F, Voigt xx yy zz xy xz yz
  MatX6 green_lagrange;  ///< n_ip x 6: total Green-Lagrange strain, tensor shear components
  VecX energy_density;   ///< n_ip: S : (E - E_thermal) / 2 per unit reference volume
};

/// One element at nodal displacements u (n x 3) from reference coordinates X, temperature
/// changes dT at the nodes. C3D8R adds its hourglass stiffness in the reference configuration
/// (small hourglass strains); C3D8I is not available under NLGEOM (SolverError).
void nlgeom_element(ElementType type, const MatX3& X, const LinearElastic& mat, const MatX3& u,
                    const VecX& dT, bool want_tangent, NlgeomResult& out);

}  // namespace kontakt::element

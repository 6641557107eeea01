// Geometrically nonlinear (total Lagrangian) solid kernels with St. Venant-Kirchhoff elasticity,
// what ccx does for *ELASTIC under NLGEOM: second Piola-Kirchhoff S = D : E_m with the
// Green-Lagrange strain E_m of ccx's mechanical deformation gradient F - alpha dT 1
// (solid_kernels.hpp), Cauchy stress F S F^T / det F. Pure functions of nodal data; node-major
// DOFs.
#pragma once

#include "core/types.hpp"
#include "element/element_type.hpp"
#include "element/solid_linear.hpp"

namespace kontakt::element {

struct NlgeomResult {
  VecX internal_force;   ///< 3n: integral of B_NL^T S over the reference volume
  /// 3n x 3n: material + geometric stiffness (when requested). Exact derivative of
  /// internal_force; unsymmetric by O(alpha dT) when a thermal strain is present (the
  /// mechanical deformation gradient is not F), symmetric otherwise.
  MatX tangent;
  MatX6 cauchy;          ///< n_ip x 6: sigma = F S F^T / det F, Voigt xx yy zz xy xz yz
  MatX6 green_lagrange;  ///< n_ip x 6: total Green-Lagrange strain, tensor shear components
  VecX energy_density;   ///< n_ip: S : E_m / 2 per unit reference volume
  MatX3 modes;           ///< C3D8I: incompatible mode amplitudes reached (3 x 3); else empty
};

/// One element at nodal displacements u (n x 3) from reference coordinates X, temperature
/// changes dT at the nodes (empty: none). C3D8R adds its hourglass stiffness in the reference
/// configuration (small hourglass strains); C3D8I condenses its incompatible modes, which enter
/// the deformation gradient, by a local Newton iteration from `modes_start` (the amplitudes of
/// the last converged state; empty: zero). SolverError for an inverted element.
void nlgeom_element(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                    const VecX& dT, bool want_tangent, NlgeomResult& out,
                    const MatX3& modes_start = MatX3());

}  // namespace kontakt::element

// T3D2 trusses (model::Connector::Kind::Truss) as ccx 2.20 solves them: ccx expands a truss
// into a brick of the truss's cross-section with hinged ends, so the bar carries only an axial
// force, from that brick's material law (measured against ccx; tests/peer/README.md).
#pragma once

#include "analysis/connector.hpp"
#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

/// The axial force of truss `c` of initial length `length0` at `elongation`. Linear steps:
/// E A / L e. NLGEOM: the brick's St. Venant-Kirchhoff law with free lateral faces,
/// N = E A lambda E_11 with lambda = l / L and the Green-Lagrange strain E_11 = (lambda^2 - 1) / 2
/// (energy E A L E_11^2 / 2).
AxialForce truss_axial_force(const model::Connector& c, Real length0, Real elongation,
                             bool nlgeom);

/// What ccx prints at each of the 8 integration points of the truss's expanded brick, in global
/// components (xx, yy, zz, xy, xz, yz; tensor shear).
struct TrussPointOutput {
  /// Cauchy stress sigma a a^T along the current axis a: N over the current section (NLGEOM:
  /// the section shrinks by 1 - 2 nu E_11).
  Vec6 stress = Vec6::Zero();
  /// Uniaxial strain along the initial axis A with the lateral contraction:
  /// eps (A A^T - nu (I - A A^T)), eps = e / L (linear) or E_11 (NLGEOM).
  Vec6 strain = Vec6::Zero();
  Real energy_density = 0;  ///< E eps^2 / 2 per unit initial volume
};

/// The output of truss `c` between nodes at X1, X2 displaced by u1, u2.
TrussPointOutput truss_point_output(const model::Connector& c, const Vec3& X1, const Vec3& X2,
                                    const Vec3& u1, const Vec3& u2, bool nlgeom);

}  // namespace kontakt::analysis

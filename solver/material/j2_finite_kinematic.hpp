// Finite-strain J2 plasticity with KINEMATIC or COMBINED hardening: the multiplicative model of
// j2_finite_strain.hpp with a back stress, as ccx 2.20 integrates *PLASTIC, HARDENING=
// KINEMATIC / COMBINED under NLGEOM (its manual's "Incremental (visco)plasticity", Simo 1988).
//
// State in the reference configuration: P = Cp^-1 (stored as (1 - P)/2), the equivalent
// plastic strain alpha, the back stress G (stored as it is, pulled back). With J = sqrt(det C),
// a bar for the isochoric part (x J^-2/3) and dev_C(A) = A - tr(C A)/3 C^-1:
//   trial       s = mu dev_C(P-bar), b = dev_C(G-bar), xi = s - b, |xi| = sqrt(tr(xi C xi C))
//   yield       |xi| <= sqrt(2/3) J R(alpha); R the *CYCLIC HARDENING curve (COMBINED) or the
//               kinematic curve's first stress (KINEMATIC): the tables are true (Cauchy)
//               stresses, J times them Kirchhoff
//   return      with m = mu tr(C P-bar)/3 - tr(C G-bar)/3 and dg the consistency parameter:
//               |xi| - sqrt(2/3) J [R(a) - R(a_n)] - m (2 dg + sqrt(2/3) J [H(a) - H(a_n)] / mu)
//               = 0, a = a_n + sqrt(2/3) dg, H the kinematic curve
//   update      S = K/2 (J^2 - 1) C^-1 + s - c xi,   c = 2 m dg / |xi|
//               P <- P - 3 c/(3 mu) J^2/3 xi,  G <- G + c/(3 mu) J H'(a) J^2/3 xi
// The tangent is exact: the closed form of dg on the segments the return ends on,
// differentiated forward with respect to E.
#pragma once

#include "core/types.hpp"
#include "material/hardening_table.hpp"
#include "material/j2_kinematic.hpp"

namespace kontakt::material {

struct J2FiniteKinematicResult {
  Vec6 stress = Vec6::Zero();   ///< second Piola-Kirchhoff S
  Mat6 tangent = Mat6::Zero();  ///< dS/dE, engineering shear
  J2KinematicState state;       ///< plastic_strain (1 - Cp^-1)/2, alpha, back stress G
  bool yielded = false;
  Real delta_alpha = 0;
};

/// Return mapping from the committed state for the mechanical right Cauchy-Green tensor C.
/// `cyclic` is the *CYCLIC HARDENING curve for COMBINED hardening, nullptr for KINEMATIC.
/// Throws like j2_finite_strain.
J2FiniteKinematicResult j2_finite_kinematic(Real young, Real poisson,
                                            const HardeningTable& kinematic,
                                            const HardeningTable* cyclic,
                                            const J2KinematicState& committed, const Mat3& C);

}  // namespace kontakt::material

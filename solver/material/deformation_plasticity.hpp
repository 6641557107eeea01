// Deformation plasticity (*DEFORMATION PLASTICITY; ccx manual, "Deformation plasticity"): the
// Ramberg-Osgood law as a one-to-one relation between the Cauchy stress sigma and the Eulerian
// (Almansi) strain e = (1 - b^-1) / 2,
//     E e = (1 + nu) sigma - nu tr(sigma) 1 + 3/2 alpha (q / sigma0)^(n-1) dev(sigma),
// q the von Mises stress. Its volumetric part is linear, tr(sigma) = E tr(e) / (1 - 2 nu); its
// deviatoric part is dev(sigma) = E dev(e) / g(q), g(q) = 1 + nu + 3/2 alpha (q/sigma0)^(n-1),
// with q solving q g(q) = E sqrt(3/2) |dev(e)|. Measured against ccx 2.20 on a stretched cube
// (NLGEOM): Cauchy stress and printed strain (ccx prints e for this material) agree.
//
// Pulled back with e = F^-T E F^-1, everything is a function of C = 1 + 2E:
//     S = J F^-1 sigma F^-T = J [ tr(sigma)/3 C^-1 + E/g (C^-1 E C^-1 - tr(e)/3 C^-1) ],
//     tr(e) = E : C^-1,  e : e = tr(E C^-1 E C^-1).
// The tangent dS/dE is exact, by forward-mode automatic differentiation of that expression.
//
// Conventions: Voigt order xx, yy, zz, xy, xz, yz; stresses with tensor components; the tangent
// is dS/dE with E the Green-Lagrange strain in ENGINEERING shear.
#pragma once

#include "core/types.hpp"

namespace kontakt::material {

/// The card's constants: E, nu, sigma0 (yield offset), n (exponent), alpha (yield offset).
struct RambergOsgood {
  Real young = 0;
  Real poisson = 0;
  Real yield = 0;
  Real exponent = 1;
  Real alpha = 0;
};

struct DeformationPlasticityResponse {
  Vec6 stress = Vec6::Zero();    ///< second Piola-Kirchhoff S
  Mat6 tangent = Mat6::Zero();   ///< dS/dE (engineering shear)
};

/// The response at the deformation gradient F (det F > 0; SolverError otherwise, and for
/// constants that give no law: E <= 0, nu outside (-1, 0.5), sigma0 <= 0, n < 1, alpha < 0).
DeformationPlasticityResponse deformation_plasticity(const RambergOsgood& constants, const Mat3& F);

}  // namespace kontakt::material

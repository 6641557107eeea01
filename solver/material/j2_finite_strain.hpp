// Finite-strain isotropic J2 plasticity: the multiplicative model ccx uses for *PLASTIC under
// NLGEOM (manual, "Incremental (visco)plasticity": Simo 1988, F = Fe Fp, hyperelastic isotropic
// response, isochoric plastic flow, von Mises yield), in the reference configuration.
//
// Model (tensors in the reference configuration, C the mechanical right Cauchy-Green tensor,
// J = sqrt(det C), P = Cp^-1 the inverse plastic right Cauchy-Green tensor):
//   trial      b_e = J^-2/3 F P F^T (isochoric), I_e = tr(b_e)/3, s = mu dev(b_e)
//   yield      q = sqrt(3/2) |s| / J  <=  yield(alpha): von Mises of the CAUCHY deviator s/J
//              against the hardening table (true stress over equivalent plastic strain)
//   return     q - 3 (mu I_e / J) d_alpha = yield(alpha_n + d_alpha),  s <- (1 - 3 mu I_e
//              d_alpha / (J q)) s, b_e <- s/mu + I_e 1  (Simo's radial return, flow along s)
//   stress     Kirchhoff tau = K/2 (J^2 - 1) 1 + s, i.e. the stored energy
//              K/2 ((J^2 - 1)/2 - ln J) + mu/2 (tr b_e - 3), and S = F^-1 tau F^-T.
// Checked against ccx 2.20 on homogeneous single-element paths (uniaxial, shear, mixed,
// reversed, several hardening segments): stresses and PEEQ agree to all printed digits.
// The yield test on the Cauchy deviator makes the exact plastic tangent unsymmetric: a
// volume change moves the Kirchhoff deviator of a yielding point (coupling of the order of the
// yield stress, large against the small plastic stiffness along the flow). ccx linearises the
// return as if the yield stress J sigma_y were fixed, which drops that coupling; with that
// tangent (kirchhoff_tangent, nearly symmetric) Kontakt's Newton iterates are ccx's to the
// printed digits (beampiso), and they converge faster than with the symmetric part of the
// exact one.
//
// Conventions: Voigt order xx, yy, zz, xy, xz, yz; stresses and the stored state with tensor
// components; the tangent is dS/dE with E the Green-Lagrange strain in ENGINEERING shear
// (the strain B_NL du of a total-Lagrangian element).
#pragma once

#include "core/types.hpp"
#include "material/hardening_table.hpp"
#include "material/j2_small_strain.hpp"

namespace kontakt::material {

/// J2State read by the finite-strain model: plastic_strain holds (1 - Cp^-1)/2 (what ccx
/// stores as its plastic strain; it tends to the small-strain plastic strain), alpha the
/// equivalent plastic strain. The virgin state is all zero in both models.
struct J2FiniteResult {
  Vec6 stress = Vec6::Zero();   ///< second Piola-Kirchhoff S
  Mat6 tangent = Mat6::Zero();  ///< exact dS/dE (engineering shear), unsymmetric when plastic
  /// dS/dE with the yield stress J sigma_y held fixed (ccx's); = tangent where elastic.
  Mat6 kirchhoff_tangent = Mat6::Zero();
  J2State state;                ///< trial state at the end of the increment
  bool yielded = false;
  Real delta_alpha = 0;
};

/// Return mapping from the committed state for the mechanical right Cauchy-Green tensor C
/// (symmetric, det C > 0). The committed state is not modified. Throws std::invalid_argument
/// on bad material data, SolverError for det C <= 0 or a failed local iteration.
J2FiniteResult j2_finite_strain(Real young, Real poisson, const HardeningTable& table,
                                const J2State& committed, const Mat3& C);

}  // namespace kontakt::material

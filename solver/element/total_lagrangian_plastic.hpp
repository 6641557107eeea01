// Total Lagrangian solid kernels with finite-strain J2 plasticity (material/j2_finite_strain):
// what ccx computes for *PLASTIC under NLGEOM. The material sees ccx's mechanical deformation
// gradient F - alpha dT 1; stresses are reported as Cauchy stresses F S F^T / det F. Pure
// functions; the caller owns the point states (committed on convergence, kept on cutback).
#pragma once

#include <vector>

#include "core/types.hpp"
#include "element/element_state.hpp"
#include "element/element_type.hpp"
#include "element/solid_linear.hpp"
#include "material/hardening_curves.hpp"
#include "material/j2_finite_strain.hpp"

namespace kontakt::element {

/// A *PLASTIC material's hardening: its curves by temperature and rule, and for COMBINED the
/// *CYCLIC HARDENING curves. KINEMATIC and COMBINED integrate material/j2_finite_kinematic.
struct PlasticHardening {
  explicit PlasticHardening(const material::HardeningCurves& isotropic) : curves(&isotropic) {}
  PlasticHardening(const material::HardeningCurves& c, material::HardeningRule r,
                   const material::HardeningCurves* cyclic_curves)
      : curves(&c), rule(r), cyclic(cyclic_curves) {}
  const material::HardeningCurves* curves;
  material::HardeningRule rule = material::HardeningRule::Isotropic;
  const material::HardeningCurves* cyclic = nullptr;
};

/// Which material tangent the element integrates.
enum class PlasticTangent {
  exact,      ///< the derivative of the forces (unsymmetric where points yield)
  kirchhoff,  ///< ccx's: yield stress J sigma_y held fixed (nearly symmetric; ccx's iterates)
};

struct NlgeomPlasticResult {
  VecX internal_force;   ///< 3n: integral of B_NL^T S over the reference volume
  /// 3n x 3n tangent (when requested), as chosen by PlasticTangent; either is unsymmetric by
  /// O(alpha dT) where a thermal strain is present (ccx's mechanical deformation gradient).
  MatX tangent;
  MatX6 cauchy;          ///< n_ip x 6
  MatX6 green_lagrange;  ///< n_ip x 6 total Green-Lagrange strain, tensor shear components
  VecX peeq;             ///< n_ip equivalent plastic strain
  VecX energy_density;   ///< n_ip ccx's ENER: the work S : dE summed over the increments
  ElementState state;    ///< trial state: point states, C3D8I's mode amplitudes
};

/// One element at nodal displacements u (n x 3) from the committed state (n_ip point states;
/// C3D8I: the mode amplitudes its local solve starts from, empty for zero). C3D8R adds its
/// hourglass stiffness (reference configuration, as under SVK) with ccx's modulus for this
/// material, the current C_1111 of the point's tangent; C3D8I condenses its
/// incompatible modes by a local Newton iteration (with the chosen tangent too). SolverError for
/// an inverted element or a failed local iteration. Each point reads the hardening at its
/// temperature.
void nlgeom_plastic_element(ElementType type, const MatX3& X, const ThermoElastic& mat,
                            const PlasticHardening& hardening, const MatX3& u,
                            const VecX& dT, const ElementState& committed, bool want_tangent,
                            NlgeomPlasticResult& out,
                            PlasticTangent tangent = PlasticTangent::kirchhoff);
/// The same for isotropic hardening.
inline void nlgeom_plastic_element(ElementType type, const MatX3& X, const ThermoElastic& mat,
                                   const material::HardeningCurves& hardening, const MatX3& u,
                                   const VecX& dT, const ElementState& committed,
                                   bool want_tangent, NlgeomPlasticResult& out,
                                   PlasticTangent tangent = PlasticTangent::kirchhoff) {
  nlgeom_plastic_element(type, X, mat, PlasticHardening(hardening), u, dT, committed, want_tangent,
                         out, tangent);
}

}  // namespace kontakt::element

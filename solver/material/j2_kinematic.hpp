// Small-strain J2 plasticity with piecewise-linear KINEMATIC (and optionally combined)
// hardening, as ccx's *PLASTIC, HARDENING=KINEMATIC / HARDENING=COMBINED (+ *CYCLIC
// HARDENING) defines it, integrated by radial return with the consistent tangent.
//
// Same conventions as j2_small_strain.hpp: Voigt xx, yy, zz, xy, xz, yz; input strain
// with ENGINEERING shear; plastic strain stored with TENSOR shear; back stress is a
// deviatoric stress (ordinary components); tangent = d(stress)/d(engineering strain).
//
// Model (small-strain reading of ccx incplas.f):
//   f = sqrt(3/2) |dev(sigma) - beta| - R(alpha) <= 0
//   R(alpha) = cyclic.yield(alpha) for COMBINED, kinematic.points[0] stress (constant)
//              for pure KINEMATIC;
//   d beta = sqrt(2/3) d[Hk(alpha)] n, Hk = kinematic.yield, n = unit flow direction,
//   so that in monotonic uniaxial loading sigma = R(alpha) + Hk(alpha) - Hk(0): the
//   kinematic table is the same (von Mises stress, equivalent plastic strain) curve.
#pragma once

#include "material/j2_small_strain.hpp"

namespace kontakt::material {

/// The isotropic model's point state, its back stress in use (deviatoric, stress components).
using J2KinematicState = J2State;

struct J2KinematicResult {
  Vec6 stress = Vec6::Zero();
  Mat6 tangent = Mat6::Zero();  ///< consistent tangent, engineering shear input
  J2KinematicState state;
  bool yielded = false;
  Real delta_alpha = 0;
};

/// Radial return with kinematic hardening table `kinematic`; pass `cyclic` (the
/// *CYCLIC HARDENING isotropic curve) for HARDENING=COMBINED, nullptr for KINEMATIC.
/// Throws like j2_return_map.
J2KinematicResult j2_kinematic_return_map(Real young, Real poisson, const HardeningTable& kinematic,
                                          const HardeningTable* cyclic,
                                          const J2KinematicState& committed, const Vec6& strain,
                                          Real thermal_strain = 0);

}  // namespace kontakt::material

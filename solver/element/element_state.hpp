// What a nonlinear element carries from one converged increment to the next.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "material/j2_small_strain.hpp"

namespace kontakt::element {

/// The strain energy density ccx reports (ENER) for a *PLASTIC material under NLGEOM: the work
/// of the second Piola-Kirchhoff stress on the mechanical Green-Lagrange strain (of F - alpha
/// dT 1), summed over the converged increments by the trapezoidal rule (measured: 66.8, 89.1,
/// 105.1 for one, two and ten increments of the same stretch; 13.5 in a held, heated cube
/// whose total strain does no work), with the stress and strain it was last summed at.
struct PointWork {
  Real density = 0;
  Vec6 stress = Vec6::Zero();  ///< S, tensor components
  Vec6 strain = Vec6::Zero();  ///< mechanical E, tensor components
};

/// Committed (input) or trial (output) state of one element: plastic point states, their
/// work account under NLGEOM, and the amplitudes of C3D8I's incompatible modes, where their
/// local solve starts next time. Plain data; the driver commits the trial state on
/// convergence and keeps the committed one on cutback.
struct ElementState {
  std::vector<material::J2State> points;  ///< plastic elements: one per integration point
  std::vector<PointWork> work;  ///< plastic elements under NLGEOM: one per point; empty = none yet
  MatX3 modes;  ///< C3D8I: 3 x 3, one row per mode (1 - xi^2, 1 - eta^2, 1 - zeta^2); else empty

  /// True for an element that carries nothing (elastic and not C3D8I).
  bool empty() const { return points.empty() && modes.size() == 0; }
};

}  // namespace kontakt::element

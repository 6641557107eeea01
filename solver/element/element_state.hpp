// What a nonlinear element carries from one converged increment to the next.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "material/j2_small_strain.hpp"

namespace kontakt::element {

/// Committed (input) or trial (output) state of one element: plastic point states and the
/// amplitudes of C3D8I's incompatible modes, where their local solve starts next time.
/// Plain data; the driver commits the trial state on convergence and keeps the committed one
/// on cutback.
struct ElementState {
  std::vector<material::J2State> points;  ///< plastic elements: one per integration point
  MatX3 modes;  ///< C3D8I: 3 x 3, one row per mode (1 - xi^2, 1 - eta^2, 1 - zeta^2); else empty

  /// True for an element that carries nothing (elastic and not C3D8I).
  bool empty() const { return points.empty() && modes.size() == 0; }
};

}  // namespace kontakt::element

// ccx's static predictor (ccx-behaviour.md section 3.4): from the second increment of a step
// on, an increment starts from the displacements extrapolated with the average velocity of the
// previous converged increment, (u_end - u_start) / dt, prescribed dofs included. A smooth
// load path then starts each increment near its solution: one Newton iteration fewer per
// increment in plastic or geometrically nonlinear steps, and the same iterates as ccx.
#pragma once

#include "core/types.hpp"

namespace kontakt::nonlinear {

/// One per step: until an increment of the step has converged there is nothing to
/// extrapolate, and the first increment starts from the converged state.
class StaticPredictor {
 public:
  /// The increment from u_start to u_end of size dt converged.
  void converged(const VecX& u_start, const VecX& u_end, Real dt) {
    velocity_ = (u_end - u_start) / dt;
  }

  /// Where an increment of size dt from the converged displacements u starts.
  VecX start(const VecX& u, Real dt) const {
    return velocity_.size() ? VecX(u + dt * velocity_) : u;
  }

 private:
  VecX velocity_;  ///< empty until an increment of the step has converged
};

}  // namespace kontakt::nonlinear

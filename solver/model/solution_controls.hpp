// *CONTROLS parameters for mechanical fields, with ccx 2.20's defaults and names spelled out.
// The ccx symbol of each is given so the manual's "Convergence criteria" page can be followed.
#pragma once

#include "core/types.hpp"

namespace kontakt::model {

struct SolutionControls {
  // *CONTROLS, PARAMETERS=TIME INCREMENTATION, first line
  int divergence_check_from = 4;      ///< I_0: iteration from which divergence is checked
  int log_estimate_from = 8;          ///< I_R: iteration from which the iteration count is estimated
  int loose_residual_after = 9;       ///< I_P: after it, R_p replaces R_n
  int max_iterations = 16;            ///< I_C
  int slow_increment_iterations = 10;  ///< I_L: more than this -> next increment * D_B
  int fast_increment_iterations = 4;   ///< I_G: two increments at most this fast -> * D_D
  int max_cutbacks = 5;               ///< I_A: cutbacks allowed per increment
  // second line
  Real divergence_cutback = 0.25;     ///< D_F
  Real slow_cutback = 0.5;            ///< D_C
  Real slow_next_factor = 0.75;       ///< D_B
  Real growth_factor = 1.5;           ///< D_D
  // *CONTROLS, PARAMETERS=FIELD
  Real residual_tolerance = 0.005;    ///< R_n: largest residual / q~
  Real correction_tolerance = 0.01;   ///< C_n: largest correction / largest change in the step
  Real initial_force_average = 0;     ///< q_0 (0 = unset)
  Real fixed_force_average = 0;       ///< q_u (0 = unset)
  Real loose_residual_tolerance = 0.02;  ///< R_p
  Real zero_flux_ratio = 1e-5;        ///< epsilon: q_bar below eps * q~ is "zero flux"
  Real zero_flux_correction_tolerance = 1e-3;  ///< C_epsilon
  Real linear_residual_ratio = 1e-8;  ///< R_l: residual small enough to skip the correction test
};

}  // namespace kontakt::model

// ccx's convergence and divergence rules for the mechanical field (ccx manual, "Convergence
// criteria"; ../shared/reference/ccx-behaviour.md section 3), one object per step.
//
// Measures per iteration i:  q_bar (average nodal force magnitude over all elements),
// r_max (largest residual over free dofs), c_max (largest Newton correction).
// Carried along the step:    q~ (time average of q_bar over converged increments),
// du_max (largest correction of the whole step), r_{i-1}, r_{i-2} (never reset in a step).
#pragma once

#include <string>

#include "nonlinear/solution_controls.hpp"

namespace kontakt::nonlinear {

struct IterationMeasures {
  Real force_average = 0;   ///< q_bar
  Real max_residual = 0;    ///< r_max
  Real max_correction = 0;  ///< c_max
  bool active_set_changed = false;  ///< an extra constraint (contact) changed its active set
};

struct Verdict {
  enum class Kind { Converged, Iterate, Cutback };
  Kind kind = Kind::Iterate;
  Real cutback_factor = 1;  ///< for Cutback: multiply the increment by this
  std::string reason;       ///< for Cutback: which rule fired, with the numbers
  Real residual_ratio = 0;  ///< r_max / q~, for logs (ccx .cvg "residual force %": * 100)
  Real correction_ratio = 0;  ///< c_max / du_max
};

class Convergence {
 public:
  /// `previous_force_average` is the last q_bar of the previous step (0 if none).
  Convergence(const SolutionControls& controls, Real previous_force_average);

  /// Starts a new increment (after convergence or a cutback).
  void begin_increment();
  /// Judges iteration `iteration` (1-based) of the current increment.
  Verdict check(int iteration, const IterationMeasures& m);
  /// Records that the current increment converged: q~ takes in its last q_bar.
  void commit_increment();

  Real force_reference() const { return q_tilde_; }  ///< q~ of the committed increments
  Real last_force_average() const { return last_q_bar_; }

 private:
  Real current_q_tilde(Real q_bar) const;

  SolutionControls c_;
  Real q_tilde_ = 0;       ///< q~ after the last converged increment
  int n_averaged_ = 0;     ///< j: converged increments that entered q~
  Real q_tilde_trial_ = 0;  ///< q~ including the current iteration's q_bar
  bool trial_averaged_ = false;
  Real last_q_bar_ = 0;
  Real du_max_ = 0;
  Real r1_ = 0, r2_ = 0;   ///< r_{i-1}, r_{i-2}
};

}  // namespace kontakt::nonlinear

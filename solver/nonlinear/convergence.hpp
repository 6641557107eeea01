// ccx's convergence and divergence rules for the mechanical field (ccx manual, "Convergence
// criteria"; ../shared/reference/ccx-behaviour.md section 3), one object per step.
//
// Measures per iteration i:  q_bar (average nodal force magnitude over all elements),
// r_max (largest residual over free dofs), c_max (largest Newton correction).
// Carried along the step:    q~ (time average of q_bar over converged increments),
// du_max (largest correction of the whole step), r_{i-1}, r_{i-2} (never reset in a step).
#pragma once

#include <string>
#include <vector>

#include "model/solution_controls.hpp"

namespace kontakt::nonlinear {

struct IterationMeasures {
  Real force_average = 0;   ///< q_bar
  Real max_residual = 0;    ///< r_max
  Real max_correction = 0;  ///< c_max
  int contact_elements = -1;  ///< active contact elements after the iteration; -1 without contact
};

/// Which contact rules apply (ccx-behaviour.md section 3.5; thesis sections 4.4.2-4.4.3).
enum class ContactCriteria {
  None,
  /// ccx node-to-face: any change of the contact elements blocks convergence and restarts the
  /// divergence and slow-convergence clocks (I_0 >= it + 4, I_R >= it + 8, one more iteration).
  NodeToSurface,
  /// The linear surface-to-surface variants: changes within delcon (1 per mille) count as
  /// none; no logarithmic estimate, the iteration cap is the *CONTROLS CONTACT itf2f; divergence
  /// needs growing residuals (thesis figure 27, condition I) and either a settled contact set
  /// (II) or a repeating pattern of residuals and contact counts (III), here of any period
  /// from 2 to 6 iterations rather than only 2.
  SurfaceToSurface
};

/// Node-to-face contact re-pairs in iterations 2 to 8 of an increment (ccx: iit <= 8), then
/// freezes its pairing.
inline constexpr int kRepairingIterations = 8;

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
  Convergence(const model::SolutionControls& controls, Real previous_force_average);

  /// Contact rules and the 1 per mille tolerance (delcon) for surface-to-surface contact.
  void set_contact_criteria(ContactCriteria criteria, Real delcon);
  /// Starts a new increment (after convergence or a cutback); `contact_elements` is the
  /// active count at its start (-1 without contact).
  void begin_increment(int contact_elements = -1);
  /// Judges iteration `iteration` (1-based) of the current increment.
  Verdict check(int iteration, const IterationMeasures& m);
  /// Records that the current increment converged: q~ takes in its last q_bar.
  void commit_increment();

  Real force_reference() const { return q_tilde_; }  ///< q~ of the committed increments
  Real last_force_average() const { return last_q_bar_; }

 private:
  Real current_q_tilde(Real q_bar) const;
  bool contact_changed(int before, int after) const;
  bool surface_divergence(int iteration, Real r, Real c1q) const;

  model::SolutionControls c_;
  Real q_tilde_ = 0;       ///< q~ after the last converged increment
  int n_averaged_ = 0;     ///< j: converged increments that entered q~
  Real q_tilde_trial_ = 0;  ///< q~ including the current iteration's q_bar
  bool trial_averaged_ = false;
  Real last_q_bar_ = 0;
  Real du_max_ = 0;
  Real r1_ = 0, r2_ = 0;   ///< r_{i-1}, r_{i-2}
  ContactCriteria contact_ = ContactCriteria::None;
  Real delcon_ = 1e-3;
  // per increment
  int divergence_from_ = 0, estimate_from_ = 0, max_iterations_ = 0;  ///< I_0, I_R, I_C in force
  std::vector<Real> residuals_;  ///< r of each iteration of the increment
  std::vector<int> counts_;      ///< contact elements: at the start, then after each iteration
  std::vector<char> changed_;    ///< per iteration: the contact set changed
};

}  // namespace kontakt::nonlinear

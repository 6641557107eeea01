// Pseudo-transient continuation (Kelley and Keyes' PTC with switched evolution relaxation):
// Newton steps on K + s diag|K| instead of K, the shift s following the residual, s_next =
// s * |r| / |r_before|, so it fades as the residual falls and the steps become Newton's. Each
// step is an implicit step of a damped motion, which passes a snap (a tilting point contact
// falling onto the nodes that hold it) that load control and Newton cannot cross, and settles
// where that motion stops: a stable equilibrium, not the saddle a Newton step on an indefinite
// tangent heads for. The residual is the undamped one, so what converges is the equilibrium
// of the unstabilised problem. Pure bookkeeping.
#pragma once

#include "core/types.hpp"

namespace kontakt::nonlinear {

class PseudoTransient {
 public:
  /// The first shift, relative to each diagonal: a step moves a free mode by about its load
  /// over a hundredth of the stiffness around it.
  static constexpr Real kFirstShift = 1e-2;
  /// Below this the shift changes a step by less than round-off: a Newton step.
  static constexpr Real kNewtonShift = 1e-12;
  /// A shift this large leaves the steps too short to get anywhere.
  static constexpr Real kMaxShift = 1e4;
  /// The most a shift changes per step (either way): one contact event must not make a step
  /// a hundred times longer or shorter than the last.
  static constexpr Real kMaxChange = 10;
  /// Steps of one continuation.
  static constexpr int kMaxSteps = 150;
  /// Steps without a new smallest residual after which the motion has settled somewhere that
  /// is not an equilibrium (contact chattering between two states): the snaps it is for set a
  /// new smallest residual within 5 steps (22 continuations: coarse punches, gap patches).
  static constexpr int kMaxStall = 30;

  bool active() const { return active_; }
  /// The shift of the next step (0: Newton).
  Real shift() const { return shift_ < kNewtonShift ? 0 : shift_; }
  int steps() const { return steps_; }
  /// Energy the continuation absorbed: what the springs held where it started (leaving them
  /// takes it out) plus what the damping took out of the motion, the sum over steps of
  /// dx . s diag|K| dx.
  Real absorbed_energy() const { return held_energy_ + dissipated_; }

  /// Starts a continuation (its first step has the first shift) from a state where
  /// stabilisation springs held `held_energy`.
  void start(Real held_energy);
  void stop() { active_ = false; }
  /// The shifted tangent was indefinite (the motion's own stiffness is negative beyond what
  /// the shift covers): shift more. False when the shift cannot grow any further.
  bool raise();
  /// A step with the shift of shift() moved the solution by a damping energy `dissipated`
  /// and left the residual norm `residual`.
  void stepped(Real residual, Real dissipated);
  /// The continuation used up its steps, or kMaxStall of them found no smaller residual.
  bool exhausted() const { return steps_ >= kMaxSteps || steps_since_best_ >= kMaxStall; }

 private:
  bool active_ = false;
  Real shift_ = 0;
  Real residual_ = 0;  ///< norm before the next step
  int steps_ = 0;
  Real best_residual_ = 0;  ///< smallest residual since start()
  int steps_since_best_ = 0;
  Real held_energy_ = 0;
  Real dissipated_ = 0;
};

}  // namespace kontakt::nonlinear

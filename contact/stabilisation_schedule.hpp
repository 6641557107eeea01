// The continuation of contact stabilisation within one increment (contact/README.md, "Bodies
// that only contact holds"). Engaged when the tangent of an increment is singular because a
// body held only by contact does not touch yet (or when an attempt with contact failed): normal
// springs (ContactSystem::set_stabilisation) of a factor times the penalty then hold the body,
// and the factor steps down per converged level, each level starting from the last one's
// solution: while nothing touches, by as much as moves the bodies about 1.2 times the
// smallest open gap further (so they land on contact instead of far through it), once
// something touches by 10. When contact carries nearly all the load the springs are released
// and the increment converges without them; if that release fails, the levels go on down
// (from the last stabilised solution) until the springs carry a negligible share of the normal
// force, which leaves the solution of the unstabilised problem to within that share, or until
// the weakest level, which is released once more before the increment fails. A level
// that fails is retried from the last converged one with half the step in log(factor) (a
// point contact that tilts as the springs weaken must reach its next node gradually, not jump
// past it); each converged level doubles the step again, up to the factor of 10.
// Pure bookkeeping.
#pragma once

#include <optional>

#include "core/types.hpp"

namespace kontakt::contact {

class StabilisationSchedule {
 public:
  static constexpr Real kFirstFactor = 1e-2;  ///< spring stiffness / penalty, first level
  static constexpr Real kLevelRatio = 0.1;    ///< between levels once something touches
  /// Bounds of the ratio between levels while nothing touches.
  static constexpr Real kMinApproachRatio = 1e-3, kMaxApproachRatio = 0.5;
  /// Weaker springs than this fraction of the penalty no longer hold a body numerically (the
  /// pivot of its free motion drops to round-off against the element stiffness).
  static constexpr Real kMinFactor = 1e-9;
  /// A converged level whose springs carry at most this share of the normal force is
  /// released (Newton without springs from its solution).
  static constexpr Real kReleaseShare = 1e-2;
  /// ... and at most this share counts as released already: the springs change the answer
  /// by less than this relative amount, far below the residual tolerance of convergence.
  static constexpr Real kNegligibleShare = 1e-7;
  /// A failed level is not retried once its ratio to the last converged level exceeds this:
  /// levels closer than that change the springs too little to cross anything new.
  static constexpr Real kMaxRetryRatio = 0.8;

  enum class Next {
    Continue,            ///< iterate on at factor() from the current solution
    RestoreAndContinue,  ///< go back to the last stabilised solution, iterate on at factor()
    Done,                ///< the increment has converged (without springs, or negligible ones)
    GiveUp,              ///< no level left: the increment fails
  };

  bool engaged() const { return factor_ > 0; }
  bool releasing() const { return releasing_; }
  /// The spring factor now: 0 when not engaged or releasing.
  Real factor() const { return releasing_ ? 0 : factor_; }

  /// Starts at the first level (again, for a retry of the increment).
  void engage();
  /// Off, for the next increment.
  void disengage();

  /// The current level converged; on a stabilised level the springs held `energy` and carried
  /// `share` of the normal force. `approach` (ContactSystem::approach_ratio) is the factor
  /// ratio that lands the bodies on contact, when nothing touches.
  Next converged(Real energy, Real share, std::optional<Real> approach);
  /// The current level, or the release, failed to converge: RestoreAndContinue goes back to
  /// the last converged level's solution with a milder factor (or springs one level weaker
  /// after a failed release); GiveUp when no level converged yet, the step is exhausted or
  /// the release from the weakest level failed.
  Next failed();

  /// The energy the springs held when they were released (that of the last converged level):
  /// what the release took out of the stabilised solution on its way to the unstabilised one,
  /// the measure of how far the path went from an unstabilised one (Abaqus reports the like
  /// as ALLSD). Earlier levels hand their solutions on through the continuation.
  Real absorbed_energy() const { return released_energy_; }
  /// The spring factor of the last converged level (0: none converged in this attempt).
  Real held_factor() const { return held_factor_; }

 private:
  Real factor_ = 0;              ///< 0: not engaged
  Real held_factor_ = 0;         ///< of the last converged level (0: none yet)
  Real step_ = kLevelRatio;      ///< between touching levels, halved in log per failed level
  bool releasing_ = false;
  bool release_failed_ = false;  ///< a release failed in this attempt: step down to negligible
  bool last_release_tried_ = false;  ///< the release from the weakest level (once an attempt)
  Real released_energy_ = 0;     ///< spring energy of the last converged level
};

}  // namespace kontakt::contact

// Automatic incrementation of a static step as ccx does it: the next increment grows after
// fast convergence, shrinks after slow convergence, is cut back on divergence, and the step
// fails below the minimum increment or beyond the cutback or increment limits.
#pragma once

#include <string>
#include <vector>

#include "model/solution_controls.hpp"

namespace kontakt::nonlinear {

struct StepTiming {
  Real period = 1;            ///< step time
  Real initial_increment = 1;
  Real min_increment = 0;     ///< 0 = default
  Real max_increment = 0;     ///< 0 = default (1e30)
  bool direct = false;        ///< *STATIC, DIRECT: fixed increments, no cutbacks
  int max_increments = 100;   ///< *STEP, INC=
  /// *TIME POINTS in force (step times, ascending): an increment that would pass the next one
  /// ends on it instead (ccx); the size the next increment grows from is not clipped by it.
  std::vector<Real> time_points{};
};

class IncrementControl {
 public:
  IncrementControl(const StepTiming& timing, const model::SolutionControls& controls);

  Real step_time() const { return time_; }      ///< time reached by converged increments
  Real increment() const { return dt_; }        ///< size of the increment being attempted
  int increment_number() const { return n_increments_ + 1; }  ///< 1-based, being attempted
  int attempt() const { return n_cutbacks_ + 1; }
  bool finished() const;
  Real min_increment() const { return dt_min_; }
  Real max_increment() const { return dt_max_; }
  /// The attempted increment was shortened (or stretched by less than 1e-6 of the step) to end
  /// on a time point: ccx writes its output there.
  bool ends_at_time_point() const { return at_time_point_; }

  /// The attempted increment converged in `iterations`; sets up the next one. Throws
  /// NonConvergence when the shrunken next increment falls below the minimum or the
  /// step needs more increments than allowed.
  void converged(int iterations);
  /// The attempted increment failed; retries it smaller. Throws NonConvergence (naming
  /// `reason`) for DIRECT steps, past the cutback limit, or below the minimum increment.
  void cut_back(Real factor, const std::string& reason);

 private:
  void clip_to_step_end();
  void clip_to_time_point();

  StepTiming t_;
  model::SolutionControls c_;
  Real dt_min_ = 0, dt_max_ = 0;
  Real time_ = 0, dt_ = 0;
  /// The size growth and shrinkage act on: dt_ before a time point shortened it (ccx's
  /// dthetaref); every other limit and a cutback set both.
  Real dt_ref_ = 0;
  std::size_t next_point_ = 0;  ///< first time point after time_
  bool at_time_point_ = false;
  int n_increments_ = 0, n_cutbacks_ = 0;
  bool previous_was_fast_ = false;
};

}  // namespace kontakt::nonlinear

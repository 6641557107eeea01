// Nonlinear static analysis: steps -> increments -> Newton iterations, with ccx's convergence
// criteria and automatic incrementation (nonlinear/convergence.hpp, increment_control.hpp).
// Used for steps with NLGEOM, plasticity or contact; the linear driver keeps models that need
// no iteration.
#pragma once

#include <atomic>
#include <optional>

#include "analysis/events.hpp"
#include "analysis/linear_static.hpp"
#include "model/solution_controls.hpp"

namespace kontakt::analysis {

/// When contact stabilisation (contact/stabilisation_schedule.hpp) engages: when an increment
/// needs it (a singular tangent with contact, or the retry of a failed attempt), in every
/// increment (to show that it leaves the unstabilised answer), or never.
enum class ContactStabilisation { Auto, Always, Never };

struct NonlinearOptions {
  int threads = 0;                                ///< 0 = all cores
  const std::atomic<bool>* cancel = nullptr;      ///< polled once per iteration
  /// Overrides every step's *CONTROLS when set (tests, expert use).
  std::optional<model::SolutionControls> controls;
  ContactStabilisation contact_stabilisation = ContactStabilisation::Auto;
  /// Whether a linear variant's increment whose frozen gaps drifted from fresh projections is
  /// redone smaller (contact/README.md); off only to measure what the check costs and saves.
  bool drift_check = true;
};

/// Solves every step. Throws NonConvergence when an increment cannot be completed (after the
/// frames of every converged increment were handed to `frames`), Cancelled, SolverError.
void run_nonlinear_static(const model::Model& model, const NonlinearOptions& options,
                          FrameSink& frames, EventSink& events);

/// True when some step of the model needs Newton iterations (NLGEOM, *PLASTIC, contact,
/// springs and gaps).
bool needs_newton(const model::Model& model);

}  // namespace kontakt::analysis

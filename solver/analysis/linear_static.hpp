// Linear static analysis: one factorisation, one solve per step, no Newton loop.
// Chosen by the plan when a model has no NLGEOM, no plasticity and no contact.
#pragma once

#include <atomic>
#include <stdexcept>

#include "analysis/events.hpp"
#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::analysis {

struct RunOptions {
  int threads = 0;                            ///< 0 = all cores
  /// Polled at every step and between assembly, factorisation and output: a factorisation
  /// itself runs to its end.
  const std::atomic<bool>* cancel = nullptr;
};

/// The run was cancelled through the options' flag; the frames of finished steps (increments)
/// are kept.
class Cancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Receives each step's converged result.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void on_frame(const model::Step& step, const output::Frame& frame) = 0;
};

/// Solves every step of a linear model. Throws InputError for a model this analysis cannot run
/// (the message names the step), SolverError for singular systems (naming the dofs or the
/// unsupported body where it can), Cancelled.
void run_linear_static(const model::Model& model, const RunOptions& options, FrameSink& frames,
                       EventSink& events);

}  // namespace kontakt::analysis

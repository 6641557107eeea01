// A worker thread's watch over one job's run (an Execution: a local process, a Slurm job):
// every event the run reports goes to the job's sink (the store and the SSE streams) as it
// arrives; a stop request or the wall-time limit stops it gracefully (SIGTERM: the solver stops
// at its next iteration and finishes its files) and, if it is still there after the grace
// period, hard (SIGKILL: a factorisation cannot be interrupted otherwise). The hard stop waits
// while a result frame is being written (a `*.partial` file in the work folder), so the
// results of converged increments stay whole. A drain leaves a run that outlives the daemon
// (Slurm) running: the supervisor lets go of it, and the next daemon attaches to it.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "analysis/events.hpp"
#include "server/child_process.hpp"
#include "server/execution.hpp"

namespace kontakt::server {

/// Why a running job's process is being stopped.
enum class StopCause { None, Request, TimeLimit, Drain };

/// A running job's stop request, raised from other threads (cancel, drain) and seen at once by
/// the supervisor, which polls its descriptor.
class StopSignal {
 public:
  StopSignal();
  ~StopSignal();
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  /// Records `cause` unless a cause was recorded before, and wakes the supervisor.
  void request(StopCause cause);
  StopCause cause() const { return cause_.load(); }
  int wake_fd() const { return event_fd_; }

 private:
  std::atomic<StopCause> cause_{StopCause::None};
  int event_fd_ = -1;
};

struct SupervisionSettings {
  double time_limit = 0;                          ///< wall-time seconds; 0 = none
  std::chrono::milliseconds grace{2000};          ///< SIGTERM -> SIGKILL
  std::chrono::milliseconds max_frame_write{30000};  ///< the longest a SIGKILL waits for a frame
};

/// How a job process ended and what the supervisor saw and did.
struct ProcessEnd {
  ExitStatus exit;
  StopCause cause = StopCause::None;
  bool killed = false;                   ///< the supervisor stopped it hard (SIGKILL)
  bool detached = false;                 ///< a drain let go of a run that goes on (Slurm)
  std::optional<ExecutorFailure> failure;  ///< the executor's verdict when `exit` is not the run's
  std::optional<analysis::Event> done;   ///< the last `done` event reported
  std::size_t n_events = 0;
  std::size_t n_bad_reports = 0;         ///< lines that were not events, overlong or cut off
  std::optional<std::string> sink_error; ///< the first event the sink could not take
  double seconds = 0;                    ///< wall time from start to end
};

/// Supervises `process` until it ends (see the file comment). The stop request is read from
/// `stop`; a time limit reached records StopCause::TimeLimit in it.
ProcessEnd supervise_job(Execution& process, analysis::EventSink& sink, StopSignal& stop,
                         const SupervisionSettings& settings,
                         const std::filesystem::path& work_dir);

/// True while a result file is being written in `dir` (a `*.partial` file exists).
bool writing_results(const std::filesystem::path& dir);

}  // namespace kontakt::server

// One job handed to an executor, running or waiting to run there: the daemon's handle on it.
// The supervisor (job_supervisor.hpp) polls it for the events the run reports and for its end,
// and stops it gracefully (the solver stops at its next iteration and finishes its files) or
// hard. A local job process is one (worker_process.hpp), a Slurm batch job another
// (slurm_executor.hpp).
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

#include "server/child_process.hpp"
#include "server/line_splitter.hpp"

namespace kontakt::server {

/// A run that ended without an exit status of its own: the executor lost it or refused it
/// (Slurm killed it, it never started, sbatch failed). The verdict is this reason code and
/// message (the executor's own words), unless the daemon itself asked the run to stop.
struct ExecutorFailure {
  std::string reason;   ///< a ReasonCode: time_limit, memory_limit, worker_lost, ...
  std::string message;
};

class Execution {
 public:
  virtual ~Execution() = default;
  /// Waits up to `timeout` for reports, the run's end or (when >= 0) `wake_fd` becoming
  /// readable; hands every complete report line to `on_line`. Returns the exit status once
  /// the run has ended and everything it reported was read (see failure()).
  virtual std::optional<ExitStatus> poll(std::chrono::milliseconds timeout,
                                         const LineHandler& on_line, int wake_fd) = 0;
  /// Graceful: SIGTERM to the solver; otherwise kill it. False when the run has ended.
  virtual bool stop(bool graceful) = 0;
  /// Report lines dropped: overlong, or cut off by the run's end.
  virtual std::size_t n_dropped_lines() const = 0;
  /// Once poll() returned a status: set when that status is not the run's own.
  virtual std::optional<ExecutorFailure> failure() const { return std::nullopt; }
  /// The run goes on without the daemon: a drain leaves it running, a restart attaches to it.
  virtual bool outlives_daemon() const { return false; }
};

}  // namespace kontakt::server

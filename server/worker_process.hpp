// A worker process (`EXE job-worker standby`) and its two channels: a request socket (its
// stdin) and the report pipe (its descriptor 3). It is started ahead of need: the dynamic
// loading of the solver's ~50 libraries (tens of ms of CPU) happens while it waits, and
// start() hands it its work when there is some. A run is its last piece of work; a check
// process takes one deck after the other until its channel closes. Deck checks and job runs
// both go through it; a job run is the local executor's Execution.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>

#include "server/child_process.hpp"
#include "server/execution.hpp"
#include "server/line_splitter.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server {

class WorkerProcess final : public Execution {
 public:
  /// Starts `exe job-worker standby` for work with `threads` solver threads (its BLAS starts
  /// that many, no more); throws std::system_error when it cannot.
  WorkerProcess(const std::filesystem::path& exe, int threads);
  ~WorkerProcess() override;  ///< kills a process still running (ChildProcess)
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  /// Gives the waiting process its work. False when it is gone (killed while it waited).
  bool start(const worker::Args& args);
  /// Lets a check process go: it ends once its channel is closed.
  void end_requests();
  /// Still running (for a standby process: still waiting).
  bool alive() { return !child_->try_wait(); }

  /// Waits up to `timeout` for reports, the process's end or (when >= 0) `wake_fd` becoming
  /// readable; hands every complete report line to `on_line`. Returns the exit status once the
  /// process has ended and everything it reported was read.
  std::optional<ExitStatus> poll(std::chrono::milliseconds timeout, const LineHandler& on_line,
                                 int wake_fd = -1) override;
  /// Sends a signal; false when the process has ended.
  bool send(int signal) { return child_->send(signal); }
  /// SIGTERM (graceful) or SIGKILL.
  bool stop(bool graceful) override;
  /// Report lines dropped: overlong, or cut off by the process's end.
  std::size_t n_dropped_lines() const override { return lines_.n_dropped(); }

 private:
  int report_ = -1;   ///< our end of the report pipe; -1 once it reached end of file
  int request_ = -1;  ///< our end of the request socket; -1 once closed
  std::optional<ChildProcess> child_;
  LineSplitter lines_;
};

}  // namespace kontakt::server

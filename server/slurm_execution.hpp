// One job's Slurm batch job, as the supervisor sees it (slurm_executor.hpp says how it is
// made): poll() tails the run's events.ndjson and ends with its outcome.json; when Slurm says
// the job has ended and no outcome file comes within the wait, Slurm's own record (state,
// reason, exit code, the end of slurm-N.out) becomes the run's failure. stop() is scancel.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "server/execution.hpp"
#include "server/line_splitter.hpp"
#include "server/slurm_protocol.hpp"
#include "server/slurm_queue.hpp"

namespace kontakt::server {

class SlurmExecution final : public Execution {
 public:
  using Clock = std::chrono::steady_clock;
  /// Slurm's record of a job no longer in squeue (scontrol, jobcomp).
  using FinishedState = std::function<std::optional<slurm::JobState>(const std::string&)>;

  /// `known_since`: the job was in Slurm from then on (squeue runs before it may miss it);
  /// `skip_events`: the first events of the file, stored already (a re-attached run).
  SlurmExecution(std::string slurm_id, slurm::RunFiles files, SlurmQueue& queue,
                 FinishedState finished_state, std::chrono::milliseconds outcome_wait,
                 Clock::time_point known_since, std::size_t skip_events);
  ~SlurmExecution() override;
  SlurmExecution(const SlurmExecution&) = delete;
  SlurmExecution& operator=(const SlurmExecution&) = delete;

  std::optional<ExitStatus> poll(std::chrono::milliseconds timeout, const LineHandler& on_line,
                                 int wake_fd) override;
  /// Graceful: `scancel --signal=TERM --batch` (a plain scancel for a job not running, e.g.
  /// pending); otherwise a plain scancel (Slurm's TERM, then KILL after its KillWait).
  bool stop(bool graceful) override;
  std::size_t n_dropped_lines() const override { return lines_.n_dropped(); }
  std::optional<ExecutorFailure> failure() const override { return failure_; }
  bool outlives_daemon() const override { return true; }

 private:
  /// Reads the events appended since the last call.
  void read_events(const LineHandler& on_line);
  /// The run's end from its outcome file; nullopt while there is none.
  std::optional<ExitStatus> outcome();
  /// Slurm's word on the job when it has ended without an outcome; nullopt while it has not.
  std::optional<ExitStatus> slurm_end();
  /// The job's state in a fresh squeue (RUNNING, PENDING, ...); empty when unknown.
  std::string state_now() const;

  const std::string slurm_id_;
  const slurm::RunFiles files_;
  SlurmQueue& queue_;
  const FinishedState finished_state_;
  const std::chrono::milliseconds outcome_wait_;
  const Clock::time_point known_since_;
  std::size_t skip_events_;
  int events_fd_ = -1;
  LineSplitter lines_;
  std::optional<Clock::time_point> seen_ended_;  ///< when Slurm first said it had ended
  std::optional<slurm::JobState> ended_state_;   ///< what squeue said then (none: not listed)
  std::optional<ExecutorFailure> failure_;
  bool over_ = false;
};

}  // namespace kontakt::server

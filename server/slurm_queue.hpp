// kontaktd's view of Slurm's queue: one `squeue --me --states=all` for every job the daemon
// watches, at most once per interval however many jobs ask (a thread per running job polls
// its job; a call per job would load slurmctld with hundreds of requests a second). A failed
// squeue (controller down, timeout) answers "unknown": nothing is concluded from it.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "server/slurm_protocol.hpp"

namespace kontakt::server {

class SlurmQueue {
 public:
  using Clock = std::chrono::steady_clock;
  /// The output of `squeue --me --noheader --states=all --format=kSqueueFormat`; nullopt when
  /// it failed.
  using Squeue = std::function<std::optional<std::string>()>;
  /// `squeue`: the real one unless a test gives its own.
  explicit SlurmQueue(std::chrono::milliseconds interval, Squeue squeue = run_squeue);
  static std::optional<std::string> run_squeue();

  struct Answer {
    enum class Kind { Unknown, Listed, Absent } kind = Kind::Unknown;
    slurm::JobState state;  ///< when Listed
  };
  /// Job `slurm_id` as of a squeue run that started after `since` (one is run when the last
  /// is older than the interval); Unknown when there is none yet or squeue failed.
  Answer look_up(const std::string& slurm_id, Clock::time_point since);
  /// The Slurm job whose --comment is kontaktd's `job_id` (a fresh squeue); nullopt when none
  /// is listed or squeue failed.
  std::optional<std::string> find_by_comment(const std::string& job_id);

 private:
  /// Runs squeue when the snapshot is older than the interval; false when it failed.
  void refresh_if_old();

  const std::chrono::milliseconds interval_;
  const Squeue squeue_;
  std::mutex mutex_;
  std::map<std::string, slurm::JobState> jobs_;
  std::optional<Clock::time_point> taken_;  ///< when the last good squeue started
  Clock::time_point tried_{};               ///< when the last squeue started
};

}  // namespace kontakt::server

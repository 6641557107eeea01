// The worker pool: N threads that claim queued jobs from the store and hand each to the
// executor (executor.hpp: a worker process of the daemon, or a Slurm batch job), at most N
// at once. The thread relays the run's events into the store, stops it on cancel, at the
// wall-time limit or on drain (job_supervisor.hpp), publishes its files and records the
// verdict (job_outcome.hpp). A run that crashes fails its job, never the daemon. drain() stops
// claiming, lets running jobs finish for a grace period and requeues the rest; runs that
// outlive the daemon (Slurm) are left running, and adopt() takes them up again after a restart.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "server/executor.hpp"
#include "server/handlers/api_context.hpp"
#include "server/job_files.hpp"
#include "server/job_outcome.hpp"
#include "server/job_store.hpp"
#include "server/job_supervisor.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server {

struct WorkerSettings {
  int workers = 2;             ///< jobs handed to the executor at once
  int threads_per_job = 1;
  double job_time_limit = 0;   ///< seconds of wall time per run; 0 = none
  int max_attempts = 3;        ///< runs of a job whose process is killed from outside
  worker::Limits limits;       ///< per job process
  std::chrono::milliseconds kill_grace{2000};  ///< SIGTERM -> SIGKILL of a stopped job
};

class WorkerPool final : public handlers::JobControl {
 public:
  WorkerPool(JobStore& store, const JobFiles& files, Executor& executor, WorkerSettings settings);
  ~WorkerPool() override;  ///< drains without grace if still running
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void start();
  /// Before start(): running and canceling jobs of a previous daemon whose runs may go on in
  /// the executor. Each is supervised again (ahead of queued jobs) or, when the executor never
  /// had it, queued again.
  void adopt(std::vector<JobRecord> jobs);
  /// Stops claiming jobs, waits up to `grace` for running ones, stops and requeues the rest.
  void drain(std::chrono::milliseconds grace);

  void job_queued() override;
  void cancel_running(const std::string& id) override;
  void cancel_unclaimed(const std::string& id) override;
  int n_workers() const override { return settings_.workers; }
  int n_busy() const override;

 private:
  void worker_loop();
  /// The next adopted job, else the oldest queued one (now running); nullopt when none.
  std::optional<std::pair<JobRecord, bool>> next_job();
  /// Runs the job through the executor (`adopted`: attaches to its run instead).
  void run(const JobRecord& job, bool adopted);
  JobLaunch launch_of(const JobRecord& job) const;
  /// The sweep of a row on its first run, for an executor that starts sweeps whole.
  std::shared_ptr<const SweepLaunch> sweep_launch_of(const JobRecord& job);
  /// Records the verdict: finish (publishing the files), requeue or retry.
  void conclude(const JobRecord& job, const JobVerdict& verdict, const JobSummary& summary);

  JobStore& store_;
  const JobFiles& files_;
  Executor& executor_;
  const WorkerSettings settings_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  int pending_wakeups_ = 0;  ///< job_queued() calls not yet seen by a worker
  std::map<std::string, std::shared_ptr<StopSignal>> running_;
  std::deque<JobRecord> adopted_;  ///< not yet supervised again
  std::vector<std::thread> threads_;
};

}  // namespace kontakt::server

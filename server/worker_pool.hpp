// The worker pool: N threads that claim queued jobs from the store and run them through
// app::run_job, so solver work never runs on the HTTP threads. A watchdog raises a job's cancel
// flag at its wall-time limit; drain() stops claiming, lets running jobs finish for a grace
// period and requeues the rest.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "server/handlers/api_context.hpp"
#include "server/job_files.hpp"
#include "server/job_store.hpp"

namespace kontakt::server {

struct WorkerSettings {
  int workers = 2;
  int threads_per_job = 1;
  double job_time_limit = 0;  ///< seconds of wall time per run; 0 = none
};

class WorkerPool final : public handlers::JobControl {
 public:
  WorkerPool(JobStore& store, const JobFiles& files, WorkerSettings settings);
  ~WorkerPool() override;  ///< drains without grace if still running
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void start();
  /// Stops claiming jobs, waits up to `grace` for running ones, cancels and requeues the rest.
  void drain(std::chrono::milliseconds grace);

  void job_queued() override;
  void cancel_running(const std::string& id) override;
  int n_workers() const override { return settings_.workers; }
  int n_busy() const override;

 private:
  /// Why a running job's cancel flag was raised.
  enum class StopCause { None, Request, TimeLimit, Drain };
  struct RunningJob {
    std::atomic<bool> cancel{false};
    StopCause cause = StopCause::None;  ///< guarded by mutex_
    std::chrono::steady_clock::time_point started;
  };

  void worker_loop();
  void watchdog_loop();
  void run(const JobRecord& job);
  void stop(RunningJob& job, StopCause cause);  // caller holds mutex_

  JobStore& store_;
  const JobFiles& files_;
  const WorkerSettings settings_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  int pending_wakeups_ = 0;  ///< job_queued() calls not yet seen by a worker
  std::map<std::string, std::shared_ptr<RunningJob>> running_;
  std::vector<std::thread> threads_;
};

}  // namespace kontakt::server

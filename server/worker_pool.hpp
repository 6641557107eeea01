// The worker pool: N threads that claim queued jobs from the store. Each job runs in a worker
// process of its own (job_worker.hpp) under the resource limits; a spawner thread keeps N + 1
// processes loaded and waiting, so a job does not wait for its process's libraries. The
// thread relays the process's events into the store, stops it on cancel, at the wall-time
// limit or on drain (job_supervisor.hpp), publishes its files and records the verdict
// (job_outcome.hpp). A process that crashes fails its job, never the daemon. drain() stops
// claiming, lets running jobs finish for a grace period and requeues the rest.
#pragma once

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "server/handlers/api_context.hpp"
#include "server/job_files.hpp"
#include "server/job_outcome.hpp"
#include "server/job_store.hpp"
#include "server/job_supervisor.hpp"
#include "server/worker_process.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server {

struct WorkerSettings {
  int workers = 2;
  int threads_per_job = 1;
  double job_time_limit = 0;   ///< seconds of wall time per run; 0 = none
  int max_attempts = 3;        ///< runs of a job whose process is killed from outside
  worker::Limits limits;       ///< per job process
  std::chrono::milliseconds kill_grace{2000};  ///< SIGTERM -> SIGKILL of a stopped job
  std::filesystem::path worker_exe;  ///< started as `worker_exe job-worker standby ...`
};

class WorkerPool final : public handlers::JobControl {
 public:
  WorkerPool(JobStore& store, const JobFiles& files, WorkerSettings settings);
  ~WorkerPool() override;  ///< drains without grace if still running
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void start();
  /// Stops claiming jobs, waits up to `grace` for running ones, stops and requeues the rest.
  void drain(std::chrono::milliseconds grace);

  void job_queued() override;
  void cancel_running(const std::string& id) override;
  int n_workers() const override { return settings_.workers; }
  int n_busy() const override;

 private:
  void worker_loop();
  /// Starts processes while fewer than workers + 1 wait. The processes die with the thread
  /// that started them (PR_SET_PDEATHSIG): this one outlives every job.
  void spawner_loop();
  /// A waiting process, or one started here (for this thread's job) when none waits.
  std::unique_ptr<WorkerProcess> take_process();
  void run(const JobRecord& job);
  /// Records the verdict: finish (publishing the files), requeue or retry.
  void conclude(const JobRecord& job, const JobVerdict& verdict, const JobSummary& summary);

  JobStore& store_;
  const JobFiles& files_;
  const WorkerSettings settings_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  int pending_wakeups_ = 0;  ///< job_queued() calls not yet seen by a worker
  std::map<std::string, std::shared_ptr<StopSignal>> running_;
  std::vector<std::unique_ptr<WorkerProcess>> waiting_;  ///< loaded, waiting for a job
  std::condition_variable spawn_;   ///< a process was taken, or the spawner is retired
  bool spawner_retired_ = false;    ///< set once every worker thread has ended
  std::vector<std::thread> threads_;
  std::thread spawner_;
};

}  // namespace kontakt::server

// The default executor: each job runs in a worker process of the daemon (worker_process.hpp)
// under the per-process limits. A spawner thread keeps `keep_waiting` processes loaded and
// waiting, so a job does not wait for its process's ~50 libraries. Processes die with the
// thread that started them (PR_SET_PDEATHSIG): the spawner outlives every job, and shutdown()
// ends it only after the last job's supervision.
#pragma once

#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "server/executor.hpp"
#include "server/worker_process.hpp"

namespace kontakt::server {

class LocalExecutor final : public Executor {
 public:
  /// Processes run `worker_exe job-worker standby` with `threads_per_job` BLAS threads.
  LocalExecutor(std::filesystem::path worker_exe, int threads_per_job, std::size_t keep_waiting);
  ~LocalExecutor() override;  ///< shutdown()
  LocalExecutor(const LocalExecutor&) = delete;
  LocalExecutor& operator=(const LocalExecutor&) = delete;

  void start() override;
  void shutdown() override;
  std::unique_ptr<Execution> submit(const JobLaunch& job) override;
  /// A job process dies with the daemon: there is never one to attach to.
  std::unique_ptr<Execution> attach(const JobLaunch&) override { return nullptr; }
  bool outlives_daemon() const override { return false; }

 private:
  /// The one place a job process is started.
  std::unique_ptr<WorkerProcess> new_process() const;
  /// A waiting process, or one started here (for the calling thread's job) when none waits.
  std::unique_ptr<WorkerProcess> take_process();
  /// Starts processes while fewer than keep_waiting_ wait.
  void spawner_loop();

  const std::filesystem::path worker_exe_;
  const int threads_per_job_;
  const std::size_t keep_waiting_;
  std::mutex mutex_;
  std::condition_variable spawn_;  ///< a process was taken, or the spawner is retired
  bool retired_ = false;
  std::vector<std::unique_ptr<WorkerProcess>> waiting_;
  std::thread spawner_;
};

}  // namespace kontakt::server

#include "server/local_executor.hpp"

#include <cstdio>
#include <system_error>

namespace kontakt::server {

namespace {

/// How long the spawner waits before trying again after a failed start.
constexpr auto kRetryStart = std::chrono::milliseconds(500);

}  // namespace

LocalExecutor::LocalExecutor(std::filesystem::path worker_exe, int threads_per_job,
                             std::size_t keep_waiting)
    : worker_exe_(std::move(worker_exe)), threads_per_job_(threads_per_job),
      keep_waiting_(keep_waiting) {}

LocalExecutor::~LocalExecutor() { shutdown(); }

void LocalExecutor::start() {
  spawner_ = std::thread([this] { spawner_loop(); });
}

void LocalExecutor::shutdown() {
  {
    std::lock_guard lock(mutex_);
    retired_ = true;
  }
  spawn_.notify_all();
  if (spawner_.joinable()) spawner_.join();
  std::lock_guard lock(mutex_);
  waiting_.clear();  // killed and reaped
}

std::unique_ptr<WorkerProcess> LocalExecutor::new_process() const {
  return std::make_unique<WorkerProcess>(worker_exe_, threads_per_job_);
}

void LocalExecutor::spawner_loop() {
  std::unique_lock lock(mutex_);
  while (!retired_) {
    if (waiting_.size() >= keep_waiting_) {
      spawn_.wait(lock);
      continue;
    }
    lock.unlock();
    std::unique_ptr<WorkerProcess> process;
    try {
      process = new_process();
    } catch (const std::system_error& e) {  // out of processes or descriptors: retry later
      std::fprintf(stderr, "kontaktd: cannot start a job process: %s\n", e.what());
    }
    lock.lock();
    if (process) waiting_.push_back(std::move(process));
    else spawn_.wait_for(lock, kRetryStart);
  }
}

std::unique_ptr<WorkerProcess> LocalExecutor::take_process() {
  {
    std::lock_guard lock(mutex_);
    while (!waiting_.empty()) {
      std::unique_ptr<WorkerProcess> process = std::move(waiting_.back());
      waiting_.pop_back();
      spawn_.notify_one();
      if (process->alive()) return process;  // else: killed while it waited
    }
  }
  return new_process();
}

std::unique_ptr<Execution> LocalExecutor::submit(const JobLaunch& job) {
  std::unique_ptr<WorkerProcess> process = take_process();
  if (!process->start(job.args)) {  // died between the check and now: a fresh one
    process = new_process();
    if (!process->start(job.args)) throw std::runtime_error("the job process ended before its job");
  }
  return process;
}

}  // namespace kontakt::server

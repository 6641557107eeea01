#include "server/worker_pool.hpp"

#include <cstdio>

#include "app/run_job.hpp"
#include "server/result_publisher.hpp"
#include "server/store_event_sink.hpp"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace kontakt::server {

namespace {

/// How long an idle worker sleeps before looking at the queue again (jobs requeued by
/// recovery need no wake-up call).
constexpr auto kIdlePoll = std::chrono::milliseconds(500);
constexpr auto kWatchdogPeriod = std::chrono::milliseconds(50);

struct FinalState {
  JobStatus status;
  std::string reason;
};

FinalState final_state(app::RunStatus run, bool time_limit_hit) {
  switch (run) {
    case app::RunStatus::Converged: return {JobStatus::Succeeded, ""};
    case app::RunStatus::NotConverged: return {JobStatus::Failed, "not_converged"};
    case app::RunStatus::InputError: return {JobStatus::Failed, "input_error"};
    case app::RunStatus::Cancelled:
      return time_limit_hit ? FinalState{JobStatus::Failed, "time_limit"}
                            : FinalState{JobStatus::Canceled, "canceled"};
    case app::RunStatus::Error: return {JobStatus::Failed, "solver_error"};
  }
  return {JobStatus::Failed, "internal"};
}

}  // namespace

WorkerPool::WorkerPool(JobStore& store, const JobFiles& files, WorkerSettings settings)
    : store_(store), files_(files), settings_(settings) {}

WorkerPool::~WorkerPool() {
  if (!threads_.empty()) drain(std::chrono::milliseconds(0));
}

void WorkerPool::start() {
  for (int i = 0; i < settings_.workers; ++i) threads_.emplace_back([this] { worker_loop(); });
  threads_.emplace_back([this] { watchdog_loop(); });
}

void WorkerPool::job_queued() {
  {
    std::lock_guard lock(mutex_);
    ++pending_wakeups_;
  }
  wake_.notify_all();  // notify_one could wake the watchdog, which shares the condition
}

void WorkerPool::stop(RunningJob& job, StopCause cause) {
  if (job.cause == StopCause::None) job.cause = cause;
  job.cancel.store(true);
}

void WorkerPool::cancel_running(const std::string& id) {
  std::lock_guard lock(mutex_);
  if (const auto it = running_.find(id); it != running_.end()) stop(*it->second, StopCause::Request);
}

int WorkerPool::n_busy() const {
  std::lock_guard lock(mutex_);
  return static_cast<int>(running_.size());
}

void WorkerPool::drain(std::chrono::milliseconds grace) {
  std::unique_lock lock(mutex_);
  stopping_ = true;
  wake_.notify_all();
  wake_.wait_for(lock, grace, [this] { return running_.empty(); });
  for (auto& [id, job] : running_) stop(*job, StopCause::Drain);
  lock.unlock();
  wake_.notify_all();
  for (auto& t : threads_) t.join();
  threads_.clear();
}

void WorkerPool::worker_loop() {
  while (true) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, kIdlePoll, [this] { return stopping_ || pending_wakeups_ > 0; });
      if (stopping_) return;
      if (pending_wakeups_ > 0) --pending_wakeups_;
    }
    // Claim until the queue is empty, so one wake-up never strands a job.
    while (true) {
      {
        std::lock_guard lock(mutex_);
        if (stopping_) return;
      }
      std::optional<JobRecord> job;
      try {
        job = store_.claim_next();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "kontaktd: cannot claim a job: %s\n", e.what());
      }
      if (!job) break;
      run(*job);
    }
  }
}

void WorkerPool::watchdog_loop() {
  std::unique_lock lock(mutex_);
  while (!stopping_ || !running_.empty()) {
    wake_.wait_for(lock, kWatchdogPeriod);
    if (settings_.job_time_limit <= 0) continue;
    const auto limit = std::chrono::duration<double>(settings_.job_time_limit);
    for (auto& [id, job] : running_)
      if (Clock::now() - job->started > limit) stop(*job, StopCause::TimeLimit);
  }
}

void WorkerPool::run(const JobRecord& job) {
  const auto running = std::make_shared<RunningJob>();
  running->started = Clock::now();
  {
    std::lock_guard lock(mutex_);
    running_[job.id] = running;
    if (stopping_) stop(*running, StopCause::Drain);  // claimed while drain() began
  }
  // A cancel that came between the claim and the line above found no flag to raise.
  if (const auto now = store_.find_job(job.id); now && now->status == JobStatus::Canceling)
    cancel_running(job.id);

  const fs::path work = files_.work_dir(job.id), results = files_.results_dir(job.id);
  std::error_code ec;
  fs::remove_all(work, ec);  // a requeued job starts from a clean slate
  fs::remove_all(results, ec);
  StoreEventSink sink(store_, job.id);
  const app::RunOutcome outcome =
      app::run_job({.deck = files_.input_dir(job.id) / job.main_file,
                    .out_dir = work,
                    .job_name = fs::path(job.main_file).stem().string(),
                    .threads = settings_.threads_per_job,
                    .scheme = job.scheme},
                   sink, running->cancel);
  StopCause cause;
  {
    std::lock_guard lock(mutex_);
    cause = running->cause;
    running_.erase(job.id);
  }
  wake_.notify_all();  // drain() waits for running_ to empty
  try {
    if (cause == StopCause::Drain && outcome.status == app::RunStatus::Cancelled) {
      store_.requeue(job.id);
      fs::remove_all(work, ec);
      return;
    }
    JobSummary summary = sink.summary();
    summary.wall_time = std::chrono::duration<double>(Clock::now() - running->started).count();
    const FinalState state = final_state(outcome.status, cause == StopCause::TimeLimit);
    const std::string message =
        cause == StopCause::TimeLimit
            ? "stopped at the wall-time limit of " + std::to_string(settings_.job_time_limit) + " s"
            : outcome.message;
    const std::vector<Artifact> artifacts = publish_results(work, results);
    // The cancel handler raises the flag before it records `canceling`: the solver may win.
    if (state.status == JobStatus::Canceled) store_.request_cancel(job.id);
    store_.finish_job(job.id, state.status, state.reason, message, summary, artifacts);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: job %s: %s\n", job.id.c_str(), e.what());
    try {
      store_.finish_job(job.id, JobStatus::Failed, "internal", e.what(), std::nullopt, {});
    } catch (const std::exception&) {  // the store itself is failing: recovery requeues it
    }
  }
}

}  // namespace kontakt::server

#include "server/worker_pool.hpp"

#include <unistd.h>

#include <cstdio>

#include "server/result_publisher.hpp"
#include "server/store_event_sink.hpp"

namespace fs = std::filesystem;

namespace kontakt::server {

namespace {

/// How long an idle worker sleeps before looking at the queue again (jobs requeued by
/// recovery need no wake-up call).
constexpr auto kIdlePoll = std::chrono::milliseconds(500);

}  // namespace

WorkerPool::WorkerPool(JobStore& store, const JobFiles& files, Executor& executor,
                       WorkerSettings settings)
    : store_(store), files_(files), executor_(executor), settings_(std::move(settings)) {}

WorkerPool::~WorkerPool() {
  if (!threads_.empty()) drain(std::chrono::milliseconds(0));
}

void WorkerPool::adopt(std::vector<JobRecord> jobs) {
  std::lock_guard lock(mutex_);
  for (JobRecord& job : jobs) adopted_.push_back(std::move(job));
}

void WorkerPool::start() {
  executor_.start();
  for (int i = 0; i < settings_.workers; ++i) threads_.emplace_back([this] { worker_loop(); });
}

void WorkerPool::job_queued() {
  {
    std::lock_guard lock(mutex_);
    ++pending_wakeups_;
  }
  wake_.notify_all();
}

void WorkerPool::cancel_running(const std::string& id) {
  std::lock_guard lock(mutex_);
  if (const auto it = running_.find(id); it != running_.end())
    it->second->request(StopCause::Request);
}

void WorkerPool::cancel_unclaimed(const std::string& id) {
  try {
    if (const auto job = store_.find_job(id)) executor_.cancel_unclaimed(launch_of(*job));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: job %s: %s\n", id.c_str(), e.what());
  }
}

int WorkerPool::n_busy() const {
  std::lock_guard lock(mutex_);
  return static_cast<int>(running_.size());
}

void WorkerPool::drain(std::chrono::milliseconds grace) {
  std::unique_lock lock(mutex_);
  stopping_ = true;
  wake_.notify_all();
  // Runs that outlive the daemon are let go at once: they go on, and the next daemon adopts them.
  if (!executor_.outlives_daemon())
    wake_.wait_for(lock, grace, [this] { return running_.empty(); });
  for (auto& [id, stop] : running_) stop->request(StopCause::Drain);
  lock.unlock();
  for (auto& t : threads_) t.join();
  threads_.clear();
  // Only now: the running jobs' processes die with the local executor's spawner thread.
  executor_.shutdown();
}

std::optional<std::pair<JobRecord, bool>> WorkerPool::next_job() {
  {
    std::lock_guard lock(mutex_);
    if (!adopted_.empty()) {
      JobRecord job = std::move(adopted_.front());
      adopted_.pop_front();
      return std::pair{std::move(job), true};
    }
  }
  try {
    if (auto job = store_.claim_next()) return std::pair{std::move(*job), false};
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: cannot claim a job: %s\n", e.what());
  }
  return std::nullopt;
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
      const auto job = next_job();
      if (!job) break;
      run(job->first, job->second);
    }
  }
}

JobLaunch WorkerPool::launch_of(const JobRecord& job) const {
  return {.id = job.id,
          .job_dir = files_.job_dir(job.id),
          .args = {.mode = worker::Mode::Run,
                   .deck = files_.input_dir(job.id) / job.main_file,
                   .scheme = job.scheme,
                   .limits = settings_.limits,
                   .parent_pid = getpid(),
                   .out_dir = files_.work_dir(job.id),
                   .job_name = fs::path(job.main_file).stem().string(),
                   .threads = settings_.threads_per_job},
          .resources = job.resources,
          .sweep_row = static_cast<std::size_t>(job.sweep_row)};
}

std::shared_ptr<const SweepLaunch> WorkerPool::sweep_launch_of(const JobRecord& job) {
  // A retried row runs alone: its array task has ended.
  if (!job.sweep_id || job.attempts != 1 || !executor_.starts_sweeps_whole()) return nullptr;
  const auto sweep = store_.find_sweep(*job.sweep_id);
  if (!sweep) return nullptr;
  auto launch = std::make_shared<SweepLaunch>();
  launch->id = sweep->id;
  launch->dir = files_.sweep_dir(sweep->id);
  launch->max_parallel = sweep->max_parallel;
  // Rows canceled or deleted before the array is started are left out of it.
  for (const JobRecord& row : store_.sweep_jobs(sweep->id))
    if (!is_terminal(row.status)) launch->rows.push_back(launch_of(row));
  return launch;
}

void WorkerPool::run(const JobRecord& job, bool adopted) {
  const auto stop = std::make_shared<StopSignal>();
  {
    std::lock_guard lock(mutex_);
    running_[job.id] = stop;
    if (stopping_) stop->request(StopCause::Drain);  // claimed while drain() began
  }
  // A cancel that came between the claim and the line above found no run to stop.
  if (const auto now = store_.find_job(job.id); now && now->status == JobStatus::Canceling)
    stop->request(StopCause::Request);

  JobLaunch launch = launch_of(job);
  if (adopted) launch.events_stored = static_cast<std::size_t>(store_.count_run_events(job.id));
  // The first run of a sweep's row: its array task may have run already.
  if (!adopted) launch.sweep = sweep_launch_of(job);
  if (!adopted && !launch.sweep) {  // a requeued job starts from a clean slate
    std::error_code ec;
    fs::remove_all(launch.args.out_dir, ec);
    fs::remove_all(files_.results_dir(job.id), ec);
  }
  StoreEventSink sink(store_, job.id);
  std::optional<ProcessEnd> end;
  std::optional<JobVerdict> refused;
  bool never_submitted = false;
  try {
    std::unique_ptr<Execution> execution =
        adopted ? executor_.attach(launch) : executor_.submit(launch);
    if (execution) {
      const double time_limit =
          executor_.daemon_enforces_time_limit() ? settings_.job_time_limit : 0;
      end = supervise_job(*execution, sink, *stop,
                          {.time_limit = time_limit, .grace = settings_.kill_grace},
                          launch.args.out_dir);
    } else {
      never_submitted = true;
    }
  } catch (const ExecutorRefused& e) {  // e.g. sbatch: no such partition, too much memory
    refused = JobVerdict{.status = JobStatus::Failed, .reason = "executor_refused",
                         .message = e.what()};
  } catch (const std::exception& e) {  // no process (descriptor or process limits): fail the job
    refused = JobVerdict{.status = JobStatus::Failed, .reason = "internal",
                         .message = std::string("cannot start the job process: ") + e.what()};
  }
  {
    std::lock_guard lock(mutex_);
    running_.erase(job.id);
  }
  wake_.notify_all();  // drain() waits for running_ to empty
  if (never_submitted) {  // adopted, but the executor never had it: run it again
    conclude(job, {.action = JobVerdict::Action::Requeue}, sink.summary());
    job_queued();
    return;
  }
  if (refused) {
    std::fprintf(stderr, "kontaktd: job %s: %s\n", job.id.c_str(), refused->message.c_str());
    conclude(job, stop->cause() == StopCause::Request
                      ? JobVerdict{.status = JobStatus::Canceled, .reason = "canceled",
                                   .message = "canceled"}
                      : *refused,
             sink.summary());
    return;
  }
  if (end->detached) return;  // goes on in the executor; the next daemon adopts it
  if (end->sink_error)
    std::fprintf(stderr, "kontaktd: job %s: events not stored: %s\n", job.id.c_str(),
                 end->sink_error->c_str());
  JobSummary summary = sink.summary();
  summary.wall_time = end->seconds;
  conclude(job,
           judge(*end, {.attempts = job.attempts, .max_attempts = settings_.max_attempts,
                        .time_limit = settings_.job_time_limit, .limits = settings_.limits}),
           summary);
}

void WorkerPool::conclude(const JobRecord& job, const JobVerdict& verdict,
                          const JobSummary& summary) {
  const fs::path work = files_.work_dir(job.id);
  std::error_code ec;
  try {
    switch (verdict.action) {
      // Both need a running job; one canceled meanwhile is finished below (as canceled).
      case JobVerdict::Action::Requeue:
        if (!store_.requeue(job.id)) break;
        fs::remove_all(work, ec);
        return;
      case JobVerdict::Action::Retry:
        if (!store_.retry(job.id, verdict.message)) break;
        fs::remove_all(work, ec);
        return;
      case JobVerdict::Action::Finish:
        break;
    }
    if (!verdict.keep_results) fs::remove_all(work, ec);
    const std::vector<Artifact> artifacts =
        verdict.keep_results ? publish_results(work, files_.results_dir(job.id))
                             : std::vector<Artifact>{};
    // The cancel handler stops the process before it records `canceling`: the process may win.
    if (verdict.status == JobStatus::Canceled) store_.request_cancel(job.id);
    store_.finish_job(job.id, verdict.status, verdict.reason, verdict.message, summary,
                      artifacts);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: job %s: %s\n", job.id.c_str(), e.what());
    try {
      store_.finish_job(job.id, JobStatus::Failed, "internal", e.what(), std::nullopt, {});
    } catch (const std::exception&) {  // the store itself is failing: recovery requeues it
    }
  }
}

}  // namespace kontakt::server

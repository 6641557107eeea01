#include "server/worker_pool.hpp"

#include <unistd.h>

#include <cstdio>
#include <system_error>

#include "server/result_publisher.hpp"
#include "server/store_event_sink.hpp"

namespace fs = std::filesystem;

namespace kontakt::server {

namespace {

/// How long an idle worker sleeps before looking at the queue again (jobs requeued by
/// recovery need no wake-up call).
constexpr auto kIdlePoll = std::chrono::milliseconds(500);

}  // namespace

WorkerPool::WorkerPool(JobStore& store, const JobFiles& files, WorkerSettings settings)
    : store_(store), files_(files), settings_(std::move(settings)) {}

WorkerPool::~WorkerPool() {
  if (!threads_.empty() || spawner_.joinable()) drain(std::chrono::milliseconds(0));
}

void WorkerPool::start() {
  spawner_ = std::thread([this] { spawner_loop(); });
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

int WorkerPool::n_busy() const {
  std::lock_guard lock(mutex_);
  return static_cast<int>(running_.size());
}

void WorkerPool::drain(std::chrono::milliseconds grace) {
  std::unique_lock lock(mutex_);
  stopping_ = true;
  wake_.notify_all();
  wake_.wait_for(lock, grace, [this] { return running_.empty(); });
  for (auto& [id, stop] : running_) stop->request(StopCause::Drain);
  lock.unlock();
  for (auto& t : threads_) t.join();
  threads_.clear();
  // Only now: the running jobs' processes die with the spawner's thread.
  {
    std::lock_guard guard(mutex_);
    spawner_retired_ = true;
  }
  spawn_.notify_all();
  if (spawner_.joinable()) spawner_.join();
  waiting_.clear();  // killed and reaped
}

void WorkerPool::spawner_loop() {
  const std::size_t keep = static_cast<std::size_t>(settings_.workers) + 1;
  std::unique_lock lock(mutex_);
  while (!spawner_retired_) {
    if (waiting_.size() >= keep || stopping_) {
      spawn_.wait(lock);
      continue;
    }
    lock.unlock();
    std::unique_ptr<WorkerProcess> process;
    try {
      process = std::make_unique<WorkerProcess>(settings_.worker_exe, settings_.threads_per_job);
    } catch (const std::system_error& e) {  // out of processes or descriptors: retry later
      std::fprintf(stderr, "kontaktd: cannot start a job process: %s\n", e.what());
    }
    lock.lock();
    if (process) waiting_.push_back(std::move(process));
    else spawn_.wait_for(lock, kIdlePoll);
  }
}

std::unique_ptr<WorkerProcess> WorkerPool::take_process() {
  {
    std::lock_guard lock(mutex_);
    while (!waiting_.empty()) {
      std::unique_ptr<WorkerProcess> process = std::move(waiting_.back());
      waiting_.pop_back();
      spawn_.notify_one();
      if (process->alive()) return process;  // else: killed while it waited
    }
  }
  return std::make_unique<WorkerProcess>(settings_.worker_exe, settings_.threads_per_job);
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

void WorkerPool::run(const JobRecord& job) {
  const auto stop = std::make_shared<StopSignal>();
  {
    std::lock_guard lock(mutex_);
    running_[job.id] = stop;
    if (stopping_) stop->request(StopCause::Drain);  // claimed while drain() began
  }
  // A cancel that came between the claim and the line above found no process to stop.
  if (const auto now = store_.find_job(job.id); now && now->status == JobStatus::Canceling)
    stop->request(StopCause::Request);

  const fs::path work = files_.work_dir(job.id);
  std::error_code ec;
  fs::remove_all(work, ec);  // a requeued job starts from a clean slate
  fs::remove_all(files_.results_dir(job.id), ec);
  StoreEventSink sink(store_, job.id);
  std::optional<ProcessEnd> end;
  std::string start_error;
  try {
    const worker::Args args{.mode = worker::Mode::Run,
                            .deck = files_.input_dir(job.id) / job.main_file,
                            .scheme = job.scheme,
                            .limits = settings_.limits,
                            .parent_pid = getpid(),
                            .out_dir = work,
                            .job_name = fs::path(job.main_file).stem().string(),
                            .threads = settings_.threads_per_job};
    std::unique_ptr<WorkerProcess> process = take_process();
    if (!process->start(args)) {  // died between the check and now: a fresh one
      process = std::make_unique<WorkerProcess>(settings_.worker_exe, settings_.threads_per_job);
      if (!process->start(args)) throw std::runtime_error("the job process ended before its job");
    }
    end = supervise_job(*process, sink, *stop,
                        {.time_limit = settings_.job_time_limit, .grace = settings_.kill_grace},
                        work);
  } catch (const std::exception& e) {  // no process (descriptor or process limits): fail the job
    start_error = e.what();
  }
  {
    std::lock_guard lock(mutex_);
    running_.erase(job.id);
  }
  wake_.notify_all();  // drain() waits for running_ to empty
  if (!end) {
    std::fprintf(stderr, "kontaktd: job %s: cannot run its process: %s\n", job.id.c_str(),
                 start_error.c_str());
    conclude(job, {.status = JobStatus::Failed, .reason = "internal",
                   .message = "cannot start the job process: " + start_error},
             sink.summary());
    return;
  }
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

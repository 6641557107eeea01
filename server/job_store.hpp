// The job store: every job, its event log and its published artifacts in one SQLite database
// (WAL). One writer connection, guarded by a mutex, makes every change in a BEGIN IMMEDIATE
// transaction of its own; readers use a small pool of connections and never block it. Every
// status change goes through the transition table (job_state.hpp) and appends a `status`
// event in the same transaction, so the event log and the record never disagree.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "server/job_record.hpp"
#include "server/sqlite_db.hpp"

namespace kontakt::server {

/// Filters and cursor of GET /v1/jobs.
struct JobQuery {
  std::vector<JobStatus> statuses;                          ///< empty: any
  std::vector<std::pair<std::string, std::string>> labels;  ///< every one must match
  std::vector<std::string> label_keys;                      ///< every key must be present
  int limit = 50;
  /// Resume after this (created_ms, id): the last row of the previous page.
  std::optional<std::pair<std::int64_t, std::string>> after;
};

struct JobPage {
  std::vector<JobRecord> jobs;
  bool more = false;  ///< another page follows the last row
};

enum class InsertResult { Created, Replayed, KeyConflict };

struct StoreCounts {
  int queued = 0, running = 0, canceling = 0;
  std::map<std::string, int> finished;  ///< by terminal status
};

/// One label key and the jobs that carry it: a sweep.
struct LabelKeyCount {
  std::string key;
  int jobs = 0;
  std::int64_t latest_ms = 0;  ///< creation time of its newest job
};

struct RecoveryReport {
  int requeued = 0, failed = 0, canceled = 0;
};

class JobStore {
 public:
  /// Opens (creating) the database and applies pending migrations.
  explicit JobStore(const std::filesystem::path& db_file);

  /// Inserts a queued job. With an idempotency key already used: Replayed (and that job) when
  /// the fingerprint matches, KeyConflict otherwise.
  std::pair<InsertResult, JobRecord> insert_job(const NewJob& job);
  /// Inserts the sweep and its rows (queued jobs, in this order: row i is rows[i]) in one
  /// transaction. Idempotency key as for insert_job, on the sweep.
  std::pair<InsertResult, SweepRecord> insert_sweep(const SweepRecord& sweep,
                                                    std::vector<NewJob> rows);
  std::optional<SweepRecord> find_sweep(const std::string& id);
  std::optional<SweepRecord> find_sweep_by_key(const std::string& idempotency_key);
  /// The sweep's jobs, by row.
  std::vector<JobRecord> sweep_jobs(const std::string& sweep_id);
  /// Its jobs by status name.
  std::map<std::string, int> sweep_counts(const std::string& sweep_id);
  std::optional<JobRecord> find_job(const std::string& id);
  std::optional<JobRecord> find_by_key(const std::string& idempotency_key);
  JobPage list_jobs(const JobQuery& query);
  /// 1-based place of a queued job in the queue (oldest first); none once a worker has
  /// claimed it or it was canceled, however recently the record was read.
  std::optional<int> queue_position(const JobRecord& job);

  /// The oldest queued job, now running (attempts + 1); nullopt when the queue is empty. A
  /// sweep's row is passed over while its sweep has max_parallel rows running or canceling.
  std::optional<JobRecord> claim_next();
  /// queued -> canceled, running -> canceling; other states unchanged. nullopt: no such job.
  std::optional<JobRecord> request_cancel(const std::string& id);
  /// Ends a run: running or canceling -> `to` (a canceling job always ends canceled), with the
  /// summary and the published artifacts. False when the transition is not allowed.
  bool finish_job(const std::string& id, JobStatus to, const std::string& reason,
                  const std::string& message, const std::optional<JobSummary>& summary,
                  const std::vector<Artifact>& artifacts);
  /// running -> queued (drain); the attempt is not counted against the job.
  bool requeue(const std::string& id);
  /// running -> queued to run again after its process was killed from outside; the attempt
  /// counts (claim_next counted it) and `message` says why.
  bool retry(const std::string& id, const std::string& message);
  /// After a crash: running jobs are requeued, or failed with reason worker_lost once they
  /// have had `max_attempts` runs; canceling jobs end canceled.
  RecoveryReport recover(int max_attempts);
  enum class DeleteResult { Deleted, NotFound, NotFinished };
  DeleteResult delete_job(const std::string& id);

  /// Appends a solver event of the job's current run and, when given, its new progress.
  std::int64_t append_event(const std::string& id, const std::string& kind,
                            const std::string& data, const std::optional<JobProgress>& progress);
  /// Events with seq > since, oldest first; `kinds` empty = every kind.
  std::vector<StoredEvent> events_since(const std::string& id, std::int64_t since,
                                        const std::vector<std::string>& kinds, int limit);
  std::vector<Artifact> artifacts(const std::string& id);
  /// Solver events (not status changes) stored from the job's current run: where a daemon
  /// that adopts the run after a restart picks up its event log.
  std::int64_t count_run_events(const std::string& id);

  StoreCounts counts();
  /// Every label key in use, the most recently used first.
  std::vector<LabelKeyCount> label_keys();
  /// Run times in seconds of every job that started and finished.
  std::vector<double> run_durations();
  std::vector<std::string> all_ids();

  /// Grows with every committed change: SSE streams look at it instead of the database.
  std::uint64_t generation() const { return generation_.load(); }
  /// Calls `wake` once: from the thread that commits the next change, or at once when the
  /// generation is already past `seen`. Dropped unheard when `owner` is gone by then.
  void on_next_change(std::uint64_t seen, std::weak_ptr<void> owner, std::function<void()> wake);

 private:
  class ReadLease;
  ReadLease read();
  bool transition(const std::string& id, JobStatus to, const std::string& reason,
                  const std::string& message);  // caller holds writer_mutex_ in a transaction

  std::filesystem::path file_;
  std::mutex writer_mutex_;
  SqliteDb writer_;
  std::mutex readers_mutex_;
  std::vector<std::unique_ptr<SqliteDb>> idle_readers_;
  std::atomic<std::uint64_t> generation_{0};
  /// After every commit: the generation grows and the waiters are woken.
  void changed();
  struct ChangeWaiter {
    std::weak_ptr<void> owner;
    std::function<void()> wake;
  };
  std::mutex change_mutex_;
  std::vector<ChangeWaiter> change_waiters_;
  std::size_t prune_at_ = 64;  ///< waiters whose owner is gone are dropped past this many
};

/// Milliseconds since the Unix epoch.
std::int64_t now_ms();

}  // namespace kontakt::server

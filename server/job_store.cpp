#include "server/job_store.hpp"

#include <chrono>
#include <nlohmann/json.hpp>

#include "server/job_json.hpp"
#include "server/job_store_schema.hpp"

namespace kontakt::server {

using nlohmann::json;

namespace {

constexpr const char* kJobColumns =
    "id, name, status, reason, message, main_file, scheme, labels, created_ms, updated_ms, "
    "started_ms, finished_ms, attempts, n_steps, planned_time, progress, summary, "
    "idempotency_key, fingerprint, resources, sweep_id, sweep_row";
constexpr const char* kSweepColumns =
    "id, name, created_ms, n_rows, max_parallel, idempotency_key, fingerprint";

json progress_to_json(const JobProgress& p) {
  json j{{"step", p.step},           {"increment", p.increment}, {"attempt", p.attempt},
         {"iteration", p.iteration}, {"step_time", p.step_time}, {"total_time", p.total_time},
         {"dt", p.dt}};
  if (p.residual) j["residual"] = *p.residual;
  if (p.contact_elements) j["contact_elements"] = *p.contact_elements;
  return j;
}

JobProgress progress_from_json(const json& j) {
  JobProgress p;
  p.step = j.value("step", 0);
  p.increment = j.value("increment", 0);
  p.attempt = j.value("attempt", 0);
  p.iteration = j.value("iteration", 0);
  p.step_time = j.value("step_time", 0.0);
  p.total_time = j.value("total_time", 0.0);
  p.dt = j.value("dt", 0.0);
  if (j.contains("residual")) p.residual = j["residual"].get<double>();
  if (j.contains("contact_elements")) p.contact_elements = j["contact_elements"].get<int>();
  return p;
}

json summary_to_json(const JobSummary& s) {
  json j{{"iterations", s.iterations}, {"wall_time", s.wall_time}};
  if (s.max_displacement) j["max_displacement"] = *s.max_displacement;
  if (s.max_mises) j["max_mises"] = *s.max_mises;
  if (s.max_contact_pressure) j["max_contact_pressure"] = *s.max_contact_pressure;
  if (s.total_contact_force) j["total_contact_force"] = *s.total_contact_force;
  return j;
}

JobSummary summary_from_json(const json& j) {
  JobSummary s;
  s.iterations = j.value("iterations", 0);
  s.wall_time = j.value("wall_time", 0.0);
  if (j.contains("max_displacement")) s.max_displacement = j["max_displacement"].get<double>();
  if (j.contains("max_mises")) s.max_mises = j["max_mises"].get<double>();
  if (j.contains("max_contact_pressure"))
    s.max_contact_pressure = j["max_contact_pressure"].get<double>();
  if (j.contains("total_contact_force"))
    s.total_contact_force = j["total_contact_force"].get<double>();
  return s;
}

/// The row read with kJobColumns, in that order.
JobRecord record_from_row(const Statement& st) {
  JobRecord r;
  r.id = st.text(0);
  r.name = st.text(1);
  r.status = status_from_name(st.text(2)).value_or(JobStatus::Failed);
  r.reason = st.text(3);
  r.message = st.text(4);
  r.main_file = st.text(5);
  r.scheme = st.optional_text(6);
  r.labels = json::parse(st.text(7)).get<std::map<std::string, std::string>>();
  r.created_ms = st.integer(8);
  r.updated_ms = st.integer(9);
  if (!st.is_null(10)) r.started_ms = st.integer(10);
  if (!st.is_null(11)) r.finished_ms = st.integer(11);
  r.attempts = static_cast<int>(st.integer(12));
  r.n_steps = static_cast<int>(st.integer(13));
  r.planned_time = st.real(14);
  r.progress = progress_from_json(json::parse(st.text(15)));
  if (!st.is_null(16)) r.summary = summary_from_json(json::parse(st.text(16)));
  r.idempotency_key = st.optional_text(17);
  r.fingerprint = st.text(18);
  read_resources(json::parse(st.text(19)), r.resources);  // written by insert_job: valid
  r.sweep_id = st.optional_text(20);
  r.sweep_row = static_cast<int>(st.integer(21));
  return r;
}

std::optional<SweepRecord> select_sweep(SqliteDb& db, const std::string& where,
                                        const std::string& value) {
  Statement st(db, std::string("SELECT ") + kSweepColumns + " FROM sweeps WHERE " + where + " = ?");
  st.bind(1, value);
  if (!st.step()) return std::nullopt;
  return SweepRecord{.id = st.text(0),
                     .name = st.text(1),
                     .created_ms = st.integer(2),
                     .n_rows = static_cast<int>(st.integer(3)),
                     .max_parallel = static_cast<int>(st.integer(4)),
                     .idempotency_key = st.optional_text(5),
                     .fingerprint = st.text(6)};
}

std::optional<JobRecord> select_job(SqliteDb& db, const std::string& where,
                                    const std::string& value) {
  Statement st(db, std::string("SELECT ") + kJobColumns + " FROM jobs WHERE " + where + " = ?");
  st.bind(1, value);
  if (!st.step()) return std::nullopt;
  return record_from_row(st);
}

std::optional<JobStatus> status_of(SqliteDb& db, const std::string& id) {
  Statement st(db, "SELECT status FROM jobs WHERE id = ?");
  st.bind(1, id);
  if (!st.step()) return std::nullopt;
  return status_from_name(st.text(0));
}

/// Appends one event with the job's next sequence number; returns it.
std::int64_t insert_event(SqliteDb& db, const std::string& id, const std::string& kind,
                          const std::string& data) {
  Statement next(db, "UPDATE jobs SET next_seq = next_seq + 1 WHERE id = ? "
                     "RETURNING next_seq - 1, attempts");
  next.bind(1, id);
  if (!next.step()) throw StoreError("no job " + id);
  const std::int64_t seq = next.integer(0);
  const std::int64_t run = next.integer(1);
  next.run();
  Statement ins(db, "INSERT INTO job_events (job_id, seq, run, kind, data) VALUES (?, ?, ?, ?, ?)");
  ins.bind(1, id).bind(2, seq).bind(3, run).bind(4, kind).bind(5, data).run();
  return seq;
}

}  // namespace

std::int64_t now_ms() {
  using namespace std::chrono;
  return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

/// A reader connection borrowed from the pool for one call.
class JobStore::ReadLease {
 public:
  ReadLease(JobStore& store, std::unique_ptr<SqliteDb> db) : store_(store), db_(std::move(db)) {}
  ~ReadLease() {
    std::lock_guard lock(store_.readers_mutex_);
    store_.idle_readers_.push_back(std::move(db_));
  }
  ReadLease(const ReadLease&) = delete;
  ReadLease& operator=(const ReadLease&) = delete;
  SqliteDb& db() { return *db_; }

 private:
  JobStore& store_;
  std::unique_ptr<SqliteDb> db_;
};

JobStore::JobStore(const std::filesystem::path& db_file) : file_(db_file), writer_(db_file) {
  migrate(writer_);
}

JobStore::ReadLease JobStore::read() {
  {
    std::lock_guard lock(readers_mutex_);
    if (!idle_readers_.empty()) {
      auto db = std::move(idle_readers_.back());
      idle_readers_.pop_back();
      return ReadLease(*this, std::move(db));
    }
  }
  return ReadLease(*this, std::make_unique<SqliteDb>(file_));
}

bool JobStore::transition(const std::string& id, JobStatus to, const std::string& reason,
                          const std::string& message) {
  const auto from = status_of(writer_, id);
  if (!from || !transition_allowed(*from, to)) return false;
  const std::int64_t now = now_ms();
  Statement st(writer_,
               "UPDATE jobs SET status = ?, reason = ?, message = ?, updated_ms = ?, "
               "finished_ms = CASE WHEN ? THEN ? ELSE NULL END WHERE id = ?");
  st.bind(1, status_name(to)).bind(2, reason).bind(3, message).bind(4, now);
  st.bind(5, static_cast<std::int64_t>(is_terminal(to))).bind(6, now).bind(7, id).run();
  json event{{"event", "status"}, {"status", status_name(to)}};
  if (!reason.empty()) event["reason"] = reason;
  if (!message.empty()) event["message"] = message;
  insert_event(writer_, id, "status", json_text(event));
  return true;
}

namespace {

/// Inserts one queued job with its first event (the caller's transaction).
void insert_job_row(SqliteDb& db, const NewJob& job, std::int64_t now) {
  Statement st(db,
               "INSERT INTO jobs (id, name, status, main_file, scheme, labels, created_ms, "
               "updated_ms, n_steps, planned_time, idempotency_key, fingerprint, resources, "
               "sweep_id, sweep_row) VALUES (?, ?, 'queued', ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  st.bind(1, job.id).bind(2, job.name).bind(3, job.main_file).bind_optional(4, job.scheme);
  st.bind(5, json_text(json(job.labels))).bind(6, now).bind(7, now);
  st.bind(8, static_cast<std::int64_t>(job.n_steps)).bind(9, job.planned_time);
  st.bind_optional(10, job.idempotency_key).bind(11, job.fingerprint);
  st.bind(12, json_text(to_json(job.resources))).bind_optional(13, job.sweep_id);
  st.bind(14, static_cast<std::int64_t>(job.sweep_row)).run();
  insert_event(db, job.id, "status", json_text(json{{"event", "status"}, {"status", "queued"}}));
}

}  // namespace

std::pair<InsertResult, JobRecord> JobStore::insert_job(const NewJob& job) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  if (job.idempotency_key) {
    if (auto existing = select_job(writer_, "idempotency_key", *job.idempotency_key)) {
      const auto result = existing->fingerprint == job.fingerprint ? InsertResult::Replayed
                                                                   : InsertResult::KeyConflict;
      return {result, *existing};
    }
  }
  insert_job_row(writer_, job, now_ms());
  auto record = select_job(writer_, "id", job.id);
  tx.commit();
  changed();
  return {InsertResult::Created, *record};
}

std::pair<InsertResult, SweepRecord> JobStore::insert_sweep(const SweepRecord& sweep,
                                                            std::vector<NewJob> rows) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  if (sweep.idempotency_key) {
    if (auto existing = select_sweep(writer_, "idempotency_key", *sweep.idempotency_key)) {
      const auto result = existing->fingerprint == sweep.fingerprint ? InsertResult::Replayed
                                                                     : InsertResult::KeyConflict;
      return {result, *existing};
    }
  }
  const std::int64_t now = now_ms();
  Statement st(writer_, "INSERT INTO sweeps (id, name, created_ms, n_rows, max_parallel, "
                        "idempotency_key, fingerprint) VALUES (?, ?, ?, ?, ?, ?, ?)");
  st.bind(1, sweep.id).bind(2, sweep.name).bind(3, now);
  st.bind(4, static_cast<std::int64_t>(rows.size()));
  st.bind(5, static_cast<std::int64_t>(sweep.max_parallel));
  st.bind_optional(6, sweep.idempotency_key).bind(7, sweep.fingerprint).run();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].sweep_id = sweep.id;
    rows[i].sweep_row = static_cast<int>(i);
    insert_job_row(writer_, rows[i], now);
  }
  auto record = select_sweep(writer_, "id", sweep.id);
  tx.commit();
  changed();
  return {InsertResult::Created, *record};
}

std::optional<SweepRecord> JobStore::find_sweep(const std::string& id) {
  auto lease = read();
  return select_sweep(lease.db(), "id", id);
}

std::optional<SweepRecord> JobStore::find_sweep_by_key(const std::string& idempotency_key) {
  auto lease = read();
  return select_sweep(lease.db(), "idempotency_key", idempotency_key);
}

std::vector<JobRecord> JobStore::sweep_jobs(const std::string& sweep_id) {
  auto lease = read();
  Statement st(lease.db(), std::string("SELECT ") + kJobColumns +
                               " FROM jobs WHERE sweep_id = ? ORDER BY sweep_row");
  st.bind(1, sweep_id);
  std::vector<JobRecord> jobs;
  while (st.step()) jobs.push_back(record_from_row(st));
  return jobs;
}

std::map<std::string, int> JobStore::sweep_counts(const std::string& sweep_id) {
  auto lease = read();
  Statement st(lease.db(), "SELECT status, COUNT(*) FROM jobs WHERE sweep_id = ? GROUP BY status");
  st.bind(1, sweep_id);
  std::map<std::string, int> counts;
  while (st.step()) counts[st.text(0)] = static_cast<int>(st.integer(1));
  return counts;
}

std::optional<JobRecord> JobStore::find_job(const std::string& id) {
  auto lease = read();
  return select_job(lease.db(), "id", id);
}

std::optional<JobRecord> JobStore::find_by_key(const std::string& idempotency_key) {
  auto lease = read();
  return select_job(lease.db(), "idempotency_key", idempotency_key);
}

JobPage JobStore::list_jobs(const JobQuery& query) {
  std::string sql = std::string("SELECT ") + kJobColumns + " FROM jobs WHERE 1";
  if (!query.statuses.empty()) {
    sql += " AND status IN (";
    for (std::size_t i = 0; i < query.statuses.size(); ++i) sql += i ? ", ?" : "?";
    sql += ")";
  }
  for (std::size_t i = 0; i < query.labels.size(); ++i)
    sql += " AND json_extract(labels, '$.\"' || ? || '\"') = ?";
  for (std::size_t i = 0; i < query.label_keys.size(); ++i)
    sql += " AND EXISTS (SELECT 1 FROM json_each(jobs.labels) WHERE json_each.key = ?)";
  // Newest first; jobs of the same millisecond in reverse insertion order (rowid). A page
  // resumes after its last job's row (a job deleted since leaves the rest of its millisecond).
  if (query.after)
    sql += " AND (created_ms < ? OR (created_ms = ? AND "
           "rowid < COALESCE((SELECT rowid FROM jobs WHERE id = ?), 0)))";
  sql += " ORDER BY created_ms DESC, rowid DESC LIMIT ?";
  auto lease = read();
  Statement st(lease.db(), sql);
  int b = 1;
  for (JobStatus s : query.statuses) st.bind(b++, status_name(s));
  for (const auto& [key, value] : query.labels) {
    st.bind(b++, key);
    st.bind(b++, value);
  }
  for (const std::string& key : query.label_keys) st.bind(b++, key);
  if (query.after) {
    st.bind(b++, query.after->first);
    st.bind(b++, query.after->first);
    st.bind(b++, query.after->second);
  }
  st.bind(b, static_cast<std::int64_t>(query.limit + 1));
  JobPage page;
  while (st.step()) page.jobs.push_back(record_from_row(st));
  if (static_cast<int>(page.jobs.size()) > query.limit) {
    page.jobs.pop_back();
    page.more = true;
  }
  return page;
}

std::optional<int> JobStore::queue_position(const JobRecord& job) {
  auto lease = read();
  // One statement, one snapshot: the job itself counts only while it is still queued. Jobs of
  // the same millisecond are in insertion order (rowid), the order claim_next takes them in.
  Statement st(lease.db(),
               "SELECT COUNT(*) FROM jobs WHERE status = 'queued' AND "
               "(created_ms < ? OR (created_ms = ? AND "
               "rowid <= (SELECT rowid FROM jobs WHERE id = ?))) AND "
               "EXISTS (SELECT 1 FROM jobs WHERE id = ? AND status = 'queued')");
  st.bind(1, job.created_ms).bind(2, job.created_ms).bind(3, job.id).bind(4, job.id);
  st.step();
  const int position = static_cast<int>(st.integer(0));
  return position > 0 ? std::optional(position) : std::nullopt;
}

std::optional<JobRecord> JobStore::claim_next() {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  // A sweep's row waits while max_parallel rows of its sweep run; other jobs go ahead of it.
  Statement next(writer_,
                 "SELECT id FROM jobs AS j WHERE status = 'queued' AND (sweep_id IS NULL OR "
                 "(SELECT COUNT(*) FROM jobs AS r WHERE r.sweep_id = j.sweep_id AND "
                 "r.status IN ('running', 'canceling')) < "
                 "(SELECT max_parallel FROM sweeps WHERE sweeps.id = j.sweep_id)) "
                 "ORDER BY created_ms, rowid LIMIT 1");  // rowid: the order of insertion
  if (!next.step()) return std::nullopt;
  const std::string id = next.text(0);
  Statement st(writer_, "UPDATE jobs SET attempts = attempts + 1, started_ms = ?, "
                        "progress = '{}', summary = NULL WHERE id = ?");
  st.bind(1, now_ms()).bind(2, id).run();
  transition(id, JobStatus::Running, "", "");
  auto record = select_job(writer_, "id", id);
  tx.commit();
  changed();
  return record;
}

std::optional<JobRecord> JobStore::request_cancel(const std::string& id) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  const auto status = status_of(writer_, id);
  if (!status) return std::nullopt;
  if (*status == JobStatus::Queued) transition(id, JobStatus::Canceled, "canceled", "canceled before it started");
  if (*status == JobStatus::Running) transition(id, JobStatus::Canceling, "", "");
  auto record = select_job(writer_, "id", id);
  tx.commit();
  changed();
  return record;
}

bool JobStore::finish_job(const std::string& id, JobStatus to, const std::string& reason,
                          const std::string& message, const std::optional<JobSummary>& summary,
                          const std::vector<Artifact>& artifacts) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  if (status_of(writer_, id) == JobStatus::Canceling) to = JobStatus::Canceled;
  const std::string why = to == JobStatus::Canceled && reason.empty() ? "canceled" : reason;
  if (!transition(id, to, why, message)) return false;
  if (summary) {
    Statement st(writer_, "UPDATE jobs SET summary = ? WHERE id = ?");
    st.bind(1, json_text(summary_to_json(*summary))).bind(2, id).run();
  }
  Statement clear(writer_, "DELETE FROM artifacts WHERE job_id = ?");
  clear.bind(1, id).run();
  for (const Artifact& a : artifacts) {
    Statement st(writer_, "INSERT INTO artifacts (job_id, name, media_type, size, sha256) "
                          "VALUES (?, ?, ?, ?, ?)");
    st.bind(1, id).bind(2, a.name).bind(3, a.media_type).bind(4, a.size).bind(5, a.sha256).run();
  }
  tx.commit();
  changed();
  return true;
}

bool JobStore::requeue(const std::string& id) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  if (!transition(id, JobStatus::Queued, "requeued", "the daemon stopped during the run")) return false;
  Statement st(writer_, "UPDATE jobs SET attempts = attempts - 1, started_ms = NULL WHERE id = ?");
  st.bind(1, id).run();
  tx.commit();
  changed();
  return true;
}

bool JobStore::retry(const std::string& id, const std::string& message) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  if (!transition(id, JobStatus::Queued, "requeued", message)) return false;
  Statement st(writer_, "UPDATE jobs SET started_ms = NULL WHERE id = ?");
  st.bind(1, id).run();
  tx.commit();
  changed();
  return true;
}

RecoveryReport JobStore::recover(int max_attempts) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  RecoveryReport report;
  std::vector<std::pair<std::string, std::pair<JobStatus, int>>> stale;
  {
    Statement st(writer_, "SELECT id, status, attempts FROM jobs "
                          "WHERE status IN ('running', 'canceling')");
    while (st.step())
      stale.push_back({st.text(0), {*status_from_name(st.text(1)), static_cast<int>(st.integer(2))}});
  }
  for (const auto& [id, state] : stale) {
    const auto [status, attempts] = state;
    if (status == JobStatus::Canceling) {
      transition(id, JobStatus::Canceled, "canceled", "the daemon stopped while canceling");
      ++report.canceled;
    } else if (attempts >= max_attempts) {
      transition(id, JobStatus::Failed, "worker_lost",
                 "the daemon stopped during each of " + std::to_string(attempts) + " runs");
      ++report.failed;
    } else {
      transition(id, JobStatus::Queued, "requeued", "the daemon stopped during the run");
      ++report.requeued;
    }
  }
  tx.commit();
  changed();
  return report;
}

JobStore::DeleteResult JobStore::delete_job(const std::string& id) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_);
  const auto status = status_of(writer_, id);
  if (!status) return DeleteResult::NotFound;
  if (!is_terminal(*status)) return DeleteResult::NotFinished;
  Statement st(writer_, "DELETE FROM jobs WHERE id = ?");
  st.bind(1, id).run();
  tx.commit();
  changed();
  return DeleteResult::Deleted;
}

std::int64_t JobStore::append_event(const std::string& id, const std::string& kind,
                                    const std::string& data,
                                    const std::optional<JobProgress>& progress) {
  std::lock_guard lock(writer_mutex_);
  WriteTransaction tx(writer_, Durability::Flushed);  // one per solver event: no fsync each
  const std::int64_t seq = insert_event(writer_, id, kind, data);
  Statement st(writer_, "UPDATE jobs SET updated_ms = ?, progress = coalesce(?, progress) "
                        "WHERE id = ?");
  st.bind(1, now_ms());
  if (progress) st.bind(2, json_text(progress_to_json(*progress)));
  else st.bind_null(2);
  st.bind(3, id).run();
  tx.commit();
  changed();
  return seq;
}

std::vector<StoredEvent> JobStore::events_since(const std::string& id, std::int64_t since,
                                                const std::vector<std::string>& kinds,
                                                int limit) {
  std::string sql = "SELECT seq, run, kind, data FROM job_events WHERE job_id = ? AND seq > ?";
  if (!kinds.empty()) {
    sql += " AND kind IN (";
    for (std::size_t i = 0; i < kinds.size(); ++i) sql += i ? ", ?" : "?";
    sql += ")";
  }
  sql += " ORDER BY seq LIMIT ?";
  auto lease = read();
  Statement st(lease.db(), sql);
  int b = 1;
  st.bind(b++, id);
  st.bind(b++, since);
  for (const auto& k : kinds) st.bind(b++, k);
  st.bind(b, static_cast<std::int64_t>(limit));
  std::vector<StoredEvent> events;
  while (st.step())
    events.push_back({st.integer(0), static_cast<int>(st.integer(1)), st.text(2), st.text(3)});
  return events;
}

std::vector<Artifact> JobStore::artifacts(const std::string& id) {
  auto lease = read();
  Statement st(lease.db(), "SELECT name, media_type, size, sha256 FROM artifacts "
                           "WHERE job_id = ? ORDER BY name");
  st.bind(1, id);
  std::vector<Artifact> list;
  while (st.step()) list.push_back({st.text(0), st.text(1), st.integer(2), st.text(3)});
  return list;
}

std::int64_t JobStore::count_run_events(const std::string& id) {
  auto lease = read();
  Statement st(lease.db(), "SELECT COUNT(*) FROM job_events AS e JOIN jobs ON jobs.id = e.job_id "
                           "WHERE e.job_id = ? AND e.run = jobs.attempts AND e.kind != 'status'");
  st.bind(1, id);
  st.step();
  return st.integer(0);
}

StoreCounts JobStore::counts() {
  auto lease = read();
  Statement st(lease.db(), "SELECT status, COUNT(*) FROM jobs GROUP BY status");
  StoreCounts c;
  while (st.step()) {
    const auto status = status_from_name(st.text(0));
    const int n = static_cast<int>(st.integer(1));
    if (!status) continue;
    if (*status == JobStatus::Queued) c.queued = n;
    else if (*status == JobStatus::Running) c.running = n;
    else if (*status == JobStatus::Canceling) c.canceling = n;
    else c.finished[status_name(*status)] = n;
  }
  return c;
}

std::vector<LabelKeyCount> JobStore::label_keys() {
  auto lease = read();
  Statement st(lease.db(), "SELECT l.key, COUNT(*), MAX(jobs.created_ms) FROM jobs, "
                           "json_each(jobs.labels) AS l GROUP BY l.key "
                           "ORDER BY MAX(jobs.created_ms) DESC, l.key");
  std::vector<LabelKeyCount> keys;
  while (st.step())
    keys.push_back({st.text(0), static_cast<int>(st.integer(1)), st.integer(2)});
  return keys;
}

std::vector<double> JobStore::run_durations() {
  auto lease = read();
  Statement st(lease.db(), "SELECT finished_ms - started_ms FROM jobs "
                           "WHERE finished_ms IS NOT NULL AND started_ms IS NOT NULL");
  std::vector<double> seconds;
  while (st.step()) seconds.push_back(static_cast<double>(st.integer(0)) / 1000.0);
  return seconds;
}

std::vector<std::string> JobStore::all_ids() {
  auto lease = read();
  Statement st(lease.db(), "SELECT id FROM jobs");
  std::vector<std::string> ids;
  while (st.step()) ids.push_back(st.text(0));
  return ids;
}

void JobStore::on_next_change(std::uint64_t seen, std::weak_ptr<void> owner,
                              std::function<void()> wake) {
  {
    std::lock_guard lock(change_mutex_);
    if (generation_.load() == seen) {
      if (change_waiters_.size() >= prune_at_) {  // streams that closed while no job changed
        std::erase_if(change_waiters_, [](const ChangeWaiter& w) { return w.owner.expired(); });
        prune_at_ = std::max<std::size_t>(64, 2 * change_waiters_.size());
      }
      change_waiters_.push_back({std::move(owner), std::move(wake)});
      return;
    }
  }
  wake();
}

void JobStore::changed() {
  std::vector<ChangeWaiter> waiters;
  {
    std::lock_guard lock(change_mutex_);
    ++generation_;
    waiters.swap(change_waiters_);
  }
  for (const ChangeWaiter& w : waiters)
    if (!w.owner.expired()) w.wake();
}

}  // namespace kontakt::server

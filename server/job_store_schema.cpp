#include "server/job_store_schema.hpp"

#include <array>
#include <string>

namespace kontakt::server {

namespace {

/// Migration i takes the schema from version i to i + 1. Append only; never edit a released one.
constexpr std::array<const char*, 3> kMigrations{
    R"sql(
CREATE TABLE jobs (
  id              TEXT PRIMARY KEY,
  name            TEXT NOT NULL,
  status          TEXT NOT NULL,
  reason          TEXT NOT NULL DEFAULT '',
  message         TEXT NOT NULL DEFAULT '',
  main_file       TEXT NOT NULL,
  scheme          TEXT,
  labels          TEXT NOT NULL DEFAULT '{}',   -- JSON object
  created_ms      INTEGER NOT NULL,
  updated_ms      INTEGER NOT NULL,
  started_ms      INTEGER,
  finished_ms     INTEGER,
  attempts        INTEGER NOT NULL DEFAULT 0,
  n_steps         INTEGER NOT NULL DEFAULT 0,
  planned_time    REAL NOT NULL DEFAULT 0,
  progress        TEXT NOT NULL DEFAULT '{}',   -- JSON: JobProgress
  summary         TEXT,                         -- JSON: JobSummary, once finished
  idempotency_key TEXT UNIQUE,
  fingerprint     TEXT NOT NULL DEFAULT '',
  next_seq        INTEGER NOT NULL DEFAULT 1
);
CREATE INDEX jobs_by_created ON jobs (created_ms DESC, id DESC);
CREATE INDEX jobs_by_status ON jobs (status, created_ms);
CREATE TABLE job_events (
  job_id TEXT NOT NULL REFERENCES jobs (id) ON DELETE CASCADE,
  seq    INTEGER NOT NULL,
  run    INTEGER NOT NULL,
  kind   TEXT NOT NULL,
  data   TEXT NOT NULL,
  PRIMARY KEY (job_id, seq)
) WITHOUT ROWID;
CREATE TABLE artifacts (
  job_id     TEXT NOT NULL REFERENCES jobs (id) ON DELETE CASCADE,
  name       TEXT NOT NULL,
  media_type TEXT NOT NULL,
  size       INTEGER NOT NULL,
  sha256     TEXT NOT NULL,
  PRIMARY KEY (job_id, name)
) WITHOUT ROWID;
)sql",
    // The executor resources a submission asked for (job_resources.hpp), a JSON object.
    R"sql(
ALTER TABLE jobs ADD COLUMN resources TEXT NOT NULL DEFAULT '{}';
)sql",
    // Sweeps (POST /v1/sweeps): one record each, its rows are jobs with their row number.
    R"sql(
CREATE TABLE sweeps (
  id              TEXT PRIMARY KEY,
  name            TEXT NOT NULL,
  created_ms      INTEGER NOT NULL,
  n_rows          INTEGER NOT NULL,
  max_parallel    INTEGER NOT NULL,
  idempotency_key TEXT UNIQUE,
  fingerprint     TEXT NOT NULL DEFAULT ''
);
ALTER TABLE jobs ADD COLUMN sweep_id TEXT REFERENCES sweeps (id);
ALTER TABLE jobs ADD COLUMN sweep_row INTEGER NOT NULL DEFAULT 0;
CREATE INDEX jobs_by_sweep ON jobs (sweep_id, status) WHERE sweep_id IS NOT NULL;
)sql"};

int current_version(SqliteDb& db) {
  Statement st(db, "PRAGMA user_version");
  st.step();
  return static_cast<int>(st.integer(0));
}

}  // namespace

int schema_version() { return static_cast<int>(kMigrations.size()); }

void migrate(SqliteDb& db) {
  const int found = current_version(db);
  if (found > schema_version())
    throw StoreError("the job database has schema version " + std::to_string(found) +
                     ", newer than this kontaktd (" + std::to_string(schema_version()) + ")");
  for (int v = found; v < schema_version(); ++v) {
    WriteTransaction tx(db);
    db.exec(kMigrations[static_cast<std::size_t>(v)]);
    db.exec("PRAGMA user_version = " + std::to_string(v + 1));
    tx.commit();
  }
}

}  // namespace kontakt::server

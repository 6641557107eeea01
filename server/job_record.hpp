// Plain data the job store keeps and hands out: one job's record, its events and artifacts.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "server/job_resources.hpp"
#include "server/job_state.hpp"

namespace kontakt::server {

/// Where the solver is, from the latest step/increment/iteration event of the current run.
struct JobProgress {
  int step = 0, increment = 0, attempt = 0, iteration = 0;
  double step_time = 0, total_time = 0, dt = 0;
  std::optional<double> residual;          ///< ccx residual ratio in %, from the last iteration
  std::optional<int> contact_elements;     ///< active contact elements; none without contact
};

/// The scalar outcome of a finished run: counts for every run, result figures from the
/// solver's Done event of a converged one.
struct JobSummary {
  int iterations = 0;               ///< Newton iterations (every attempt)
  double wall_time = 0;             ///< seconds the run took
  std::optional<double> max_displacement, max_mises;       ///< converged runs
  std::optional<double> max_contact_pressure, total_contact_force;  ///< converged contact runs
};

struct JobRecord {
  std::string id;                    ///< 32 hex digits, random
  std::string name;
  JobStatus status = JobStatus::Queued;
  std::string reason;                ///< not_converged, input_error, ...; empty when none
  std::string message;               ///< human-readable detail of the reason
  std::string main_file;             ///< the deck, relative to the job's input folder
  std::optional<std::string> scheme; ///< contact scheme override
  std::map<std::string, std::string> labels;
  std::int64_t created_ms = 0, updated_ms = 0;  ///< Unix time in milliseconds
  std::optional<std::int64_t> started_ms, finished_ms;
  int attempts = 0;                  ///< runs started (a requeued job runs again)
  int n_steps = 0;
  double planned_time = 0;           ///< sum of the step periods, for the progress fraction
  JobProgress progress;
  std::optional<JobSummary> summary;
  std::optional<std::string> idempotency_key;
  std::string fingerprint;           ///< sha256 of the submission, to check key reuse
  JobResources resources;            ///< the submission's own, over the executor's defaults
  std::optional<std::string> sweep_id;  ///< a row of this sweep (POST /v1/sweeps)
  int sweep_row = 0;                 ///< 0-based row in its sweep (the Slurm array index)
};

/// What a submission stores; the store fills in status, times and counters.
struct NewJob {
  std::string id, name, main_file;
  std::optional<std::string> scheme;
  std::map<std::string, std::string> labels;
  int n_steps = 0;
  double planned_time = 0;
  std::optional<std::string> idempotency_key;
  std::string fingerprint;
  JobResources resources;
  std::optional<std::string> sweep_id;  ///< set by insert_sweep
  int sweep_row = 0;
};

/// A sweep (POST /v1/sweeps): its rows are jobs (JobRecord::sweep_id), each labelled
/// sweep=<id> and with its parameter values.
struct SweepRecord {
  std::string id;                    ///< 32 hex digits, random
  std::string name;
  std::int64_t created_ms = 0;
  int n_rows = 0;
  int max_parallel = 0;              ///< rows running at once, at most
  std::optional<std::string> idempotency_key;
  std::string fingerprint;
};

/// One entry of a job's event log; `seq` is the SSE id and the `since` cursor.
struct StoredEvent {
  std::int64_t seq = 0;
  int run = 0;                       ///< the attempt that produced it
  std::string kind;                  ///< status, step, increment, iteration, cutback, ..., done
  std::string data;                  ///< the event as a JSON object
};

/// A published result file.
struct Artifact {
  std::string name, media_type;
  std::int64_t size = 0;
  std::string sha256;                ///< lower-case hex
};

}  // namespace kontakt::server

// The JSON documents of the API (schemas in proto/openapi.yaml): the job status document,
// the summary, the artifact list, the queue, sweeps, and RFC 3339 times.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "server/job_record.hpp"
#include "server/job_store.hpp"

namespace kontakt::server {

/// Serialised JSON that never throws: bytes that are not UTF-8 (a name, a label or a deck's
/// line quoted in a message) become U+FFFD instead of a type_error.
std::string json_text(const nlohmann::json& j);

/// "2026-11-22T10:00:00.123Z".
std::string rfc3339(std::int64_t unix_ms);

/// The status document: identity, status and reason, timestamps, progress, links.
/// `queue_position` is set for queued jobs.
nlohmann::json job_document(const JobRecord& job, std::optional<int> queue_position,
                            bool results_available);

/// GET /v1/jobs/{id}/summary: what a design loop reads.
nlohmann::json summary_document(const JobRecord& job);

nlohmann::json artifacts_document(const std::vector<Artifact>& artifacts);

/// GET /v1/queue: jobs per state and the workers' use.
nlohmann::json queue_document(const StoreCounts& counts, int workers, int busy_workers);

/// GET /v1/sweeps: the label keys in use.
nlohmann::json sweep_list_document(const std::vector<LabelKeyCount>& keys);

/// One row of GET /v1/sweeps/{key}: the summary plus the job's value of `key`, its scheme and
/// times.
nlohmann::json sweep_row_document(const JobRecord& job, const std::string& key);

/// GET /v1/sweeps/id/{id}: a sweep made by POST /v1/sweeps, its jobs counted by status
/// (`counts`: status name -> jobs), and its Slurm array's id once submitted.
nlohmann::json sweep_document(const SweepRecord& sweep, const std::map<std::string, int>& counts,
                              const std::optional<std::string>& slurm_array_id);

/// One job of GET /v1/sweeps/id/{id}/jobs: its row, the summary, its labels.
nlohmann::json sweep_job_document(const JobRecord& job);

}  // namespace kontakt::server

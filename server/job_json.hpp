// The JSON documents of the API (schemas in proto/openapi.yaml): the job status document,
// the summary, the artifact list, and RFC 3339 times.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "server/job_record.hpp"

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

}  // namespace kontakt::server

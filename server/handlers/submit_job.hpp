// POST /v1/jobs and POST /v1/jobs/{id}/resubmit: check the submission, store the deck, parse
// it, and only then queue it.
#pragma once

#include <optional>
#include <string>

#include "server/handlers/api_context.hpp"
#include "server/http_types.hpp"

namespace kontakt::server::handlers {

/// Bodies: text/plain or application/octet-stream (one .inp), application/zip (?main= names
/// the deck), application/json {"deck": "...", "name", "scheme", "labels", "main"}. Options
/// also as query parameters name=, scheme=, label=k=v (repeatable). 201 + Location + status
/// document; 400 for a bad option (naming it), 415 for another body type, 422 for a deck the
/// reader refuses (file, line, keyword, message) or a reused Idempotency-Key.
HttpResponse submit_job(ApiContext& ctx, const HttpRequest& request);

/// POST /v1/jobs/{id}/resubmit: a new job from the input of job `source_id` (its deck and
/// *INCLUDE files, copied), with the source's name, scheme and labels unless the JSON body
/// sets "name", "scheme" (null: the deck's own) or "labels". Idempotency-Key as for submit.
HttpResponse resubmit_job(ApiContext& ctx, const HttpRequest& request, const std::string& source_id);

/// Shared with POST /v1/sweeps (submit_sweep.hpp):
/// The Idempotency-Key header: nullopt when absent; a 400 when malformed.
std::optional<HttpResponse> read_key(const HttpRequest& request, std::optional<std::string>& key);
/// 422: the key was used for a different submission.
HttpResponse key_reused();
/// Checks the deck in place in the job's input folder (in a worker process) and records its
/// steps and time in `job`; a 422 when the reader refuses it or the check itself fails.
std::optional<HttpResponse> check_stored_deck(ApiContext& ctx, NewJob& job);

}  // namespace kontakt::server::handlers

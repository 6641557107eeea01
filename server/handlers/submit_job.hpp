// POST /v1/jobs and POST /v1/jobs/{id}/resubmit: check the submission, store the deck, parse
// it, and only then queue it.
#pragma once

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

}  // namespace kontakt::server::handlers

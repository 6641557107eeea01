// POST /v1/jobs: check the submission, store the deck, parse it, and only then queue it.
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

}  // namespace kontakt::server::handlers

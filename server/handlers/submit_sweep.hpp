// POST /v1/sweeps: a parametric study as one request. The body (application/json) is a deck
// template with `<name>` placeholders and a parameter table, or a list of complete decks:
//   {"template": "...", "rows": [{"t": 1.5, "mu": "0.2"}, ...]}  or  {"decks": ["...", ...]}
// with the options of a job submission ("name", "labels", "scheme", "resources") and
// "max_parallel" (rows running at once; default: all). Everything is checked before anything
// is stored; each row's deck goes through the deck check of POST /v1/jobs, and one refused
// deck refuses the whole sweep (422 naming the row), so a pipeline never gets half a study.
// Each row becomes a queued job, labelled sweep=<id> and with its parameter values.
#pragma once

#include "server/handlers/api_context.hpp"
#include "server/http_types.hpp"

namespace kontakt::server::handlers {

/// 201 + Location + the sweep document; 400 naming the bad field; 415 for a body that is not
/// JSON; 422 for a refused row (its row, file, line, keyword, message) or a reused
/// Idempotency-Key.
HttpResponse submit_sweep(ApiContext& ctx, const HttpRequest& request);

/// The sweep document with its Slurm array id (DATA/sweeps/ID/slurm/array_id) when it has one.
nlohmann::json sweep_document_of(ApiContext& ctx, const SweepRecord& sweep);

}  // namespace kontakt::server::handlers

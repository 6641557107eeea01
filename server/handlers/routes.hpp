// The API's routes, registered per resource family.
#pragma once

#include "server/handlers/api_context.hpp"
#include "server/router.hpp"

namespace kontakt::server::handlers {

/// POST/GET /v1/jobs, GET/DELETE /v1/jobs/{id}, POST /v1/jobs/{id}/cancel, /resubmit.
void add_job_routes(Router& router, ApiContext& ctx);
/// GET /v1/jobs/{id}/events (SSE), /iterations, /increments.
void add_event_routes(Router& router, ApiContext& ctx);
/// GET /v1/jobs/{id}/results, /results/{name}, /summary.
void add_result_routes(Router& router, ApiContext& ctx);
/// GET /v1/sweeps (label keys in use), /v1/sweeps/{key} (one summary row per job);
/// POST /v1/sweeps, GET /v1/sweeps/id/{id}, /v1/sweeps/id/{id}/jobs, POST .../cancel.
void add_sweep_routes(Router& router, ApiContext& ctx);
/// GET /healthz, /metrics, /v1/queue, /v1/openapi.json, and the dashboard: / (job list),
/// /jobs/{id} (job page), /sweeps (sweep page), /assets/{name}.
void add_service_routes(Router& router, ApiContext& ctx);

/// All of the above: the daemon's router.
Router make_router(ApiContext& ctx);

}  // namespace kontakt::server::handlers

// Canceling one job, for POST /v1/jobs/{id}/cancel and POST /v1/sweeps/id/{id}/cancel.
#pragma once

#include <optional>
#include <string>

#include "server/handlers/api_context.hpp"

namespace kontakt::server::handlers {

/// Queued -> canceled (and its run stopped if an executor started it ahead of its claim),
/// running -> canceling (its run is stopped); other states unchanged. The job as it is now;
/// nullopt when there is no such job.
std::optional<JobRecord> cancel_one(ApiContext& ctx, const std::string& id);

}  // namespace kontakt::server::handlers

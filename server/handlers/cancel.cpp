#include "server/handlers/cancel.hpp"

namespace kontakt::server::handlers {

std::optional<JobRecord> cancel_one(ApiContext& ctx, const std::string& id) {
  // The flag goes up before the store records `canceling`, so every solver event stored after
  // that status comes from the one iteration in flight (a no-op for jobs not running).
  ctx.control.cancel_running(id);
  const auto before = ctx.store.find_job(id);
  const auto job = ctx.store.request_cancel(id);
  if (!job) return std::nullopt;
  if (job->status == JobStatus::Canceling) ctx.control.cancel_running(id);
  if (before && before->status == JobStatus::Queued && job->status == JobStatus::Canceled)
    ctx.control.cancel_unclaimed(id);
  return job;
}

}  // namespace kontakt::server::handlers

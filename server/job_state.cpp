#include "server/job_state.hpp"

#include <array>
#include <utility>

namespace kontakt::server {

namespace {

using S = JobStatus;

/// Every allowed (from, to) pair; anything else is refused.
constexpr std::array<std::pair<S, S>, 7> kTransitions{{
    {S::Queued, S::Running},      // a worker claims it
    {S::Queued, S::Canceled},     // cancelled before it started
    {S::Running, S::Succeeded},   // converged
    {S::Running, S::Failed},      // not converged, input or solver error, time limit, worker lost
    {S::Running, S::Canceling},   // cancel requested; the solver stops at its next iteration
    {S::Running, S::Queued},      // drain or restart after a lost worker
    {S::Canceling, S::Canceled},  // however the run ended: a granted cancel request wins
}};

constexpr std::array<const char*, 6> kNames{"queued",    "running", "canceling",
                                            "succeeded", "failed",  "canceled"};

}  // namespace

const char* status_name(JobStatus status) { return kNames[static_cast<std::size_t>(status)]; }

std::optional<JobStatus> status_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (name == kNames[i]) return static_cast<JobStatus>(i);
  return std::nullopt;
}

bool is_terminal(JobStatus status) {
  return status == S::Succeeded || status == S::Failed || status == S::Canceled;
}

bool transition_allowed(JobStatus from, JobStatus to) {
  for (const auto& [a, b] : kTransitions)
    if (a == from && b == to) return true;
  return false;
}

}  // namespace kontakt::server

// The job state machine of the API (ecosystem notes section 1.6):
//
//   queued ──► running ──► succeeded | failed        (reason: not_converged, input_error, ...)
//     │           ├──────► canceling ──► canceled     (whatever the run's own outcome)
//     │           └──────► queued                     (requeued after a drain or a lost worker)
//     └──────────────────► canceled                   (cancelled before it started)
//
// Every status change in the store goes through transition_allowed.
#pragma once

#include <optional>
#include <string_view>

namespace kontakt::server {

enum class JobStatus { Queued, Running, Canceling, Succeeded, Failed, Canceled };

/// The API spelling: queued, running, canceling, succeeded, failed, canceled.
const char* status_name(JobStatus status);
std::optional<JobStatus> status_from_name(std::string_view name);

/// succeeded, failed and canceled: the job will not change again.
bool is_terminal(JobStatus status);

/// The one transition table of the job state machine.
bool transition_allowed(JobStatus from, JobStatus to);

/// Every reason code a job or its status events can carry: proto/openapi.yaml's ReasonCode
/// (a test holds the two equal). job_outcome.hpp says when each applies.
inline constexpr std::string_view kReasonCodes[] = {
    "not_converged", "input_error", "solver_error", "solver_crashed", "memory_limit",
    "time_limit",    "disk_full",   "file_size_limit", "worker_lost", "internal",
    "canceled",      "requeued",    "executor_refused"};

}  // namespace kontakt::server

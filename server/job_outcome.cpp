#include "server/job_outcome.hpp"

#include <csignal>
#include <cstdio>

namespace kontakt::server {

namespace {

using Action = JobVerdict::Action;
using worker::Exit;

JobVerdict finish(JobStatus status, std::string reason, std::string message,
                  bool keep_results = true) {
  return {.action = Action::Finish, .status = status, .reason = std::move(reason),
          .message = std::move(message), .keep_results = keep_results};
}

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", s);
  return text;
}

/// "what: the solver's own words" when the done event said something.
std::string with_detail(const std::string& what, const ProcessEnd& end) {
  const std::string said = end.done ? end.done->message : "";
  return said.empty() ? what : what + ": " + said;
}

std::string killed_note(const ProcessEnd& end) {
  return end.killed ? " (the solver did not stop within the grace period and was killed; the "
                      "results of converged increments are kept)"
                    : "";
}

/// A process stopped because the daemon asked it to (cancel, time limit, drain).
JobVerdict stopped_on_request(const ProcessEnd& end, const OutcomeContext& context) {
  switch (end.cause) {
    case StopCause::Drain: return {.action = Action::Requeue};
    case StopCause::Request: return finish(JobStatus::Canceled, "canceled", "canceled" + killed_note(end));
    case StopCause::TimeLimit:
      return finish(JobStatus::Failed, "time_limit",
                    "stopped at the wall-time limit of " + seconds(context.time_limit) +
                        killed_note(end));
    case StopCause::None: break;
  }
  return finish(JobStatus::Failed, "internal", "stopped without a cause");
}

JobVerdict crashed(const ProcessEnd& end, const OutcomeContext& context) {
  std::string message = "the solver process died with " + describe(end.exit);
  if (end.exit.code == SIGKILL) {
    message += ", sent from outside the daemon (the system's out-of-memory killer?)";
    // Killed from outside, not by the deck: worth another run, as after a daemon crash.
    if (context.attempts < context.max_attempts)
      return {.action = Action::Retry, .status = JobStatus::Queued, .reason = "requeued",
              .message = message + "; run again"};
  }
  return finish(JobStatus::Failed, "solver_crashed",
                message + " (after " + std::to_string(end.n_events) + " events)");
}

}  // namespace

JobVerdict judge(const ProcessEnd& end, const OutcomeContext& context) {
  const bool ours = end.cause != StopCause::None;
  if (end.failure)
    return ours ? stopped_on_request(end, context)
                : finish(JobStatus::Failed, end.failure->reason, end.failure->message);
  if (end.exit.signaled) return ours ? stopped_on_request(end, context) : crashed(end, context);
  switch (static_cast<Exit>(end.exit.code)) {
    case Exit::Converged: return finish(JobStatus::Succeeded, "", "");
    case Exit::Cancelled:
      if (ours) return stopped_on_request(end, context);
      return finish(JobStatus::Failed, "solver_crashed",
                    "the solver process was stopped by a signal the daemon did not send");
    case Exit::NotConverged:
      return finish(JobStatus::Failed, "not_converged", with_detail("not converged", end));
    case Exit::InputError:
      return finish(JobStatus::Failed, "input_error", with_detail("input error", end));
    case Exit::SolverError:
      return finish(JobStatus::Failed, "solver_error", with_detail("solver error", end));
    case Exit::OutOfMemory:
      return finish(JobStatus::Failed, "memory_limit",
                    context.limits.memory_bytes
                        ? "the run needed more than the memory limit of " +
                              worker::byte_size(context.limits.memory_bytes) + " (--job-memory-limit)"
                        : "the run ran out of memory");
    case Exit::DiskFull:
      return finish(JobStatus::Failed, "disk_full",
                    with_detail("no space left for the results in the data folder; the "
                                "unfinished files were removed",
                                end),
                    false);
    case Exit::FileSizeLimit:
      return finish(JobStatus::Failed, "file_size_limit",
                    with_detail("a result file reached the file size limit of " +
                                    worker::byte_size(context.limits.file_size_bytes) +
                                    " (--job-file-size-limit); the unfinished files were removed",
                                end),
                    false);
    case Exit::Usage: break;
  }
  return finish(JobStatus::Failed, "internal",
                "the job process ended with " + describe(end.exit));
}

}  // namespace kontakt::server

// The verdict on a job process that has ended: the job's status, reason code and message, and
// whether the job is finished, requeued (a drain: the attempt does not count) or run again (a
// process killed from outside the daemon: counted against --max-attempts). Pure.
//
// Reason codes of failed jobs (proto/openapi.yaml, Reason): not_converged, input_error,
// solver_error, solver_crashed (a signal: named in the message), memory_limit, time_limit,
// disk_full, file_size_limit, internal; worker_lost comes from recovery after a daemon crash,
// or from an executor that lost the run (ProcessEnd::failure, e.g. a Slurm NODE_FAIL).
#pragma once

#include <string>

#include "server/job_state.hpp"
#include "server/job_supervisor.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server {

struct OutcomeContext {
  int attempts = 1;       ///< runs started, this one included
  int max_attempts = 3;
  double time_limit = 0;  ///< seconds, for the message
  worker::Limits limits{};  ///< for the messages
};

struct JobVerdict {
  enum class Action { Finish, Requeue, Retry };
  Action action = Action::Finish;
  JobStatus status = JobStatus::Failed;
  std::string reason{}, message{};
  /// Publish the work folder. False when a full disk cut the files short: nothing is published
  /// and the folder is removed (which also gives the store its space back).
  bool keep_results = true;
};

JobVerdict judge(const ProcessEnd& end, const OutcomeContext& context);

}  // namespace kontakt::server

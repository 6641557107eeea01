// The verdict on an ended job process: every exit code and signal, with and without a stop
// request from the daemon.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <nlohmann/json.hpp>

#include "server/embedded_assets.hpp"
#include "server/job_outcome.hpp"

namespace kontakt::server {
namespace {

using Action = JobVerdict::Action;
using worker::Exit;

ProcessEnd exited(Exit code, StopCause cause = StopCause::None, std::string said = {}) {
  ProcessEnd end;
  end.exit = {.signaled = false, .code = static_cast<int>(code)};
  end.cause = cause;
  if (!said.empty()) end.done = analysis::Event{.kind = analysis::Event::Kind::Done, .message = said};
  return end;
}

ProcessEnd signaled(int signal, StopCause cause = StopCause::None, bool killed = false) {
  ProcessEnd end;
  end.exit = {.signaled = true, .code = signal};
  end.cause = cause;
  end.killed = killed;
  end.n_events = 7;
  return end;
}

const OutcomeContext kContext{.attempts = 1, .max_attempts = 3, .time_limit = 2.5,
                              .limits = {.memory_bytes = 512ull << 20,
                                         .file_size_bytes = 1ull << 20}};

bool known(const std::string& reason) {
  return reason.empty() ||
         std::find(std::begin(kReasonCodes), std::end(kReasonCodes), reason) != std::end(kReasonCodes);
}

TEST(JobOutcome, ReasonCodesAreTheOpenApiEnum) {
  const auto asset = find_asset("v1/openapi.json");
  ASSERT_TRUE(asset.has_value());
  const auto doc = nlohmann::json::parse(asset->body);
  const auto listed = doc["components"]["schemas"]["ReasonCode"]["enum"].get<std::vector<std::string>>();
  EXPECT_EQ(listed, std::vector<std::string>(std::begin(kReasonCodes), std::end(kReasonCodes)));
}

TEST(JobOutcome, ExitCodesMapToStatusAndReason) {
  struct Case {
    Exit code;
    JobStatus status;
    const char* reason;
  };
  for (const Case& c : {Case{Exit::Converged, JobStatus::Succeeded, ""},
                        Case{Exit::NotConverged, JobStatus::Failed, "not_converged"},
                        Case{Exit::InputError, JobStatus::Failed, "input_error"},
                        Case{Exit::SolverError, JobStatus::Failed, "solver_error"},
                        Case{Exit::OutOfMemory, JobStatus::Failed, "memory_limit"},
                        Case{Exit::DiskFull, JobStatus::Failed, "disk_full"},
                        Case{Exit::FileSizeLimit, JobStatus::Failed, "file_size_limit"},
                        Case{Exit::Usage, JobStatus::Failed, "internal"}}) {
    const JobVerdict v = judge(exited(c.code, StopCause::None, "details"), kContext);
    EXPECT_TRUE(known(v.reason)) << v.reason;
    EXPECT_EQ(v.action, Action::Finish);
    EXPECT_EQ(v.status, c.status) << c.reason;
    EXPECT_EQ(v.reason, c.reason);
  }
  EXPECT_EQ(judge(exited(Exit::NotConverged, StopCause::None, "min increment"), kContext).message,
            "not converged: min increment");
  EXPECT_NE(judge(exited(Exit::OutOfMemory), kContext).message.find("512 MiB"), std::string::npos);
}

TEST(JobOutcome, AFullDiskKeepsNoHalfWrittenResults) {
  EXPECT_FALSE(judge(exited(Exit::DiskFull), kContext).keep_results);
  EXPECT_FALSE(judge(exited(Exit::FileSizeLimit), kContext).keep_results);
  EXPECT_TRUE(judge(exited(Exit::NotConverged), kContext).keep_results);
  EXPECT_TRUE(judge(signaled(SIGSEGV), kContext).keep_results);
}

TEST(JobOutcome, ACrashFailsTheJobNamingTheSignal) {
  const JobVerdict v = judge(signaled(SIGSEGV), kContext);
  EXPECT_EQ(v.action, Action::Finish);
  EXPECT_EQ(v.status, JobStatus::Failed);
  EXPECT_EQ(v.reason, "solver_crashed");
  EXPECT_NE(v.message.find("SIGSEGV"), std::string::npos) << v.message;
  EXPECT_NE(v.message.find("7 events"), std::string::npos) << v.message;
}

TEST(JobOutcome, AKillFromOutsideRunsTheJobAgainUntilMaxAttempts) {
  const JobVerdict again = judge(signaled(SIGKILL), kContext);
  EXPECT_EQ(again.action, Action::Retry);
  EXPECT_NE(again.message.find("SIGKILL"), std::string::npos);
  OutcomeContext last = kContext;
  last.attempts = 3;
  const JobVerdict failed = judge(signaled(SIGKILL), last);
  EXPECT_EQ(failed.action, Action::Finish);
  EXPECT_EQ(failed.reason, "solver_crashed");
}

TEST(JobOutcome, StopsTheDaemonAskedFor) {
  // Clean stop at an iteration or SIGKILL after the grace period: the same verdict.
  for (const ProcessEnd& end : {exited(Exit::Cancelled, StopCause::Request),
                                signaled(SIGKILL, StopCause::Request, true),
                                signaled(SIGTERM, StopCause::Request)}) {
    const JobVerdict v = judge(end, kContext);
    EXPECT_EQ(v.status, JobStatus::Canceled);
    EXPECT_EQ(v.action, Action::Finish);
  }
  const JobVerdict late = judge(signaled(SIGKILL, StopCause::TimeLimit, true), kContext);
  EXPECT_EQ(late.reason, "time_limit");
  EXPECT_NE(late.message.find("2.5 s"), std::string::npos);
  EXPECT_NE(late.message.find("killed"), std::string::npos);
  EXPECT_EQ(judge(exited(Exit::Cancelled, StopCause::Drain), kContext).action, Action::Requeue);
  EXPECT_EQ(judge(signaled(SIGKILL, StopCause::Drain, true), kContext).action, Action::Requeue);
  // A run that converged before the stop took effect keeps its success.
  EXPECT_EQ(judge(exited(Exit::Converged, StopCause::TimeLimit), kContext).status,
            JobStatus::Succeeded);
  // SIGTERM from someone else: not a cancel.
  EXPECT_EQ(judge(exited(Exit::Cancelled), kContext).reason, "solver_crashed");
}

}  // namespace
}  // namespace kontakt::server

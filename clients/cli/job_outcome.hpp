// Exit codes of the daemon commands, so shell pipelines can tell outcomes apart, and the
// one-line progress display of `kontakt wait`.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace kontakt::cli {

enum ExitCode {
  kSucceeded = 0,
  kUsage = 1,
  kInputError = 2,    ///< as `kontakt solve`
  kNotConverged = 3,  ///< as `kontakt solve`
  kFailed = 4,        ///< any other failure: solver error, time limit, worker lost
  kCanceled = 5,
  kTransport = 6,     ///< could not reach the daemon, or it refused the request
  kWaitTimeout = 7,   ///< `wait --timeout` expired first
};

/// The exit code for a finished job's status document (status + reason.code).
int exit_code_for_job(const nlohmann::json& job);

/// "running  step 1/2  inc 3  it 4  [#####-----]  52%  res 1.2e-03  ce 14"; `width` is the
/// bar's length in characters.
std::string progress_line(const nlohmann::json& job, int width);

}  // namespace kontakt::cli

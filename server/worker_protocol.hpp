// The contract between kontaktd and the processes it starts for deck checks and jobs
// (`kontaktd job-worker check|run ...`, server/job_worker.cpp): the command line, the report
// pipe on descriptor 3 and the exit codes. Both sides build and read the command line here.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace kontakt::server::worker {

/// argv[1] of a worker process. `kontaktd job-worker standby PARENT_PID` waits for its work:
/// one line on stdin, the JSON array of to_argv(); `kontaktd job-worker ARGS...` (to_argv(),
/// by hand) works at once.
inline constexpr const char* kCommand = "job-worker";
inline constexpr const char* kStandby = "standby";

/// A run writes its solver events here as JSON lines (the `Event` schema); a check writes one
/// JSON line with its result (deck_check.hpp).
inline constexpr int kReportFd = 3;

/// How a worker ended; the last `done` event (run) or the result line (check) says more.
enum class Exit : int {
  Converged = 0,       ///< run converged; check: the deck is valid
  Usage = 1,           ///< bad worker command line (a daemon bug)
  InputError = 2,      ///< the deck was refused
  NotConverged = 3,
  SolverError = 4,     ///< numerical or internal error
  Cancelled = 5,       ///< stopped by SIGTERM/SIGINT at an iteration boundary
  OutOfMemory = 6,     ///< an allocation failed (the memory limit)
  DiskFull = 7,        ///< a result could not be written: no space left
  FileSizeLimit = 8,   ///< a result file reached the file size limit
};

enum class Mode { Check, Run };

/// Per-process resource limits; 0 = none.
struct Limits {
  std::uint64_t memory_bytes = 0;     ///< RLIMIT_AS
  std::uint64_t file_size_bytes = 0;  ///< RLIMIT_FSIZE
};

/// "256 KiB", "400 MiB", "8 GiB", "12345 bytes": a limit in the words of the messages.
std::string byte_size(std::uint64_t bytes);

struct Args {
  Mode mode = Mode::Run;
  std::filesystem::path deck{};
  std::optional<std::string> scheme{};
  Limits limits{};
  long parent_pid = 0;  ///< the worker exits when this process is gone (checked at start)
  // Run only:
  std::filesystem::path out_dir{};
  std::string job_name{};
  int threads = 1;
  /// When set, the run's end is written here too (for executors that are not its parent).
  std::filesystem::path outcome_file{};
};

/// The outcome file of a run: `{"exit_code": N}` (an Exit), written once the run has ended.
std::string outcome_text(Exit exit);
/// The exit code in an outcome file; nullopt when it is not one (cut short, garbled).
std::optional<int> parse_outcome(const std::string& text);

/// The arguments after kCommand.
std::vector<std::string> to_argv(const Args& args);

/// Inverse of to_argv (argv after kCommand); a message naming the bad argument otherwise.
std::variant<Args, std::string> parse_args(const std::vector<std::string>& argv);

}  // namespace kontakt::server::worker

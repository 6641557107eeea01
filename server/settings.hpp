// kontaktd's settings: defaults, then environment variables (KONTAKTD_*), then the command
// line. Pure: the caller passes argv and an environment lookup, so tests need no process.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "server/job_resources.hpp"

namespace kontakt::server {

struct Settings {
  unsigned short port = 8080;            ///< 0 = any free port (printed at start)
  std::string bind = "127.0.0.1";        ///< loopback unless asked otherwise
  std::string data_dir = "kontaktd-data";
  int workers = 2;                       ///< jobs run at once
  int threads_per_job = 1;               ///< solver threads of each job
  std::uint64_t max_body = 64ull << 20;  ///< request body limit, bytes (413 above)
  std::string token_file;                ///< bearer tokens, one per line; empty = no auth
  int request_timeout = 30;              ///< seconds to read a request or write a response
  double job_time_limit = 0;             ///< wall-time seconds per run; 0 = none
  std::uint64_t job_memory_limit = 0;    ///< address space of a job's process, bytes; 0 = none
  std::uint64_t job_file_size_limit = 0; ///< largest file a job may write, bytes; 0 = none
  double kill_grace = 2;                 ///< seconds from SIGTERM to SIGKILL of a stopped job
  int max_attempts = 3;                  ///< runs lost to crashes before a job fails
  double drain_timeout = 10;             ///< seconds running jobs get to finish on SIGTERM
  int io_threads = 2;
  int handler_threads = 4;
  std::string executor = "local";        ///< local (worker processes) or slurm (sbatch)
  JobResources slurm;                    ///< --slurm-*: the defaults of every Slurm job
};

/// The usage text, listing every option and its variable.
std::string settings_usage();

/// Settings from `args` (argv without the program name) over `getenv`. A string is an error
/// message naming the option; "help" when --help was given.
std::variant<Settings, std::string> parse_settings(
    const std::vector<std::string>& args,
    const std::function<std::optional<std::string>(const std::string&)>& getenv);

/// The tokens of a token file: one per line, blank lines and '#' comments skipped.
std::vector<std::string> parse_token_file(const std::string& text);

}  // namespace kontakt::server

#include "server/settings.hpp"

#include <cmath>
#include <cstdlib>

namespace kontakt::server {

namespace {

/// One option: its flag, its environment variable, and how to store a value.
struct Option {
  const char* flag;
  const char* env;
  const char* help;
  std::function<std::optional<std::string>(Settings&, const std::string&)> set;  ///< error
};

std::optional<long long> whole_number(const std::string& v) {
  if (v.empty()) return std::nullopt;
  char* end = nullptr;
  const long long n = std::strtoll(v.c_str(), &end, 10);
  if (*end) return std::nullopt;
  return n;
}

auto integer_in(int Settings::*field, long long lo, long long hi) {
  return [field, lo, hi](Settings& s, const std::string& v) -> std::optional<std::string> {
    const auto n = whole_number(v);
    if (!n || *n < lo || *n > hi)
      return "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
    s.*field = static_cast<int>(*n);
    return std::nullopt;
  };
}

auto seconds(double Settings::*field) {
  return [field](Settings& s, const std::string& v) -> std::optional<std::string> {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || !std::isfinite(x) || x < 0) return "a number of seconds >= 0";
    s.*field = x;
    return std::nullopt;
  };
}

/// "64M", "512K", "1G" or bytes, from `min` to `max` bytes; 0 too when `zero_is_none`.
auto bytes(std::uint64_t Settings::*field, std::uint64_t min, std::uint64_t max,
           bool zero_is_none = false) {
  return [=](Settings& s, const std::string& v) -> std::optional<std::string> {
    const std::string expected = std::string(zero_is_none ? "0 (none) or " : "") +
                                 "a size such as 65536, 512K, 64M or 1G, from " +
                                 std::to_string(min) + " bytes to " + std::to_string(max >> 30) +
                                 "G";
    if (v.empty()) return expected;
    std::uint64_t scale = 1;
    std::string digits = v;
    switch (v.back()) {
      case 'K': case 'k': scale = 1ull << 10; digits.pop_back(); break;
      case 'M': case 'm': scale = 1ull << 20; digits.pop_back(); break;
      case 'G': case 'g': scale = 1ull << 30; digits.pop_back(); break;
      default: break;
    }
    const auto n = whole_number(digits);
    if (n && *n == 0 && zero_is_none) {
      s.*field = 0;
      return std::nullopt;
    }
    if (!n || *n < 0 || static_cast<std::uint64_t>(*n) > max / scale ||
        static_cast<std::uint64_t>(*n) * scale < min)
      return expected;
    s.*field = static_cast<std::uint64_t>(*n) * scale;
    return std::nullopt;
  };
}

/// A --slurm-* option checked by `check` (job_resources.hpp) into `field`.
auto slurm_text(std::optional<std::string> JobResources::*field,
                std::optional<std::string> (*check)(const std::string&)) {
  return [=](Settings& s, const std::string& v) -> std::optional<std::string> {
    if (auto bad = check(v)) return bad;
    s.slurm.*field = v;
    return std::nullopt;
  };
}

const std::vector<Option>& options() {
  static const std::vector<Option> kOptions{
      {"--port", "KONTAKTD_PORT", "TCP port (default 8080; 0 = any free port)",
       [](Settings& s, const std::string& v) -> std::optional<std::string> {
         const auto n = whole_number(v);
         if (!n || *n < 0 || *n > 65535) return "a port from 0 to 65535";
         s.port = static_cast<unsigned short>(*n);
         return std::nullopt;
       }},
      {"--bind", "KONTAKTD_BIND", "address to listen on (default 127.0.0.1)",
       [](Settings& s, const std::string& v) -> std::optional<std::string> {
         if (v.empty()) return "an IP address";
         s.bind = v;
         return std::nullopt;
       }},
      {"--data-dir", "KONTAKTD_DATA_DIR", "SQLite database and job folders (default ./kontaktd-data)",
       [](Settings& s, const std::string& v) -> std::optional<std::string> {
         if (v.empty()) return "a folder";
         s.data_dir = v;
         return std::nullopt;
       }},
      {"--workers", "KONTAKTD_WORKERS", "jobs run at once (default 2)",
       integer_in(&Settings::workers, 1, 256)},
      {"--threads-per-job", "KONTAKTD_THREADS_PER_JOB", "solver threads per job (default 1)",
       integer_in(&Settings::threads_per_job, 1, 1024)},
      {"--max-body", "KONTAKTD_MAX_BODY", "request body limit, e.g. 64M (default 64M)",
       bytes(&Settings::max_body, 1, 16ull << 30)},
      {"--token-file", "KONTAKTD_TOKEN_FILE", "bearer tokens, one per line (default: no auth)",
       [](Settings& s, const std::string& v) -> std::optional<std::string> {
         s.token_file = v;
         return std::nullopt;
       }},
      {"--request-timeout", "KONTAKTD_REQUEST_TIMEOUT", "seconds to read a request (default 30)",
       integer_in(&Settings::request_timeout, 1, 3600)},
      {"--job-time-limit", "KONTAKTD_JOB_TIME_LIMIT", "wall-time seconds per run (default 0 = none)",
       seconds(&Settings::job_time_limit)},
      {"--job-memory-limit", "KONTAKTD_JOB_MEMORY_LIMIT",
       "address space of each job and deck check, e.g. 8G (default 0 = none)",
       bytes(&Settings::job_memory_limit, 64ull << 20, 1ull << 50, true)},
      {"--job-file-size-limit", "KONTAKTD_JOB_FILE_SIZE_LIMIT",
       "largest result file a job may write, e.g. 10G (default 0 = none)",
       bytes(&Settings::job_file_size_limit, 4096, 1ull << 50, true)},
      {"--kill-grace", "KONTAKTD_KILL_GRACE",
       "seconds a canceled or timed-out job gets before SIGKILL (default 2)",
       seconds(&Settings::kill_grace)},
      {"--max-attempts", "KONTAKTD_MAX_ATTEMPTS", "runs lost to crashes (the daemon's or a killed job process) before a job fails (default 3)",
       integer_in(&Settings::max_attempts, 1, 100)},
      {"--drain-timeout", "KONTAKTD_DRAIN_TIMEOUT", "seconds running jobs get on SIGTERM (default 10)",
       seconds(&Settings::drain_timeout)},
      {"--io-threads", "KONTAKTD_IO_THREADS", "HTTP I/O threads (default 2)",
       integer_in(&Settings::io_threads, 1, 64)},
      {"--handler-threads", "KONTAKTD_HANDLER_THREADS",
       "threads running request handlers (default 4)", integer_in(&Settings::handler_threads, 1, 64)},
      {"--executor", "KONTAKTD_EXECUTOR",
       "where jobs run: local (worker processes, default) or slurm (sbatch; --workers jobs "
       "submitted at once; the data dir on a path the compute nodes share)",
       [](Settings& s, const std::string& v) -> std::optional<std::string> {
         if (v != "local" && v != "slurm") return "local or slurm";
         s.executor = v;
         return std::nullopt;
       }},
      {"--slurm-partition", "KONTAKTD_SLURM_PARTITION",
       "partition of Slurm jobs (default: the cluster's default)",
       slurm_text(&JobResources::partition, check_partition)},
      {"--slurm-cpus", "KONTAKTD_SLURM_CPUS", "CPUs per Slurm job, its solver threads (default 1)",
       [](Settings& s, const std::string& v) -> std::optional<std::string> {
         const auto n = whole_number(v);
         if (auto bad = check_cpus(n.value_or(0))) return bad;
         s.slurm.cpus = static_cast<int>(*n);
         return std::nullopt;
       }},
      {"--slurm-mem", "KONTAKTD_SLURM_MEM", "memory of a Slurm job, sbatch --mem, e.g. 4G",
       slurm_text(&JobResources::memory, check_memory)},
      {"--slurm-time", "KONTAKTD_SLURM_TIME", "time limit of a Slurm job, sbatch --time, e.g. 1:00:00",
       slurm_text(&JobResources::time, check_time)},
  };
  return kOptions;
}

}  // namespace

std::string settings_usage() {
  std::string text = "usage: kontaktd [OPTIONS]\n\n";
  for (const Option& o : options()) {
    std::string flag = std::string("  ") + o.flag + " VALUE";
    flag.resize(std::max<std::size_t>(flag.size() + 1, 26), ' ');
    text += flag + o.help + "  [" + o.env + "]\n";
  }
  return text;
}

std::variant<Settings, std::string> parse_settings(
    const std::vector<std::string>& args,
    const std::function<std::optional<std::string>(const std::string&)>& getenv) {
  Settings s;
  for (const Option& o : options()) {
    if (const auto v = getenv(o.env)) {
      if (auto error = o.set(s, *v)) return std::string(o.env) + ": " + *error;
    }
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--help" || args[i] == "-h") return std::string("help");
    std::string flag = args[i], value;
    bool has_value = false;
    if (const std::size_t eq = flag.find('='); eq != std::string::npos) {
      value = flag.substr(eq + 1);
      flag = flag.substr(0, eq);
      has_value = true;
    }
    const Option* option = nullptr;
    for (const Option& o : options())
      if (flag == o.flag) option = &o;
    if (!option) return "unknown option " + args[i];
    if (!has_value) {
      if (i + 1 >= args.size()) return flag + " needs a value";
      value = args[++i];
    }
    if (auto error = option->set(s, value)) return flag + ": " + *error;
  }
  if (s.executor == "slurm" && s.job_time_limit > 0)
    return std::string("--job-time-limit: the local executor's; Slurm jobs have --slurm-time");
  return s;
}

std::vector<std::string> parse_token_file(const std::string& text) {
  std::vector<std::string> tokens;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
      line.pop_back();
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] != '#') tokens.push_back(line.substr(first));
    start = end + 1;
  }
  return tokens;
}

}  // namespace kontakt::server

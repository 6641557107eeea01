#include "server/worker_protocol.hpp"

#include <charconv>
#include <nlohmann/json.hpp>

namespace kontakt::server::worker {

namespace {

template <class T>
std::optional<T> number(const std::string& text) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

std::string byte_size(std::uint64_t bytes) {
  for (const auto& [shift, unit] : {std::pair{30, " GiB"}, {20, " MiB"}, {10, " KiB"}})
    if (bytes >= (1ull << shift) && bytes % (1ull << shift) == 0)
      return std::to_string(bytes >> shift) + unit;
  return std::to_string(bytes) + " bytes";
}

std::string outcome_text(Exit exit) {
  return nlohmann::json{{"exit_code", static_cast<int>(exit)}}.dump() + "\n";
}

std::optional<int> parse_outcome(const std::string& text) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object() || !j.contains("exit_code") || !j["exit_code"].is_number_integer())
    return std::nullopt;
  return j["exit_code"].get<int>();
}

std::vector<std::string> to_argv(const Args& a) {
  std::vector<std::string> argv{a.mode == Mode::Check ? "check" : "run", "--deck", a.deck.string(),
                                "--parent", std::to_string(a.parent_pid)};
  if (a.scheme) argv.insert(argv.end(), {"--scheme", *a.scheme});
  if (a.limits.memory_bytes)
    argv.insert(argv.end(), {"--memory-limit", std::to_string(a.limits.memory_bytes)});
  if (a.limits.file_size_bytes)
    argv.insert(argv.end(), {"--file-size-limit", std::to_string(a.limits.file_size_bytes)});
  if (a.mode == Mode::Run)
    argv.insert(argv.end(), {"--out", a.out_dir.string(), "--name", a.job_name, "--threads",
                             std::to_string(a.threads)});
  if (a.mode == Mode::Run && !a.outcome_file.empty())
    argv.insert(argv.end(), {"--outcome", a.outcome_file.string()});
  return argv;
}

std::variant<Args, std::string> parse_args(const std::vector<std::string>& argv) {
  if (argv.empty() || (argv[0] != "check" && argv[0] != "run")) return "expected check or run";
  Args a;
  a.mode = argv[0] == "check" ? Mode::Check : Mode::Run;
  for (std::size_t i = 1; i < argv.size(); i += 2) {
    const std::string& flag = argv[i];
    if (i + 1 >= argv.size()) return flag + " needs a value";
    const std::string& value = argv[i + 1];
    if (flag == "--deck") {
      a.deck = value;
    } else if (flag == "--scheme") {
      a.scheme = value;
    } else if (flag == "--out") {
      a.out_dir = value;
    } else if (flag == "--outcome") {
      a.outcome_file = value;
    } else if (flag == "--name") {
      a.job_name = value;
    } else if (flag == "--parent" || flag == "--threads" || flag == "--memory-limit" ||
               flag == "--file-size-limit") {
      const auto n = number<std::uint64_t>(value);
      if (!n) return flag + ": not a whole number: " + value;
      if (flag == "--parent") a.parent_pid = static_cast<long>(*n);
      else if (flag == "--threads") a.threads = static_cast<int>(*n);
      else if (flag == "--memory-limit") a.limits.memory_bytes = *n;
      else a.limits.file_size_bytes = *n;
    } else {
      return "unknown argument " + flag;
    }
  }
  if (a.deck.empty()) return "--deck is required";
  if (a.mode == Mode::Run && (a.out_dir.empty() || a.job_name.empty()))
    return "run needs --out and --name";
  if (a.threads < 1 || a.threads > 1024) return "--threads: 1 to 1024";
  return a;
}

}  // namespace kontakt::server::worker

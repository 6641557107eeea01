#include "server/job_resources.hpp"

#include <cctype>
#include <cstdlib>
#include <vector>

namespace kontakt::server {

namespace {

bool all_digits(const std::string& s) {
  if (s.empty() || s.size() > 9) return false;  // at most 9 digits: no overflow below
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

long long number(const std::string& s) { return std::strtoll(s.c_str(), nullptr, 10); }

/// Splits `s` at every `sep`.
std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t at; (at = s.find(sep, start)) != std::string::npos; start = at + 1)
    parts.push_back(s.substr(start, at - start));
  parts.push_back(s.substr(start));
  return parts;
}

}  // namespace

std::optional<std::string> check_partition(const std::string& v) {
  bool ok = !v.empty() && v.size() <= 64;
  for (char c : v)
    ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.');
  if (ok) return std::nullopt;
  return "a partition name: 1 to 64 of A-Z a-z 0-9 _ - .";
}

std::optional<std::string> check_cpus(long long v) {
  if (v >= 1 && v <= 1024) return std::nullopt;
  return "a whole number of CPUs from 1 to 1024";
}

std::optional<std::string> check_memory(const std::string& v) {
  std::string digits = v;
  if (!digits.empty() && std::string("KMGTkmgt").find(digits.back()) != std::string::npos)
    digits.pop_back();
  if (all_digits(digits) && number(digits) > 0) return std::nullopt;
  return "a memory size as sbatch --mem takes it: a whole number of MiB, or with K, M, G or T "
         "(e.g. 500M, 4G)";
}

std::optional<long long> time_seconds(const std::string& v) {
  std::string rest = v;
  long long days = 0;
  const bool with_days = rest.find('-') != std::string::npos;
  if (with_days) {
    const std::size_t dash = rest.find('-');
    if (!all_digits(rest.substr(0, dash))) return std::nullopt;
    days = number(rest.substr(0, dash));
    rest = rest.substr(dash + 1);
  }
  const std::vector<std::string> parts = split(rest, ':');
  if (parts.size() > 3) return std::nullopt;
  for (const std::string& p : parts)
    if (!all_digits(p)) return std::nullopt;
  long long h = 0, m = 0, s = 0;
  if (with_days) {  // days-hours[:minutes[:seconds]]
    h = number(parts[0]);
    if (parts.size() > 1) m = number(parts[1]);
    if (parts.size() > 2) s = number(parts[2]);
  } else if (parts.size() == 1) {  // minutes
    m = number(parts[0]);
  } else if (parts.size() == 2) {  // minutes:seconds
    m = number(parts[0]);
    s = number(parts[1]);
  } else {  // hours:minutes:seconds
    h = number(parts[0]);
    m = number(parts[1]);
    s = number(parts[2]);
  }
  const long long total = ((days * 24 + h) * 60 + m) * 60 + s;
  if (total <= 0) return std::nullopt;
  return total;
}

std::optional<std::string> check_time(const std::string& v) {
  if (time_seconds(v)) return std::nullopt;
  return "a time limit as sbatch --time takes it: minutes, minutes:seconds, hours:minutes:seconds, "
         "days-hours, days-hours:minutes or days-hours:minutes:seconds, more than 0";
}

JobResources merged(const JobResources& defaults, const JobResources& overrides) {
  JobResources r = defaults;
  if (overrides.partition) r.partition = overrides.partition;
  if (overrides.cpus) r.cpus = overrides.cpus;
  if (overrides.memory) r.memory = overrides.memory;
  if (overrides.time) r.time = overrides.time;
  return r;
}

nlohmann::json to_json(const JobResources& r) {
  nlohmann::json j = nlohmann::json::object();
  if (r.partition) j["partition"] = *r.partition;
  if (r.cpus) j["cpus"] = *r.cpus;
  if (r.memory) j["memory"] = *r.memory;
  if (r.time) j["time"] = *r.time;
  return j;
}

std::optional<ResourcesError> read_resources(const nlohmann::json& j, JobResources& r) {
  if (!j.is_object())
    return ResourcesError{"resources", "an object with partition, cpus, memory and time"};
  for (const auto& [key, value] : j.items()) {
    const std::string field = "resources." + key;
    if (value.is_null()) continue;
    if (key == "cpus") {
      if (!value.is_number_integer()) return ResourcesError{field, *check_cpus(0)};
      if (auto bad = check_cpus(value.get<long long>())) return ResourcesError{field, *bad};
      r.cpus = value.get<int>();
      continue;
    }
    const auto check = key == "partition" ? check_partition
                       : key == "memory"  ? check_memory
                       : key == "time"    ? check_time
                                          : nullptr;
    if (!check) return ResourcesError{field, "unknown member (partition, cpus, memory, time)"};
    if (!value.is_string()) return ResourcesError{field, "must be a string"};
    const std::string v = value.get<std::string>();
    if (auto bad = check(v)) return ResourcesError{field, *bad};
    (key == "partition" ? r.partition : key == "memory" ? r.memory : r.time) = v;
  }
  return std::nullopt;
}

}  // namespace kontakt::server

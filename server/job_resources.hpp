// What a job asks of the executor: partition, CPUs, memory and wall time, in Slurm's own
// spellings (sbatch --partition, --cpus-per-task, --mem, --time). The daemon's options give
// the defaults (--slurm-*), a submission may override each ("resources" in its JSON). The
// local executor keeps them with the job and runs with its own --threads-per-job and limits.
// Pure.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace kontakt::server {

struct JobResources {
  std::optional<std::string> partition;  ///< none: the cluster's default partition
  std::optional<int> cpus;               ///< CPUs per task, also the solver's threads
  std::optional<std::string> memory;     ///< "4G", "500M", "2000" (MiB)
  std::optional<std::string> time;       ///< "30", "1:30:00", "2-00:00:00"
};

/// Each check returns what the value must be, or nullopt when it is good.
std::optional<std::string> check_partition(const std::string& v);
std::optional<std::string> check_cpus(long long v);
std::optional<std::string> check_memory(const std::string& v);
std::optional<std::string> check_time(const std::string& v);

/// The members of `overrides` that are set, over `defaults`.
JobResources merged(const JobResources& defaults, const JobResources& overrides);

/// Seconds of a valid Slurm time ("UNLIMITED" and "infinite": none).
std::optional<long long> time_seconds(const std::string& v);

/// {"partition": ..., "cpus": ..., "memory": ..., "time": ...}: the members that are set.
nlohmann::json to_json(const JobResources& r);

/// Reads a "resources" object; on error the field ("resources.cpus") and what it must be.
struct ResourcesError {
  std::string field, message;
};
std::optional<ResourcesError> read_resources(const nlohmann::json& j, JobResources& r);

}  // namespace kontakt::server

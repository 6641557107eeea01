// Where jobs run: the daemon hands an executor a prepared job folder with the run's arguments
// and resources, and gets an Execution to poll and stop. `local` runs each job in a worker
// process of the daemon (local_executor.hpp, the default); `slurm` submits it as a batch job
// (slurm_executor.hpp). Both run the same program, `kontaktd job-worker run`.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "server/execution.hpp"
#include "server/job_resources.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server {

struct SweepLaunch;

/// A job ready to run: its folder (input/ written, work/ empty) and what its run needs.
struct JobLaunch {
  std::string id;
  std::filesystem::path job_dir;
  worker::Args args;        ///< Mode::Run; out_dir is the job's work folder
  JobResources resources;   ///< the job's own, over the executor's defaults
  /// attach(): events of the run the store has already (a run's events are read from its start).
  std::size_t events_stored = 0;
  /// The sweep the job is a row of, for an executor that starts a sweep whole (a Slurm job
  /// array; starts_sweeps_whole()), on the row's first run; none otherwise.
  std::shared_ptr<const SweepLaunch> sweep{};
  std::size_t sweep_row = 0;
};

/// A sweep (POST /v1/sweeps) as an executor that starts it whole sees it.
struct SweepLaunch {
  std::string id;
  std::filesystem::path dir;  ///< DATA/sweeps/ID: what the executor keeps of it
  int max_parallel = 1;       ///< rows running at once
  /// Its rows not finished (queued, or claimed meanwhile), by row; JobLaunch::sweep_row is
  /// each one's index (the array task).
  std::vector<JobLaunch> rows;
};

/// The executor refused the job (e.g. sbatch's error); the job fails with this message.
class ExecutorRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Executor {
 public:
  virtual ~Executor() = default;
  /// Starts what the executor needs (the local one its waiting processes).
  virtual void start() {}
  /// After the last job's supervision ended: stops what start() started.
  virtual void shutdown() {}
  /// Hands over the job. Throws ExecutorRefused when the executor will not take it, or
  /// std::exception when the daemon cannot hand it over.
  virtual std::unique_ptr<Execution> submit(const JobLaunch& job) = 0;
  /// After a daemon restart: the job's run if the executor still has it, or had it and knows
  /// how it ended; nullptr when it never reached the executor (run it again).
  virtual std::unique_ptr<Execution> attach(const JobLaunch& job) = 0;
  /// Runs go on while the daemon is away (attach() finds them).
  virtual bool outlives_daemon() const = 0;
  /// Whether the daemon's --job-time-limit applies (Slurm enforces its own --time).
  virtual bool daemon_enforces_time_limit() const { return true; }
  /// Whether the first row of a sweep that submit() gets starts every row (a Slurm job
  /// array); the other rows' submit() then watch what runs already. Otherwise a sweep's rows
  /// are jobs like any other.
  virtual bool starts_sweeps_whole() const { return false; }
  /// A job canceled while queued: stops its run if one was started ahead of its claim.
  virtual void cancel_unclaimed(const JobLaunch& /*job*/) {}
};

}  // namespace kontakt::server

// The Slurm executor (`kontaktd --executor slurm`): each job is one batch job. The daemon
// writes DATA/jobs/ID/slurm/run.sh, which execs this same program (`kontaktd job-worker run`,
// at the daemon's own path: the compute nodes must see it there, and DATA on the same path,
// e.g. over NFS), and submits it with `sbatch --parsable` (name, --chdir, --output, CPUs,
// memory, time, --signal=B:TERM@grace, --comment=<job id>). The run appends its events to
// events.ndjson and writes outcome.json at its end; the execution tails both, so the store,
// the SSE streams and the API see what a local run shows. The outcome file is the truth;
// Slurm's state (squeue, then scontrol, then the jobcomp/filetxt log) is the fallback for a
// run that left none (killed, never started). Cancel: `scancel --signal=TERM --batch`, then a
// plain scancel after the grace. Runs go on while the daemon is away; attach() finds them
// again from slurm_job_id (or the --comment).
//
// A sweep (POST /v1/sweeps) is one job array: the claim of its first row writes every row's
// run.sh and submits DATA/sweeps/ID/slurm/run.sh with `--array=0-(N-1)%K` (K: the lower of
// max_parallel and --workers), whose task i execs row i's run.sh. Each row's slurm_job_id is
// then its task, "<array>_<i>", which its execution watches and stops like a lone job's id;
// later rows' claims find their task running or done. An sbatch refusal is kept
// (slurm/refused) and fails every row with it.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "server/executor.hpp"
#include "server/slurm_execution.hpp"
#include "server/slurm_queue.hpp"

namespace kontakt::server {

struct SlurmSettings {
  JobResources defaults;             ///< --slurm-partition, --slurm-cpus, --slurm-mem, --slurm-time
  std::filesystem::path worker_exe;  ///< the daemon's own file, on the same path on the nodes
  int signal_grace = 60;             ///< seconds: --signal=B:TERM@grace before the time limit
  std::chrono::milliseconds poll_interval{1000};  ///< squeue at most this often
  /// How long a job Slurm reports ended may take to show its outcome file (NFS attribute
  /// caches) before Slurm's state is taken for its end.
  std::chrono::milliseconds outcome_wait{5000};
  /// An array runs at most this many tasks at once (--workers: the jobs the daemon watches),
  /// whatever the sweep's max_parallel, so no task runs unwatched while its row shows queued.
  int max_array_parallel = 1000;
};

class SlurmExecutor final : public Executor {
 public:
  explicit SlurmExecutor(SlurmSettings settings);
  std::unique_ptr<Execution> submit(const JobLaunch& job) override;
  std::unique_ptr<Execution> attach(const JobLaunch& job) override;
  bool outlives_daemon() const override { return true; }
  bool daemon_enforces_time_limit() const override { return false; }
  bool starts_sweeps_whole() const override { return true; }
  /// scancel of the job's array task, when the array runs it already.
  void cancel_unclaimed(const JobLaunch& job) override;

  /// Slurm's record of a job that left squeue: scontrol, then the jobcomp/filetxt log.
  std::optional<slurm::JobState> finished_state(const std::string& slurm_id);

 private:
  /// The array of the job's sweep, submitted by the first row that asks; its id.
  std::string array_of(const JobLaunch& job);
  /// Writes the job's run.sh and makes its folders; returns its run's arguments.
  void prepare_run(const JobLaunch& job, const JobResources& resources) const;
  std::unique_ptr<Execution> execution(const std::string& slurm_id, const JobLaunch& job,
                                       SlurmExecution::Clock::time_point known_since,
                                       std::size_t skip_events);

  const SlurmSettings settings_;
  SlurmQueue queue_;
  std::once_flag jobcomp_once_;
  std::optional<std::string> jobcomp_file_;  ///< from `scontrol show config`, once
  std::mutex arrays_mutex_;  ///< one array submission per sweep
  /// When this daemon submitted an array (its tasks are in squeue from then on), by sweep.
  std::map<std::string, SlurmExecution::Clock::time_point> arrays_submitted_;
};

}  // namespace kontakt::server

// What kontaktd says to Slurm and reads back, as pure functions: the batch script and the
// sbatch command line of a job, the job id sbatch prints, the job states squeue, scontrol and
// the jobcomp/filetxt log report, and the verdict on a job that ended without an outcome file.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "server/execution.hpp"
#include "server/job_resources.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server::slurm {

/// The files of a job's Slurm run, in DATA/jobs/ID/slurm/ (on the shared file system).
struct RunFiles {
  std::filesystem::path dir;
  std::filesystem::path script() const { return dir / "run.sh"; }
  std::filesystem::path events() const { return dir / "events.ndjson"; }
  std::filesystem::path outcome() const { return dir / "outcome.json"; }
  std::filesystem::path slurm_id() const { return dir / "slurm_job_id"; }
  /// sbatch --output: the batch job's stdout and stderr ("%j": the Slurm job id).
  std::filesystem::path output_pattern() const { return dir / "slurm-%j.out"; }
  std::filesystem::path output(const std::string& slurm_id) const {
    return dir / ("slurm-" + slurm_id + ".out");
  }
};

/// `#!/bin/sh` that execs `exe job-worker run ARGS` with its events appended to the events
/// file (the worker's report descriptor 3) and `threads` BLAS threads. The worker is the batch
/// shell itself, so Slurm's signals to the batch shell (--signal=B:..., scancel --batch) reach
/// the solver.
std::string batch_script(const std::filesystem::path& exe, const worker::Args& args,
                         const RunFiles& files, const std::string& job_id);

/// sbatch --parsable with the job's name, folder, output, resources, the pre-timeout SIGTERM
/// `grace_seconds` before the time limit, and `--comment=<job id>` (found again by squeue).
std::vector<std::string> sbatch_argv(const std::string& job_id, const RunFiles& files,
                                     const std::filesystem::path& work_dir,
                                     const JobResources& resources, int grace_seconds);

/// The batch script of a sweep's job array: task i (SLURM_ARRAY_TASK_ID) execs the batch
/// script of row i, `row_dirs.at(i)`/run.sh (batch_script), with its output in that folder
/// as slurm-<array>_<task>.out, where a lone job has its slurm-<id>.out.
std::string array_script(const std::string& sweep_id,
                         const std::map<std::size_t, std::filesystem::path>& row_dirs);

/// sbatch's --array value: the tasks as ranges ("0-4,6,8-19") and the throttle ("%3").
std::string array_spec(const std::vector<std::size_t>& tasks, int max_parallel);

/// sbatch --parsable of a sweep's array (`--array=array_spec(tasks)`, the options of
/// sbatch_argv with `--comment=<sweep id>`), its own output in `files.dir` (slurm-%A_%a.out).
std::vector<std::string> sbatch_array_argv(const std::string& sweep_id, const RunFiles& files,
                                           const std::vector<std::size_t>& tasks,
                                           int max_parallel, const JobResources& resources,
                                           int grace_seconds);

/// An array task's id: "<array>_<task>".
std::string array_task_id(const std::string& array_id, std::size_t task);

/// The job id of `sbatch --parsable` ("123" or "123;cluster"); nullopt when it is not one.
std::optional<std::string> parse_sbatch_id(const std::string& out);

/// A Slurm job as one of Slurm's tools reports it.
struct JobState {
  std::string state{};  ///< PENDING, RUNNING, COMPLETED, FAILED, TIMEOUT, ...
  std::string reason{};  ///< Slurm's reason ("NonZeroExitCode", "None", ...); may be empty
  std::string comment{};  ///< squeue only: --comment, kontaktd's job id
  std::optional<ExitStatus> exit{};  ///< scontrol and jobcomp: ExitCode=code:signal
};

/// The squeue format these parsers read: id|state|reason|comment.
inline constexpr const char* kSqueueFormat = "%i|%T|%r|%k";
/// `squeue --noheader --format=kSqueueFormat` output, by Slurm job id; an array's pending
/// tasks listed as one line ("12_[3-9%2]", without --array) count as each task (12_3 ...).
std::map<std::string, JobState> parse_squeue(const std::string& out);
/// `scontrol show job ID` output (JobState=, Reason=, ExitCode=).
std::optional<JobState> parse_scontrol_job(const std::string& out);
/// The last record of job `slurm_id` in a jobcomp/filetxt log; an array task's ("12_3") is
/// the line with ArrayJobId=12 ArrayTaskId=3.
std::optional<JobState> find_in_jobcomp(const std::string& log, const std::string& slurm_id);
/// `scontrol show config` output: JobCompLoc when JobCompType is jobcomp/filetxt.
std::optional<std::string> jobcomp_file(const std::string& config);

/// The job will not run (again): COMPLETED, FAILED, CANCELLED, TIMEOUT, NODE_FAIL, ...
bool is_finished(const std::string& state);

/// The verdict on Slurm job `slurm_id` that ended in `state` without an outcome file: Slurm's
/// state and reason in the message, with `output_tail` (the end of its slurm-N.out) when any.
ExecutorFailure failure_from(const std::string& slurm_id, const JobState& state,
                             const std::string& output_tail);

}  // namespace kontakt::server::slurm

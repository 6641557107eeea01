#include "server/slurm_executor.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "server/command.hpp"
#include "server/slurm_execution.hpp"

namespace fs = std::filesystem;

namespace kontakt::server {

namespace {

/// sbatch waits for slurmctld's answer (MessageTimeout, 10 s by default, and retries).
constexpr auto kSbatchTimeout = std::chrono::seconds(60);
constexpr auto kQueryTimeout = std::chrono::seconds(30);

slurm::RunFiles run_files(const JobLaunch& job) { return {job.job_dir / "slurm"}; }

/// Written whole, then renamed: a daemon that crashes meanwhile leaves no half file.
void write_file(const fs::path& file, const std::string& text, fs::perms perms) {
  const fs::path partial = file.string() + ".tmp";
  {
    std::ofstream out(partial, std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + file.string());
  }
  fs::permissions(partial, perms);
  fs::rename(partial, file);
}

std::optional<std::string> read_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line) || line.empty()) return std::nullopt;
  return line;
}

std::optional<std::string> query(const std::vector<std::string>& argv) {
  try {
    const CommandResult r = run_command(argv, kQueryTimeout);
    if (r.ok()) return r.out;
  } catch (const std::exception&) {  // not installed: no record to read
  }
  return std::nullopt;
}

}  // namespace

SlurmExecutor::SlurmExecutor(SlurmSettings settings)
    : settings_(std::move(settings)), queue_(settings_.poll_interval) {}

std::optional<slurm::JobState> SlurmExecutor::finished_state(const std::string& slurm_id) {
  if (const auto shown = query({"scontrol", "show", "job", slurm_id}))
    if (auto state = slurm::parse_scontrol_job(*shown)) return state;
  // Past MinJobAge scontrol has forgotten it; the jobcomp/filetxt log, if kept, has not.
  std::call_once(jobcomp_once_, [this] {
    if (const auto config = query({"scontrol", "show", "config"}))
      jobcomp_file_ = slurm::jobcomp_file(*config);
  });
  if (!jobcomp_file_) return std::nullopt;
  std::ifstream in(*jobcomp_file_);
  std::stringstream log;
  log << in.rdbuf();
  return slurm::find_in_jobcomp(log.str(), slurm_id);
}

void SlurmExecutor::prepare_run(const JobLaunch& job, const JobResources& resources) const {
  const slurm::RunFiles files = run_files(job);
  std::error_code ec;
  fs::remove_all(files.dir, ec);  // an earlier attempt's files
  fs::create_directories(files.dir);
  fs::create_directories(job.args.out_dir);  // sbatch --chdir needs it
  worker::Args args = job.args;
  args.parent_pid = 0;  // its parent is slurmstepd
  args.threads = resources.cpus.value_or(1);
  args.outcome_file = files.outcome();
  write_file(files.script(), slurm::batch_script(settings_.worker_exe, args, files, job.id),
             fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
}

std::unique_ptr<Execution> SlurmExecutor::execution(const std::string& slurm_id,
                                                    const JobLaunch& job,
                                                    SlurmExecution::Clock::time_point known_since,
                                                    std::size_t skip_events) {
  return std::make_unique<SlurmExecution>(
      slurm_id, run_files(job), queue_, [this](const std::string& id) { return finished_state(id); },
      settings_.outcome_wait, known_since, skip_events);
}

std::string SlurmExecutor::array_of(const JobLaunch& job) {
  const SweepLaunch& sweep = *job.sweep;
  std::lock_guard lock(arrays_mutex_);
  const slurm::RunFiles files{sweep.dir / "slurm"};
  const fs::path array_file = files.dir / "array_id", refused_file = files.dir / "refused";
  if (const auto refused = read_line(refused_file)) throw ExecutorRefused(*refused);
  if (const auto id = read_line(array_file)) return *id;
  // sbatch answered, the daemon stopped before it wrote the id down: the comment finds it.
  std::optional<std::string> array_id;
  if (const auto task = queue_.find_by_comment(sweep.id)) array_id = task->substr(0, task->find('_'));
  if (!array_id) {
    fs::create_directories(files.dir);
    const JobResources resources = merged(settings_.defaults, job.resources);
    std::map<std::size_t, fs::path> row_dirs;
    std::vector<std::size_t> tasks;
    for (const JobLaunch& row : sweep.rows) {
      prepare_run(row, resources);
      row_dirs[row.sweep_row] = run_files(row).dir;
      tasks.push_back(row.sweep_row);
    }
    write_file(files.script(), slurm::array_script(sweep.id, row_dirs),
               fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
    const CommandResult r = run_command(
        slurm::sbatch_array_argv(sweep.id, files, tasks,
                                 std::min(sweep.max_parallel, settings_.max_array_parallel),
                                 resources, settings_.signal_grace),
        kSbatchTimeout);
    std::optional<std::string> refusal;
    if (!r.ok()) refusal = command_error(r);
    else if (!(array_id = slurm::parse_sbatch_id(r.out))) refusal = "sbatch printed no job id: " + r.out;
    if (refusal) {
      // Every row fails with sbatch's words, not only the one that asked.
      std::string line = *refusal;
      for (char& c : line)
        if (c == '\n') c = ' ';
      write_file(refused_file, line + "\n", fs::perms::owner_read | fs::perms::owner_write);
      throw ExecutorRefused(*refusal);
    }
    arrays_submitted_[sweep.id] = SlurmExecution::Clock::now();
  }
  for (const JobLaunch& row : sweep.rows)
    write_file(run_files(row).slurm_id(), slurm::array_task_id(*array_id, row.sweep_row) + "\n",
               fs::perms::owner_read | fs::perms::owner_write);
  write_file(array_file, *array_id + "\n", fs::perms::owner_read | fs::perms::owner_write);
  return *array_id;
}

std::unique_ptr<Execution> SlurmExecutor::submit(const JobLaunch& job) {
  if (job.sweep) {
    const std::string task = slurm::array_task_id(array_of(job), job.sweep_row);
    const auto submitted = [&] {
      std::lock_guard lock(arrays_mutex_);
      const auto it = arrays_submitted_.find(job.sweep->id);
      return it == arrays_submitted_.end() ? SlurmExecution::Clock::time_point{} : it->second;
    }();
    return execution(task, job, submitted, 0);
  }
  const slurm::RunFiles files = run_files(job);
  const JobResources resources = merged(settings_.defaults, job.resources);
  prepare_run(job, resources);
  const CommandResult r = run_command(
      slurm::sbatch_argv(job.id, files, job.args.out_dir, resources, settings_.signal_grace),
      kSbatchTimeout);
  if (!r.ok()) throw ExecutorRefused(command_error(r));
  const auto slurm_id = slurm::parse_sbatch_id(r.out);
  if (!slurm_id) throw ExecutorRefused("sbatch printed no job id: " + r.out);
  // A squeue that starts from now on lists the job (one that ran during sbatch may not).
  const auto known = SlurmExecution::Clock::now();
  write_file(files.slurm_id(), *slurm_id + "\n", fs::perms::owner_read | fs::perms::owner_write);
  return execution(*slurm_id, job, known, 0);
}

std::unique_ptr<Execution> SlurmExecutor::attach(const JobLaunch& job) {
  const slurm::RunFiles files = run_files(job);
  std::optional<std::string> slurm_id = read_line(files.slurm_id());
  // sbatch answered, the daemon stopped before it wrote the id down: the comment finds it.
  if (!slurm_id) slurm_id = queue_.find_by_comment(job.id);
  if (!slurm_id) return nullptr;
  fs::create_directories(files.dir);
  write_file(files.slurm_id(), *slurm_id + "\n", fs::perms::owner_read | fs::perms::owner_write);
  return execution(*slurm_id, job, SlurmExecution::Clock::time_point{}, job.events_stored);
}

void SlurmExecutor::cancel_unclaimed(const JobLaunch& job) {
  const auto slurm_id = read_line(run_files(job).slurm_id());
  if (!slurm_id || slurm_id->find('_') == std::string::npos) return;  // not an array task
  try {
    const CommandResult r = run_command({"scancel", "--quiet", *slurm_id}, kQueryTimeout);
    if (!r.ok()) std::fprintf(stderr, "kontaktd: scancel %s: %s\n", slurm_id->c_str(), command_error(r).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: scancel %s: %s\n", slurm_id->c_str(), e.what());
  }
}

}  // namespace kontakt::server

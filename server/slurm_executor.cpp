#include "server/slurm_executor.hpp"

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

std::unique_ptr<Execution> SlurmExecutor::submit(const JobLaunch& job) {
  const slurm::RunFiles files = run_files(job);
  std::error_code ec;
  fs::remove_all(files.dir, ec);  // an earlier attempt's files
  fs::create_directories(files.dir);
  fs::create_directories(job.args.out_dir);  // sbatch --chdir needs it
  const JobResources resources = merged(settings_.defaults, job.resources);
  worker::Args args = job.args;
  args.parent_pid = 0;  // its parent is slurmstepd
  args.threads = resources.cpus.value_or(1);
  args.outcome_file = files.outcome();
  write_file(files.script(), slurm::batch_script(settings_.worker_exe, args, files, job.id),
             fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
  const CommandResult r = run_command(
      slurm::sbatch_argv(job.id, files, job.args.out_dir, resources, settings_.signal_grace),
      kSbatchTimeout);
  if (!r.ok()) throw ExecutorRefused(command_error(r));
  const auto slurm_id = slurm::parse_sbatch_id(r.out);
  if (!slurm_id) throw ExecutorRefused("sbatch printed no job id: " + r.out);
  // A squeue that starts from now on lists the job (one that ran during sbatch may not).
  const auto known = SlurmExecution::Clock::now();
  write_file(files.slurm_id(), *slurm_id + "\n", fs::perms::owner_read | fs::perms::owner_write);
  return std::make_unique<SlurmExecution>(
      *slurm_id, files, queue_, [this](const std::string& id) { return finished_state(id); },
      settings_.outcome_wait, known, 0);
}

std::unique_ptr<Execution> SlurmExecutor::attach(const JobLaunch& job) {
  const slurm::RunFiles files = run_files(job);
  std::optional<std::string> slurm_id = read_line(files.slurm_id());
  // sbatch answered, the daemon stopped before it wrote the id down: the comment finds it.
  if (!slurm_id) slurm_id = queue_.find_by_comment(job.id);
  if (!slurm_id) return nullptr;
  fs::create_directories(files.dir);
  write_file(files.slurm_id(), *slurm_id + "\n", fs::perms::owner_read | fs::perms::owner_write);
  return std::make_unique<SlurmExecution>(
      *slurm_id, files, queue_, [this](const std::string& id) { return finished_state(id); },
      settings_.outcome_wait, SlurmExecution::Clock::time_point{}, job.events_stored);
}

}  // namespace kontakt::server

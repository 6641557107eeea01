#include "server/slurm_protocol.hpp"

#include <cctype>
#include <sstream>

namespace kontakt::server::slurm {

namespace {

/// One word for sh, whatever it holds.
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// The value of `key=` in a line of `key=value` words (scontrol, jobcomp); empty when absent.
std::string word_value(const std::string& text, const std::string& key) {
  std::size_t at = 0;
  while ((at = text.find(key + "=", at)) != std::string::npos) {
    if (at == 0 || std::isspace(static_cast<unsigned char>(text[at - 1]))) {
      const std::size_t start = at + key.size() + 1;
      std::size_t end = start;
      while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
      return text.substr(start, end - start);
    }
    at += key.size();
  }
  return {};
}

/// "3:0" (exit code 3) or "0:9" (signal 9).
std::optional<ExitStatus> exit_code(const std::string& v) {
  const std::size_t colon = v.find(':');
  if (v.empty() || colon == std::string::npos) return std::nullopt;
  try {
    const int code = std::stoi(v.substr(0, colon)), signal = std::stoi(v.substr(colon + 1));
    if (signal != 0) return ExitStatus{.signaled = true, .code = signal};
    return ExitStatus{.signaled = false, .code = code};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// "12_[3-5,8%2]" -> 12_3 12_4 12_5 12_8; any other id as it is.
std::vector<std::string> array_ids(const std::string& id) {
  const std::size_t open = id.find("_["), close = id.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return {id};
  const std::string array = id.substr(0, open);
  std::string ranges = id.substr(open + 2, close - open - 2);
  ranges = ranges.substr(0, ranges.find('%'));  // the throttle
  std::vector<std::string> ids;
  std::istringstream parts(ranges);
  for (std::string part; std::getline(parts, part, ',');) {
    try {
      const std::size_t dash = part.find('-');
      const long first = std::stol(part.substr(0, dash));
      const long last = dash == std::string::npos ? first : std::stol(part.substr(dash + 1));
      if (first < 0 || last < first || last - first > 100000) return {id};
      for (long t = first; t <= last; ++t) ids.push_back(array + "_" + std::to_string(t));
    } catch (const std::exception&) {
      return {id};
    }
  }
  return ids;
}

JobState from_words(const std::string& text) {
  JobState s;
  s.state = word_value(text, "JobState");
  s.reason = word_value(text, "Reason");
  s.exit = exit_code(word_value(text, "ExitCode"));
  return s;
}

}  // namespace

std::string batch_script(const std::filesystem::path& exe, const worker::Args& args,
                         const RunFiles& files, const std::string& job_id) {
  std::string command = "exec " + quoted(exe.string()) + " " + worker::kCommand;
  for (const std::string& a : worker::to_argv(args)) command += " " + quoted(a);
  return "#!/bin/sh\n"
         "# kontaktd job " + job_id + ": the solver's run as a Slurm batch job; its events go\n"
         "# to events.ndjson, its end to outcome.json (server/slurm_executor.hpp).\n"
         "export OPENBLAS_NUM_THREADS=" + std::to_string(args.threads) + "\n" +
         command + " 3>>" + quoted(files.events().string()) + "\n";
}

std::string array_script(const std::string& sweep_id,
                         const std::map<std::size_t, std::filesystem::path>& row_dirs) {
  std::string script =
      "#!/bin/sh\n"
      "# kontaktd sweep " + sweep_id + ": one Slurm job array; task i runs row i's batch script\n"
      "# (server/slurm_executor.hpp).\n"
      "case \"$SLURM_ARRAY_TASK_ID\" in\n";
  for (const auto& [task, dir] : row_dirs)
    script += "  " + std::to_string(task) + ") dir=" + quoted(dir.string()) + " ;;\n";
  script += "  *) echo \"kontaktd sweep " + sweep_id +
            " has no row $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;\n"
            "esac\n"
            "exec \"$dir/run.sh\" >\"$dir/slurm-${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID}.out\" "
            "2>&1\n";
  return script;
}

namespace {

/// sbatch's options for a job or an array, up to the resources and the script.
std::vector<std::string> sbatch_common(const std::string& name, const std::string& comment,
                                       const std::filesystem::path& work_dir,
                                       const std::filesystem::path& output,
                                       const JobResources& r, int grace_seconds,
                                       const std::filesystem::path& script) {
  std::vector<std::string> argv{"sbatch", "--parsable",
                                "--job-name=" + name,
                                "--chdir=" + work_dir.string(),
                                "--output=" + output.string(),
                                "--signal=B:TERM@" + std::to_string(grace_seconds),
                                "--comment=" + comment, "--no-requeue"};
  if (r.partition) argv.push_back("--partition=" + *r.partition);
  argv.push_back("--cpus-per-task=" + std::to_string(r.cpus.value_or(1)));
  if (r.memory) argv.push_back("--mem=" + *r.memory);
  if (r.time) argv.push_back("--time=" + *r.time);
  argv.push_back(script.string());
  return argv;
}

}  // namespace

std::vector<std::string> sbatch_argv(const std::string& job_id, const RunFiles& files,
                                     const std::filesystem::path& work_dir,
                                     const JobResources& r, int grace_seconds) {
  return sbatch_common("kontakt-" + job_id.substr(0, 12), job_id, work_dir,
                       files.output_pattern(), r, grace_seconds, files.script());
}

std::string array_spec(const std::vector<std::size_t>& tasks, int max_parallel) {
  std::string spec;
  for (std::size_t i = 0; i < tasks.size();) {
    std::size_t j = i;
    while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
    if (!spec.empty()) spec += ",";
    spec += std::to_string(tasks[i]);
    if (j > i) spec += "-" + std::to_string(tasks[j]);
    i = j + 1;
  }
  return spec + "%" + std::to_string(max_parallel);
}

std::vector<std::string> sbatch_array_argv(const std::string& sweep_id, const RunFiles& files,
                                           const std::vector<std::size_t>& tasks,
                                           int max_parallel, const JobResources& r,
                                           int grace_seconds) {
  std::vector<std::string> argv =
      sbatch_common("kontakt-sweep-" + sweep_id.substr(0, 12), sweep_id, files.dir,
                    files.dir / "slurm-%A_%a.out", r, grace_seconds, files.script());
  argv.insert(argv.begin() + 2, "--array=" + array_spec(tasks, max_parallel));
  return argv;
}

std::string array_task_id(const std::string& array_id, std::size_t task) {
  return array_id + "_" + std::to_string(task);
}

std::optional<std::string> parse_sbatch_id(const std::string& out) {
  std::string id = out.substr(0, out.find_first_of(";\n"));
  if (id.empty() || id.size() > 20) return std::nullopt;
  for (char c : id)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  return id;
}

std::map<std::string, JobState> parse_squeue(const std::string& out) {
  std::map<std::string, JobState> jobs;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t a = line.find('|'), b = line.find('|', a + 1),
                      c = line.find('|', b == std::string::npos ? b : b + 1);
    if (a == std::string::npos || b == std::string::npos || c == std::string::npos) continue;
    const JobState state{.state = line.substr(a + 1, b - a - 1),
                         .reason = line.substr(b + 1, c - b - 1),
                         .comment = line.substr(c + 1),
                         .exit = std::nullopt};
    for (const std::string& id : array_ids(line.substr(0, a))) jobs[id] = state;
  }
  return jobs;
}

std::optional<JobState> parse_scontrol_job(const std::string& out) {
  JobState s = from_words(out);
  if (s.state.empty()) return std::nullopt;
  return s;
}

std::optional<JobState> find_in_jobcomp(const std::string& log, const std::string& slurm_id) {
  std::optional<JobState> found;
  std::istringstream lines(log);
  const std::size_t underscore = slurm_id.find('_');
  for (std::string line; std::getline(lines, line);) {
    const bool match =
        underscore == std::string::npos
            ? line.rfind("JobId=" + slurm_id + " ", 0) == 0
            : word_value(line, "ArrayJobId") == slurm_id.substr(0, underscore) &&
                  word_value(line, "ArrayTaskId") == slurm_id.substr(underscore + 1);
    if (match) found = from_words(line);
  }
  return found;
}

std::optional<std::string> jobcomp_file(const std::string& config) {
  std::optional<std::string> type, location;
  std::istringstream lines(config);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    while (!key.empty() && key.back() == ' ') key.pop_back();
    value.erase(0, value.find_first_not_of(' '));
    if (key == "JobCompType") type = value;
    if (key == "JobCompLoc") location = value;
  }
  if (type != "jobcomp/filetxt" || !location || location->empty()) return std::nullopt;
  return location;
}

bool is_finished(const std::string& state) {
  for (const char* s : {"COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "PREEMPTED",
                        "BOOT_FAIL", "DEADLINE", "OUT_OF_MEMORY", "REVOKED", "SPECIAL_EXIT"})
    if (state == s) return true;
  return false;
}

ExecutorFailure failure_from(const std::string& slurm_id, const JobState& s,
                             const std::string& output_tail) {
  std::string said = "Slurm job " + slurm_id + " ended " + s.state;
  if (!s.reason.empty() && s.reason != "None") said += " (" + s.reason + ")";
  if (s.exit) said += " with " + describe(*s.exit);
  said += " and left no outcome";
  if (!output_tail.empty()) said += "; its output ends: " + output_tail;
  std::string reason = "worker_lost";
  if (s.state == "TIMEOUT" || s.state == "DEADLINE") reason = "time_limit";
  else if (s.state == "OUT_OF_MEMORY") reason = "memory_limit";
  else if (s.state == "FAILED" && s.exit && s.exit->signaled) reason = "solver_crashed";
  return {.reason = reason, .message = said};
}

}  // namespace kontakt::server::slurm

// Runs a short command (sbatch, squeue, scancel, scontrol) and collects what it printed.
// No shell: argv as given. A command that takes longer than its timeout is killed (a Slurm
// controller that does not answer makes its clients wait for MessageTimeout and more).
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "server/child_process.hpp"

namespace kontakt::server {

struct CommandResult {
  ExitStatus exit;
  std::string out, err;  ///< stdout and stderr, each cut at 1 MiB
  bool timed_out = false;
  bool ok() const { return !timed_out && !exit.signaled && exit.code == 0; }
};

/// Throws std::system_error when the command cannot be started (e.g. not installed).
CommandResult run_command(const std::vector<std::string>& argv, std::chrono::milliseconds timeout);

/// "sbatch: error: ...": stderr without trailing blank lines, or the exit status when empty.
std::string command_error(const CommandResult& r);

}  // namespace kontakt::server

// One child process of the daemon: started with posix_spawn in its own process group (so a
// terminal's Ctrl-C or a signal to the daemon's group never reaches it), every descriptor
// closed but stdin (a request channel, or /dev/null), stdout (/dev/null), stderr (shared) and
// an optional report pipe on descriptor 3, and watched through a pidfd (waits with timeouts,
// signals that can never hit a reused pid).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace kontakt::server {

/// How a process ended.
struct ExitStatus {
  bool signaled = false;
  int code = 0;  ///< the exit code, or the signal number when signaled
};

/// "exit code 3", "signal 11 (SIGSEGV: segmentation fault)".
std::string describe(const ExitStatus& status);
/// "SIGSEGV", "SIGKILL", ... ("signal N" for one without a name).
std::string signal_name(int signal);

/// A pipe whose ends are closed on exec; `read_end` is non-blocking.
struct Pipe {
  int read_end = -1, write_end = -1;
};
/// Throws std::system_error.
Pipe make_report_pipe();

class ChildProcess {
 public:
  /// Starts argv[0] with argv and the daemon's environment with `env` ("NAME=value") over it;
  /// `report_fd` becomes descriptor 3 of the child and `request_fd` its stdin (either may be
  /// -1). Throws std::system_error when it cannot be started.
  ChildProcess(const std::vector<std::string>& argv, int report_fd, int request_fd = -1,
               const std::vector<std::string>& env = {});
  /// A child still running is killed (SIGKILL) and reaped: no process outlives its owner.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  /// Readable (poll) once the process has ended.
  int pidfd() const { return pidfd_; }
  /// Sends `signal` to the process; false when it has already ended. SIGKILL goes to its whole
  /// process group, so nothing the child started outlives a hard stop.
  bool send(int signal);
  /// The status once the process has ended (it is reaped then); nullopt while it runs.
  std::optional<ExitStatus> try_wait();
  /// Waits until the process ends or `timeout` passes.
  std::optional<ExitStatus> wait_for(std::chrono::milliseconds timeout);

 private:
  pid_t pid_ = -1;
  int pidfd_ = -1;
  std::optional<ExitStatus> status_;
};

}  // namespace kontakt::server

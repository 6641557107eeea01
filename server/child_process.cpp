#include "server/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>
#include <system_error>

extern char** environ;

namespace kontakt::server {

namespace {

std::system_error system_error(const std::string& what) {
  return std::system_error(errno, std::generic_category(), what);
}

// glibc 2.36's <sys/pidfd.h> lacks C linkage for C++: the system calls themselves.
int open_pidfd(pid_t pid) { return static_cast<int>(syscall(SYS_pidfd_open, pid, 0)); }
int send_to_pidfd(int pidfd, int signal) {
  return static_cast<int>(syscall(SYS_pidfd_send_signal, pidfd, signal, nullptr, 0));
}

/// posix_spawn's attributes and file actions, released on every path.
struct SpawnSetup {
  posix_spawnattr_t attr;
  posix_spawn_file_actions_t actions;
  SpawnSetup() {
    posix_spawnattr_init(&attr);
    posix_spawn_file_actions_init(&actions);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
};

}  // namespace

std::string signal_name(int signal) {
  const char* abbrev = sigabbrev_np(signal);
  return abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(signal);
}

std::string describe(const ExitStatus& status) {
  if (!status.signaled) return "exit code " + std::to_string(status.code);
  const char* text = sigdescr_np(status.code);
  return "signal " + std::to_string(status.code) + " (" + signal_name(status.code) +
         (text ? std::string(": ") + text : std::string()) + ")";
}

Pipe make_report_pipe() {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw system_error("pipe2");
  // One page of buffer, not 64 KiB: a process reporting faster than the store takes its events
  // waits (as the solver did in the daemon), so clients and the store stay a few events behind
  // it, not hundreds - a cancel is seen as the run's last events, not before them.
  fcntl(fds[0], F_SETPIPE_SZ, 4096);
  if (fcntl(fds[0], F_SETFL, O_NONBLOCK) != 0) {
    const std::system_error error = system_error("fcntl");
    close(fds[0]);
    close(fds[1]);
    throw error;
  }
  return {fds[0], fds[1]};
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, int report_fd, int request_fd,
                           const std::vector<std::string>& env) {
  SpawnSetup setup;
  // Its own process group; no blocked signals; default dispositions (an ignored signal would
  // stay ignored across exec).
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  sigdelset(&all, SIGKILL);
  sigdelset(&all, SIGSTOP);
  posix_spawnattr_setflags(&setup.attr,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&setup.attr, 0);
  posix_spawnattr_setsigmask(&setup.attr, &none);
  posix_spawnattr_setsigdefault(&setup.attr, &all);

  // dup2(n, n) would keep close-on-exec, and a later dup2 could overwrite a source: move
  // descriptors 0 to 3 out of the way first.
  std::vector<int> moved;
  const auto out_of_the_way = [&moved](int& fd) {
    if (fd < 0 || fd > 3) return;
    fd = fcntl(fd, F_DUPFD_CLOEXEC, 10);
    if (fd < 0) {
      for (int m : moved) close(m);
      throw system_error("fcntl");
    }
    moved.push_back(fd);
  };
  out_of_the_way(report_fd);
  out_of_the_way(request_fd);
  if (request_fd >= 0) posix_spawn_file_actions_adddup2(&setup.actions, request_fd, 0);
  else posix_spawn_file_actions_addopen(&setup.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&setup.actions, 1, "/dev/null", O_WRONLY, 0);
  if (report_fd >= 0) posix_spawn_file_actions_adddup2(&setup.actions, report_fd, 3);
  posix_spawn_file_actions_addclosefrom_np(&setup.actions, report_fd >= 0 ? 4 : 3);

  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<char*> envp;
  for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  const auto overridden = [&env](std::string_view entry) {
    const std::string_view name = entry.substr(0, entry.find('=') + 1);
    for (const std::string& e : env)
      if (std::string_view(e).starts_with(name)) return true;
    return false;
  };
  for (char** e = environ; *e; ++e)
    if (!overridden(*e)) envp.push_back(*e);
  envp.push_back(nullptr);
  const int error = posix_spawn(&pid_, args[0], &setup.actions, &setup.attr, args.data(), envp.data());
  for (int m : moved) close(m);
  if (error != 0) throw std::system_error(error, std::generic_category(), "posix_spawn " + argv[0]);
  // The child stays a zombie until we reap it, so its pidfd can always be opened.
  pidfd_ = open_pidfd(pid_);
  if (pidfd_ < 0) {
    const std::system_error e = system_error("pidfd_open");
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    throw e;
  }
}

ChildProcess::~ChildProcess() {
  if (!status_) {
    send(SIGKILL);
    siginfo_t info{};
    while (waitid(P_PIDFD, static_cast<id_t>(pidfd_), &info, WEXITED) != 0 && errno == EINTR) {
    }
  }
  close(pidfd_);
}

bool ChildProcess::send(int signal) {
  if (status_) return false;
  // The group id is the child's pid, which cannot be reused while the child is not reaped.
  if (signal == SIGKILL) killpg(pid_, SIGKILL);
  return send_to_pidfd(pidfd_, signal) == 0;
}

std::optional<ExitStatus> ChildProcess::try_wait() {
  if (status_) return status_;
  siginfo_t info{};
  if (waitid(P_PIDFD, static_cast<id_t>(pidfd_), &info, WEXITED | WNOHANG) != 0) {
    if (errno == EINTR) return std::nullopt;
    throw system_error("waitid");
  }
  if (info.si_pid == 0) return std::nullopt;  // still running
  status_ = ExitStatus{.signaled = info.si_code != CLD_EXITED, .code = info.si_status};
  return status_;
}

std::optional<ExitStatus> ChildProcess::wait_for(std::chrono::milliseconds timeout) {
  if (status_) return status_;
  pollfd p{.fd = pidfd_, .events = POLLIN, .revents = 0};
  const int n = poll(&p, 1, static_cast<int>(timeout.count()));
  if (n < 0 && errno != EINTR) throw system_error("poll");
  return try_wait();
}

}  // namespace kontakt::server

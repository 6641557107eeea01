#include "server/command.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

extern char** environ;

namespace kontakt::server {

namespace {

constexpr std::size_t kMaxOutput = 1u << 20;

std::system_error system_error(const char* what) {
  return std::system_error(errno, std::generic_category(), what);
}

/// Reads what `fd` has into `text`; false at end of file.
bool drain(int fd, std::string& text) {
  char block[4096];
  const ssize_t n = read(fd, block, sizeof block);
  if (n < 0) return errno == EINTR || errno == EAGAIN;
  if (n == 0) return false;
  if (text.size() < kMaxOutput) text.append(block, static_cast<std::size_t>(n));
  return true;
}

}  // namespace

CommandResult run_command(const std::vector<std::string>& argv,
                          std::chrono::milliseconds timeout) {
  int out[2], err[2];
  if (pipe2(out, O_CLOEXEC) != 0) throw system_error("pipe2");
  if (pipe2(err, O_CLOEXEC) != 0) {
    const std::system_error e = system_error("pipe2");
    close(out[0]);
    close(out[1]);
    throw e;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_adddup2(&actions, err[1], 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  close(err[1]);
  if (spawned != 0) {
    close(out[0]);
    close(err[0]);
    errno = spawned;
    throw system_error(("cannot run " + argv[0]).c_str());
  }
  CommandResult r;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  bool out_open = true, err_open = true;
  while (out_open || err_open) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      r.timed_out = true;
      kill(pid, SIGKILL);
      break;
    }
    pollfd fds[2] = {{.fd = out_open ? out[0] : -1, .events = POLLIN, .revents = 0},
                     {.fd = err_open ? err[0] : -1, .events = POLLIN, .revents = 0}};
    if (::poll(fds, 2, static_cast<int>(left.count())) < 0 && errno != EINTR) break;
    if (out_open && fds[0].revents) out_open = drain(out[0], r.out);
    if (err_open && fds[1].revents) err_open = drain(err[0], r.err);
  }
  close(out[0]);
  close(err[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.exit = WIFSIGNALED(status) ? ExitStatus{.signaled = true, .code = WTERMSIG(status)}
                               : ExitStatus{.signaled = false, .code = WEXITSTATUS(status)};
  return r;
}

std::string command_error(const CommandResult& r) {
  std::string text = r.err;
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (r.timed_out) return "no answer within the time limit" + (text.empty() ? "" : ": " + text);
  return text.empty() ? describe(r.exit) : text;
}

}  // namespace kontakt::server

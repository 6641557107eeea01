#include "server/worker_process.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <nlohmann/json.hpp>
#include <system_error>

namespace kontakt::server {

namespace {

/// Events are a few hundred bytes; a check report is one line. Longer lines are dropped.
constexpr std::size_t kMaxReportLine = 1u << 20;

std::system_error system_error(const char* what) {
  return std::system_error(errno, std::generic_category(), what);
}

}  // namespace

WorkerProcess::WorkerProcess(const std::filesystem::path& exe, int threads)
    : lines_(kMaxReportLine) {
  const Pipe pipe = make_report_pipe();
  int request[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, request) != 0) {
    const std::system_error e = system_error("socketpair");
    close(pipe.read_end);
    close(pipe.write_end);
    throw e;
  }
  report_ = pipe.read_end;
  request_ = request[0];
  try {
    // OpenBLAS starts its threads when it loads: as many as the work will use. A process
    // with one thread also flushes its TLB without interrupting the other cores.
    child_.emplace(std::vector<std::string>{exe.string(), worker::kCommand, worker::kStandby,
                                            std::to_string(getpid())},
                   pipe.write_end, request[1],
                   std::vector<std::string>{"OPENBLAS_NUM_THREADS=" + std::to_string(threads)});
  } catch (...) {
    for (int fd : {pipe.write_end, request[1], report_, request_}) close(fd);
    throw;
  }
  // The child holds the other ends now: its exit is our end of file.
  close(pipe.write_end);
  close(request[1]);
}

WorkerProcess::~WorkerProcess() {
  if (report_ >= 0) close(report_);
  if (request_ >= 0) close(request_);
}

void WorkerProcess::end_requests() {
  if (request_ >= 0) close(request_);
  request_ = -1;
}

bool WorkerProcess::stop(bool graceful) { return send(graceful ? SIGTERM : SIGKILL); }

bool WorkerProcess::start(const worker::Args& args) {
  if (request_ < 0) return false;
  const std::string line =
      nlohmann::json(worker::to_argv(args))
          .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) +
      '\n';
  std::string_view rest = line;
  while (!rest.empty()) {
    const ssize_t n = ::send(request_, rest.data(), rest.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    rest.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

std::optional<ExitStatus> WorkerProcess::poll(std::chrono::milliseconds timeout,
                                              const LineHandler& on_line, int wake_fd) {
  pollfd fds[3];
  nfds_t n = 0;
  fds[n++] = {.fd = child_->pidfd(), .events = POLLIN, .revents = 0};
  if (report_ >= 0) fds[n++] = {.fd = report_, .events = POLLIN, .revents = 0};
  if (wake_fd >= 0) fds[n++] = {.fd = wake_fd, .events = POLLIN, .revents = 0};
  if (::poll(fds, n, static_cast<int>(timeout.count())) < 0 && errno != EINTR)
    throw std::system_error(errno, std::generic_category(), "poll");
  if (report_ >= 0 && !pump_lines(report_, lines_, on_line)) {
    close(report_);
    report_ = -1;
  }
  const std::optional<ExitStatus> status = child_->try_wait();
  if (!status) return std::nullopt;
  // Ended: what it wrote before is in the pipe (nobody else holds the write end).
  if (report_ >= 0) {
    pump_lines(report_, lines_, on_line);
    lines_.finish();
    close(report_);
    report_ = -1;
  }
  return status;
}

}  // namespace kontakt::server

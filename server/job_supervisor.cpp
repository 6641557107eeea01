#include "server/job_supervisor.hpp"

#include <sys/eventfd.h>
#include <unistd.h>

#include <system_error>

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

namespace kontakt::server {

namespace {

/// How often the supervisor looks at the clock when nothing happens.
constexpr auto kTick = std::chrono::milliseconds(50);

}  // namespace

StopSignal::StopSignal() : event_fd_(eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
  if (event_fd_ < 0) throw std::system_error(errno, std::generic_category(), "eventfd");
}

StopSignal::~StopSignal() { close(event_fd_); }

void StopSignal::request(StopCause cause) {
  StopCause none = StopCause::None;
  cause_.compare_exchange_strong(none, cause);
  const std::uint64_t one = 1;
  // The counter only has to become non-zero; a full counter is as good as written.
  [[maybe_unused]] const ssize_t n = write(event_fd_, &one, sizeof one);
}

bool writing_results(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().extension() == ".partial") return true;
  return false;
}

ProcessEnd supervise_job(Execution& process, analysis::EventSink& sink, StopSignal& stop,
                         const SupervisionSettings& settings, const fs::path& work_dir) {
  ProcessEnd end;
  const auto started = Clock::now();
  std::optional<Clock::time_point> term_sent;
  const auto relay = [&](std::string_view line) {
    std::optional<analysis::Event> event = analysis::from_json_line(line);
    if (!event) {
      ++end.n_bad_reports;
      return;
    }
    ++end.n_events;
    if (event->kind == analysis::Event::Kind::Done) end.done = *event;
    try {
      sink.on_event(*event);
    } catch (const std::exception& e) {  // e.g. a full disk under the store: keep reading
      if (!end.sink_error) end.sink_error = e.what();
    }
  };
  while (true) {
    // The wake-up descriptor stays readable once raised: watch it only until SIGTERM is sent.
    const auto status = process.poll(kTick, relay, term_sent ? -1 : stop.wake_fd());
    if (status) {
      end.exit = *status;
      break;
    }
    const auto now = Clock::now();
    if (settings.time_limit > 0 &&
        now - started > std::chrono::duration<double>(settings.time_limit))
      stop.request(StopCause::TimeLimit);
    if (stop.cause() == StopCause::None) continue;
    if (stop.cause() == StopCause::Drain && process.outlives_daemon()) {
      end.detached = true;
      break;
    }
    if (!term_sent) {
      process.stop(true);
      term_sent = now;
      continue;
    }
    const auto waited = now - *term_sent;
    const bool frame_in_progress =
        waited < settings.grace + settings.max_frame_write && writing_results(work_dir);
    if (!end.killed && waited > settings.grace && !frame_in_progress)
      end.killed = process.stop(false);
  }
  end.cause = stop.cause();
  end.failure = process.failure();
  end.n_bad_reports += process.n_dropped_lines();
  end.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return end;
}

}  // namespace kontakt::server

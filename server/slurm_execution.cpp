#include "server/slurm_execution.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>

#include "server/command.hpp"

namespace kontakt::server {

namespace {

constexpr std::size_t kMaxEventLine = 1u << 20;
/// The run's files are looked at no more often (they may be on NFS, one reader per job).
constexpr auto kFilePoll = std::chrono::milliseconds(100);
constexpr auto kScancelTimeout = std::chrono::seconds(30);
/// The end of slurm-N.out quoted in a failure: the last lines, at most this many bytes.
constexpr std::size_t kOutputTail = 600;

std::optional<std::string> read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The last bytes of the batch job's output, on one line.
std::string output_tail(const std::filesystem::path& file) {
  std::string text = read_text(file).value_or("");
  if (text.size() > kOutputTail) text = "..." + text.substr(text.size() - kOutputTail);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (char& c : text)
    if (c == '\n') c = ' ';
  return text;
}

bool scancel(const std::vector<std::string>& argv) {
  try {
    const CommandResult r = run_command(argv, kScancelTimeout);
    if (!r.ok()) std::fprintf(stderr, "kontaktd: %s: %s\n", argv[0].c_str(), command_error(r).c_str());
    return r.ok();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: scancel: %s\n", e.what());
    return false;
  }
}

}  // namespace

SlurmExecution::SlurmExecution(std::string slurm_id, slurm::RunFiles files, SlurmQueue& queue,
                               FinishedState finished_state,
                               std::chrono::milliseconds outcome_wait,
                               Clock::time_point known_since, std::size_t skip_events)
    : slurm_id_(std::move(slurm_id)), files_(std::move(files)), queue_(queue),
      finished_state_(std::move(finished_state)), outcome_wait_(outcome_wait),
      known_since_(known_since), skip_events_(skip_events), lines_(kMaxEventLine) {}

SlurmExecution::~SlurmExecution() {
  if (events_fd_ >= 0) close(events_fd_);
}

void SlurmExecution::read_events(const LineHandler& on_line) {
  if (events_fd_ < 0) {  // the run creates the file when it starts
    events_fd_ = open(files_.events().c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (events_fd_ < 0) return;
  }
  // A regular file: read to its current end; what is appended later is read next time (a
  // line cut at the end waits for its rest: not pump_lines, which ends the stream there).
  const LineHandler relay = [&](std::string_view line) {
    if (skip_events_ > 0) --skip_events_;
    else on_line(line);
  };
  char block[65536];
  ssize_t n;
  while ((n = read(events_fd_, block, sizeof block)) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) lines_.feed(std::string_view(block, static_cast<std::size_t>(n)), relay);
}

std::optional<ExitStatus> SlurmExecution::outcome() {
  const auto text = read_text(files_.outcome());
  if (!text) return std::nullopt;
  const auto code = worker::parse_outcome(*text);
  if (!code) return std::nullopt;  // renamed into place whole: garbled means not ours
  if (*code == static_cast<int>(worker::Exit::Cancelled))
    // Not the daemon's stop (the supervisor's cause says so then): Slurm's, ahead of --time.
    failure_ = ExecutorFailure{
        .reason = "time_limit",
        .message = "Slurm job " + slurm_id_ +
                   " was stopped by SIGTERM from outside kontaktd: the --signal=B:TERM warning "
                   "ahead of its time limit, or an scancel; the results of converged "
                   "increments are kept"};
  return ExitStatus{.signaled = false, .code = *code};
}

std::optional<ExitStatus> SlurmExecution::slurm_end() {
  if (!seen_ended_) {
    const SlurmQueue::Answer answer = queue_.look_up(slurm_id_, known_since_);
    if (answer.kind == SlurmQueue::Answer::Kind::Unknown) return std::nullopt;
    if (answer.kind == SlurmQueue::Answer::Kind::Listed && !slurm::is_finished(answer.state.state))
      return std::nullopt;
    seen_ended_ = Clock::now();
    if (answer.kind == SlurmQueue::Answer::Kind::Listed) ended_state_ = answer.state;
  }
  if (Clock::now() - *seen_ended_ < outcome_wait_) return std::nullopt;
  // Ended, and no outcome came: Slurm's record says how (scontrol has the exit code).
  std::optional<slurm::JobState> state = finished_state_(slurm_id_);
  if (state && !slurm::is_finished(state->state)) {  // squeue was wrong after all: watch on
    seen_ended_.reset();
    ended_state_.reset();
    return std::nullopt;
  }
  if (!state) state = ended_state_;
  if (!state) state = slurm::JobState{.state = "UNKNOWN", .reason = "no longer known to Slurm"};
  failure_ = slurm::failure_from(slurm_id_, *state, output_tail(files_.output(slurm_id_)));
  return ExitStatus{.signaled = false, .code = -1};
}

std::optional<ExitStatus> SlurmExecution::poll(std::chrono::milliseconds timeout,
                                               const LineHandler& on_line, int wake_fd) {
  if (over_) return std::nullopt;
  pollfd fd{.fd = wake_fd, .events = POLLIN, .revents = 0};
  const auto wait = std::max(timeout, kFilePoll);
  if (::poll(&fd, wake_fd >= 0 ? 1 : 0, static_cast<int>(wait.count())) < 0 && errno != EINTR)
    throw std::system_error(errno, std::generic_category(), "poll");
  read_events(on_line);
  std::optional<ExitStatus> end = outcome();
  if (!end) end = slurm_end();
  if (!end) return std::nullopt;
  read_events(on_line);  // written before the outcome: all there now
  lines_.finish();
  over_ = true;
  return end;
}

bool SlurmExecution::stop(bool graceful) {
  if (over_) return false;
  // Only a running job has a batch shell to signal: Slurm answers a signal to a pending job
  // with success, and the job starts later all the same (seen with Slurm 22.05).
  if (graceful && state_now() == "RUNNING")
    return scancel({"scancel", "--quiet", "--signal=TERM", "--batch", slurm_id_});
  return scancel({"scancel", "--quiet", slurm_id_});
}

std::string SlurmExecution::state_now() const {
  try {
    const CommandResult r = run_command(
        {"squeue", "--noheader", "--jobs=" + slurm_id_, "--format=%T"}, kScancelTimeout);
    std::string state = r.out.substr(0, r.out.find('\n'));
    return r.ok() ? state : std::string();
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace kontakt::server

#include "server/slurm_queue.hpp"

#include <cstdio>

#include "server/command.hpp"

namespace kontakt::server {

namespace {

constexpr auto kSqueueTimeout = std::chrono::seconds(30);

}  // namespace

SlurmQueue::SlurmQueue(std::chrono::milliseconds interval, Squeue squeue)
    : interval_(interval), squeue_(std::move(squeue)) {}

std::optional<std::string> SlurmQueue::run_squeue() {
  try {
    const CommandResult r = run_command({"squeue", "--me", "--noheader", "--states=all",
                                         std::string("--format=") + slurm::kSqueueFormat},
                                        kSqueueTimeout);
    if (r.ok()) return r.out;
    std::fprintf(stderr, "kontaktd: squeue: %s\n", command_error(r).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: squeue: %s\n", e.what());
  }
  return std::nullopt;
}

void SlurmQueue::refresh_if_old() {
  const Clock::time_point now = Clock::now();
  if (now - tried_ < interval_) return;
  tried_ = now;
  if (const auto out = squeue_()) {
    jobs_ = slurm::parse_squeue(*out);
    taken_ = now;
  }
}

SlurmQueue::Answer SlurmQueue::look_up(const std::string& slurm_id, Clock::time_point since) {
  std::lock_guard lock(mutex_);  // the other threads wait for this squeue rather than run theirs
  refresh_if_old();
  if (!taken_ || *taken_ < since) return {};
  const auto it = jobs_.find(slurm_id);
  if (it == jobs_.end()) return {.kind = Answer::Kind::Absent, .state = {}};
  return {.kind = Answer::Kind::Listed, .state = it->second};
}

std::optional<std::string> SlurmQueue::find_by_comment(const std::string& job_id) {
  std::lock_guard lock(mutex_);
  tried_ = Clock::time_point{};  // a fresh one
  refresh_if_old();
  if (!taken_) return std::nullopt;
  for (const auto& [id, state] : jobs_)
    if (state.comment == job_id && !slurm::is_finished(state.state)) return id;
  return std::nullopt;
}

}  // namespace kontakt::server

#include "server/deck_check.hpp"

#include <unistd.h>

#include <csignal>
#include <memory>
#include <mutex>
#include <system_error>
#include <vector>
#include <nlohmann/json.hpp>

#include "server/worker_process.hpp"

using nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace kontakt::server {

namespace {

constexpr auto kPollTick = std::chrono::milliseconds(100);

/// Why a check that produced no report failed, in words for the 422 response.
std::string check_failure(const ExitStatus& status, const worker::Limits& limits) {
  if (!status.signaled && status.code == static_cast<int>(worker::Exit::OutOfMemory))
    return limits.memory_bytes
               ? "reading the deck needs more than the memory limit of " +
                     worker::byte_size(limits.memory_bytes)
               : "reading the deck ran out of memory";
  if (status.signaled)
    return "the deck reader stopped with " + describe(status) +
           (status.code == SIGKILL ? " (the system may have run out of memory)" : "");
  return "the deck check ended with " + describe(status);
}

}  // namespace

std::string deck_check_to_json(const app::DeckCheck& check) {
  json j;
  if (check.error) {
    j["error"] = {{"file", check.error->file},
                  {"line", check.error->line},
                  {"keyword", check.error->keyword},
                  {"message", check.error->message}};
  } else {
    j["n_steps"] = check.n_steps;
    j["total_time"] = check.total_time;
  }
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::optional<app::DeckCheck> deck_check_from_json(std::string_view line) {
  const json j = json::parse(line.begin(), line.end(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  app::DeckCheck check;
  if (const auto e = j.find("error"); e != j.end()) {
    if (!e->is_object()) return std::nullopt;
    const auto text = [&](const char* name) {
      const auto it = e->find(name);
      return it != e->end() && it->is_string() ? it->get<std::string>() : std::string();
    };
    const auto line_no = e->find("line");
    check.error = app::DeckError{
        .file = text("file"),
        .line = line_no != e->end() && line_no->is_number_integer() ? line_no->get<int>() : 0,
        .keyword = text("keyword"),
        .message = text("message")};
    return check;
  }
  const auto steps = j.find("n_steps");
  const auto time = j.find("total_time");
  if (steps == j.end() || !steps->is_number_integer() || time == j.end() || !time->is_number())
    return std::nullopt;
  check.n_steps = steps->get<int>();
  check.total_time = time->get<double>();
  return check;
}

namespace {

/// Check processes waiting for decks. Each checks one deck after the other - a check costs no
/// process start - and is dropped after any failure (the next check gets a fresh one) or after
/// kChecksPerProcess checks (whatever the reader's heap became). Thread-safe.
class CheckProcesses {
 public:
  struct Lease {
    std::unique_ptr<WorkerProcess> process;
    int checks = 0;
  };

  explicit CheckProcesses(std::filesystem::path exe) : exe_(std::move(exe)) {}

  void fill() {
    while (size() < kIdleCheckProcesses) {
      try {
        give_back({std::make_unique<WorkerProcess>(exe_, 1), 0});
      } catch (const std::system_error&) {
        return;  // out of processes: take() starts one when needed (and reports it)
      }
    }
  }

  Lease take() {
    {
      std::lock_guard lock(mutex_);
      while (!idle_.empty()) {
        Lease lease = std::move(idle_.back());
        idle_.pop_back();
        if (lease.process->alive()) return lease;
      }
    }
    return {std::make_unique<WorkerProcess>(exe_, 1), 0};
  }

  void give_back(Lease lease) {
    if (lease.checks >= kChecksPerProcess) return;  // dropped: the process ends
    std::lock_guard lock(mutex_);
    if (idle_.size() < kIdleCheckProcesses) idle_.push_back(std::move(lease));
  }

 private:
  static constexpr std::size_t kIdleCheckProcesses = 2;
  static constexpr int kChecksPerProcess = 1000;

  std::size_t size() {
    std::lock_guard lock(mutex_);
    return idle_.size();
  }

  const std::filesystem::path exe_;
  std::mutex mutex_;
  std::vector<Lease> idle_;
};

std::string seconds(std::chrono::milliseconds time) {
  return std::to_string(std::chrono::duration_cast<std::chrono::seconds>(time).count()) + " s";
}

}  // namespace

DeckChecker process_deck_checker(std::filesystem::path exe, worker::Limits limits,
                                 std::chrono::milliseconds time_limit) {
  auto processes = std::make_shared<CheckProcesses>(exe);
  processes->fill();
  return [processes, limits, time_limit](const std::filesystem::path& deck,
                                         const std::optional<std::string>& scheme) {
    const worker::Args args{.mode = worker::Mode::Check, .deck = deck, .scheme = scheme,
                            .limits = limits, .parent_pid = getpid()};
    CheckProcesses::Lease lease = processes->take();
    if (!lease.process->start(args)) {  // gone while it waited: a fresh one
      lease = processes->take();
      lease.process->start(args);
    }
    std::optional<app::DeckCheck> report;
    bool reported = false;
    const auto on_line = [&](std::string_view line) {
      report = deck_check_from_json(line);
      reported = true;
    };
    const auto deadline = Clock::now() + time_limit;
    while (!reported) {
      if (const auto status = lease.process->poll(kPollTick, on_line); status && !reported)
        return DeckCheckResult{.check = {}, .failure = check_failure(*status, limits)};
      if (!reported && Clock::now() > deadline)  // dropping the lease kills the process
        return DeckCheckResult{.check = {},
                               .failure = "reading the deck took longer than " + seconds(time_limit)};
    }
    if (!report) return DeckCheckResult{.check = {}, .failure = "the deck check's report was unreadable"};
    ++lease.checks;
    processes->give_back(std::move(lease));
    processes->fill();
    return DeckCheckResult{.check = *report, .failure = {}};
  };
}

}  // namespace kontakt::server

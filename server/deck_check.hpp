// The deck check of a submission, run in a worker process (`kontaktd job-worker`): a deck
// that crashes the reader, exhausts memory or takes forever to read costs that process, never
// the daemon. The process reports one JSON line per deck (to_json / from_json below).
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "app/run_job.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server {

struct DeckCheckResult {
  app::DeckCheck check{};              ///< the deck's error, or its steps and planned time
  /// Set when the check itself did not finish (crash, memory or time limit): why, in words.
  std::optional<std::string> failure{};
};

/// Checks the deck at the path (the main file of an upload) with the scheme override.
using DeckChecker = std::function<DeckCheckResult(const std::filesystem::path& deck,
                                                  const std::optional<std::string>& scheme)>;

/// The daemon's checker: worker processes of `exe` waiting for decks, each checking one after
/// the other, with `limits` and a wall-time limit per deck. A process that crashes, exhausts
/// its memory or runs past the limit (killed then) fails that deck's check only.
DeckChecker process_deck_checker(std::filesystem::path exe, worker::Limits limits,
                                 std::chrono::milliseconds time_limit);

/// The report line of a check (no newline).
std::string deck_check_to_json(const app::DeckCheck& check);
/// nullopt when `line` is not a check report.
std::optional<app::DeckCheck> deck_check_from_json(std::string_view line);

}  // namespace kontakt::server

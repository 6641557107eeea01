// What the API handlers work with: the store, the job folders, the worker pool seen through
// JobControl (so handler tests run without workers) and the deck checker (a worker process in
// the daemon, deck_check.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "server/deck_check.hpp"
#include "server/job_files.hpp"
#include "server/job_store.hpp"

namespace kontakt::server::handlers {

/// The worker pool as the handlers see it.
class JobControl {
 public:
  virtual ~JobControl() = default;
  /// A job was queued: wake an idle worker.
  virtual void job_queued() = 0;
  /// The job is now canceling: raise its cancel flag if it runs here.
  virtual void cancel_running(const std::string& id) = 0;
  /// The job was canceled while queued: an executor that started it ahead of its claim (a
  /// sweep's Slurm array task) stops it.
  virtual void cancel_unclaimed(const std::string& /*id*/) {}
  /// Workers configured / busy, for /healthz and /metrics.
  virtual int n_workers() const = 0;
  virtual int n_busy() const = 0;
};

struct ApiContext {
  JobStore& store;
  JobFiles& files;
  JobControl& control;
  DeckChecker check_deck;
  std::uint64_t max_unpacked = 1ull << 30;  ///< zip uploads unpack to at most this many bytes
};

}  // namespace kontakt::server::handlers

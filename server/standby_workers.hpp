// Job processes started ahead of need, so that a job does not wait for its process to load
// the solver's libraries: take() hands out a waiting one; fill(), called when a job has ended
// (off the next job's path), starts replacements. Each process runs one job only. Thread-safe.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

#include "server/worker_process.hpp"

namespace kontakt::server {

class StandbyWorkers {
 public:
  /// Keeps up to `keep` processes of `exe` waiting, for jobs with `threads` solver threads.
  StandbyWorkers(std::filesystem::path exe, std::size_t keep, int threads)
      : exe_(std::move(exe)), keep_(keep), threads_(threads) {}
  /// Starts processes until `keep` wait (failures are left to take()).
  void fill();
  /// A waiting process, or a fresh one when none waits; throws std::system_error when none can
  /// be started.
  std::unique_ptr<WorkerProcess> take();

 private:
  const std::filesystem::path exe_;
  const std::size_t keep_;
  const int threads_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<WorkerProcess>> idle_;
};

}  // namespace kontakt::server

#include "server/standby_workers.hpp"

#include <system_error>

namespace kontakt::server {

void StandbyWorkers::fill() {
  while (true) {
    {
      std::lock_guard lock(mutex_);
      if (idle_.size() >= keep_) return;
    }
    std::unique_ptr<WorkerProcess> fresh;
    try {
      fresh = std::make_unique<WorkerProcess>(exe_, threads_);  // outside the lock: a spawn takes ~ms
    } catch (const std::system_error&) {
      return;  // out of processes or descriptors: take() will try again (and report it)
    }
    std::lock_guard lock(mutex_);
    idle_.push_back(std::move(fresh));
  }
}

std::unique_ptr<WorkerProcess> StandbyWorkers::take() {
  std::unique_ptr<WorkerProcess> ready;
  {
    std::lock_guard lock(mutex_);
    while (!ready && !idle_.empty()) {
      ready = std::move(idle_.back());
      idle_.pop_back();
      if (!ready->alive()) ready.reset();  // killed while it waited
    }
  }
  if (!ready) ready = std::make_unique<WorkerProcess>(exe_, threads_);
  return ready;
}

}  // namespace kontakt::server

// The daemon's EventSink for one run: every event the job's process reports (decoded from its
// pipe by the supervisor) goes into the job's event log in the store, with the progress it
// implies; the Done event's summary is kept for the worker.
#pragma once

#include <optional>
#include <string>

#include "analysis/events.hpp"
#include "server/job_store.hpp"

namespace kontakt::server {

class StoreEventSink final : public analysis::EventSink {
 public:
  StoreEventSink(JobStore& store, std::string job_id) : store_(store), id_(std::move(job_id)) {}
  void on_event(const analysis::Event& event) override;
  /// Iterations so far and, after a converged Done event, its figures (wall_time unset).
  const JobSummary& summary() const { return summary_; }

 private:
  JobStore& store_;  ///< not owned
  std::string id_;
  JobProgress progress_;
  JobSummary summary_;
};

/// The progress after `event` (unchanged for kinds that say nothing about it).
JobProgress advance_progress(JobProgress progress, const analysis::Event& event);

}  // namespace kontakt::server

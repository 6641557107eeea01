// EventSink that appends one JSON object per line to a file, flushed per event so that
// `tail -f` and the daemon see progress as it happens.
#pragma once

#include <filesystem>
#include <fstream>

#include "analysis/events.hpp"

namespace kontakt::analysis {

class JsonlEventLog final : public EventSink {
 public:
  explicit JsonlEventLog(const std::filesystem::path& path);
  void on_event(const Event& event) override;

 private:
  std::ofstream out_;
};

/// Forwards every event to several sinks (log file, progress line, ...).
class EventFanout final : public EventSink {
 public:
  void add(EventSink& sink) { sinks_.push_back(&sink); }
  void on_event(const Event& event) override {
    for (EventSink* s : sinks_) s->on_event(event);
  }

 private:
  std::vector<EventSink*> sinks_;  ///< not owned
};

}  // namespace kontakt::analysis

// The sink the driver tests hand an analysis: it keeps every frame and every event reported.
#pragma once

#include <vector>

#include "analysis/events.hpp"
#include "analysis/linear_static.hpp"

namespace kontakt::testing_decks {

struct Collect : analysis::FrameSink, analysis::EventSink {
  std::vector<output::Frame> frames;
  std::vector<analysis::Event> events;
  void on_frame(const model::Step&, const output::Frame& f) override { frames.push_back(f); }
  void on_event(const analysis::Event& e) override { events.push_back(e); }
};

}  // namespace kontakt::testing_decks

// EventSink for the terminal: a one-line, rewritten progress display on a TTY and plain lines
// otherwise (pipes, CI logs).
#pragma once

#include <cstdio>

#include "analysis/events.hpp"

namespace kontakt::app {

class ProgressPrinter final : public analysis::EventSink {
 public:
  explicit ProgressPrinter(std::FILE* out);
  void on_event(const analysis::Event& event) override;

 private:
  std::FILE* out_;
  bool tty_;
};

}  // namespace kontakt::app

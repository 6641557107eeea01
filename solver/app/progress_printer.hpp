// EventSink for the terminal: a one-line, rewritten progress display on a TTY and plain lines
// otherwise (pipes, CI logs). Warnings always go to stderr, even when quiet.
#pragma once

#include <cstdio>

#include "analysis/events.hpp"

namespace kontakt::app {

class ProgressPrinter final : public analysis::EventSink {
 public:
  explicit ProgressPrinter(std::FILE* out, bool quiet = false);
  void on_event(const analysis::Event& event) override;

 private:
  std::FILE* out_;
  bool tty_;
  bool quiet_;
};

}  // namespace kontakt::app

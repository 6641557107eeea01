// Lines from a pipe: what a worker process reports arrives as newline-terminated JSON, in
// chunks that split lines anywhere. Memory is bounded: an overlong line is dropped, not kept.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace kontakt::server {

using LineHandler = std::function<void(std::string_view line)>;

class LineSplitter {
 public:
  explicit LineSplitter(std::size_t max_line) : max_line_(max_line) {}
  /// Calls `on_line` for every line `bytes` completes (without its '\n').
  void feed(std::string_view bytes, const LineHandler& on_line);
  /// Lines longer than max_line, and an unterminated last line (see finish()), so far.
  std::size_t n_dropped() const { return n_dropped_; }
  /// End of the stream: an unterminated rest is dropped (a writer that died mid-line).
  void finish();

 private:
  std::size_t max_line_;
  std::string partial_;
  bool skipping_ = false;  ///< inside an overlong line, until its '\n'
  std::size_t n_dropped_ = 0;
};

/// Reads everything available from the non-blocking `fd` into `lines`. False at end of file
/// (or a read error): the writer is gone.
bool pump_lines(int fd, LineSplitter& lines, const LineHandler& on_line);

}  // namespace kontakt::server

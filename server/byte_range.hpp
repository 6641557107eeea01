// The one byte range a download honours (RFC 9110 section 14): "bytes=a-b", "bytes=a-",
// "bytes=-n". Multiple ranges and other units are answered with the whole file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace kontakt::server {

struct ByteRange {
  std::uint64_t offset = 0, length = 0;
};

enum class RangeResult { Whole, Partial, Unsatisfiable };

/// Interprets a Range header against a file of `size` bytes; `range` is set for Partial.
RangeResult parse_byte_range(const std::optional<std::string>& header, std::uint64_t size,
                             ByteRange& range);

}  // namespace kontakt::server

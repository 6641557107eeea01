#include "server/byte_range.hpp"

namespace kontakt::server {

namespace {

std::optional<std::uint64_t> parse_number(const std::string& s) {
  if (s.empty() || s.size() > 19) return std::nullopt;
  std::uint64_t n = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return n;
}

}  // namespace

RangeResult parse_byte_range(const std::optional<std::string>& header, std::uint64_t size,
                             ByteRange& range) {
  const std::string prefix = "bytes=";
  if (!header || header->rfind(prefix, 0) != 0) return RangeResult::Whole;
  const std::string spec = header->substr(prefix.size());
  const std::size_t dash = spec.find('-');
  if (dash == std::string::npos || spec.find(',') != std::string::npos) return RangeResult::Whole;
  const std::string first = spec.substr(0, dash), last = spec.substr(dash + 1);
  if (first.empty()) {  // suffix: the last n bytes
    const auto n = parse_number(last);
    if (!n) return RangeResult::Whole;
    if (*n == 0 || size == 0) return RangeResult::Unsatisfiable;
    range.length = std::min(*n, size);
    range.offset = size - range.length;
    return RangeResult::Partial;
  }
  const auto a = parse_number(first);
  const auto b = last.empty() ? std::optional<std::uint64_t>(size ? size - 1 : 0) : parse_number(last);
  if (!a || !b) return RangeResult::Whole;
  if (*a >= size) return RangeResult::Unsatisfiable;
  if (*b < *a) return RangeResult::Whole;
  range.offset = *a;
  range.length = std::min(*b, size - 1) - *a + 1;
  return RangeResult::Partial;
}

}  // namespace kontakt::server

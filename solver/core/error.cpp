#include "core/error.hpp"

#include <sstream>

namespace kontakt {

namespace {

/// Messages quote the deck (keywords, fields, names); a pathological deck line must not turn
/// into a megabyte error message.
constexpr std::size_t kMaxKeyword = 80, kMaxMessage = 1000;

std::string clip(const std::string& text, std::size_t max) {
  return text.size() <= max ? text : text.substr(0, max) + "...";
}

std::string format_input_error(const SourceLoc& where, const std::string& keyword,
                               const std::string& message) {
  std::ostringstream text;
  text << (where.file.empty() ? "<input>" : where.file);
  if (where.line > 0) text << ':' << where.line;
  text << ": ";
  if (!keyword.empty()) text << keyword << ": ";
  text << clip(message, kMaxMessage);
  return text.str();
}

}  // namespace

InputError::InputError(const SourceLoc& where, const std::string& keyword,
                       const std::string& message)
    : std::runtime_error(format_input_error(where, clip(keyword, kMaxKeyword), message)),
      where_(where),
      keyword_(clip(keyword, kMaxKeyword)) {}

}  // namespace kontakt

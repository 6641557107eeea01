#include "core/error.hpp"

#include <sstream>

namespace kontakt {

namespace {
std::string format_input_error(const SourceLoc& where, const std::string& keyword,
                               const std::string& message) {
  std::ostringstream text;
  text << (where.file.empty() ? "<input>" : where.file);
  if (where.line > 0) text << ':' << where.line;
  text << ": ";
  if (!keyword.empty()) text << keyword << ": ";
  text << message;
  return text.str();
}
}  // namespace

InputError::InputError(const SourceLoc& where, const std::string& keyword,
                       const std::string& message)
    : std::runtime_error(format_input_error(where, keyword, message)),
      where_(where),
      keyword_(keyword) {}

}  // namespace kontakt

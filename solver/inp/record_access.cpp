#include "inp/record_access.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace kontakt::inp {

std::string trim(std::string_view text) {
  const auto is_blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return std::string(text);
}

std::string to_upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return out;
}

std::string remove_blanks(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c != ' ' && c != '\t') out += c;
  }
  return out;
}

void fail(const Record& record, const std::string& message) {
  throw InputError(record.where, record.keyword, message);
}

void fail(const Record& record, const DataLine& line, const std::string& message) {
  throw InputError(line.where, record.keyword, message);
}

void check_params(const Record& record, std::initializer_list<std::string_view> allowed) {
  for (std::size_t i = 0; i < record.params.size(); ++i) {
    const std::string& name = record.params[i].name;
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      fail(record, "unknown or unsupported parameter " + name);
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (record.params[j].name == name) fail(record, "parameter " + name + " given twice");
    }
  }
}

const Param* find_param(const Record& record, std::string_view name) {
  for (const Param& p : record.params) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

bool has_param(const Record& record, std::string_view name) {
  return find_param(record, name) != nullptr;
}

std::string required_value(const Record& record, std::string_view name) {
  const Param* param = find_param(record, name);
  if (param == nullptr || param->value.empty()) {
    fail(record, "parameter " + std::string(name) + "= is required");
  }
  return param->value;
}

std::optional<std::string> name_value(const Record& record, std::string_view name) {
  const Param* param = find_param(record, name);
  if (param == nullptr) return std::nullopt;
  if (param->value.empty()) fail(record, "parameter " + std::string(name) + "= needs a value");
  return remove_blanks(to_upper(param->value));
}

std::optional<int> int_param(const Record& record, std::string_view name) {
  const Param* param = find_param(record, name);
  if (param == nullptr) return std::nullopt;
  const std::optional<int> value = parse_int(param->value);
  if (!value) {
    fail(record, "parameter " + std::string(name) + "=" + param->value + " is not an integer");
  }
  return value;
}

std::optional<Real> parse_real(std::string_view text) {
  std::string s = remove_blanks(text);
  if (s.empty()) return std::nullopt;
  for (char& c : s) {
    if (c == 'd' || c == 'D') c = 'e';  // Fortran double-precision exponent
  }
  std::size_t start = s.front() == '+' ? 1 : 0;
  Real value = 0;
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data() + start, end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> parse_int(std::string_view text) {
  std::string s = remove_blanks(text);
  if (s.empty()) return std::nullopt;
  std::size_t start = s.front() == '+' ? 1 : 0;
  int value = 0;
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data() + start, end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

namespace {
std::string describe_field(const DataLine& line, std::size_t index) {
  const std::string text = index < line.fields.size() ? line.fields[index] : "";
  return "field " + std::to_string(index + 1) + " ('" + text + "')";
}
}  // namespace

Real real_field(const Record& record, const DataLine& line, std::size_t index) {
  if (index >= line.fields.size() || line.fields[index].empty()) {
    fail(record, line, "field " + std::to_string(index + 1) + " is missing");
  }
  const std::optional<Real> value = parse_real(line.fields[index]);
  if (!value) fail(record, line, describe_field(line, index) + " is not a number");
  return *value;
}

int int_field(const Record& record, const DataLine& line, std::size_t index) {
  if (index >= line.fields.size() || line.fields[index].empty()) {
    fail(record, line, "field " + std::to_string(index + 1) + " is missing");
  }
  const std::optional<int> value = parse_int(line.fields[index]);
  if (!value) fail(record, line, describe_field(line, index) + " is not an integer");
  return *value;
}

std::optional<Real> optional_real_field(const Record& record, const DataLine& line,
                                        std::size_t index) {
  if (index >= line.fields.size() || line.fields[index].empty()) return std::nullopt;
  return real_field(record, line, index);
}

Real real_field_or(const Record& record, const DataLine& line, std::size_t index,
                   Real fallback) {
  return optional_real_field(record, line, index).value_or(fallback);
}

void require_one_temperature(const Record& record, const DataLine& line, std::size_t index,
                             std::optional<Real>& seen, const std::string& what) {
  const std::optional<Real> t = optional_real_field(record, line, index);
  if (!t) return;
  if (seen && *t != *seen) fail(record, line, what + " is not supported");
  seen = t;
}

void require_line_count(const Record& record, std::size_t min, std::size_t max) {
  const std::size_t n = record.lines.size();
  if (n < min) fail(record, "expected at least " + std::to_string(min) + " data line(s)");
  if (n > max) {
    fail(record, record.lines[max], "expected at most " + std::to_string(max) +
                                        " data line(s)");
  }
}

void require_field_count(const Record& record, const DataLine& line, std::size_t min,
                         std::size_t max) {
  const std::size_t n = line.fields.size();
  if (n < min) {
    fail(record, line, "expected at least " + std::to_string(min) + " field(s), got " +
                           std::to_string(n));
  }
  if (n > max) {
    fail(record, line, "expected at most " + std::to_string(max) + " field(s), got " +
                           std::to_string(n));
  }
}

}  // namespace kontakt::inp

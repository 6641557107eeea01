#include "cli/parameter_table.hpp"

#include <set>

namespace kontakt::cli {

namespace {

std::string trimmed(const std::string& s) {
  const std::size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

/// One record's fields from `at` (advanced past its line end); `line` counts the file's lines.
std::vector<std::string> read_record(const std::string& csv, std::size_t& at, int& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false, was_quoted = false;
  const int first_line = line;
  for (; at < csv.size(); ++at) {
    const char c = csv[at];
    if (quoted) {
      if (c == '"' && at + 1 < csv.size() && csv[at + 1] == '"') {
        field += '"';
        ++at;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
    } else if (c == '"' && trimmed(field).empty()) {
      quoted = was_quoted = true;
      field.clear();
    } else if (c == ',') {
      fields.push_back(was_quoted ? field : trimmed(field));
      field.clear();
      was_quoted = false;
    } else if (c == '\n') {
      ++at;
      ++line;
      break;
    } else if (c != '\r') {
      field += c;
    }
  }
  if (quoted) throw TableError("line " + std::to_string(first_line) + ": a quote is not closed");
  fields.push_back(was_quoted ? field : trimmed(field));
  return fields;
}

/// Moves `at` past lines of nothing but spaces.
void skip_blank_lines(const std::string& csv, std::size_t& at, int& line) {
  while (at < csv.size()) {
    const std::size_t end = csv.find('\n', at);
    const std::string text = csv.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (text.find_first_not_of(" \t\r") != std::string::npos) return;
    at = end == std::string::npos ? csv.size() : end + 1;
    ++line;
  }
}

}  // namespace

std::vector<std::map<std::string, std::string>> parse_parameter_table(const std::string& csv) {
  std::size_t at = 0;
  int line = 1;
  skip_blank_lines(csv, at, line);
  if (at == csv.size()) throw TableError("line 1: no header row (the parameter names)");
  const int header_line = line;
  const std::vector<std::string> header = read_record(csv, at, line);
  std::set<std::string> names;
  for (const std::string& name : header) {
    if (name.empty()) throw TableError("line " + std::to_string(header_line) + ": an empty column name");
    if (!names.insert(name).second)
      throw TableError("line " + std::to_string(header_line) + ": column '" + name + "' twice");
  }
  std::vector<std::map<std::string, std::string>> rows;
  for (skip_blank_lines(csv, at, line); at < csv.size(); skip_blank_lines(csv, at, line)) {
    const int row_line = line;
    const std::vector<std::string> fields = read_record(csv, at, line);
    if (fields.size() != header.size())
      throw TableError("line " + std::to_string(row_line) + ": " + std::to_string(fields.size()) +
                       " fields, the header has " + std::to_string(header.size()));
    auto& row = rows.emplace_back();
    for (std::size_t i = 0; i < header.size(); ++i) row[header[i]] = fields[i];
  }
  if (rows.empty()) throw TableError("line " + std::to_string(line) + ": no row below the header");
  return rows;
}

}  // namespace kontakt::cli

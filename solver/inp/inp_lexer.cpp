#include "inp/inp_lexer.hpp"

#include <fstream>
#include <sstream>

#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

/// Deeper nesting than this is almost certainly an include cycle.
constexpr int kMaxIncludeDepth = 16;

std::vector<std::string> split_commas(std::string_view line) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    parts.push_back(trim(line.substr(start, comma == std::string_view::npos
                                                ? std::string_view::npos
                                                : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return parts;
}

std::string collapse_blanks(std::string_view text) {
  std::string out;
  for (char c : text) {
    const bool blank = c == ' ' || c == '\t';
    if (blank && (out.empty() || out.back() == ' ')) continue;
    out += blank ? ' ' : c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

Record parse_keyword_line(std::string_view line, const SourceLoc& where) {
  std::vector<std::string> parts = split_commas(line.substr(1));
  Record record;
  record.keyword = '*';  // appended, not "*" + ...: avoids a GCC 12 -Wrestrict false positive
  record.keyword += to_upper(collapse_blanks(parts.front()));
  record.key = remove_blanks(to_upper(parts.front()));
  record.where = where;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    if (parts[i].empty()) continue;  // "*NODE, NSET=A," is common
    Param param;
    const std::size_t eq = parts[i].find('=');
    param.name = remove_blanks(to_upper(parts[i].substr(0, eq)));
    if (eq != std::string::npos) {
      param.value = trim(parts[i].substr(eq + 1));
      param.has_value = true;
    }
    record.params.push_back(std::move(param));
  }
  return record;
}

DataLine parse_data_line(std::string_view line, const SourceLoc& where) {
  DataLine data;
  data.where = where;
  data.fields = split_commas(line);
  if (data.fields.size() > 1 && data.fields.back().empty()) {
    data.fields.pop_back();
    data.ends_with_comma = true;
  }
  return data;
}

class Lexer {
 public:
  std::vector<Record> records;

  void lex(std::string_view text, const std::string& file, const std::filesystem::path& dir,
           int depth) {
    std::istringstream stream{std::string(text)};
    std::string raw;
    int line_number = 0;
    while (std::getline(stream, raw)) {
      ++line_number;
      if (!raw.empty() && raw.back() == '\r') raw.pop_back();
      const std::string line = trim(raw);
      if (line.empty() || line.starts_with("**")) continue;
      const SourceLoc where{file, line_number};
      if (line.front() == '*') {
        Record record = parse_keyword_line(line, where);
        if (record.key.empty()) throw InputError(where, "*", "no keyword after '*'");
        if (record.key == "INCLUDE") {
          include(record, dir, depth);
        } else {
          records.push_back(std::move(record));
        }
      } else if (records.empty() || records.back().key == "INCLUDE") {
        throw InputError(where, "", "data line before any keyword");
      } else {
        records.back().lines.push_back(parse_data_line(line, where));
      }
    }
  }

  void include(const Record& record, const std::filesystem::path& dir, int depth) {
    const Param* input = nullptr;
    for (const Param& p : record.params) {
      if (p.name == "INPUT") input = &p;
      else throw InputError(record.where, record.keyword, "unknown parameter " + p.name);
    }
    if (input == nullptr || input->value.empty())
      throw InputError(record.where, record.keyword, "INPUT= is required");
    if (depth >= kMaxIncludeDepth)
      throw InputError(record.where, record.keyword, "includes nested too deeply (cycle?)");
    std::string name = input->value;
    if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'')) {
      name = name.substr(1, name.size() - 2);
    }
    std::filesystem::path path = name;
    if (path.is_relative()) path = dir / path;
    // A FIFO or a device (/dev/zero, /dev/stdin) would never end; a folder has no text.
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
      throw InputError(record.where, record.keyword,
                       "include file '" + path.string() + "' is not a regular file");
    std::ifstream file(path, std::ios::binary);
    if (!file) {
      throw InputError(record.where, record.keyword, "cannot open include file '" +
                                                         path.string() + "'");
    }
    std::ostringstream content;
    content << file.rdbuf();
    lex(content.str(), path.string(), path.parent_path(), depth + 1);
    // Data lines after the include belong to no keyword: mark with a sentinel record.
    records.push_back(Record{"*INCLUDE", "INCLUDE", {}, {}, record.where});
  }
};

std::vector<Record> drop_include_sentinels(std::vector<Record> records) {
  std::vector<Record> kept;
  kept.reserve(records.size());
  for (Record& r : records) {
    if (r.key != "INCLUDE") kept.push_back(std::move(r));
  }
  return kept;
}

}  // namespace

std::vector<Record> lex_deck_text(std::string_view text, const std::string& file_name,
                                  const std::filesystem::path& include_dir) {
  Lexer lexer;
  lexer.lex(text, file_name, include_dir, 0);
  return drop_include_sentinels(std::move(lexer.records));
}

std::vector<Record> lex_deck_file(const std::filesystem::path& deck) {
  std::ifstream file(deck, std::ios::binary);
  if (!file) throw InputError(SourceLoc{deck.string(), 0}, "", "cannot open deck");
  std::ostringstream content;
  content << file.rdbuf();
  return lex_deck_text(content.str(), deck.string(), deck.parent_path());
}

}  // namespace kontakt::inp

// Splits a deck into keyword records: keyword line + parameters + the data lines below it.
// Handles ** comments, blank lines, case-insensitive keywords/parameter names and *INCLUDE.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace kontakt::inp {

struct Param {
  std::string name;   ///< upper case, blanks removed ("TIME" of TIME=TOTAL TIME)
  std::string value;  ///< as written, trimmed (file names keep their case); empty if none
  bool has_value = false;
};

struct DataLine {
  std::vector<std::string> fields;  ///< comma-separated, trimmed; a trailing comma adds no field
  bool ends_with_comma = false;     ///< the line continues on the next one (*ELEMENT)
  SourceLoc where;
};

struct Record {
  std::string keyword;  ///< display form: "*SOLID SECTION" (upper case, single blanks)
  std::string key;      ///< lookup form: "SOLIDSECTION" (ccx ignores blanks in keywords)
  std::vector<Param> params;
  std::vector<DataLine> lines;
  SourceLoc where;
};

/// Reads a deck file and all its includes (INPUT= relative to the including file).
std::vector<Record> lex_deck_file(const std::filesystem::path& deck);

/// Lexes deck text; includes are resolved relative to `include_dir`.
std::vector<Record> lex_deck_text(std::string_view text, const std::string& file_name,
                                  const std::filesystem::path& include_dir);

}  // namespace kontakt::inp

// The parameter table of `kontakt sweep TEMPLATE.inp PARAMS.csv`: a CSV file whose header row
// names the template's <name> placeholders and whose every other row is one job. Fields are
// separated by commas; a field may be quoted ("a, b", "" for a quote); spaces around an
// unquoted field are dropped; blank lines are skipped. Pure.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace kontakt::cli {

/// A malformed table; the message starts with "line N: ".
class TableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The rows (column name -> value), in file order. Throws TableError for an empty or
/// duplicate column name, a row with another number of fields than the header, an unclosed
/// quote, or a table without a row.
std::vector<std::map<std::string, std::string>> parse_parameter_table(const std::string& csv);

}  // namespace kontakt::cli

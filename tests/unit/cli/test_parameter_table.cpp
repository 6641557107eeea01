// The CSV parameter table of `kontakt sweep`: fields, quotes, blank lines, and every error
// naming its line.
#include <gtest/gtest.h>

#include "cli/parameter_table.hpp"

namespace kontakt::cli {
namespace {

using Rows = std::vector<std::map<std::string, std::string>>;

std::string error_of(const std::string& csv) {
  try {
    parse_parameter_table(csv);
  } catch (const TableError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ParameterTable, RowsByHeaderName) {
  EXPECT_EQ(parse_parameter_table("load, mu\n-10, 0.2\r\n\n -20 ,\"0.3\"\n"),
            (Rows{{{"load", "-10"}, {"mu", "0.2"}}, {{"load", "-20"}, {"mu", "0.3"}}}));
  EXPECT_EQ(parse_parameter_table("\nname,t\n\"a, \"\"b\"\"\",1\n\"two\nlines\",2"),
            (Rows{{{"name", "a, \"b\""}, {"t", "1"}}, {{"name", "two\nlines"}, {"t", "2"}}}));
  EXPECT_EQ(parse_parameter_table("x\n\"\"\n"), (Rows{{{"x", ""}}}));
}

TEST(ParameterTable, ErrorsNameTheLine) {
  EXPECT_EQ(error_of(""), "line 1: no header row (the parameter names)");
  EXPECT_EQ(error_of("a,b\n"), "line 2: no row below the header");
  EXPECT_EQ(error_of("a,,b\n1,2,3\n"), "line 1: an empty column name");
  EXPECT_EQ(error_of("a,a\n1,2\n"), "line 1: column 'a' twice");
  EXPECT_EQ(error_of("a,b\n1,2\n\n3\n"), "line 4: 1 fields, the header has 2");
  EXPECT_EQ(error_of("a\n\"1\n"), "line 2: a quote is not closed");
}

}  // namespace
}  // namespace kontakt::cli

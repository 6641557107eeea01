// A sweep's template expansion (sweep_template.hpp): placeholders, substitution, and every
// error naming its field and row.
#include <gtest/gtest.h>

#include "server/sweep_template.hpp"

namespace kontakt::server {
namespace {

const std::string kTemplate =
    "*HEADING\n** <= not a placeholder, nor <1x> nor < t>\n*ELASTIC\n<E>, 0.3\n"
    "*CLOAD\nTIP, 3, <load>\n*STATIC\n<dt>, 1.0, <dt>\n";

SweepError error_of(const std::vector<SweepRow>& rows, const std::string& deck = kTemplate) {
  auto r = expand_sweep(deck, rows);
  EXPECT_TRUE(std::holds_alternative<SweepError>(r));
  return std::holds_alternative<SweepError>(r) ? std::get<SweepError>(r) : SweepError{};
}

TEST(SweepTemplate, FindsThePlaceholdersOnly) {
  EXPECT_EQ(placeholders(kTemplate), (std::set<std::string>{"E", "dt", "load"}));
  EXPECT_EQ(placeholders("<a.b-c_1> <_x> <" + std::string(64, 'y') + ">"),
            (std::set<std::string>{"a.b-c_1", "_x", std::string(64, 'y')}));
  EXPECT_TRUE(placeholders("<" + std::string(65, 'y') + "> <a b> <> <a").empty());
}

TEST(SweepTemplate, EachRowGetsItsOwnDeck) {
  auto r = expand_sweep(kTemplate, {{{"E", "210000"}, {"load", "-5"}, {"dt", "0.1"}},
                                    {{"E", "70000"}, {"load", "-2.5e1"}, {"dt", "1"}}});
  ASSERT_TRUE(std::holds_alternative<std::vector<std::string>>(r));
  const auto& decks = std::get<std::vector<std::string>>(r);
  ASSERT_EQ(decks.size(), 2u);
  EXPECT_EQ(decks[0],
            "*HEADING\n** <= not a placeholder, nor <1x> nor < t>\n*ELASTIC\n210000, 0.3\n"
            "*CLOAD\nTIP, 3, -5\n*STATIC\n0.1, 1.0, 0.1\n");
  EXPECT_NE(decks[1].find("70000, 0.3\n"), std::string::npos);
  EXPECT_NE(decks[1].find("TIP, 3, -2.5e1\n"), std::string::npos);
  EXPECT_NE(decks[1].find("1, 1.0, 1\n"), std::string::npos);
}

TEST(SweepTemplate, ErrorsNameTheFieldAndTheRow) {
  const SweepRow full{{"E", "1"}, {"load", "2"}, {"dt", "3"}};
  auto e = error_of({});
  EXPECT_EQ(e.field, "rows");
  e = error_of(std::vector<SweepRow>(kMaxSweepRows + 1, full));
  EXPECT_EQ(e.field, "rows");
  EXPECT_NE(e.message.find("at most 1000"), std::string::npos);
  EXPECT_EQ(error_of({full}, "*HEADING\n").field, "template");
  // A placeholder without a column.
  e = error_of({{{"E", "1"}, {"load", "2"}}});
  EXPECT_EQ(e.field, "template");
  EXPECT_NE(e.message.find("<dt>"), std::string::npos);
  // A column without a placeholder (a misspelt name).
  SweepRow extra = full;
  extra["lod"] = "3";
  e = error_of({extra});
  EXPECT_EQ(e.field, "rows");
  EXPECT_NE(e.message.find("'lod'"), std::string::npos);
  e = error_of({full, extra});
  EXPECT_EQ(e.row, 1u);
  // A later row without a value.
  e = error_of({full, full, {{"E", "1"}, {"load", "2"}}});
  EXPECT_EQ(e.row, 2u);
  EXPECT_NE(e.message.find("'dt'"), std::string::npos);
  // Values that would change the deck's lines, or overlong ones.
  SweepRow bad = full;
  bad["load"] = "2\n*STEP";
  e = error_of({full, bad});
  EXPECT_EQ(e.row, 1u);
  EXPECT_NE(e.message.find("control character"), std::string::npos);
  bad["load"] = std::string(kMaxSweepValue + 1, '1');
  EXPECT_EQ(error_of({bad}).row, 0u);
}

}  // namespace
}  // namespace kontakt::server

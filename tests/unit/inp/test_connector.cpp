// SPRINGA and GAPUNI elements with *SPRING and *GAP: the connectors the reader builds (nodes,
// laws, ccx's gap defaults, element sets that hold them beside solids) and every malformed
// form (run by test_errors.cpp through connector_bad_decks()). Against ccx 2.20: the suite's
// spring1, spring2, gap and gap2 in tests/peer/coverage_baseline.txt.
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

namespace {

/// The two cubes (lines 1-26), a node 100 and spring 10 from node 11 to it, gap 11 from node
/// 12 to it, both in EALL: lines 27-32; a card appended starts at line 33.
std::string connector_model() {
  return two_cubes_model() +
         "*NODE\n100, 3, 0, 0\n*ELEMENT, TYPE=SPRINGA, ELSET=EALL\n10, 11, 100\n"
         "*ELEMENT, TYPE=GAPUNI, ELSET=G\n11, 12, 100\n";
}

}  // namespace

std::vector<BadDeck> connector_bad_decks() {
  const auto plus = [](const std::string& tail) { return connector_model() + tail; };
  const std::string gap = "*GAP, ELSET=G\n0.5, 1, 0, 0\n";
  return {
      {"spring without law", plus(gap), 30, "*ELEMENT", "element 10 has no *SPRING card"},
      {"gap without law", plus("*SPRING, ELSET=EALL\n10.\n"), 32, "*ELEMENT",
       "element 11 has no *GAP card"},
      {"spring without elset", plus(gap + "*SPRING\n10.\n"), 35, "*SPRING",
       "parameter ELSET= is required"},
      {"spring law on a gap", plus(gap + "*SPRING, ELSET=G\n10.\n"), 35, "*SPRING",
       "element 11 of set G is a GAPUNI element"},
      {"spring two constants", plus(gap + "*SPRING, ELSET=EALL\n10.\n20.\n"), 37, "*SPRING",
       "a linear spring has one line"},
      {"spring temperatures", plus(gap + "*SPRING, ELSET=EALL, NONLINEAR\n0, 0, 20\n1, 1, 30\n"),
       37, "*SPRING", "temperature-dependent springs are not supported"},
      {"spring curve not ascending",
       plus(gap + "*SPRING, ELSET=EALL, NONLINEAR\n0, 0\n5, 1\n6, 1\n"), 38, "*SPRING",
       "the elongations must ascend"},
      {"spring undefined set", plus(gap + "*SPRING, ELSET=NOPE\n10.\n"), 35, "*SPRING",
       "element set NOPE is not defined"},
      {"gap zero direction", plus("*GAP, ELSET=G\n0.5, 0, 0, 0\n"), 34, "*GAP",
       "the gap direction is the zero vector"},
      {"gap negative stiffness", plus("*GAP, ELSET=G\n0.5, 1, 0, 0, , -1.\n"), 34, "*GAP",
       "the gap stiffness and tensile force must be positive"},
      {"connector twice", plus("*ELEMENT, TYPE=SPRINGA\n10, 1, 2\n"), 34, "*ELEMENT",
       "element 10 defined twice"},
      {"connector solid label", plus("*ELEMENT, TYPE=SPRINGA\n1, 1, 2\n"), 34, "*ELEMENT",
       "element 1 defined twice"},
      {"connector undefined node", plus("*ELEMENT, TYPE=GAPUNI\n12, 1, 77\n"), 34, "*ELEMENT",
       "node 77 of element 12 is not defined"},
      {"connector one node", plus("*ELEMENT, TYPE=SPRINGA\n12, 1\n"), 34, "*ELEMENT",
       "expected at least 3 field(s)"},
      {"spring of zero length",
       plus(gap + "*SPRING, ELSET=EALL\n10.\n*NODE\n101, 3, 0, 0\n*ELEMENT, TYPE=SPRINGA, "
                  "ELSET=EALL\n12, 100, 101\n"),
       40, "*ELEMENT", "spring element 12 has zero length"},
  };
}

}  // namespace test

namespace {

TEST(inpConnector, SpringsAndGapsTakeTheirLawsAndLeaveTheSolidSets) {
  const model::Model m = read_deck_text(test::connector_model() +
                                        "*SPRING, ELSET=EALL, NONLINEAR\n\n0., 0.\n10., 1.\n100., "
                                        "20.\n*GAP, ELSET=G\n0.5, 0, 3, 4\n");
  EXPECT_EQ(m.element_sets.at("EALL").elements.size(), 2u);  // the cubes only
  ASSERT_EQ(m.connectors.size(), 2u);
  const auto& spring = m.connectors[0];
  EXPECT_EQ(spring.kind, model::Connector::Kind::Spring);
  EXPECT_EQ(spring.id, 10);
  EXPECT_EQ(spring.nodes[0], m.mesh.node_index.at(11));
  EXPECT_EQ(spring.nodes[1], m.mesh.node_index.at(100));
  EXPECT_EQ(spring.curve, (std::vector<std::pair<Real, Real>>{{0, 0}, {1, 10}, {20, 100}}));
  const auto& gap = m.connectors[1];
  EXPECT_EQ(gap.kind, model::Connector::Kind::Gap);
  EXPECT_EQ(gap.clearance, 0.5);
  EXPECT_NEAR((gap.direction - Vec3(0, 0.6, 0.8)).norm(), 0, 1e-15);
  EXPECT_EQ(gap.stiffness, 1e12);  // ccx's defaults
  EXPECT_EQ(gap.tension, 1e-3);
}

}  // namespace
}  // namespace kontakt::inp

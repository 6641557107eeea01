// *DISTRIBUTING COUPLING with its DCOUP3D element: the equations the reader builds and every
// malformed form (run by test_errors.cpp through coupling_bad_decks()). Against ccx 2.20: the
// suite's distcoup (coverage_baseline.txt) and make_constraint_decks.py's coupling decks.
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

namespace {

/// The two cubes (lines 1-26) and a reference node 100 in DCOUP3D element 50 of set C: lines
/// 27-30; a card appended starts at line 31.
std::string coupling_model() {
  return two_cubes_model() + "*NODE\n100, 3, 0, 0\n*ELEMENT, TYPE=DCOUP3D, ELSET=C\n50, 100\n";
}

}  // namespace

std::vector<BadDeck> coupling_bad_decks() {
  const auto plus = [](const std::string& tail) { return coupling_model() + tail; };
  const std::string card = "*DISTRIBUTING COUPLING, ELSET=";
  return {
      {"coupling without elset", plus("*DISTRIBUTING COUPLING\nTIP, 1.\n"), 31,
       "*DISTRIBUTING COUPLING", "parameter ELSET= is required"},
      {"coupling without nodes", plus(card + "C\n"), 31, "*DISTRIBUTING COUPLING",
       "expected at least 1 data line"},
      {"coupling zero weight", plus(card + "C\nTIP, 0.\n"), 32, "*DISTRIBUTING COUPLING",
       "the weight must be positive"},
      {"coupling undefined set", plus(card + "NOPE\nTIP, 1.\n"), 31, "*DISTRIBUTING COUPLING",
       "element set NOPE is not defined"},
      {"coupling on solids", plus(card + "EALL\nTIP, 1.\n"), 31, "*DISTRIBUTING COUPLING",
       "element set EALL must hold exactly one DCOUP3D element"},
      {"coupling undefined node set", plus(card + "C\nNOPE, 1.\n"), 31, "*DISTRIBUTING COUPLING",
       "node set NOPE is not defined"},
      {"coupling node twice", plus(card + "C\nTIP, 1.\n9, 2.\n"), 31, "*DISTRIBUTING COUPLING",
       "node 9 is coupled twice"},
      {"coupling reference coupled", plus(card + "C\n100, 1.\n"), 31, "*DISTRIBUTING COUPLING",
       "the reference node is one of the coupled nodes"},
      {"coupling undefined reference",
       two_cubes_model() + "*ELEMENT, TYPE=DCOUP3D, ELSET=C\n50, 77\n" + card + "C\nTIP, 1.\n", 29,
       "*DISTRIBUTING COUPLING", "reference node 77 is not defined"},
      {"coupling element twice", plus("*ELEMENT, TYPE=DCOUP3D\n50, 1\n"), 32, "*ELEMENT",
       "element 50 defined twice"},
  };
}

}  // namespace test

namespace {

TEST(inpCoupling, EachDirectionTiesTheWeightedNodesToTheReferenceNode) {
  const model::Model m =
      read_deck_text(test::coupling_model() + "*DISTRIBUTING COUPLING, ELSET=C\n6, 3.\nTIP, 1.\n");
  ASSERT_EQ(m.equations.size(), 3u);
  const auto& idx = m.mesh.node_index;
  for (int dof = 0; dof < 3; ++dof) {
    const model::Equation& eq = m.equations[static_cast<std::size_t>(dof)];
    EXPECT_EQ(eq.keyword, "*DISTRIBUTING COUPLING");
    // node 6 first (weight 3, dependent), then TIP's 9 to 12, the reference node last
    ASSERT_EQ(eq.terms.size(), 6u);
    EXPECT_EQ(eq.terms[0].node, idx.at(6));
    EXPECT_EQ(eq.terms[0].coef, 3.0);
    EXPECT_EQ(eq.terms[1].node, idx.at(9));
    EXPECT_EQ(eq.terms.back().node, idx.at(100));
    EXPECT_EQ(eq.terms.back().coef, -7.0);
    for (const auto& t : eq.terms) EXPECT_EQ(t.dof, dof);
  }
  EXPECT_TRUE(m.element_sets.at("C").elements.empty());
}

}  // namespace
}  // namespace kontakt::inp

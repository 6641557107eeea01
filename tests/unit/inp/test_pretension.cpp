// *PRE-TENSION SECTION: the cut the reader makes (copies, the owning element's connectivity,
// the equations u_copy = u_original + u_ref n, temperatures of the copies) and every malformed
// form (run by test_errors.cpp through pretension_bad_decks()). Against ccx 2.20:
// tests/peer/make_pretension_decks.py (CTest peer_ccx_pretension).
#include <gtest/gtest.h>

#include <map>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

namespace {

/// The two cubes (lines 1-26) with the face they share (x = 1, owned by element 1) as CUT and
/// a reference node 100: lines 27-30; a *PRE-TENSION SECTION appended starts at line 31.
std::string cut_model() {
  return two_cubes_model() + "*SURFACE, NAME=CUT\n1, S4\n*NODE\n100, 0, 0, 0\n";
}

}  // namespace

std::vector<BadDeck> pretension_bad_decks() {
  const auto plus = [](const std::string& tail) { return cut_model() + tail; };
  return {
      {"pretension by a beam", plus("*PRE-TENSION SECTION, ELEMENT=3, NODE=100\n1, 0, 0\n"), 31,
       "*PRE-TENSION SECTION", "ELEMENT= (a beam element as the bolt) is not supported"},
      {"pretension without node", plus("*PRE-TENSION SECTION, SURFACE=CUT\n1, 0, 0\n"), 31,
       "*PRE-TENSION SECTION", "NODE= is required"},
      {"pretension node not a label",
       plus("*PRE-TENSION SECTION, SURFACE=CUT, NODE=REF\n1, 0, 0\n"), 31,
       "*PRE-TENSION SECTION", "NODE=REF is not a node label"},
      {"pretension undefined node",
       plus("*PRE-TENSION SECTION, SURFACE=CUT, NODE=555\n1, 0, 0\n"), 31,
       "*PRE-TENSION SECTION", "reference node 555 is not defined"},
      {"pretension zero normal", plus("*PRE-TENSION SECTION, SURFACE=CUT, NODE=100\n0, 0, 0\n"),
       32, "*PRE-TENSION SECTION", "the normal is the zero vector"},
      {"pretension two numbers", plus("*PRE-TENSION SECTION, SURFACE=CUT, NODE=100\n1, 0\n"), 32,
       "*PRE-TENSION SECTION", "expected at least 3 field(s)"},
      {"pretension without normal", plus("*PRE-TENSION SECTION, SURFACE=CUT, NODE=100\n"), 31,
       "*PRE-TENSION SECTION", "expected at least 1 data line"},
      {"pretension undefined surface",
       plus("*PRE-TENSION SECTION, SURFACE=NOPE, NODE=100\n1, 0, 0\n"), 31,
       "*PRE-TENSION SECTION", "surface NOPE is not defined"},
      {"pretension node surface",
       plus("*SURFACE, NAME=NODES, TYPE=NODE\n2, 3\n"
            "*PRE-TENSION SECTION, SURFACE=NODES, NODE=100\n1, 0, 0\n"),
       33, "*PRE-TENSION SECTION", "surface NODES is a node surface"},
      {"pretension reference node in an element",
       plus("*PRE-TENSION SECTION, SURFACE=CUT, NODE=9\n1, 0, 0\n"), 31, "*PRE-TENSION SECTION",
       "reference node 9 belongs to an element"},
      {"pretension node in two sections",
       plus("*NODE\n101, 0, 0, 0\n*PRE-TENSION SECTION, SURFACE=CUT, NODE=100\n1, 0, 0\n"
            "*PRE-TENSION SECTION, SURFACE=CUT, NODE=101\n1, 0, 0\n"),
       35, "*PRE-TENSION SECTION", "node 2 is also in the pre-tension section at"},
  };
}

}  // namespace test

namespace {

TEST(inpPretension, TheOwningElementTakesCopiesTiedToTheOriginalsThroughTheReferenceNode) {
  const model::Model m = read_deck_text(
      test::cut_model() + "*PRE-TENSION SECTION, SURFACE=CUT, NODE=100\n3, 4, 0\n"
                          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 273.\n100, 5.\n");
  const auto& mesh = m.mesh;
  ASSERT_EQ(m.n_nodes(), 12 + 1 + 4);
  // Copies of the face's nodes 2, 3, 7, 6 (its corner order), labelled after the largest label.
  const std::map<int, int> copy_label{{2, 101}, {3, 102}, {7, 103}, {6, 104}};
  for (const auto& [original, copy] : copy_label) {
    const int o = mesh.node_index.at(original), c = mesh.node_index.at(copy);
    EXPECT_EQ(mesh.coords.row(o), mesh.coords.row(c)) << copy;
    EXPECT_EQ(m.initial_temperatures[c], 273.) << copy;
  }
  // Element 1 owns the face: it takes the copies; element 2 keeps the originals.
  const auto labels = [&](int element) {
    std::vector<int> out;
    for (int n : mesh.elements[static_cast<std::size_t>(element)].nodes)
      out.push_back(mesh.node_ids[static_cast<std::size_t>(n)]);
    return out;
  };
  EXPECT_EQ(labels(0), (std::vector<int>{1, 101, 102, 4, 5, 104, 103, 8}));
  EXPECT_EQ(labels(1), (std::vector<int>{2, 9, 10, 3, 6, 11, 12, 7}));
  // u_copy - u_original - u_ref n = 0 per component, n = (0.6, 0.8, 0).
  ASSERT_EQ(m.equations.size(), 12u);
  const int ref = mesh.node_index.at(100);
  for (std::size_t k = 0; k < m.equations.size(); ++k) {
    const model::Equation& eq = m.equations[k];
    const int dof = static_cast<int>(k % 3);
    EXPECT_EQ(eq.keyword, "*PRE-TENSION SECTION");
    EXPECT_EQ(eq.where.line, 31);
    ASSERT_EQ(eq.terms.size(), dof == 2 ? 2u : 3u) << k;
    EXPECT_EQ(mesh.node_ids[static_cast<std::size_t>(eq.terms[0].node)],
              copy_label.at(mesh.node_ids[static_cast<std::size_t>(eq.terms[1].node)]));
    EXPECT_EQ(eq.terms[0].dof, dof);
    EXPECT_EQ(eq.terms[0].coef, 1.0);
    EXPECT_EQ(eq.terms[1].dof, dof);
    EXPECT_EQ(eq.terms[1].coef, -1.0);
    if (dof == 2) continue;
    EXPECT_EQ(eq.terms[2].node, ref);
    EXPECT_EQ(eq.terms[2].dof, 0);
    EXPECT_NEAR(eq.terms[2].coef, dof == 0 ? -0.6 : -0.8, 1e-15);
  }
}

}  // namespace
}  // namespace kontakt::inp

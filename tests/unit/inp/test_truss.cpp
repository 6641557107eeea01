// T3D2 trusses: the connectors the reader builds from *ELEMENT and *SOLID SECTION (area,
// isotropic elastic constants, element sets beside solids) and every refused form (run by
// test_errors.cpp through truss_bad_decks()). Against ccx 2.20: the suite's truss in
// tests/peer/coverage_baseline.txt and tests/peer/make_truss_decks.py.
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

namespace {

/// The two cubes (lines 1-26), a node 100 and trusses 20, 21 from nodes 11 and 12 to it in
/// set BARS: lines 27-31; a card appended starts at line 32.
std::string truss_model() {
  return two_cubes_model() +
         "*NODE\n100, 3, 0, 0\n*ELEMENT, TYPE=T3D2, ELSET=BARS\n20, 11, 100\n21, 12, 100\n";
}

/// Material AL (lines 32-34) and the trusses' section with area 0.5 (lines 35-36).
const std::string kAluminium = "*MATERIAL, NAME=AL\n*ELASTIC\n70000., 0.33\n";
const std::string kSection = "*SOLID SECTION, ELSET=BARS, MATERIAL=AL\n0.5\n";

}  // namespace

std::vector<BadDeck> truss_bad_decks() {
  const auto plus = [](const std::string& tail) { return truss_model() + tail; };
  const std::string bars = "*SOLID SECTION, ELSET=BARS, MATERIAL=AL\n";
  return {
      {"truss without section", plus(kAluminium), 30, "*ELEMENT",
       "truss element 20 has no *SOLID SECTION"},
      {"truss without area", plus(kAluminium + bars), 35, "*SOLID SECTION",
       "truss element 20: the data line must give the cross-sectional area"},
      {"truss of zero area", plus(kAluminium + bars + "0.\n"), 35, "*SOLID SECTION",
       "the cross-sectional area must be positive"},
      {"truss of zero length",
       plus("*NODE\n101, 3, 0, 0\n*ELEMENT, TYPE=T3D2, ELSET=BARS\n22, 100, 101\n" + kAluminium +
            kSection),
       35, "*ELEMENT", "truss element 22 has zero length"},
      {"truss joins a node to itself", plus("*ELEMENT, TYPE=T3D2\n22, 100, 100\n"), 33,
       "*ELEMENT", "element 22 joins a node to itself"},
      {"truss plastic",
       plus("*MATERIAL, NAME=AL\n*ELASTIC\n70000., 0.33\n*PLASTIC\n100., 0.\n" + kSection), 37,
       "*SOLID SECTION", "material AL has *PLASTIC: trusses take an isotropic *ELASTIC"},
      {"truss hyperelastic", plus("*MATERIAL, NAME=AL\n*HYPERELASTIC, NEO HOOKE\n1., 0.001\n" + kSection),
       35, "*SOLID SECTION", "material AL has *HYPERELASTIC"},
      {"truss elastic by temperature",
       plus("*MATERIAL, NAME=AL\n*ELASTIC\n70000., 0.33, 20.\n60000., 0.33, 200.\n" + kSection), 36,
       "*SOLID SECTION", "material AL has a temperature-dependent *ELASTIC"},
      {"truss expansion with temperatures",
       plus(kAluminium + "*EXPANSION\n1e-5\n" + kSection +
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"),
       37, "*SOLID SECTION", "material AL has *EXPANSION with temperatures"},
      {"truss orientation",
       plus(kAluminium + "*ORIENTATION, NAME=OR\n1, 0, 0, 0, 1, 0\n"
                         "*SOLID SECTION, ELSET=BARS, MATERIAL=AL, ORIENTATION=OR\n0.5\n"),
       37, "*SOLID SECTION", "ORIENTATION= is not supported for trusses"},
      {"truss contact surface", plus(kAluminium + kSection + "*SURFACE, NAME=S\n20, S1\n"), 38,
       "*SURFACE", "element 20 is a T3D2 element: it has no faces"},
      {"truss gravity",
       plus(kAluminium + "*DENSITY\n2.7e-9\n" + kSection +
            "*STEP\n*STATIC\n*DLOAD\nBARS, GRAV, 9810., 0, 0, -1\n*END STEP\n"),
       42, "*DLOAD", "element 20 is a truss (T3D2): distributed loads on trusses"},
      {"truss removed by model change",
       plus(kAluminium + kSection +
            "*STEP\n*STATIC\n*MODEL CHANGE, TYPE=ELEMENT, REMOVE\nBARS\n*END STEP\n"),
       40, "*MODEL CHANGE", "element 20 is a T3D2 element: TYPE=ELEMENT takes solid elements"},
      {"truss section changed",
       plus(kAluminium + kSection +
            "*STEP\n*STATIC\n*CHANGE SOLID SECTION, ELSET=BARS, MATERIAL=AL\n*END STEP\n"),
       39, "*CHANGE SOLID SECTION", "element 20 is a truss (T3D2): its section cannot change"},
      {"spring law on a truss", plus(kAluminium + kSection + "*SPRING, ELSET=BARS\n10.\n"), 37,
       "*SPRING", "element 20 of set BARS is a T3D2 element"},
  };
}

}  // namespace test

namespace {

TEST(inpTruss, TrussesTakeAreaAndConstantsFromTheirSectionAndLeaveTheSolidSets) {
  const model::Model m = read_deck_text(test::truss_model() + test::kAluminium + test::kSection +
                                        "*ELSET, ELSET=BOTH\nEALL, BARS\n");
  EXPECT_EQ(m.element_sets.at("BOTH").elements.size(), 2u);  // the cubes only
  ASSERT_EQ(m.connectors.size(), 2u);
  const model::Connector& bar = m.connectors[1];
  EXPECT_EQ(bar.kind, model::Connector::Kind::Truss);
  EXPECT_EQ(bar.id, 21);
  EXPECT_EQ(bar.nodes[0], m.mesh.node_index.at(12));
  EXPECT_EQ(bar.nodes[1], m.mesh.node_index.at(100));
  EXPECT_EQ(bar.area, 0.5);
  EXPECT_EQ(bar.young, 70000.);
  EXPECT_EQ(bar.poisson, 0.33);
}

}  // namespace
}  // namespace kontakt::inp

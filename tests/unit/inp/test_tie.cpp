// *TIE: its parameters and ccx's defaults, surfaces named before or after it, and every
// malformed form (run by test_errors.cpp through tie_bad_decks()).
#include <gtest/gtest.h>

#include <algorithm>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

std::vector<BadDeck> tie_bad_decks() {
  // The two cubes with their surfaces end at line 32: a *TIE appended is line 33, its data 34.
  const auto plus = [](const std::string& tail) { return two_cubes_surfaces() + tail; };
  const std::string tie = "*TIE, NAME=T";
  return {
      {"tie without name", plus("*TIE\nSLAVE, MASTER\n"), 33, "*TIE", "NAME= is required"},
      {"tie with empty name", plus("*TIE, NAME=\nSLAVE, MASTER\n"), 33, "*TIE",
       "NAME= needs a value"},
      {"cyclic tie without its model", plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n"), 34,
       "*TIE", "CYCLIC SYMMETRY tie T has no *CYCLIC SYMMETRY MODEL"},
      {"cyclic tie through contact", plus(tie + ", CYCLIC SYMMETRY, SCHEME=LGC7\nSLAVE, MASTER\n"),
       33, "*TIE", "a CYCLIC SYMMETRY tie is made of equations"},
      {"cyclic model without sectors",
       plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, TIE=T\n0,0,0,0,0,1\n"),
       35, "*CYCLIC SYMMETRY MODEL", "N= (the number of sectors, at least 2) is required"},
      {"cyclic model of one sector",
       plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, N=1, TIE=T\n"
                  "0,0,0,0,0,1\n"),
       35, "*CYCLIC SYMMETRY MODEL", "N= (the number of sectors, at least 2) is required"},
      {"cyclic model with more graphs",
       plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, N=4, TIE=T, "
                  "NGRAPH=4\n0,0,0,0,0,1\n"),
       35, "*CYCLIC SYMMETRY MODEL", "NGRAPH=4: results are written for the modelled sector"},
      {"cyclic model of an unknown tie",
       plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, N=4, TIE=U\n"
                  "0,0,0,0,0,1\n"),
       35, "*CYCLIC SYMMETRY MODEL", "TIE=U: no *TIE of that name before this card"},
      {"cyclic model of a plain tie",
       plus(tie + "\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, N=4, TIE=T\n0,0,0,0,0,1\n"), 35,
       "*CYCLIC SYMMETRY MODEL", "TIE=T is not a CYCLIC SYMMETRY tie"},
      {"cyclic model twice",
       plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, N=4, TIE=T\n"
                  "0,0,0,0,0,1\n*CYCLIC SYMMETRY MODEL, N=4, TIE=T\n0,0,0,0,0,1\n"),
       37, "*CYCLIC SYMMETRY MODEL", "tie T has a *CYCLIC SYMMETRY MODEL already"},
      {"cyclic model on one point",
       plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, N=4, TIE=T\n"
                  "1,2,3,1,2,3\n"),
       36, "*CYCLIC SYMMETRY MODEL", "the two points of the axis coincide"},
      {"cyclic model without axis",
       plus(tie + ", CYCLIC SYMMETRY\nSLAVE, MASTER\n*CYCLIC SYMMETRY MODEL, N=4, TIE=T\n"
                  "0,0,0\n"),
       36, "*CYCLIC SYMMETRY MODEL", "expected at least 6 field(s)"},
      {"multistage tie", plus(tie + ", MULTISTAGE\nSLAVE, MASTER\n"), 33, "*TIE",
       "MULTISTAGE ties are not supported"},
      {"tie with abaqus type", plus(tie + ", TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n"), 33,
       "*TIE", "unknown or unsupported parameter TYPE"},
      {"tie tolerance not a number", plus(tie + ", POSITION TOLERANCE=abc\nSLAVE, MASTER\n"), 33,
       "*TIE", "POSITION TOLERANCE=abc is not a number"},
      {"tie tolerance without value", plus(tie + ", POSITION TOLERANCE\nSLAVE, MASTER\n"), 33,
       "*TIE", "POSITION TOLERANCE= needs a value"},
      {"tie adjust other than no", plus(tie + ", ADJUST=0.1\nSLAVE, MASTER\n"), 33, "*TIE",
       "ADJUST=0.1: expected NO"},
      {"tie without data line", plus(tie + "\n*STEP\n*STATIC\n*END STEP\n"), 33, "*TIE",
       "expected at least 1 data line"},
      {"tie with two data lines", plus(tie + "\nSLAVE, MASTER\nSLAVENODES, MASTER\n"), 35,
       "*TIE", "expected at most 1 data line"},
      {"tie with one surface", plus(tie + "\nSLAVE\n"), 34, "*TIE",
       "expected at least 2 field(s)"},
      {"tie with three fields", plus(tie + "\nSLAVE, MASTER, 0.1\n"), 34, "*TIE",
       "expected at most 2 field(s)"},
      {"tie undefined slave", plus(tie + "\nNOPE, MASTER\n"), 34, "*TIE",
       "tie T: slave surface NOPE is not defined"},
      {"tie undefined master", plus(tie + "\nSLAVE, NOPE\n"), 34, "*TIE",
       "tie T: master surface NOPE is not defined"},
      {"tie node master", plus(tie + "\nSLAVE, SLAVENODES\n"), 34, "*TIE",
       "master surface SLAVENODES must be made of element faces"},
      {"tie empty slave", plus("*SURFACE, NAME=EMPTY\n" + tie + "\nEMPTY, MASTER\n"), 35, "*TIE",
       "slave surface EMPTY is empty"},
      {"tie surface on both sides", plus(tie + "\nMASTER, MASTER\n"), 34, "*TIE",
       "surface MASTER is both slave and master"},
      {"tie defined twice", plus(tie + "\nSLAVE, MASTER\n" + tie + "\nSLAVENODES, MASTER\n"), 35,
       "*TIE", "tie T is defined twice (first at bad.inp:34)"},
      {"tie within a step", plus("*STEP\n*STATIC\n" + tie + "\nSLAVE, MASTER\n*END STEP\n"), 35,
       "*TIE", "not allowed within a step"},
      {"tie with an unknown scheme", plus(tie + ", SCHEME=mortar\nSLAVE, MASTER\n"), 33, "*TIE",
       "SCHEME=MORTAR is not a contact scheme"},
      {"tie through node-to-surface contact", plus(tie + ", SCHEME=nts\nSLAVE, MASTER\n"), 33,
       "*TIE", "a tie through contact is face to face"},
      {"tie through contact from a node slave",
       plus(tie + ", SCHEME=lgc7\nSLAVENODES, MASTER\n"), 34, "*TIE",
       "SCHEME= ties through surface-to-surface contact, which needs element faces"},
  };
}

}  // namespace test

namespace {

const std::string kStep = "*STEP\n*STATIC\n*END STEP\n";

bool has_warning(const model::Model& m, const std::string& fragment) {
  return std::any_of(m.warnings.begin(), m.warnings.end(),
                     [&](const std::string& w) { return w.find(fragment) != std::string::npos; });
}

TEST(inpTie, ReadsNameToleranceAdjustAndSurfaces) {
  const model::Model m = read_deck_text(
      test::two_cubes_surfaces() +
          "*TIE, name=glue, POSITION TOLERANCE=5.d-2, ADJUST=no\nSlave, Master\n" + kStep,
      "tie.inp");
  ASSERT_EQ(m.ties.size(), 1u);
  const model::Tie& t = m.ties[0];
  EXPECT_EQ(t.name, "GLUE");
  EXPECT_EQ(t.slave, "SLAVE");
  EXPECT_EQ(t.master, "MASTER");
  ASSERT_TRUE(t.position_tolerance.has_value());
  EXPECT_DOUBLE_EQ(*t.position_tolerance, 0.05);
  EXPECT_FALSE(t.adjust);
  EXPECT_EQ(t.where.file, "tie.inp");
  EXPECT_EQ(t.where.line, 34);  // the data line
  EXPECT_TRUE(m.equations.empty());  // the constraints are a model-setup step, not the reader's
}

TEST(inpTie, SchemeTiesThroughContact) {
  const model::Model m = read_deck_text(
      test::two_cubes_surfaces() + "*TIE, NAME=T, SCHEME=lgc3\nSLAVE, MASTER\n" +
          "*TIE, NAME=U\nSLAVE, MASTER\n" + kStep, "tie.inp");
  ASSERT_EQ(m.ties.size(), 2u);
  ASSERT_TRUE(m.ties[0].scheme.has_value());
  EXPECT_EQ(model::contact_scheme_name(*m.ties[0].scheme), "lgc3");
  EXPECT_FALSE(m.ties[1].scheme.has_value());  // ccx's MPCs
  EXPECT_TRUE(m.contact_pairs.empty());       // the pair is a model-setup step
}

TEST(inpTie, DefaultsNodeSlaveAndSurfacesDefinedLater) {
  // Surfaces after the *TIE (ccx resolves them at the end of the input), a node slave surface,
  // no tolerance, ADJUST=YES as the explicit default, and two ties in deck order.
  const model::Model m = read_deck_text(
      test::two_cubes_model() + "*TIE, NAME=A, ADJUST=YES\nSLAVENODES, MASTER\n" +
          "*TIE, NAME=B, POSITION TOLERANCE=0.\nSLAVE, MASTER\n" +
          test::two_cubes_surfaces().substr(test::two_cubes_model().size()) + kStep,
      "tie.inp");
  ASSERT_EQ(m.ties.size(), 2u);
  EXPECT_EQ(m.ties[0].name, "A");
  EXPECT_EQ(m.ties[0].slave, "SLAVENODES");
  EXPECT_FALSE(m.ties[0].position_tolerance.has_value());
  EXPECT_TRUE(m.ties[0].adjust);
  // ccx: a tolerance below 1e-10 means the default; said in a warning.
  EXPECT_EQ(m.ties[1].name, "B");
  EXPECT_FALSE(m.ties[1].position_tolerance.has_value());
  EXPECT_TRUE(has_warning(m, "tie.inp:29: *TIE: POSITION TOLERANCE=0. is below 1e-10"));
}

}  // namespace
}  // namespace kontakt::inp

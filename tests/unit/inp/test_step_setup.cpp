// Step set-up cards: *TIME POINTS and the TIME POINTS= of output requests, *DLOAD PnNP, and every
// malformed form (run by test_errors.cpp through step_setup_bad_decks()).
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

std::vector<BadDeck> step_setup_bad_decks() {
  // The two cubes end at line 26: the first card appended is line 27.
  const auto plus = [](const std::string& tail) { return two_cubes_model() + tail; };
  const std::string points = "*TIME POINTS, NAME=T1\n.2, .5\n";  // lines 27, 28
  const std::string step = "*STEP, NLGEOM\n*STATIC\n.1, 1.\n";    // lines 29-31
  const std::string remove = "*MODEL CHANGE, TYPE=ELEMENT, REMOVE\n";  // line 30
  return {
      {"model change of an unknown element", plus(step + remove + "7\n"), 31, "*MODEL CHANGE",
       "element 7 is not defined"},
      {"model change of an unknown set", plus(step + remove + "NOPE\n"), 31, "*MODEL CHANGE",
       "element set NOPE is not defined"},
      {"model change without elements", plus(step + remove), 30, "*MODEL CHANGE",
       "expected at least 1 data line"},
      {"model change of plastic elements",
       [&] {
         std::string deck = two_cubes_model();
         deck.insert(deck.find("*SOLID SECTION"), "*PLASTIC\n800., 0.\n");
         return deck + "*STEP, NLGEOM\n*STATIC\n.1, 1.\n" + remove + "2\n*END STEP\n";
       }(),
       32, "*MODEL CHANGE", "TYPE=ELEMENT is not supported with *PLASTIC materials"},
      {"time points without name", plus("*TIME POINTS\n.2\n"), 27, "*TIME POINTS",
       "NAME= is required"},
      {"time points decreasing", plus("*TIME POINTS, NAME=T\n.2, .5\n.4\n"), 29,
       "*TIME POINTS", "must not decrease"},
      {"time points none", plus("*TIME POINTS, NAME=T\n"), 27, "*TIME POINTS",
       "no time points"},
      {"time points twice", plus(points + "*TIME POINTS, NAME=T1\n.3\n"), 29, "*TIME POINTS",
       "defined twice"},
      {"time points not a number", plus("*TIME POINTS, NAME=T\n.2, x\n"), 28, "*TIME POINTS",
       "x"},
      {"time points bad time", plus("*TIME POINTS, NAME=T, TIME=WALL\n.2\n"), 27,
       "*TIME POINTS", "TIME=WALL"},
      {"time points generate backwards", plus("*TIME POINTS, NAME=T, GENERATE\n1., 0., .1\n"),
       28, "*TIME POINTS", "positive step"},
      {"time points generate two fields", plus("*TIME POINTS, NAME=T, GENERATE\n0., 1.\n"), 28,
       "*TIME POINTS", "expected at least 3"},
      {"time points in a step",
       plus("*STEP\n*STATIC\n*TIME POINTS, NAME=T\n.2\n*END STEP\n"), 29, "*TIME POINTS",
       "not allowed within a step"},
      {"unknown time points", plus(step + "*NODE PRINT, NSET=TIP, TIME POINTS=T9\nU\n"), 30,
       "*NODE PRINT", "time points T9 are not defined"},
      {"time points and frequency",
       plus(points + step + "*EL FILE, TIME POINTS=T1, FREQUENCY=2\nS\n"), 32, "*EL FILE",
       "exclude each other"},
      {"time points with direct",
       plus(points + "*STEP, NLGEOM\n*STATIC, DIRECT\n.1, 1.\n*NODE PRINT, NSET=TIP, "
                     "TIME POINTS=T1\nU\n*END STEP\n"),
       29, "*STEP", "DIRECT"},
      {"network pressure node undefined",
       plus("*STEP\n*STATIC\n*DLOAD\n2, P4NP, 99\n*END STEP\n"), 30, "*DLOAD",
       "node 99"},
      {"network pressure without boundary",
       plus("*STEP\n*STATIC\n*DLOAD\n2, P4NP, 12\n*BOUNDARY\n12, 1, 1, 5.\n*END STEP\n"), 30,
       "*DLOAD", "node 12 has no prescribed value of dof 2"},
      {"network pressure bad face", plus("*STEP\n*STATIC\n*DLOAD\n2, P7NP, 12\n"), 30,
       "*DLOAD", "has no face 7"},
      {"network pressure not a node", plus("*STEP\n*STATIC\n*DLOAD\n2, P4NP, 1.5\n"), 30,
       "*DLOAD", "1.5"},
  };
}

}  // namespace test

namespace {

TEST(inpStepSetup, ModelChangeOfElementsHoldsFromItsStepOn) {
  const model::Model m = read_deck_text(
      test::two_cubes_model() +
      "*ELSET, ELSET=SECOND\n2\n*STEP\n*STATIC\n*END STEP\n"
      "*STEP\n*STATIC\n*MODEL CHANGE, TYPE=ELEMENT, REMOVE\nSECOND\n*END STEP\n"
      "*STEP\n*STATIC\n*END STEP\n"
      "*STEP\n*STATIC\n*MODEL CHANGE, TYPE=ELEMENT, ADD\n2,\n*END STEP\n");
  ASSERT_EQ(m.steps.size(), 4u);
  EXPECT_TRUE(m.steps[0].element_active.empty());
  EXPECT_EQ(m.steps[1].element_active, (std::vector<char>{1, 0}));
  EXPECT_EQ(m.steps[2].element_active, (std::vector<char>{1, 0}));  // until added back
  EXPECT_TRUE(m.steps[3].element_active.empty());
}

TEST(inpTimePoints, ReadsListsAndGeneratedSequences) {
  const model::Model m = read_deck_text(test::two_cubes_model() + R"(*TIME POINTS, NAME=T1
.2, .5, .5
.9
*TIME POINTS, NAME=T2, TIME=TOTAL TIME, GENERATE
1., 2., .5
2.5, 2.6, .2
)",
                                        "tp.inp");
  ASSERT_EQ(m.time_points.size(), 2u);
  EXPECT_EQ(m.time_points[0].name, "T1");
  EXPECT_FALSE(m.time_points[0].total_time);
  EXPECT_EQ(m.time_points[0].times, (std::vector<Real>{.2, .5, .9}));  // the repeat dropped
  EXPECT_TRUE(m.time_points[1].total_time);
  // ccx: start, start + k step while within the end, and the end (once)
  EXPECT_EQ(m.time_points[1].times, (std::vector<Real>{1., 1.5, 2., 2.5, 2.6}));
}

TEST(inpTimePoints, AnOutputRequestPutsThemInForceUntilAFrequency) {
  const model::Model m = read_deck_text(test::two_cubes_model() + R"(*BOUNDARY
FIX, 1, 3
*TIME POINTS, NAME=T1
.2, .5
*STEP, NLGEOM
*STATIC
.1, 1.
*CLOAD
TIP, 1, 1.
*NODE PRINT, NSET=TIP
U
*EL FILE, TIME POINTS=T1
S
*END STEP
*STEP
*STATIC
.1, 1.
*END STEP
*STEP
*STATIC
.1, 1.
*NODE PRINT, NSET=TIP, FREQUENCY=3
U
*END STEP
)",
                                        "tp.inp");
  ASSERT_EQ(m.steps.size(), 3u);
  EXPECT_EQ(m.steps[0].time_points, 0);  // named on a file request: prints follow it too
  EXPECT_EQ(m.steps[1].time_points, 0);  // stays in force
  EXPECT_EQ(m.steps[2].time_points, -1);
  EXPECT_EQ(m.steps[2].prints.front().frequency, 3);
}

TEST(inpNetworkPressure, TakesTheNodesPrescribedDof2InEachStep) {
  const model::Model m = read_deck_text(test::two_cubes_model() + R"(*BOUNDARY
FIX, 1, 3
*STEP
*STATIC
*DLOAD
2, P4NP, 12
*BOUNDARY
12, 2, 2, -3.
*END STEP
*STEP
*STATIC
*BOUNDARY
12, 2, 2, 7.
*END STEP
*STEP
*STATIC
*DLOAD
2, P4, 1.
*BOUNDARY
12, 2, 2, 9.
*END STEP
)",
                                        "np.inp");
  ASSERT_EQ(m.steps.size(), 3u);
  ASSERT_EQ(m.steps[0].pressures.size(), 1u);
  EXPECT_EQ(m.steps[0].pressures[0].face.face, 4);
  EXPECT_EQ(m.steps[0].pressures[0].value, -3.);
  EXPECT_EQ(m.steps[1].pressures[0].value, 7.);  // follows the boundary
  EXPECT_EQ(m.steps[2].pressures[0].value, 1.);  // a plain pressure replaced it
}

}  // namespace
}  // namespace kontakt::inp

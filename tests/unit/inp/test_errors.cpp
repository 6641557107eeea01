#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {
namespace {

using test::BadDeck;

/// Appends `tail` to the two-cube model: its first line is line 27.
std::string model_plus(const std::string& tail) { return test::two_cubes_model() + tail; }

std::vector<BadDeck> bad_decks() {
  const std::string step = "*STEP\n*STATIC\n";
  return {
      {"unsupported keyword", model_plus("*COUPLING, REF NODE=1, SURFACE=S\n"), 27,
       "*COUPLING", "keyword not supported"},
      {"hyperelastic arruda-boyce unsupported",
       model_plus("*MATERIAL, NAME=P\n*ELASTIC\n1,0\n*HYPERELASTIC, ARRUDA-BOYCE\n1,1,1\n"), 30,
       "*HYPERELASTIC", "ARRUDA-BOYCE"},
      {"membrane section on elements", model_plus("*MEMBRANE, ELSET=EALL, MATERIAL=M\n0.1\n"),
       27, "*MEMBRANE", "membrane sections are not supported (element set EALL)"},
      {"frequency procedure", model_plus("*STEP\n*FREQUENCY\n10\n*END STEP\n"), 28,
       "*FREQUENCY", "not supported"},
      {"unsupported element", "*NODE\n1,0,0,0\n*ELEMENT, TYPE=S8R, ELSET=E\n1, 1\n", 3,
       "*ELEMENT", "S8R"},
      {"non-numeric coordinate", "*NODE\n1, 0, 0, 0\n2, 1., abc, 0\n", 3, "*NODE",
       "field 3 ('abc') is not a number"},
      {"unknown parameter", "*NODE, NSET=A, SYSTEM=C\n1, 0, 0, 0\n", 1, "*NODE",
       "SYSTEM"},
      {"element node missing", model_plus("*ELEMENT, TYPE=C3D4, ELSET=EALL\n3, 1, 2, 3, 99\n"),
       28, "*ELEMENT", "node 99 of element 3"},
      {"duplicate element", model_plus("*ELEMENT, TYPE=C3D4, ELSET=EALL\n2, 1, 2, 3, 5\n"),
       28, "*ELEMENT", "element 2 defined twice"},
      {"too few element nodes", "*NODE\n1,0,0,0\n*ELEMENT, TYPE=C3D8\n1, 1, 2, 3\n", 4,
       "*ELEMENT", "needs 8 node numbers"},
      {"undefined set in nset", model_plus("*NSET, NSET=X\n1, NOPE\n"), 28, "*NSET",
       "NOPE is not defined"},
      {"set member undefined",  // below the largest label: ccx would print a node at rest
       model_plus("*NODE\n100, 3, 3, 3\n*NSET, NSET=X\n1, 77\n"), 30, "*NSET",
       "node 77 of set X"},
      {"element without section",
       model_plus("*ELEMENT, TYPE=C3D4\n3, 1, 2, 3, 5\n"), 28, "*ELEMENT",
       "element 3 has no *SOLID SECTION"},
      {"section with missing elset",
       model_plus("*SOLID SECTION, ELSET=GHOST, MATERIAL=STEEL\n"), 27, "*SOLID SECTION",
       "GHOST is not defined"},
      {"section with missing material",
       model_plus("*SOLID SECTION, ELSET=EALL, MATERIAL=WOOD\n"), 27, "*SOLID SECTION",
       "WOOD is not defined"},
      {"orientation undefined",
       model_plus("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL, ORIENTATION=O\n"), 27,
       "*SOLID SECTION", "orientation O is not defined"},
      {"elastic without material", "*ELASTIC\n1., .3\n", 1, "*ELASTIC", "*MATERIAL"},
      {"orthotropic elastic on one line",
       model_plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ORTHO\n1\n"), 29, "*ELASTIC",
       "9 constants take 2 data lines"},
      {"rotational dof", model_plus("*BOUNDARY\n1, 4, 6\n"), 28, "*BOUNDARY",
       "degree of freedom 4"},
      {"temperature dof", model_plus(step + "*BOUNDARY\n1, 11, 11, 20.\n*END STEP\n"), 30,
       "*BOUNDARY", "degree of freedom 11"},
      {"undefined nset in boundary", model_plus("*BOUNDARY\nNOWHERE, 1, 3\n"), 28,
       "*BOUNDARY", "node set NOWHERE"},
      {"undefined node in cload", model_plus(step + "*CLOAD\n500, 1, 1.\n*END STEP\n"), 30,
       "*CLOAD", "node 500"},
      {"cload before step", model_plus("*CLOAD\n1, 1, 1.\n"), 27, "*CLOAD",
       "only allowed between *STEP and *END STEP"},
      {"gravity without density",
       model_plus(step + "*DLOAD\nEALL, GRAV, 9.81, 0, 0, -1\n*END STEP\n"), 30, "*DLOAD",
       "material STEEL without *DENSITY"},
      {"gravity with a density table",
       model_plus("*MATERIAL, NAME=HOT\n*ELASTIC\n1., .3\n*DENSITY\n7e-9, 20.\n8e-9, 500.\n"
                  "*SOLID SECTION, ELSET=EALL, MATERIAL=HOT\n" + step +
                  "*DLOAD\nEALL, GRAV, 9.81, 0, 0, -1\n*END STEP\n"),
       37, "*DLOAD", "temperature-dependent *DENSITY"},
      {"gravity without direction", model_plus(step + "*DLOAD\nEALL, GRAV, 9.81\n*END STEP\n"),
       30, "*DLOAD", "expected at least 6 field(s), got 3"},
      {"gravity zero direction",
       model_plus(step + "*DLOAD\nEALL, GRAV, 9.81, 0, 0, 0\n*END STEP\n"), 30, "*DLOAD",
       "gravity direction is the zero vector"},
      {"centrifugal without axis",
       model_plus(step + "*DLOAD\nEALL, CENTRIF, 1e4, 0, 0, 0\n*END STEP\n"), 30, "*DLOAD",
       "expected at least 9 field(s), got 6"},
      {"centrifugal zero axis",
       model_plus(step + "*DLOAD\nEALL, CENTRIF, 1e4, 0, 0, 0, 0, 0, 0\n*END STEP\n"), 30,
       "*DLOAD", "rotation axis is the zero vector"},
      {"centrifugal negative speed",
       model_plus(step + "*DLOAD\nEALL, CENTRIF, -1, 0, 0, 0, 0, 0, 1\n*END STEP\n"), 30,
       "*DLOAD", "cannot be negative"},
      {"generalized gravity", model_plus(step + "*DLOAD\nEALL, NEWTON\n*END STEP\n"), 30,
       "*DLOAD", "load type NEWTON is not supported"},
      {"face out of range", model_plus(step + "*DLOAD\n1, P7, 1.\n*END STEP\n"), 30, "*DLOAD",
       "no face 7"},
      {"undefined amplitude", model_plus(step + "*CLOAD, AMPLITUDE=A1\n1, 1, 1.\n*END STEP\n"),
       29, "*CLOAD", "amplitude A1 is not defined"},
      {"time delay without amplitude",
       model_plus(step + "*CLOAD, TIME DELAY=1.\n1, 1, 1.\n*END STEP\n"), 29, "*CLOAD",
       "AMPLITUDE= is missing"},
      {"time delay not a number",
       model_plus("*AMPLITUDE, NAME=A\n0., 0., 1., 1.\n" + step +
                  "*CLOAD, AMPLITUDE=A, TIME DELAY=soon\n1, 1, 1.\n*END STEP\n"),
       31, "*CLOAD", "TIME DELAY=SOON is not a number"},
      {"odd amplitude data", model_plus("*AMPLITUDE, NAME=A\n0., 0., 1.\n"), 28, "*AMPLITUDE",
       "pairs"},
      {"equation with node set", model_plus("*EQUATION\n2\nTIP, 1, 1., 1, 1, -1.\n"), 29,
       "*EQUATION", "node sets are not allowed"},
      {"step without procedure", model_plus("*STEP\n*CLOAD\n1, 1, 1.\n*END STEP\n"), 27,
       "*STEP", "no procedure"},
      {"missing end step", model_plus(step + "*CLOAD\n1, 1, 1.\n"), 27, "*STEP",
       "missing *END STEP"},
      {"nested step", model_plus(step + "*STEP\n"), 29, "*STEP", "missing *END STEP?"},
      {"perturbation", model_plus("*STEP, PERTURBATION\n"), 27, "*STEP", "PERTURBATION"},
      {"material in step", model_plus(step + "*MATERIAL, NAME=X\n*END STEP\n"), 29,
       "*MATERIAL", "not allowed within a step"},
      {"node after step", model_plus(step + "*END STEP\n*NODE\n99, 0, 0, 0\n"), 30, "*NODE",
       "after the first *STEP"},
      {"data before keyword", "1, 2, 3\n*NODE\n", 1, "", "data line before any keyword"},
      // Issue 10: a lone '*' used to reach a table entry without a handler (SIGSEGV).
      {"lone asterisk", "*HEADING\n*\n*NODE\n1,0,0,0\n", 2, "*", "no keyword after '*'"},
      {"asterisk with parameters", model_plus("* , NSET=A\n1\n"), 27, "*",
       "no keyword after '*'"},
      {"node print unknown set", model_plus(step + "*NODE PRINT, NSET=Q\nU\n*END STEP\n"), 29,
       "*NODE PRINT", "set Q is not defined"},
      {"surface bad face", model_plus("*SURFACE, NAME=S\n1, S9\n"), 28, "*SURFACE", "S9"},
      {"dload before step", model_plus("*DLOAD\n1, P1, 1.\n"), 27, "*DLOAD", "only allowed"},
      {"generate backwards", model_plus("*NSET, NSET=G, GENERATE\n10, 1\n"), 28, "*NSET",
       "GENERATE"},
      {"bad op", model_plus(step + "*BOUNDARY, OP=REPLACE\n1, 1\n*END STEP\n"), 29,
       "*BOUNDARY", "OP=REPLACE"},
  };
}

class inpErrors : public ::testing::TestWithParam<BadDeck> {};

TEST_P(inpErrors, NamesFileLineAndKeyword) {
  const BadDeck& bad = GetParam();
  try {
    read_deck_text(bad.deck, "bad.inp");
    FAIL() << bad.name << ": expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.where().file, "bad.inp") << what;
    EXPECT_EQ(e.where().line, bad.line) << bad.name << ": " << what;
    EXPECT_EQ(e.keyword(), bad.keyword) << bad.name << ": " << what;
    const std::string prefix = "bad.inp:" + std::to_string(bad.line) + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(bad.fragment), std::string::npos) << bad.name << ": " << what;
  }
}

std::string case_name(const ::testing::TestParamInfo<BadDeck>& info) {
  std::string name = info.param.name;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Malformed, inpErrors, ::testing::ValuesIn(bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedContact, inpErrors,
                         ::testing::ValuesIn(test::contact_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedTie, inpErrors, ::testing::ValuesIn(test::tie_bad_decks()),
                         case_name);
INSTANTIATE_TEST_SUITE_P(MalformedTransform, inpErrors,
                         ::testing::ValuesIn(test::transform_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedCoupling, inpErrors,
                         ::testing::ValuesIn(test::coupling_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedConnector, inpErrors,
                         ::testing::ValuesIn(test::connector_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedTruss, inpErrors,
                         ::testing::ValuesIn(test::truss_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedNonlinearConstraint, inpErrors,
                         ::testing::ValuesIn(test::nonlinear_constraint_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedPretension, inpErrors,
                         ::testing::ValuesIn(test::pretension_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedMaterial, inpErrors,
                         ::testing::ValuesIn(test::material_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedPlane, inpErrors,
                         ::testing::ValuesIn(test::plane_bad_decks()), case_name);
INSTANTIATE_TEST_SUITE_P(MalformedStepSetup, inpErrors,
                         ::testing::ValuesIn(test::step_setup_bad_decks()), case_name);

}  // namespace
}  // namespace kontakt::inp

namespace kontakt::inp {
namespace {

TEST(inpErrorsText, APathologicalLineGivesABoundedMessage) {
  // A megabyte keyword or field must not become a megabyte error (422 body, event, log line).
  const std::string keyword = "*" + std::string(100000, 'K');
  const std::string field = "*NODE\n1, " + std::string(100000, 'x') + ", 0, 0\n";
  for (const std::string& deck : {keyword + "\n", field}) {
    try {
      read_deck_text(deck, "bad.inp");
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_LT(std::string(e.what()).size(), 1200u);
      EXPECT_LE(e.keyword().size(), 83u);
      EXPECT_GT(e.where().line, 0);
    }
  }
}

}  // namespace
}  // namespace kontakt::inp

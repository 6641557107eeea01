// Material cards: temperature tables of *ELASTIC, *EXPANSION and *DENSITY as the reader stores
// them, and every malformed form (run by test_errors.cpp through material_bad_decks()).
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

std::vector<BadDeck> material_bad_decks() {
  // The two cubes end at line 26: a *MATERIAL appended is line 27, its next card line 28.
  const auto plus = [](const std::string& tail) { return two_cubes_model() + tail; };
  return {
      {"elastic temperatures descending",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3, 100.\n1., .3, 20.\n"), 30, "*ELASTIC",
       "temperatures must increase from line to line"},
      {"elastic temperature repeated",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3, 100.\n1., .3, 100.\n"), 30, "*ELASTIC",
       "temperatures must increase"},
      {"elastic table without temperatures", plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3\n1., .3\n"),
       30, "*ELASTIC", "temperatures must increase"},
      {"elastic bad modulus in a table row",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3, 20.\n0., .3, 100.\n"), 30, "*ELASTIC",
       "Young's modulus must be positive"},
      {"elastic bad poisson in a table row",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3, 20.\n2., .5, 100.\n"), 30, "*ELASTIC",
       "Poisson's ratio must lie in (-1, 0.5)"},
      {"elastic temperature not a number", plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3, hot\n"), 29,
       "*ELASTIC", "hot"},
      {"elastic too many fields", plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3, 20., 1.\n"), 29,
       "*ELASTIC", "expected at most 3 field(s)"},
      {"expansion temperatures descending",
       plus("*MATERIAL, NAME=T\n*EXPANSION\n1.E-5, 100.\n2.E-5, 0.\n"), 30, "*EXPANSION",
       "temperatures must increase"},
      {"expansion without data", plus("*MATERIAL, NAME=T\n*EXPANSION\n"), 28, "*EXPANSION",
       "data line missing"},
      {"expansion bad zero", plus("*MATERIAL, NAME=T\n*EXPANSION, ZERO=warm\n1.E-5\n"), 28,
       "*EXPANSION", "ZERO=warm is not a number"},
      {"density table row not positive",
       plus("*MATERIAL, NAME=T\n*DENSITY\n7.8E-9, 0.\n0., 100.\n"), 30, "*DENSITY",
       "density must be positive"},
      {"plastic curves temperatures descending",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3\n*PLASTIC\n1., 0., 100.\n1., 0., 20.\n"), 32,
       "*PLASTIC", "temperatures must increase from curve to curve"},
      {"plastic curves interleaved",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3\n*PLASTIC\n1., 0., 20.\n1., 0., 100.\n"
            "2., .1, 20.\n"),
       33, "*PLASTIC", "temperatures must increase from curve to curve"},
      {"plastic second curve not at zero strain",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3\n*PLASTIC\n1., 0., 20.\n2., .1, 20.\n"
            "1., .05, 100.\n"),
       33, "*PLASTIC", "the first row of a curve must be at zero plastic strain"},
      {"plastic strains not increasing in the second curve",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n2., .3\n*PLASTIC\n1., 0., 20.\n1., 0., 100.\n"
            "2., 0., 100.\n"),
       33, "*PLASTIC", "plastic strains must increase from row to row"},
  };
}

}  // namespace test

namespace {

const model::Material& material(const model::Model& m, const std::string& name) {
  for (const auto& mat : m.materials)
    if (mat.name == name) return mat;
  throw std::runtime_error("no material " + name);
}

TEST(inpMaterial, TemperatureTablesAreStoredRowByRow) {
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*MATERIAL, NAME=HOT\n"
                                        "*ELASTIC\n"
                                        "210000., .3, 20.\n"
                                        "150000., .25, 600.\n"
                                        "*EXPANSION, ZERO=20.\n"
                                        "1.2E-5, 20.\n"
                                        "1.6E-5, 600.\n"
                                        "*DENSITY\n"
                                        "7.8E-9\n");
  const model::Material& hot = material(m, "HOT");
  ASSERT_EQ(hot.elastic.rows.size(), 2u);
  EXPECT_EQ(hot.elastic.temperatures, (std::vector<Real>{20., 600.}));
  EXPECT_EQ(hot.elastic.rows[1][0], 150000.);
  EXPECT_EQ(hot.elastic.rows[1][1], .25);
  ASSERT_EQ(hot.expansion.rows.size(), 2u);
  EXPECT_EQ(hot.expansion.rows[1][0], 1.6e-5);
  EXPECT_EQ(hot.expansion_zero, 20.);
  ASSERT_EQ(hot.density.rows.size(), 1u);  // no temperature column: 0
  EXPECT_EQ(hot.density.temperatures.front(), 0.);
  // The fixture's constant material: one row.
  EXPECT_EQ(material(m, "STEEL").elastic.rows.size(), 1u);
  EXPECT_EQ(material(m, "STEEL").elastic.rows[0][0], 210000.);
}

TEST(inpMaterial, PlasticCurvesByTemperature) {
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*MATERIAL, NAME=HOT\n"
                                        "*ELASTIC\n"
                                        "210000., .3\n"
                                        "*PLASTIC\n"
                                        "800., 0., 273.\n"
                                        "900., .05, 273.\n"
                                        "700., 0., 873.\n"
                                        "750., .04, 873.\n"
                                        "800., .13, 873.\n");
  const material::HardeningCurves& p = material(m, "HOT").plastic;
  EXPECT_EQ(p.temperatures, (std::vector<Real>{273., 873.}));
  ASSERT_EQ(p.curves.size(), 2u);
  EXPECT_EQ(p.curves[0].points.size(), 2u);
  ASSERT_EQ(p.curves[1].points.size(), 3u);
  EXPECT_EQ(p.curves[1].points[2], std::make_pair(800., .13));
}

TEST(inpMaterial, SofteningIsCheckedAgainstTheSmallestShearModulusOfTheTable) {
  // G = 1000/2.6 = 384.6 at 20 degrees, 100/2.6 = 38.46 at 500: a slope of -200 is fine for
  // the first row and steeper than -3G = -115.4 for the second.
  const std::string deck = test::two_cubes_model() +
                           "*MATERIAL, NAME=SOFT\n"
                           "*ELASTIC\n"
                           "1000., .3, 20.\n"
                           "100., .3, 500.\n"
                           "*PLASTIC\n"
                           "10., 0.\n"
                           "8., .01\n";
  try {
    read_deck_text(deck, "bad.inp");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 33) << e.what();
    EXPECT_NE(std::string(e.what()).find("softens faster than -3G"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace kontakt::inp

// Material cards: temperature tables of *ELASTIC, *EXPANSION and *DENSITY as the reader stores
// them, and every malformed form (run by test_errors.cpp through material_bad_decks()).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <variant>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

std::vector<BadDeck> material_bad_decks() {
  // The two cubes end at line 26: a *MATERIAL appended is line 27, its next card line 28.
  const auto plus = [](const std::string& tail) { return two_cubes_model() + tail; };
  // The cubes of material P (lines 27-29), its *PLASTIC at line 30, the curve at 31.
  const auto plastic = [](const std::string& hardening, const std::string& tail) {
    std::string deck = two_cubes_model();
    deck.replace(deck.rfind("MATERIAL=STEEL"), 14, "MATERIAL=P");
    return deck + "*MATERIAL, NAME=P\n*ELASTIC\n210000., .3\n*PLASTIC" + hardening +
           "\n800., 0.\n1000., 0.1\n" + tail;
  };
  const std::string nlgeom_step = "*STEP, NLGEOM\n*STATIC\n*END STEP\n";
  return {
      {"plastic hardening unknown", plastic(", HARDENING=FOO", nlgeom_step), 30, "*PLASTIC",
       "HARDENING=FOO is not supported (ISOTROPIC, KINEMATIC and COMBINED are)"},
      {"combined without cyclic curve", plastic(", HARDENING=COMBINED", nlgeom_step), 27,
       "*PLASTIC", "HARDENING=COMBINED needs a *CYCLIC HARDENING curve"},
      {"cyclic curve with isotropic hardening",
       plastic("", "*CYCLIC HARDENING\n800., 0.\n" + nlgeom_step), 27, "*CYCLIC HARDENING",
       "*CYCLIC HARDENING needs *PLASTIC, HARDENING=COMBINED"},
      {"kinematic curves by temperature",
       plastic(", HARDENING=KINEMATIC", "800., 0., 100.\n" + nlgeom_step), 27, "*PLASTIC",
       "HARDENING=KINEMATIC with curves by temperature is not supported"},
      {"kinematic without nlgeom", plastic(", HARDENING=KINEMATIC", "*STEP\n*STATIC\n*END STEP\n"),
       33, "*STEP", "hardens KINEMATIC (*PLASTIC): every step needs NLGEOM"},
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
      {"elastic unknown type", plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=FOO\n1., .3\n"), 28,
       "*ELASTIC", "TYPE=FOO: expected ISO, ORTHO, ENGINEERING CONSTANTS or ANISO"},
      {"orthotropic nine on the first line",
       plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ORTHO\n1, 0, 1, 0, 0, 1, 1, 1, 1\n294.\n"), 29,
       "*ELASTIC", "field(s)"},
      {"anisotropic not positive definite",
       plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ANISO\n1, 5, 1, 0, 0, 1, 0, 0\n"
            "0, 1, 0, 0, 0, 0, 1, 0\n0, 0, 0, 0, 1\n"),
       31, "*ELASTIC", "the elasticity matrix is not positive definite"},
      {"anisotropic 20 constants",
       plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ANISO\n1, 0, 1, 0, 0, 1, 0, 0\n"
            "0, 1, 0, 0, 0, 0, 1, 0\n0, 0, 0, 1\n"),
       31, "*ELASTIC", "expected at least 5 field(s)"},
      {"engineering constants modulus not positive",
       plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
            "0, 1, 1, .3, .3, .3, 1, 1\n1\n"),
       30, "*ELASTIC", "must be positive"},
      {"engineering constants not positive definite",
       plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
            "1, 1, 1, 2, .3, .3, 1, 1\n1\n"),
       30, "*ELASTIC", "not positive definite"},
      {"orthotropic temperatures descending",
       plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ORTHO\n1, 0, 1, 0, 0, 1, 1, 1\n1, 100.\n"
            "1, 0, 1, 0, 0, 1, 1, 1\n1, 20.\n"),
       32, "*ELASTIC", "temperatures must increase from set to set"},
      {"plastic with an orthotropic elastic",
       plus("*MATERIAL, NAME=T\n*ELASTIC, TYPE=ORTHO\n1, 0, 1, 0, 0, 1, 1, 1\n1\n*PLASTIC\n"
            "1., 0.\n*SOLID SECTION, ELSET=EALL, MATERIAL=T\n"),
       27, "*MATERIAL", "*PLASTIC needs an isotropic *ELASTIC"},
      {"C3D8R with an orthotropic material",
       plus("*ELEMENT, TYPE=C3D8R, ELSET=R\n3, 2, 9, 10, 3, 6, 11, 12, 7\n*MATERIAL, NAME=T\n"
            "*ELASTIC, TYPE=ORTHO\n1, 0, 1, 0, 0, 1, 1, 1\n1\n*SOLID SECTION, ELSET=R, "
            "MATERIAL=T\n"),
       33, "*SOLID SECTION", "hourglass control needs an isotropic *ELASTIC"},
      {"orientation unknown system", plus("*ORIENTATION, NAME=O, SYSTEM=SPHERICAL\n0,0,0,1,0,0\n"),
       27, "*ORIENTATION", "SYSTEM=SPHERICAL: expected RECTANGULAR or CYLINDRICAL"},
      {"orientation a at the origin", plus("*ORIENTATION, NAME=O\n0,0,0,1,0,0\n"), 28,
       "*ORIENTATION", "point a (on the local x' axis) is the origin"},
      {"orientation cylinder axis degenerate",
       plus("*ORIENTATION, NAME=O, SYSTEM=CYLINDRICAL\n1,2,3,1,2,3\n"), 28, "*ORIENTATION",
       "points a and b of the axis coincide"},
      {"orientation twice",
       plus("*ORIENTATION, NAME=O\n1,0,0,0,1,0\n*ORIENTATION, NAME=O\n1,0,0,0,1,0\n"), 29,
       "*ORIENTATION", "orientation O defined twice"},
      {"hyperelastic unknown model", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, ARRUDA-BOYCE\n1, 1, 1\n"),
       28, "*HYPERELASTIC", "ARRUDA-BOYCE"},
      {"hyperelastic D1 negative", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, NEO HOOKE\n1., -.1\n"),
       29, "*HYPERELASTIC", "D1 (field 2) must not be negative"},
      {"hyperelastic constants missing",
       plus("*MATERIAL, NAME=T\n*HYPERELASTIC, MOONEY-RIVLIN\n1., .03\n"), 29, "*HYPERELASTIC",
       "3 constants expected"},
      {"hyperelastic order 4", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, POLYNOMIAL, N=4\n1, 1\n"),
       28, "*HYPERELASTIC", "N=4: expected 1, 2 or 3"},
      {"hyperelastic unstable", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, MOONEY-RIVLIN\n1., -2., .1\n"),
       29, "*HYPERELASTIC", "C10 + C01"},
      {"ogden constants missing", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN, N=2\n1., 2., .5, 3., .1\n"),
       29, "*HYPERELASTIC", "6 constants expected (8 a line)"},
      {"ogden third order on one line",
       plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN, N=3\n1., 2., .5, -2., .1, 4., .1, 0., .2\n"), 29,
       "*HYPERELASTIC", "9 constants expected (8 a line)"},
      {"ogden order 4", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN, N=4\n1., 2., .1\n"), 28,
       "*HYPERELASTIC", "N=4: expected 1, 2 or 3"},
      {"ogden alpha zero", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN\n1., 0., .1\n"), 29,
       "*HYPERELASTIC", "alpha1 (field 2) must not be zero"},
      {"ogden second alpha zero",
       plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN, N=2\n1., 2., .5, 0., .1, 0.\n"), 29,
       "*HYPERELASTIC", "alpha2 (field 4) must not be zero"},
      {"ogden unstable",
       plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN, N=2\n1., 2., -3., -2., .1, 0.\n"), 29,
       "*HYPERELASTIC", "the sum of the mu_i (the shear modulus at rest) must be positive"},
      {"ogden D3 negative",
       plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN, N=3\n1., 2., .5, -2., .1, 4., .1, 0.\n-.2\n"),
       30, "*HYPERELASTIC", "D3 (field 1) must not be negative"},
      {"ogden and neo hooke", plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN, NEO HOOKE\n1., 2., .1\n"),
       28, "*HYPERELASTIC", "more than one model given"},
      {"hyperfoam nu one half",
       plus("*MATERIAL, NAME=T\n*HYPERFOAM, N=2\n.16, 8.9, 2e-5, -4.8, 0., .5\n"), 29, "*HYPERFOAM",
       "nu2 (field 6) must lie between -1 and 0.5"},
      {"hyperfoam nu minus one", plus("*MATERIAL, NAME=T\n*HYPERFOAM\n.5, 3., -1.\n"), 29,
       "*HYPERFOAM", "nu1 (field 3) must lie between -1 and 0.5"},
      {"hyperfoam third nu on the second line",
       plus("*MATERIAL, NAME=T\n*HYPERFOAM, N=3\n.5, 3., .2, -2., .1, 2., 0., .1\n.7\n"), 30,
       "*HYPERFOAM", "nu3 (field 1) must lie between -1 and 0.5"},
      {"hyperfoam order 0", plus("*MATERIAL, NAME=T\n*HYPERFOAM, N=0\n.5, 3., .2\n"), 28,
       "*HYPERFOAM", "N=0: expected 1, 2 or 3"},
      {"hyperfoam constants missing", plus("*MATERIAL, NAME=T\n*HYPERFOAM\n.5, 3.\n"), 29,
       "*HYPERFOAM", "3 constants expected (8 a line)"},
      {"hyperfoam two temperatures", plus("*MATERIAL, NAME=T\n*HYPERFOAM\n.5, 3., .2, 20.\n.4, 3., .2, 80.\n"),
       30, "*HYPERFOAM", "one temperature only"},
      {"hyperfoam alpha zero", plus("*MATERIAL, NAME=T\n*HYPERFOAM\n.5, 0., .2\n"), 29,
       "*HYPERFOAM", "alpha1 (field 2) must not be zero"},
      {"hyperfoam model parameter", plus("*MATERIAL, NAME=T\n*HYPERFOAM, OGDEN\n.5, 3., .2\n"), 28,
       "*HYPERFOAM", "OGDEN"},
      {"hyperfoam after hyperelastic",
       plus("*MATERIAL, NAME=T\n*HYPERELASTIC, OGDEN\n1., 2., .1\n*HYPERFOAM\n.5, 3., .2\n"), 30,
       "*HYPERFOAM", "material T has a *HYPERELASTIC or *HYPERFOAM potential already"},
      {"hyperfoam without NLGEOM",
       plus("*MATERIAL, NAME=T\n*HYPERFOAM\n.5, 3., .2\n*SOLID SECTION, ELSET=EALL, "
            "MATERIAL=T\n*STEP\n*STATIC\n*END STEP\n"),
       31, "*STEP", "material T is hyperelastic: every step needs NLGEOM"},
      {"hyperelastic without NLGEOM",
       plus("*MATERIAL, NAME=T\n*HYPERELASTIC\n1., 0., .1\n*SOLID SECTION, ELSET=EALL, "
            "MATERIAL=T\n*STEP\n*STATIC\n*END STEP\n"),
       31, "*STEP", "every step needs NLGEOM"},
      {"hyperelastic with elastic",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n1., .3\n*HYPERELASTIC, NEO HOOKE\n1., .1\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=T\n"),
       27, "*MATERIAL", "*HYPERELASTIC / *HYPERFOAM stands alone"},
      {"deformation plasticity four constants",
       plus("*MATERIAL, NAME=T\n*DEFORMATION PLASTICITY\n190000., .34, 900., 12.\n"), 29,
       "*DEFORMATION PLASTICITY", "expected at least 5 field(s)"},
      {"deformation plasticity two temperatures",
       plus("*MATERIAL, NAME=T\n*DEFORMATION PLASTICITY\n190000., .34, 900., 12., .45, 20.\n"
            "180000., .34, 800., 12., .45, 400.\n"),
       30, "*DEFORMATION PLASTICITY", "one temperature only"},
      {"deformation plasticity incompressible",
       plus("*MATERIAL, NAME=T\n*DEFORMATION PLASTICITY\n190000., .5, 900., 12., .45\n"), 29,
       "*DEFORMATION PLASTICITY", "Poisson's ratio (field 2) must lie between -1 and 0.5"},
      {"deformation plasticity exponent below one",
       plus("*MATERIAL, NAME=T\n*DEFORMATION PLASTICITY\n190000., .3, 900., .5, .45\n"), 29,
       "*DEFORMATION PLASTICITY", "the exponent n (field 4) must be at least 1"},
      {"deformation plasticity without NLGEOM",
       plus("*MATERIAL, NAME=T\n*DEFORMATION PLASTICITY\n190000., .3, 900., 12., .45\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=T\n*STEP\n*STATIC\n*END STEP\n"),
       31, "*STEP", "has *DEFORMATION PLASTICITY: every step needs NLGEOM"},
      {"deformation plasticity with elastic",
       plus("*MATERIAL, NAME=T\n*ELASTIC\n1., .3\n*DEFORMATION PLASTICITY\n"
            "190000., .3, 900., 12., .45\n*SOLID SECTION, ELSET=EALL, MATERIAL=T\n"),
       27, "*MATERIAL", "*DEFORMATION PLASTICITY stands alone"},
      {"deformation plasticity energy",
       plus("*MATERIAL, NAME=T\n*DEFORMATION PLASTICITY\n190000., .3, 900., 12., .45\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=T\n*STEP, NLGEOM\n*STATIC\n"
            "*EL PRINT, ELSET=EALL\nS, ENER\n*END STEP\n"),
       33, "*EL PRINT", "ENER of material T (*DEFORMATION PLASTICITY) is not available"},
      // *CHANGE SOLID SECTION: the cubes' material STEEL (lines 22-25), SOFT appended (27-29),
      // the step from line 30.
      {"change solid section orientation",
       plus("*MATERIAL, NAME=SOFT\n*ELASTIC\n7e4, .3\n*STEP\n*STATIC\n*CHANGE SOLID SECTION, "
            "ELSET=EALL, MATERIAL=SOFT, ORIENTATION=O\n*END STEP\n"),
       32, "*CHANGE SOLID SECTION", "ORIENTATION= is not supported"},
      {"change solid section thickness",
       plus("*MATERIAL, NAME=SOFT\n*ELASTIC\n7e4, .3\n*STEP\n*STATIC\n*CHANGE SOLID SECTION, "
            "ELSET=EALL, MATERIAL=SOFT\n2.\n*END STEP\n"),
       33, "*CHANGE SOLID SECTION", "ccx does not allow the thickness to change"},
      {"change solid section unknown material",
       plus("*STEP\n*STATIC\n*CHANGE SOLID SECTION, ELSET=EALL, MATERIAL=NOPE\n*END STEP\n"),
       29, "*CHANGE SOLID SECTION", "material NOPE is not defined"},
      {"change solid section unknown set",
       plus("*MATERIAL, NAME=SOFT\n*ELASTIC\n7e4, .3\n*STEP\n*STATIC\n*CHANGE SOLID SECTION, "
            "ELSET=NOPE, MATERIAL=SOFT\n*END STEP\n"),
       32, "*CHANGE SOLID SECTION", "element set NOPE is not defined"},
      {"change solid section to a hyperelastic material",
       plus("*MATERIAL, NAME=RUBBER\n*HYPERELASTIC, NEO HOOKE\n1., .1\n*STEP\n*STATIC\n"
            "*CHANGE SOLID SECTION, ELSET=EALL, MATERIAL=RUBBER\n*END STEP\n"),
       32, "*CHANGE SOLID SECTION", "material RUBBER needs an isotropic *ELASTIC"},
      {"change solid section under NLGEOM",
       plus("*MATERIAL, NAME=SOFT\n*ELASTIC\n7e4, .3\n*STEP, NLGEOM\n*STATIC\n"
            "*CHANGE SOLID SECTION, ELSET=EALL, MATERIAL=SOFT\n*END STEP\n"),
       32, "*CHANGE SOLID SECTION", "not supported with NLGEOM steps"},
      {"change solid section with plasticity",
       plus("*MATERIAL, NAME=SOFT\n*ELASTIC\n7e4, .3\n*PLASTIC\n100., 0.\n*STEP\n*STATIC\n"
            "*CHANGE SOLID SECTION, ELSET=EALL, MATERIAL=SOFT\n*END STEP\n"),
       34, "*CHANGE SOLID SECTION", "not supported in a deck with *PLASTIC"},
      {"change solid section in the model",
       plus("*CHANGE SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"), 27, "*CHANGE SOLID SECTION",
       "only allowed between *STEP and *END STEP"},
      {"orientation second line", plus("*ORIENTATION, NAME=O\n1,0,0,0,1,0\n3, 10.\n"), 29,
       "*ORIENTATION", "data line"},
  };
}

}  // namespace test

namespace {

const model::Material& material(const model::Model& m, const std::string& name) {
  for (const auto& mat : m.materials)
    if (mat.name == name) return mat;
  throw std::runtime_error("no material " + name);
}

TEST(inpMaterial, OgdenConstantsInCcxOrderAndTheDefaultCompressibility) {
  // N=3 over two lines; D1 = 0 takes ccx's default 0.1 / sum mu_i; a negative alpha is valid.
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*MATERIAL, NAME=RUBBER\n"
                                        "*HYPERELASTIC, OGDEN, N=3\n"
                                        "1.5, 2.5, .5, -2., .2, 4., 0., .3\n"
                                        ".7, 20.\n");
  ASSERT_TRUE(material(m, "RUBBER").hyperelastic.has_value());
  const auto* ogden = std::get_if<material::Ogden>(&*material(m, "RUBBER").hyperelastic);
  ASSERT_NE(ogden, nullptr);
  EXPECT_EQ(ogden->n_terms, 3);
  EXPECT_EQ(ogden->mu, (std::array<Real, 3>{1.5, .5, .2}));
  EXPECT_EQ(ogden->alpha, (std::array<Real, 3>{2.5, -2., 4.}));
  EXPECT_DOUBLE_EQ(ogden->d[0], 0.1 / 2.2);
  EXPECT_EQ(ogden->d[1], .3);
  EXPECT_EQ(ogden->d[2], .7);
}

TEST(inpMaterial, EveryZeroCompressibilityTakesCcxsDefault) {
  // D_k = 0: (0.1 / mu)^k, mu the shear modulus at rest (2 (C10 + C01) for the polynomials).
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*MATERIAL, NAME=POLY\n"
                                        "*HYPERELASTIC, POLYNOMIAL, N=2\n"
                                        ".75, .25, .1, 0., 0., 0., 0.\n"
                                        "*MATERIAL, NAME=OGDEN\n"
                                        "*HYPERELASTIC, OGDEN, N=3\n"
                                        "1.5, 2.5, .5, -2., .2, 4., .3, 0.\n"
                                        "0.\n");
  const auto* poly = std::get_if<material::HyperelasticPolynomial>(&*material(m, "POLY").hyperelastic);
  ASSERT_NE(poly, nullptr);
  EXPECT_DOUBLE_EQ(poly->d[0], 0.05);
  EXPECT_DOUBLE_EQ(poly->d[1], 0.05 * 0.05);
  EXPECT_EQ(poly->d[2], 0.);  // N=2: no third term
  const auto* ogden = std::get_if<material::Ogden>(&*material(m, "OGDEN").hyperelastic);
  ASSERT_NE(ogden, nullptr);
  EXPECT_EQ(ogden->d[0], .3);
  EXPECT_DOUBLE_EQ(ogden->d[1], std::pow(0.1 / 2.2, 2));
  EXPECT_DOUBLE_EQ(ogden->d[2], std::pow(0.1 / 2.2, 3));
}

TEST(inpMaterial, HyperfoamPoissonRatiosBecomeBetas) {
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*MATERIAL, NAME=FOAM\n"
                                        "*HYPERFOAM, N=2\n"
                                        "0.164861, 8.88413, 2.302e-5, -4.81798, 0., .25\n");
  const auto* foam = std::get_if<material::Hyperfoam>(&*material(m, "FOAM").hyperelastic);
  ASSERT_NE(foam, nullptr);
  EXPECT_EQ(foam->n_terms, 2);
  EXPECT_EQ(foam->mu[1], 2.302e-5);
  EXPECT_EQ(foam->alpha[1], -4.81798);
  EXPECT_EQ(foam->beta[0], 0.);
  EXPECT_EQ(foam->beta[1], .5);  // .25 / (1 - .5)
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

TEST(inpMaterial, OrthotropicAndAnisotropicConstantsAreStoredInAnisoOrder) {
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*MATERIAL, NAME=ORTHO\n"
                                        "*ELASTIC, TYPE=ORTHOTROPIC\n"
                                        "500000.,157200.,400000.,157200.,157200.,300000.,"
                                        "126200.,126200.,\n"
                                        "126200.,294.\n"
                                        "*MATERIAL, NAME=ENG\n"
                                        "*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
                                        "100., 100., 100., 0., 0., 0., 20., 30.\n"
                                        "40.\n"
                                        "*MATERIAL, NAME=ANISO\n"
                                        "*ELASTIC, TYPE=ANISO\n"
                                        "9, 1, 9, 1, 1, 9, .1, .2\n"
                                        ".3, 4, .4, .5, .6, .7, 4, .8\n"
                                        ".9, 1.1, 1.2, 1.3, 4, 50.\n");
  const model::Material& ortho = material(m, "ORTHO");
  EXPECT_TRUE(ortho.elastic.empty());
  ASSERT_EQ(ortho.anisotropic.rows.size(), 1u);
  EXPECT_EQ(ortho.anisotropic.temperatures.front(), 294.);
  const auto& o = ortho.anisotropic.rows.front();
  EXPECT_EQ(o[0], 500000.);   // D1111
  EXPECT_EQ(o[2], 400000.);   // D2222
  EXPECT_EQ(o[5], 300000.);   // D3333
  EXPECT_EQ(o[9], 126200.);   // D1212
  EXPECT_EQ(o[6], 0.);        // D1112
  // Zero Poisson's ratios: the moduli themselves on the diagonal.
  const auto& e = material(m, "ENG").anisotropic.rows.front();
  EXPECT_DOUBLE_EQ(e[0], 100.);
  EXPECT_DOUBLE_EQ(e[1], 0.);
  EXPECT_EQ(e[9], 20.);
  EXPECT_EQ(e[14], 30.);
  EXPECT_EQ(e[20], 40.);
  const auto& a = material(m, "ANISO").anisotropic.rows.front();
  EXPECT_EQ(a[6], .1);
  EXPECT_EQ(a[20], 4.);
  EXPECT_EQ(material(m, "ANISO").anisotropic.temperatures.front(), 50.);
}

TEST(inpMaterial, OrientationReachesTheSection) {
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*ORIENTATION, NAME=Cyl, SYSTEM=CYLINDRICAL\n"
                                        "0., 0., 0., 0., 0., 1.\n"
                                        "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL, "
                                        "ORIENTATION=CYL\n");
  ASSERT_EQ(m.sections.size(), 2u);
  EXPECT_FALSE(m.sections.front().orientation);
  ASSERT_TRUE(m.sections.back().orientation);
  EXPECT_EQ(m.sections.back().orientation->name, "CYL");
  EXPECT_EQ(m.sections.back().orientation->frame.kind, model::Transform::Kind::Cylindrical);
  EXPECT_EQ(m.sections.back().orientation->frame.b, Vec3(0, 0, 1));
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

// Reading plane stress, plane strain and axisymmetric elements: the 2D types are read as the
// 3D types ccx expands them into, *SOLID SECTION gives thickness and OFFSET, and malformed
// uses fail at their line (run by test_errors.cpp through plane_bad_decks()).
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace {

/// Two CPE4 on [0, 2] x [0, 1] (the second card's type replaceable): the elements are lines
/// 9 and 11, *SOLID SECTION line 15, its data line 16.
std::string strip(const std::string& type2 = "CPE4", const std::string& section = "0.5") {
  return "*NODE, NSET=NALL\n1\n2, 1, 0\n3, 2, 0\n4, 0, 1\n5, 1, 1\n6, 2, 1\n"
         "*ELEMENT, TYPE=CPE4, ELSET=EALL\n1, 1, 2, 5, 4\n"
         "*ELEMENT, TYPE=" + type2 + ", ELSET=EALL\n2, 2, 3, 6, 5\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n"
         "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n" + section + "\n";
}

/// `text` with its first `from` replaced by `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

}  // namespace

namespace test {

std::vector<BadDeck> plane_bad_decks() {
  const std::string step = "*STEP\n*STATIC\n";
  return {
      {"edge beyond a quad", strip() + step + "*DLOAD\n2, P5, 1.\n*END STEP\n", 20, "*DLOAD",
       "element 2 (CPE4) has no face 5"},
      {"surface edge beyond a triangle",
       "*NODE\n1, 0, 0\n2, 1, 0\n3, 0, 1\n*ELEMENT, TYPE=CPS3, ELSET=E\n1, 1, 2, 3\n"
       "*SURFACE, NAME=S\n1, S4\n",
       8, "*SURFACE", "element 1 (CPS3) has no face S4"},
      {"offset not a number", edited(strip(), "MATERIAL=M\n", "MATERIAL=M, OFFSET=abc\n"), 15,
       "*SOLID SECTION", "OFFSET=abc is not a number"},
      {"node off the plane", edited(strip(), "6, 2, 1", "6, 2, 1, 0.1"), 11, "*ELEMENT",
       "node 6 of plane strain element 2 is not in the z = 0 plane"},
      {"two-dimensional and solid share a node", strip("C3D4"), 9, "*ELEMENT",
       "also belongs to a solid element"},
      {"clockwise axisymmetric",
       edited(edited(strip("CAX4"), "TYPE=CPE4", "TYPE=CAX4"), "2, 2, 3, 6, 5", "2, 2, 5, 6, 3"),
       11, "*ELEMENT", "clockwise"},
      {"step amplitude step", strip() + "*STEP, AMPLITUDE=STEP\n*STATIC\n*END STEP\n", 17,
       "*STEP", "AMPLITUDE=STEP is not supported (only RAMP)"},
  };
}

}  // namespace test

TEST(inpPlaneElements, TwoDimensionalTypesAreReadAsTheirExpansion) {
  // Element 2's midside nodes: the corner nodes' labels will do for reading.
  const model::Model m = read_deck_text(
      edited(strip("CPE8R"), "2, 2, 3, 6, 5", "2, 2, 3, 6, 5, 1, 4, 5, 2"), "strip.inp");
  // CPE4 -> C3D8 and CPE8R -> C3D20R, in one layer 0.5 thick: the label-only node 1 sits at
  // the origin.
  EXPECT_EQ(m.mesh.elements[0].type, element::ElementType::C3D8);
  EXPECT_EQ(m.mesh.elements[0].planar, model::Planar::PlaneStrain);
  EXPECT_EQ(m.mesh.elements[1].type, element::ElementType::C3D20R);
  EXPECT_EQ(m.mesh.elements[1].nodes.size(), 20u);
  EXPECT_EQ(m.mesh.coords.row(0), Vec3::Zero().transpose());
  EXPECT_EQ(m.sections[0].thickness, 0.5);
  EXPECT_EQ(m.sections[0].offset, 0.0);
  EXPECT_EQ(m.planar_folds.size(), 6u);
  EXPECT_NEAR(m.mesh.coords.col(2).maxCoeff(), 0.25, 1e-15);
}

TEST(inpPlaneElements, SectionWithoutThicknessIsOneAndOffsetIsRead) {
  const model::Model m = read_deck_text(
      edited(edited(strip("CPS4", ""), "MATERIAL=M\n", "MATERIAL=M, OFFSET=-0.5\n"),
             "TYPE=CPE4", "TYPE=CPS4"),
      "strip.inp");
  EXPECT_EQ(m.sections[0].thickness, 1.0);
  EXPECT_EQ(m.sections[0].offset, -0.5);
  EXPECT_NEAR(m.mesh.coords.col(2).minCoeff(), 0.0, 1e-15);  // front face on z = 0
  EXPECT_NEAR(m.mesh.coords.col(2).maxCoeff(), 1.0, 1e-15);
}

TEST(inpPlaneElements, StepAmplitudeRampIsTheDefault) {
  EXPECT_NO_THROW(read_deck_text(strip() + "*STEP, AMPLITUDE=RAMP\n*STATIC\n*END STEP\n"));
}

}  // namespace kontakt::inp

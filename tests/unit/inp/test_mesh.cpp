#include <gtest/gtest.h>

#include "inp/read_deck.hpp"
#include "deck_fixtures.hpp"

namespace kontakt::inp {
namespace {

using model::Model;

std::vector<int> labels_of_nodes(const Model& m, const std::vector<int>& nodes) {
  std::vector<int> out;
  for (int n : nodes) out.push_back(m.mesh.node_ids[static_cast<std::size_t>(n)]);
  return out;
}
std::vector<int> labels_of_elements(const Model& m, const std::vector<int>& elements) {
  std::vector<int> out;
  for (int e : elements) out.push_back(m.mesh.elements[static_cast<std::size_t>(e)].id);
  return out;
}

TEST(inpMesh, NodesElementsMaterialSection) {
  const Model m = read_deck_text(test::two_cubes_static(), "cubes.inp");
  EXPECT_EQ(m.heading, "Two cubes");
  ASSERT_EQ(m.n_nodes(), 12);
  EXPECT_DOUBLE_EQ(m.mesh.coords(8, 0), 2.0);
  EXPECT_EQ(m.mesh.node_index.at(9), 8);
  ASSERT_EQ(m.n_elements(), 2);
  const model::Element& e2 = m.mesh.elements[1];
  EXPECT_EQ(e2.id, 2);
  EXPECT_EQ(e2.type, element::ElementType::C3D8);
  EXPECT_EQ(labels_of_nodes(m, e2.nodes), (std::vector<int>{2, 9, 10, 3, 6, 11, 12, 7}));
  EXPECT_EQ(e2.section, 0);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].name, "STEEL");
  ASSERT_EQ(m.materials[0].elastic.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(m.materials[0].elastic.rows[0][0], 210000.0);
  EXPECT_DOUBLE_EQ(m.materials[0].elastic.rows[0][1], 0.3);
  EXPECT_TRUE(m.materials[0].density.empty());
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_EQ(m.sections[0].elset, "EALL");
  EXPECT_EQ(m.sections[0].material, 0);
  EXPECT_EQ(m.node_sets.at("NALL").nodes.size(), 12u);
  EXPECT_EQ(m.element_sets.at("EALL").elements.size(), 2u);
  // *STATIC without a data line warns only in nonlinear steps (the driver says so then).
  EXPECT_TRUE(m.warnings.empty());
}

TEST(inpMesh, DensityAndExpansion) {
  std::string deck = test::two_cubes_model();
  deck += "*MATERIAL, NAME=Alu\n*ELASTIC, TYPE=ISO\n70000, .33, 20.\n*DENSITY\n2.7e-9\n"
          "*EXPANSION, ZERO=20.\n2.3d-5\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.materials.size(), 2u);
  const model::Material& alu = m.materials[1];
  EXPECT_EQ(alu.name, "ALU");
  EXPECT_DOUBLE_EQ(alu.density.at(20)[0], 2.7e-9);
  EXPECT_DOUBLE_EQ(alu.expansion.at(20)[0], 2.3e-5);
  EXPECT_DOUBLE_EQ(alu.expansion_zero, 20.0);
}

TEST(inpMesh, SetsAreSortedDeduplicatedAndUpperCase) {
  std::string deck = test::two_cubes_model();
  deck += "*NSET, NSET=mixed\n12, 3, Fix, 3\n*NSET, NSET=Mixed\n2\n"
          "*NSET, NSET=GEN, GENERATE\n2, 10, 4\n"
          "*NSET, NSET=NESTED\nMIXED, gen, 1\n"
          "*ELSET, ELSET=BACKWARDS\n2, 1, 2\n"
          "*ELSET, ELSET=EGEN, GENERATE\n1, 2\n";
  const Model m = read_deck_text(deck);
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("MIXED").nodes),
            (std::vector<int>{1, 2, 3, 4, 5, 8, 12}));
  EXPECT_EQ(m.node_sets.at("MIXED").name, "MIXED");
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("GEN").nodes), (std::vector<int>{2, 6, 10}));
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("NESTED").nodes),
            (std::vector<int>{1, 2, 3, 4, 5, 6, 8, 10, 12}));
  EXPECT_EQ(labels_of_elements(m, m.element_sets.at("BACKWARDS").elements),
            (std::vector<int>{1, 2}));
  EXPECT_EQ(m.element_sets.at("EGEN").elements.size(), 2u);
}

TEST(inpMesh, NodeLinesAreReadByPositionAsCcxReadsThem) {
  // Empty coordinates are 0; fields past z are not read, with one warning per card naming
  // the first such line (planestress.inp of the ccx suite has "21, 0.75, 1.0, ,0.0").
  const std::string deck = "*NODE\n1, 1.5, 2.5, 3.5\n2, , 2.0\n3, 0.75, 1.0, ,0.0\n"
                           "4, 1, 2, 3, 4, 5\n5, 1, 2, 3, , \n";
  const Model m = read_deck_text(deck, "nodes.inp");
  ASSERT_EQ(m.n_nodes(), 5);
  EXPECT_EQ(m.mesh.coords.row(1), (Vec3(0, 2.0, 0)).transpose());
  EXPECT_EQ(m.mesh.coords.row(2), (Vec3(0.75, 1.0, 0)).transpose());
  EXPECT_EQ(m.mesh.coords.row(3), (Vec3(1, 2, 3)).transpose());
  EXPECT_EQ(m.mesh.coords.row(4), (Vec3(1, 2, 3)).transpose());
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_EQ(m.warnings[0], "nodes.inp:4: *NODE: 2 line(s) with fields past x, y, z (first here): "
                           "not read, as ccx does not read them");
}

TEST(inpMesh, GenerateRangesSkipUndefinedLabelsLikeCcx) {
  std::string deck = test::two_cubes_model();
  deck += "*NSET, NSET=GAP, GENERATE\n1, 100\n*ELSET, ELSET=EGAP, GENERATE\n1, 50\n"
          "*SURFACE, NAME=NS, TYPE=NODE\nGAP\n";
  const Model m = read_deck_text(deck);
  EXPECT_EQ(m.node_sets.at("GAP").nodes.size(), 12u);
  EXPECT_EQ(m.element_sets.at("EGAP").elements.size(), 2u);
  EXPECT_EQ(m.surfaces.at("NS").nodes.size(), 12u);
  // The range is kept for the print: ccx prints its labels without a node as zero rows.
  const auto& ranges = m.node_sets.at("GAP").print_order;
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_EQ(ranges[0].first, 1);
  EXPECT_EQ(ranges[0].last, 100);
}

TEST(inpMesh, SetsKeepCcxsPrintOrderBesideTheirSortedMembers) {
  std::string deck = test::two_cubes_model();
  deck += "*NSET, NSET=A\n9, 2, 9\n*NSET, NSET=B, GENERATE\n1, 5, 2\n*NSET, NSET=C\nA, 4\nB\n"
          "*ELSET, ELSET=E\n2, 1\n";
  const Model m = read_deck_text(deck);
  const auto order = [](const std::vector<model::LabelRange>& ranges) {
    std::vector<std::array<int, 3>> out;
    for (const auto& r : ranges) out.push_back({r.first, r.last, r.step});
    return out;
  };
  using R = std::vector<std::array<int, 3>>;
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("C").nodes), (std::vector<int>{1, 2, 3, 4, 5, 9}));
  EXPECT_EQ(order(m.node_sets.at("C").print_order),
            (R{{9, 9, 1}, {2, 2, 1}, {9, 9, 1}, {4, 4, 1}, {1, 5, 2}}));
  EXPECT_EQ(order(m.element_sets.at("E").print_order), (R{{2, 2, 1}, {1, 1, 1}}));
  EXPECT_EQ(order(m.element_sets.at("EALL").print_order), (R{{1, 1, 1}, {2, 2, 1}}));
}

TEST(inpMesh, AGenerateRangeCostsWhatTheMeshHasNotWhatItNames) {
  // fuzz_deck_text's finding: a range of two billion labels used to be expanded label by label.
  std::string deck = test::two_cubes_model();
  deck += "*NSET, NSET=HUGE, GENERATE\n1, 2147483647, 1\n"
          "*NSET, NSET=STRIDE, GENERATE\n3, 2147483647, 4\n"  // last label past INT_MAX - 4
          "*ELSET, ELSET=EHUGE, GENERATE\n1, 2000000000\n"
          "*NSET, NSET=BOTH\nHUGE, STRIDE\n"
          "*SURFACE, NAME=NS, TYPE=NODE\nSTRIDE\n";
  const Model m = read_deck_text(deck);
  EXPECT_EQ(m.node_sets.at("HUGE").nodes.size(), 12u);
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("STRIDE").nodes), (std::vector<int>{3, 7, 11}));
  EXPECT_EQ(m.node_sets.at("BOTH").nodes.size(), 12u);
  EXPECT_EQ(m.element_sets.at("EHUGE").elements.size(), 2u);
  EXPECT_EQ(m.surfaces.at("NS").nodes.size(), 3u);
  EXPECT_EQ(m.node_sets.at("BOTH").print_order.size(), 2u);
}

TEST(inpMesh, AListedLabelWithoutANodeIsAnErrorEvenBesideARangeThatNamesIt) {
  std::string deck = test::two_cubes_model();
  deck += "*NODE\n100, 5, 5, 5\n*NSET, NSET=S, GENERATE\n1, 100\n*NSET, NSET=S\n99\n";
  try {
    read_deck_text(deck);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node 99 of set S is not defined"), std::string::npos)
        << e.what();
  }
}

TEST(inpMesh, ALabelBeyondTheLargestNodeLeavesTheSetWithAWarning) {
  // As ccx 2.20 (scheibe names node 29 of its 2D element's expansion in a set to print).
  std::string deck = test::two_cubes_model();
  deck += "*NSET, NSET=S\n3, 13, 4\n*NSET, NSET=T, GENERATE\n10, 20\n";
  const Model m = read_deck_text(deck, "d.inp");
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("S").nodes), (std::vector<int>{3, 4}));
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("T").nodes), (std::vector<int>{10, 11, 12}));
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("d.inp:"), std::string::npos) << m.warnings[0];
  EXPECT_NE(m.warnings[0].find("node 13 of set S is beyond the largest node label 12"),
            std::string::npos)
      << m.warnings[0];
}

TEST(inpMesh, AMembraneCardWithoutElementsIsSkippedWithAWarning) {
  // ccx 2.20 skips *MEMBRANE (c3d6 names an element set it never defines).
  const Model m = read_deck_text(
      test::two_cubes_model() + "*MEMBRANE, ELSET=P1, MATERIAL=M\n0.\n", "d.inp");
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("d.inp:27: *MEMBRANE: element set P1 is not defined"),
            std::string::npos)
      << m.warnings[0];
}

TEST(inpMesh, SetsSortByLabelNotDefinitionOrder) {
  const std::string deck =
      "*NODE, NSET=N\n20, 0,0,0\n10, 1,0,0\n30, 1,1,0\n40, 0,1,0\n"
      "*ELEMENT, TYPE=C3D4, ELSET=E\n7, 20, 10, 30, 40\n3, 10, 20, 30, 40\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.\n*SOLID SECTION, ELSET=E, MATERIAL=M\n";
  const Model m = read_deck_text(deck);
  EXPECT_EQ(labels_of_nodes(m, m.node_sets.at("N").nodes), (std::vector<int>{10, 20, 30, 40}));
  EXPECT_EQ(labels_of_elements(m, m.element_sets.at("E").elements), (std::vector<int>{3, 7}));
  EXPECT_EQ(m.mesh.elements[0].id, 7);  // the mesh keeps deck order
}

TEST(inpMesh, ElementContinuationLinesAndC3D20) {
  std::string deck = "*NODE\n";
  for (int i = 1; i <= 20; ++i) deck += std::to_string(i) + ", " + std::to_string(i) + ", 0, 0\n";
  deck += "*ELEMENT, TYPE=C3D20R, ELSET=E\n"
          "1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,\n16, 17, 18, 19, 20\n"
          "2, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,\n11, 12, 13, 14, 15,\n16, 17, 18, 19, 20,\n"
          "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.\n*SOLID SECTION, ELSET=E, MATERIAL=M\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.n_elements(), 2);
  for (const auto& e : m.mesh.elements) {
    EXPECT_EQ(e.type, element::ElementType::C3D20R);
    ASSERT_EQ(e.nodes.size(), 20u);
    EXPECT_EQ(e.nodes[19], 19);
    EXPECT_EQ(e.nodes[15], 15);
  }
}

TEST(inpMesh, C3D8IWithTenNodeNumbersKeepsFirstEight) {
  std::string deck = test::two_cubes_model();
  deck.replace(deck.find("TYPE=C3D8,"), 10, "TYPE=c3d8i,");
  deck.replace(deck.find("1, 1, 2, 3, 4, 5, 6, 7, 8\n"), 26, "1, 1, 2, 3, 4, 5, 6, 7, 8, 11, 12\n");
  const Model m = read_deck_text(deck);
  EXPECT_EQ(m.mesh.elements[0].type, element::ElementType::C3D8I);
  EXPECT_EQ(m.mesh.elements[0].nodes.size(), 8u);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("C3D8I"), std::string::npos);
}

TEST(inpMesh, RepeatedNodeLabelOverwritesCoordinatesWithWarning) {
  std::string deck = test::two_cubes_model();
  deck += "*NODE\n12, 5., 6., 7.\n";
  const Model m = read_deck_text(deck, "dup.inp");
  EXPECT_EQ(m.n_nodes(), 12);
  EXPECT_DOUBLE_EQ(m.mesh.coords(11, 0), 5.0);
  EXPECT_DOUBLE_EQ(m.mesh.coords(11, 2), 7.0);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_EQ(m.warnings[0].rfind("dup.inp:28: *NODE:", 0), 0u) << m.warnings[0];
}

TEST(inpMesh, ElementFaceSurfaceKeepsOrderGiven) {
  std::string deck = test::two_cubes_model();
  deck += "*ELSET, ELSET=RIGHT\n2\n*SURFACE, NAME=Load\n2, S4\nRIGHT, s3\n1, S1\n";
  const Model m = read_deck_text(deck);
  const model::Surface& s = m.surfaces.at("LOAD");
  EXPECT_EQ(s.kind, model::Surface::Kind::ElementFaces);
  ASSERT_EQ(s.faces.size(), 3u);
  EXPECT_EQ(s.faces[0].element, 1);
  EXPECT_EQ(s.faces[0].face, 4);
  EXPECT_EQ(s.faces[1].face, 3);
  EXPECT_EQ(s.faces[2].element, 0);
  EXPECT_EQ(s.faces[2].face, 1);
  EXPECT_EQ(s.where.line, 29);
}

TEST(inpMesh, NodeSurfaceTakesLabelsAndSets) {
  std::string deck = test::two_cubes_model();
  deck += "*SURFACE, NAME=SLAVE, TYPE=NODE\n7\nTIP\n";
  const Model m = read_deck_text(deck);
  const model::Surface& s = m.surfaces.at("SLAVE");
  EXPECT_EQ(s.kind, model::Surface::Kind::Nodes);
  EXPECT_EQ(labels_of_nodes(m, s.nodes), (std::vector<int>{7, 9, 10, 11, 12}));
}

TEST(inpMesh, AllSupportedElementTypesParse) {
  const std::vector<std::pair<std::string, int>> types = {
      {"C3D4", 4},  {"C3D6", 6},   {"C3D8", 8},   {"C3D8R", 8},  {"C3D8I", 8},
      {"C3D10", 10}, {"C3D15", 15}, {"C3D20", 20}, {"C3D20R", 20}};
  for (const auto& [name, n] : types) {
    std::string deck = "*NODE\n";
    for (int i = 1; i <= 20; ++i) deck += std::to_string(i) + ", 0, 0, 0\n";
    deck += "*ELEMENT, TYPE=" + name + ", ELSET=E\n1";
    for (int i = 1; i <= n; ++i) deck += (i == 11 ? ",\n" : ", ") + std::to_string(i);
    deck += "\n*MATERIAL, NAME=M\n*ELASTIC\n1., 0.\n*SOLID SECTION, ELSET=E, MATERIAL=M\n";
    const Model m = read_deck_text(deck);
    EXPECT_EQ(m.mesh.elements[0].nodes.size(), static_cast<std::size_t>(n)) << name;
  }
}

}  // namespace
}  // namespace kontakt::inp

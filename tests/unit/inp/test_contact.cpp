// The contact keywords: interactions with their laws and ccx's defaults, pairs and schemes,
// contact controls, contact output requests and *CHANGE FRICTION.
#include <gtest/gtest.h>

#include <algorithm>

#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {
namespace {

using model::ContactPair;
using model::Model;
using Law = model::SurfaceBehavior::Law;

const std::string kStep = "*STEP\n*STATIC\n*END STEP\n";

bool has_warning(const Model& m, const std::string& fragment) {
  return std::any_of(m.warnings.begin(), m.warnings.end(),
                     [&](const std::string& w) { return w.find(fragment) != std::string::npos; });
}

Model read(const std::string& tail) {
  return read_deck_text(test::two_cubes_surfaces() + tail, "contact.inp");
}

TEST(inpContact, SurfaceToSurfacePairWithDefaults) {
  const Model m = read("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSlave, Master\n" +
                       test::linear_interaction() + kStep);
  ASSERT_EQ(m.contact_pairs.size(), 1u);
  const ContactPair& p = m.contact_pairs[0];
  EXPECT_EQ(p.type, ContactPair::Type::SurfaceToSurface);
  EXPECT_EQ(p.slave, "SLAVE");
  EXPECT_EQ(p.master, "MASTER");
  EXPECT_EQ(p.interaction, 0);
  EXPECT_EQ(model::contact_scheme_name(p.scheme), "lgc7");
  EXPECT_FALSE(p.scheme_given);
  EXPECT_FALSE(p.small_sliding);
  EXPECT_FALSE(p.adjust_distance.has_value());
  EXPECT_EQ(p.where.line, 34);  // the data line
  ASSERT_EQ(m.interactions.size(), 1u);
  const auto& b = m.interactions[0].behavior;
  EXPECT_EQ(m.interactions[0].name, "SI");
  EXPECT_EQ(b.law, Law::Linear);
  EXPECT_DOUBLE_EQ(b.stiffness, 1e7);
  EXPECT_DOUBLE_EQ(b.tension_limit, 210000. / 70000);  // sigma_inf <= 0: E / 70000
  EXPECT_DOUBLE_EQ(b.clearance_c0, 1e-3);
  EXPECT_FALSE(m.interactions[0].friction.has_value());
  // sigma_inf only acts in node-to-surface contact: no warning about its default here.
  EXPECT_FALSE(has_warning(m, "sigma_inf"));
  ASSERT_EQ(m.steps[0].interaction_friction.size(), 1u);
  EXPECT_FALSE(m.steps[0].interaction_friction[0].has_value());
}

TEST(inpContact, LinearWithoutDataLineAndHardTakeTheFirstMaterialsDefaults) {
  // The interaction comes before the material here: the defaults still use its E.
  std::string deck = test::two_cubes_surfaces();
  const std::string material = "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n";
  deck.replace(deck.find(material), material.size(),
               "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n"
               "*SURFACE INTERACTION, NAME=B\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
               "-1, 0, 0.5\n" + material);
  const Model m = read_deck_text(deck + kStep);
  ASSERT_EQ(m.interactions.size(), 2u);
  for (const auto& i : m.interactions) {
    EXPECT_EQ(i.behavior.law, Law::Linear) << i.name;
    EXPECT_DOUBLE_EQ(i.behavior.stiffness, 50 * 210000.) << i.name;
    EXPECT_DOUBLE_EQ(i.behavior.tension_limit, 3.) << i.name;
  }
  EXPECT_DOUBLE_EQ(m.interactions[0].behavior.clearance_c0, 1e-3);
  EXPECT_DOUBLE_EQ(m.interactions[1].behavior.clearance_c0, 0.5);
  EXPECT_TRUE(has_warning(m, "HARD is treated as LINEAR"));
  EXPECT_TRUE(has_warning(m, "K = 50 E = 1.05e+07"));
  EXPECT_TRUE(has_warning(m, "of STEEL, the first material"));
}

TEST(inpContact, ExponentialTabularAndTiedLaws) {
  const Model m = read(
      "*SURFACE INTERACTION, NAME=EXP\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n"
      "1.5e-7, 6.5\n"
      "*SURFACE INTERACTION, NAME=TAB\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n"
      "0., -1e-3\n10., 0.\n10., 0.\n200., 1e-3, 20.\n"
      "*SURFACE INTERACTION, NAME=TIE\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n5e6\n"
      "*FRICTION\n0.3, 1e5\n" + kStep);
  const auto& exp = m.interactions[0].behavior;
  EXPECT_EQ(exp.law, Law::Exponential);
  EXPECT_DOUBLE_EQ(exp.exp_c0, 1.5e-7);
  EXPECT_DOUBLE_EQ(exp.exp_p0, 6.5);
  const auto& tab = m.interactions[1].behavior;
  EXPECT_EQ(tab.law, Law::Tabular);
  ASSERT_EQ(tab.table.size(), 4u);
  EXPECT_EQ(tab.table[0], std::make_pair(-1e-3, 0.));  // (overclosure, pressure)
  EXPECT_EQ(tab.table[1], std::make_pair(0., 10.));
  EXPECT_DOUBLE_EQ(tab.table[2].first, 1e-10);  // a repeated point is pushed apart
  EXPECT_EQ(tab.table[3], std::make_pair(1e-3, 200.));
  EXPECT_DOUBLE_EQ(tab.clearance_c0, 1e-3);
  EXPECT_TRUE(has_warning(m, "moved to 1e-10 above it"));
  const auto& tie = m.interactions[2];
  EXPECT_EQ(tie.behavior.law, Law::Tied);
  EXPECT_DOUBLE_EQ(tie.behavior.stiffness, 5e6);
  ASSERT_TRUE(tie.friction.has_value());
  EXPECT_DOUBLE_EQ(tie.friction->mu, 0.3);
  EXPECT_DOUBLE_EQ(tie.friction->stick_slope, 1e5);
}

TEST(inpContact, FrictionDefaultSlopeAndLastLine) {
  const Model m = read(test::linear_interaction() + "*FRICTION\n0.1, 500.\n0.2\n" + kStep);
  ASSERT_TRUE(m.interactions[0].friction.has_value());
  EXPECT_DOUBLE_EQ(m.interactions[0].friction->mu, 0.2);
  EXPECT_DOUBLE_EQ(m.interactions[0].friction->stick_slope, 105000.);  // E / 2
  EXPECT_TRUE(has_warning(m, "only the last data line counts"));
  EXPECT_TRUE(has_warning(m, "lambda = E / 2 = 105000"));
  ASSERT_TRUE(m.steps[0].interaction_friction[0].has_value());
  EXPECT_DOUBLE_EQ(m.steps[0].interaction_friction[0]->mu, 0.2);
}

TEST(inpContact, NodeToSurfaceOptionsSchemesAndSeveralLines) {
  const Model m = read(
      "*NSET, NSET=MOVE\n6\n" + test::linear_interaction() +
      "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE, SMALL SLIDING, ADJUST=0.01\n"
      "SLAVENODES, MASTER\nSLAVE, MASTER\n"
      "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE, ADJUST=move, SCHEME=LGC3\n"
      "SLAVE, MASTER\n" + kStep);
  ASSERT_EQ(m.contact_pairs.size(), 3u);
  const auto& a = m.contact_pairs[0];
  EXPECT_EQ(a.type, ContactPair::Type::NodeToSurface);
  EXPECT_EQ(model::contact_scheme_name(a.scheme), "nts");
  EXPECT_TRUE(a.small_sliding);
  ASSERT_TRUE(a.adjust_distance.has_value());
  EXPECT_DOUBLE_EQ(*a.adjust_distance, 0.01);
  EXPECT_EQ(a.slave, "SLAVENODES");
  EXPECT_EQ(m.contact_pairs[1].slave, "SLAVE");  // second data line: same options
  EXPECT_TRUE(m.contact_pairs[1].small_sliding);
  const auto& c = m.contact_pairs[2];
  EXPECT_EQ(c.adjust_set, "MOVE");
  EXPECT_FALSE(c.adjust_distance.has_value());
  EXPECT_TRUE(c.scheme_given);
  EXPECT_EQ(c.scheme, (model::ContactScheme{model::ContactScheme::Kind::GaussCut, true, 3}));
  EXPECT_FALSE(c.small_sliding);
  EXPECT_TRUE(has_warning(m, "defaults used: sigma_inf = E / 70000 = 3"));
}

TEST(inpContact, ARepeatedSurfaceGrowsAndANodeNamesakeServesNodeToSurfaceSlaves) {
  // As ccx 2.20: a second *SURFACE of a name and type adds to it (a face named twice counts
  // once: metalformingmortar); a node surface that shares a name with an element-face one is
  // kept apart and is the slave of node-to-surface pairs (metalforming).
  const Model m = read(
      "*SURFACE, NAME=SLAVE\n2, S6\n2, S5\n*SURFACE, NAME=SLAVE, TYPE=NODE\n7\n"
      "*SURFACE, NAME=SLAVE, TYPE=NODE\n6, 7\n" + test::linear_interaction() +
      "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE\nSLAVE, MASTER\n" + kStep);
  const model::Surface& faces = m.surfaces.at("SLAVE");
  EXPECT_EQ(faces.kind, model::Surface::Kind::ElementFaces);
  ASSERT_EQ(faces.faces.size(), 2u);  // S6 from both cards, S5
  EXPECT_EQ(faces.faces[0].face, 6);
  EXPECT_EQ(faces.faces[1].face, 5);
  ASSERT_EQ(m.contact_pairs.size(), 1u);
  const model::Surface& nodes = m.surfaces.at(m.contact_pairs[0].slave);
  EXPECT_EQ(nodes.kind, model::Surface::Kind::Nodes);
  EXPECT_EQ(nodes.nodes, (std::vector<int>{5, 6}));  // nodes 6, 7
}

TEST(inpContact, SmallSlidingIsIgnoredForSurfaceToSurface) {
  const Model m = read(test::linear_interaction() +
                       "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE, SMALL SLIDING, "
                       "SCHEME=nts\nSLAVE, MASTER\n" + kStep);
  EXPECT_FALSE(m.contact_pairs[0].small_sliding);
  EXPECT_TRUE(has_warning(m, "SMALL SLIDING only applies to NODE TO SURFACE"));
  // Any scheme may discretise a pair of face surfaces (the patch test compares them all).
  EXPECT_EQ(m.contact_pairs[0].scheme.kind, model::ContactScheme::Kind::NodeToSurface);
}

TEST(inpContact, ContactControlsCarryOverUntilReset) {
  const Model m = read(
      "*STEP\n*STATIC\n*CONTROLS, PARAMETERS=CONTACT\n0.002, , 50, 30\n"
      "*CONTROLS, PARAMETERS=LINE SEARCH\n, 0.5, 1.\n*END STEP\n"
      "*STEP\n*STATIC\n*CONTROLS, PARAMETERS=FIELD\n0.001\n*END STEP\n"
      "*STEP\n*STATIC\n*CONTROLS, RESET\n*END STEP\n");
  const auto& c = m.steps[0].contact_controls;
  EXPECT_DOUBLE_EQ(c.delcon, 0.002);
  EXPECT_DOUBLE_EQ(c.alea, 0.1);  // blank: unchanged
  EXPECT_DOUBLE_EQ(c.kscalemax, 50);
  EXPECT_EQ(c.itf2f, 30);
  EXPECT_DOUBLE_EQ(c.line_search_min, 0.5);  // 2nd value: the lower bound (ccx's code)
  EXPECT_DOUBLE_EQ(c.line_search_max, 1.);
  EXPECT_EQ(m.steps[1].contact_controls.itf2f, 30);  // carried over
  EXPECT_DOUBLE_EQ(m.steps[1].contact_controls.line_search_min, 0.5);
  EXPECT_EQ(m.steps[2].contact_controls.itf2f, 60);  // RESET
  EXPECT_DOUBLE_EQ(m.steps[2].contact_controls.line_search_max, 1.01);
}

TEST(inpContact, ContactPrintsShareCcxsPrintListOrder) {
  const Model m = read(
      test::linear_interaction() +
      "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n"
      "*STEP\n*STATIC\n*EL PRINT, ELSET=EALL\nEVOL\n*CONTACT PRINT, TOTALS=YES\ncstress, CDISP, "
      "CNUM\n*NODE PRINT, NSET=TIP\nU\n*CONTACT PRINT, TOTALS=ONLY, FREQUENCY=2\nCELS\n"
      "*CONTACT FILE\nCDIS\n*CONTACT OUTPUT\nCSTR, CELS\n*END STEP\n"
      "*STEP\n*STATIC\n*NODE PRINT, NSET=FIX\nRF\n*CONTACT FILE\nCELS\n*END STEP\n"
      "*STEP\n*STATIC\n*CONTACT PRINT\nCDIS\n*END STEP\n");
  const auto& s0 = m.steps[0];
  // ccx's order: EL PRINT, CONTACT PRINT, NODE PRINT, CONTACT PRINT (blocks follow it).
  ASSERT_EQ(s0.prints.size(), 2u);
  EXPECT_EQ(s0.prints[0].kind, model::PrintRequest::Kind::Element);
  EXPECT_EQ(s0.prints[1].kind, model::PrintRequest::Kind::Node);
  ASSERT_EQ(s0.contact_prints.size(), 2u);
  EXPECT_EQ(s0.contact_prints[0].variables, (std::vector<std::string>{"CSTR", "CDIS"}));
  EXPECT_TRUE(s0.contact_prints[0].totals);
  EXPECT_EQ(s0.contact_prints[0].after_prints, 1u);
  EXPECT_EQ(s0.contact_prints[1].variables, (std::vector<std::string>{"CELS"}));
  EXPECT_TRUE(s0.contact_prints[1].totals_only);
  EXPECT_EQ(s0.contact_prints[1].after_prints, 2u);
  EXPECT_EQ(s0.contact_prints[0].frequency, 2);  // the last FREQUENCY applies to all
  EXPECT_EQ(s0.prints[0].frequency, 2);
  ASSERT_EQ(s0.contact_files.size(), 2u);  // *CONTACT OUTPUT = *CONTACT FILE
  EXPECT_EQ(s0.contact_files[1].variables, (std::vector<std::string>{"CSTR", "CELS"}));
  EXPECT_TRUE(has_warning(m, "CNUM is not written by Kontakt"));
  // Step 2: a new node print goes to the end; the contact prints carry over in front of it.
  const auto& s1 = m.steps[1];
  ASSERT_EQ(s1.prints.size(), 2u);
  EXPECT_EQ(s1.prints[1].set, "FIX");
  EXPECT_EQ(s1.contact_prints.size(), 2u);
  EXPECT_EQ(s1.contact_prints[0].after_prints, 1u);
  EXPECT_EQ(s1.contact_prints[1].after_prints, 1u);
  ASSERT_EQ(s1.contact_files.size(), 1u);
  EXPECT_EQ(s1.contact_files[0].variables, (std::vector<std::string>{"CELS"}));
  // Step 3: the new contact print replaces both and comes last.
  const auto& s2 = m.steps[2];
  ASSERT_EQ(s2.contact_prints.size(), 1u);
  EXPECT_EQ(s2.contact_prints[0].after_prints, 2u);
  EXPECT_FALSE(s2.contact_prints[0].totals);
}

TEST(inpContact, ContactPrintWithoutPairsAndIgnoredParametersWarn) {
  const Model m = read("*STEP\n*STATIC\n*CONTACT PRINT, NSET=NALL\nCDIS\n*CONTACT FILE, LAST "
                       "ITERATIONS\nCDIS, PCON\n*END STEP\n");
  EXPECT_TRUE(has_warning(m, "NSET= ignored"));
  EXPECT_TRUE(has_warning(m, "no *CONTACT PAIR"));
  EXPECT_TRUE(has_warning(m, "LASTITERATIONS ignored"));
  EXPECT_TRUE(has_warning(m, "PCON is not written"));
}

TEST(inpContact, ChangeFrictionActsFromItsStepOn) {
  const Model m = read(test::linear_interaction() + "*FRICTION\n0.2, 80.\n" +
                       "*SURFACE INTERACTION, NAME=FREE\n*SURFACE BEHAVIOR, "
                       "PRESSURE-OVERCLOSURE=LINEAR\n1e6\n" + kStep +
                       "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=SI\n*FRICTION\n0.1, 0.\n"
                       "*CHANGE FRICTION, INTERACTION=FREE\n*FRICTION\n0.5, 9.\n*END STEP\n" +
                       kStep);
  ASSERT_EQ(m.steps.size(), 3u);
  EXPECT_DOUBLE_EQ(m.steps[0].interaction_friction[0]->mu, 0.2);
  EXPECT_FALSE(m.steps[0].interaction_friction[1].has_value());
  for (int s : {1, 2}) {
    const auto& f = m.steps[static_cast<std::size_t>(s)].interaction_friction;
    EXPECT_DOUBLE_EQ(f[0]->mu, 0.1) << s;
    EXPECT_DOUBLE_EQ(f[0]->stick_slope, 105000.) << s;  // default E / 2
    EXPECT_DOUBLE_EQ(f[1]->mu, 0.5) << s;
  }
  EXPECT_DOUBLE_EQ(m.interactions[0].friction->mu, 0.2);  // the model's own is kept
}

TEST(inpContact, ModelChangeTakesPairsOutAndBackFromItsStepOn) {
  const std::string change = "*STEP\n*STATIC\n*MODEL CHANGE, TYPE=CONTACT PAIR, ";
  const Model m = read(test::linear_interaction() +
                       "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n"
                       "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nMASTER, SLAVE\n" +
                       kStep + change + "REMOVE\nSLAVE, MASTER\n*END STEP\n" + kStep + change +
                       "ADD\nSLAVE, MASTER\n*END STEP\n");
  ASSERT_EQ(m.steps.size(), 4u);
  const std::vector<std::vector<char>> expected{{1, 1}, {0, 1}, {0, 1}, {1, 1}};
  for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(m.steps[s].contact_pair_active, expected[s]) << s;
}

TEST(inpContact, ChangeSurfaceBehaviorActsFromItsStepOn) {
  // changesurfbeh's pattern: TIED in step 1, LINEAR (here with ccx's default K) from step 2 on.
  const Model m = read("*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, "
                       "PRESSURE-OVERCLOSURE=TIED\n1e9\n*FRICTION\n1e-4, 1e3\n" + kStep +
                       "*STEP\n*STATIC\n*CHANGE SURFACE BEHAVIOR, INTERACTION=SI\n"
                       "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n*END STEP\n" + kStep);
  ASSERT_EQ(m.steps.size(), 3u);
  using Law = model::SurfaceBehavior::Law;
  EXPECT_EQ(m.steps[0].interaction_behavior.at(0).law, Law::Tied);
  EXPECT_DOUBLE_EQ(m.steps[0].interaction_behavior[0].stiffness, 1e9);
  for (int s : {1, 2}) {
    const auto& b = m.steps[static_cast<std::size_t>(s)].interaction_behavior.at(0);
    EXPECT_EQ(b.law, Law::Linear) << s;
    EXPECT_DOUBLE_EQ(b.stiffness, 50 * 210000.) << s;  // default K = 50 E, resolved at the card
    EXPECT_DOUBLE_EQ(b.clearance_c0, 1e-3) << s;
  }
  EXPECT_EQ(m.interactions[0].behavior.law, Law::Tied);  // the model's own is kept
  EXPECT_TRUE(has_warning(m, "defaults used: K = 50 E"));
}

TEST(inpContact, ElementPrintBeforeNodePrintKeepsCcxsOrder) {
  const Model m = read_deck_text(test::two_cubes_model() +
                                 "*STEP\n*STATIC\n*EL PRINT, ELSET=EALL\nS\n*NODE PRINT, "
                                 "NSET=TIP\nU\n*END STEP\n");
  ASSERT_EQ(m.steps[0].prints.size(), 2u);
  EXPECT_EQ(m.steps[0].prints[0].kind, model::PrintRequest::Kind::Element);
  EXPECT_EQ(m.steps[0].prints[1].kind, model::PrintRequest::Kind::Node);
}

}  // namespace
}  // namespace kontakt::inp

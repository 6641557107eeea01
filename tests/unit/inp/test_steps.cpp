#include <gtest/gtest.h>

#include <algorithm>

#include "inp/read_deck.hpp"
#include "deck_fixtures.hpp"

namespace kontakt::inp {
namespace {

using model::Model;

/// (node label, dof 1..3, value) of a step's boundaries, in stored order.
std::vector<std::tuple<int, int, double>> bcs(const Model& m, const model::Step& s) {
  std::vector<std::tuple<int, int, double>> out;
  for (const auto& b : s.boundaries) {
    out.emplace_back(m.mesh.node_ids[static_cast<std::size_t>(b.node)], b.dof + 1, b.value);
  }
  return out;
}
std::vector<std::tuple<int, int, double>> loads(const Model& m, const model::Step& s) {
  std::vector<std::tuple<int, int, double>> out;
  for (const auto& c : s.cloads) {
    out.emplace_back(m.mesh.node_ids[static_cast<std::size_t>(c.node)], c.dof + 1, c.value);
  }
  return out;
}

TEST(inpSteps, MinimalStaticStep) {
  const Model m = read_deck_text(test::two_cubes_static());
  ASSERT_EQ(m.steps.size(), 1u);
  const model::Step& s = m.steps[0];
  EXPECT_FALSE(s.nlgeom);
  EXPECT_EQ(s.max_increments, 100);
  EXPECT_FALSE(s.procedure.data_line_given);
  EXPECT_DOUBLE_EQ(s.procedure.period, 1.0);
  EXPECT_EQ(s.boundaries.size(), 12u);  // 4 nodes x 3 dofs, model level
  ASSERT_EQ(s.cloads.size(), 4u);
  EXPECT_DOUBLE_EQ(s.cloads[0].value, 10.0);
  ASSERT_EQ(s.prints.size(), 1u);
  EXPECT_EQ(s.prints[0].set, "TIP");
  EXPECT_EQ(s.prints[0].variables, (std::vector<std::string>{"U"}));
  EXPECT_EQ(s.temperatures.size(), 0);
  EXPECT_FALSE(s.procedure.data_line_given);  // (1, 1); only a nonlinear step warns
  EXPECT_TRUE(m.warnings.empty());
}

TEST(inpSteps, StepParametersAndStaticData) {
  std::string deck = test::two_cubes_model();
  deck += "*STEP, NLGEOM, INC=250\n*STATIC, DIRECT\n0.1, 2., 1e-5, 0.5\n*END STEP\n"
          "*STEP\n*STATIC\n0.5, 1.\n*END STEP\n*STEP, NLGEOM=NO\n*STATIC\n1,1\n*END STEP\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.steps.size(), 3u);
  const model::Step& s = m.steps[0];
  EXPECT_TRUE(s.nlgeom);
  EXPECT_EQ(s.max_increments, 250);
  EXPECT_TRUE(s.procedure.direct);
  EXPECT_TRUE(s.procedure.data_line_given);
  EXPECT_DOUBLE_EQ(s.procedure.initial_increment, 0.1);
  EXPECT_DOUBLE_EQ(s.procedure.period, 2.0);
  EXPECT_DOUBLE_EQ(*s.procedure.min_increment, 1e-5);
  EXPECT_DOUBLE_EQ(*s.procedure.max_increment, 0.5);
  EXPECT_TRUE(m.steps[1].nlgeom);  // ccx: NLGEOM stays active
  EXPECT_FALSE(m.steps[1].procedure.min_increment);
  EXPECT_FALSE(m.steps[2].nlgeom);
  EXPECT_EQ(s.where.line, 27);
}

TEST(inpSteps, BoundaryOpNewOverThreeSteps) {
  std::string deck = test::two_cubes_model();
  deck += "*BOUNDARY\n1, 1, 3\n"               // model level
          "*STEP\n*STATIC\n*BOUNDARY\n9, 1, 1, 0.5\n10, 2\n*END STEP\n"  // adds
          "*STEP\n*STATIC\n*BOUNDARY, OP=NEW\n4, 3, 3, 0.\n*BOUNDARY, OP=MOD\n9, 1, , 0.7\n"
          "*END STEP\n"
          "*STEP\n*STATIC\n*BOUNDARY\n4, 3, 3, 0.25\n*END STEP\n";  // replaces value
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.steps.size(), 3u);
  using T = std::tuple<int, int, double>;
  EXPECT_EQ(bcs(m, m.steps[0]),
            (std::vector<T>{{1, 1, 0.}, {1, 2, 0.}, {1, 3, 0.}, {9, 1, 0.5}, {10, 2, 0.}}));
  // ccx: OP=NEW removes every earlier *BOUNDARY, model-level ones included.
  EXPECT_EQ(bcs(m, m.steps[1]), (std::vector<T>{{4, 3, 0.}, {9, 1, 0.7}}));
  EXPECT_EQ(bcs(m, m.steps[2]), (std::vector<T>{{4, 3, 0.25}, {9, 1, 0.7}}));
}

TEST(inpSteps, CloadAddsWithinStepReplacesAcrossStepsAndOpNewClears) {
  std::string deck = test::two_cubes_model();
  deck += "*STEP\n*STATIC\n*CLOAD\n9, 1, 1.\n9, 1, 2.\n*CLOAD\nTIP, 2, 1.\n*END STEP\n"
          "*STEP\n*STATIC\n*CLOAD\n9, 1, 5.\n*END STEP\n"
          "*STEP\n*STATIC\n*CLOAD, OP=NEW\n10, 3, -1.\n*END STEP\n"
          "*STEP\n*STATIC\n*END STEP\n";
  const Model m = read_deck_text(deck);
  using T = std::tuple<int, int, double>;
  EXPECT_EQ(loads(m, m.steps[0]),
            (std::vector<T>{{9, 1, 3.}, {9, 2, 1.}, {10, 2, 1.}, {11, 2, 1.}, {12, 2, 1.}}));
  EXPECT_EQ(loads(m, m.steps[1]),
            (std::vector<T>{{9, 1, 5.}, {9, 2, 1.}, {10, 2, 1.}, {11, 2, 1.}, {12, 2, 1.}}));
  EXPECT_EQ(loads(m, m.steps[2]), (std::vector<T>{{10, 3, -1.}}));
  EXPECT_EQ(loads(m, m.steps[3]), (std::vector<T>{{10, 3, -1.}}));
}

TEST(inpSteps, DloadFacesAddWithinStepAndOpNew) {
  std::string deck = test::two_cubes_model();
  deck += "*ELSET, ELSET=RIGHT\n2\n*SURFACE, NAME=TOP\n1, S2\n"
          "*STEP\n*STATIC\n*DLOAD\nRIGHT, P4, 1.5\n2, p4, 0.5\n1, P1, 2.\n*END STEP\n"
          "*STEP\n*STATIC\n*DLOAD, OP=NEW\nTOP, P, 3.\n*END STEP\n";
  const Model m = read_deck_text(deck);
  const auto& p0 = m.steps[0].pressures;
  ASSERT_EQ(p0.size(), 2u);
  EXPECT_EQ(p0[0].face.element, 0);
  EXPECT_EQ(p0[0].face.face, 1);
  EXPECT_DOUBLE_EQ(p0[0].value, 2.0);
  EXPECT_EQ(p0[1].face.element, 1);
  EXPECT_EQ(p0[1].face.face, 4);
  EXPECT_DOUBLE_EQ(p0[1].value, 2.0);
  const auto& p1 = m.steps[1].pressures;
  ASSERT_EQ(p1.size(), 1u);
  EXPECT_EQ(p1[0].face.face, 2);
  EXPECT_DOUBLE_EQ(p1[0].value, 3.0);
}

TEST(inpSteps, BodyLoadsAddWithinStepAndReplaceAcrossSteps) {
  std::string deck = test::two_cubes_model();
  deck.insert(deck.find("*SOLID SECTION"), "*DENSITY\n7.8e-9\n");
  deck += "*ELSET, ELSET=RIGHT\n2\n"
          "*STEP\n*STATIC\n*DLOAD\nEALL, GRAV, 9810., 0., 0., -1.\n"
          "RIGHT, GRAV, 100., 0., 3., 4.\nEALL, GRAV, 5000., 0., 0., -1.\n"
          "Eall, CENTRIF, 1e4, 1., 2., 3., 0., 0., 2.\n*END STEP\n"
          "*STEP\n*STATIC\n*DLOAD, OP=NEW\nRIGHT, CENTRIF, 4e4, 0., 0., 0., 1., 0., 0.\n"
          "*END STEP\n"
          "*STEP\n*STATIC\n*DLOAD\nRIGHT, CENTRIF, 3e4, 0., 0., 0., 1., 0., 0.\n*END STEP\n";
  const Model m = read_deck_text(deck);
  using Kind = model::BodyLoad::Kind;
  const auto& b0 = m.steps[0].body_loads;
  ASSERT_EQ(b0.size(), 3u);  // EALL's two gravity cards along -z are one load of 14810
  const auto find = [&b0](Kind kind, Real value) {
    const auto it = std::find_if(b0.begin(), b0.end(), [&](const model::BodyLoad& b) {
      return b.kind == kind && b.value == value;
    });
    return it == b0.end() ? nullptr : &*it;
  };
  const model::BodyLoad* all = find(Kind::Gravity, 14810.);
  const model::BodyLoad* right = find(Kind::Gravity, 100.);
  const model::BodyLoad* spin = find(Kind::Centrifugal, 1e4);
  ASSERT_TRUE(all && right && spin);
  EXPECT_EQ(all->elements, (std::vector<int>{0, 1}));
  EXPECT_LT((right->direction - Vec3(0, 0.6, 0.8)).norm(), 1e-15);
  EXPECT_EQ(right->elements, (std::vector<int>{1}));
  EXPECT_EQ(spin->point, Vec3(1, 2, 3));
  EXPECT_EQ(spin->direction, Vec3(Vec3::UnitZ()));
  // Non-unit directions are normalised with a warning each (RIGHT's gravity and the axis).
  EXPECT_EQ(std::count_if(m.warnings.begin(), m.warnings.end(),
                          [](const std::string& w) { return w.find("normalised") != w.npos; }),
            2);
  const auto& b1 = m.steps[1].body_loads;  // OP=NEW removed step 1's
  ASSERT_EQ(b1.size(), 1u);
  EXPECT_EQ(b1[0].kind, Kind::Centrifugal);
  EXPECT_DOUBLE_EQ(b1[0].value, 4e4);
  ASSERT_EQ(m.steps[2].body_loads.size(), 1u);  // the same load in a later step: replaced
  EXPECT_DOUBLE_EQ(m.steps[2].body_loads[0].value, 3e4);
}

TEST(inpSteps, TemperaturesAndInitialConditions) {
  std::string deck = test::two_cubes_model();
  deck += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n1, 15.\n"
          "*STEP\n*STATIC\n*TEMPERATURE\nTIP, 100.\n*END STEP\n"
          "*STEP\n*STATIC\n*TEMPERATURE\n1, 50.\n*END STEP\n"
          "*STEP\n*STATIC\n*TEMPERATURE, OP=NEW\n*END STEP\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.initial_temperatures.size(), 12);
  EXPECT_DOUBLE_EQ(m.initial_temperatures[0], 15.0);
  EXPECT_DOUBLE_EQ(m.initial_temperatures[5], 20.0);
  const VecX& t0 = m.steps[0].temperatures;
  ASSERT_EQ(t0.size(), 12);
  EXPECT_DOUBLE_EQ(t0[0], 15.0);
  EXPECT_DOUBLE_EQ(t0[8], 100.0);
  const VecX& t1 = m.steps[1].temperatures;
  EXPECT_DOUBLE_EQ(t1[0], 50.0);
  EXPECT_DOUBLE_EQ(t1[11], 100.0);
  EXPECT_EQ(m.steps[2].temperatures.size(), 0);  // reset to the initial field
}

TEST(inpSteps, InitialStressesPerIntegrationPoint) {
  std::string deck = test::two_cubes_model();
  deck += "*INITIAL CONDITIONS, TYPE=STRESS\n2, 3, -100., -50., 0., 1., 2., 3.\n"
          "*STEP\n*STATIC\n*END STEP\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.initial_stresses.size(), 2u);
  EXPECT_EQ(m.initial_stresses[0].size(), 0);  // element 1: none
  ASSERT_EQ(m.initial_stresses[1].rows(), 8);
  EXPECT_DOUBLE_EQ(m.initial_stresses[1](2, 0), -100.0);
  EXPECT_DOUBLE_EQ(m.initial_stresses[1](2, 5), 3.0);
  EXPECT_DOUBLE_EQ(m.initial_stresses[1](0, 0), 0.0);  // points not listed: zero
  // Bad lines name the card and the line; NLGEOM steps are refused at the card.
  for (const auto& [bad, why] : std::vector<std::pair<std::string, std::string>>{
           {"2, 9, 1., 1., 1., 0., 0., 0.\n*STEP\n*STATIC\n*END STEP\n", "points 1 to 8"},
           {"7, 1, 1., 1., 1., 0., 0., 0.\n*STEP\n*STATIC\n*END STEP\n", "element 7"},
           {"1, 1, 1., 1., 1.\n*STEP\n*STATIC\n*END STEP\n", "field"},
           {"1, 1, 1., 1., 1., 0., 0., 0.\n*STEP, NLGEOM\n*STATIC\n*END STEP\n", "NLGEOM"}}) {
    try {
      read_deck_text(test::two_cubes_model() + "*INITIAL CONDITIONS, TYPE=STRESS\n" + bad,
                     "s.inp");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("s.inp:2"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("*INITIAL CONDITIONS"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
}

TEST(inpSteps, InitialInelasticStrainsBecomeTheInitialStressOfAnElasticMaterial) {
  std::string deck = test::two_cubes_model();
  deck += "*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN\n2, 3, 1e-3, -2e-4, 0., 4e-4, 0., -1e-4\n"
          "*INITIAL CONDITIONS, TYPE=STRESS\n2, 3, 10., 0., 0., 0., 0., 0.\n"
          "*STEP\n*STATIC\n*END STEP\n";
  const Model m = read_deck_text(deck);
  const auto [young, poisson] = m.materials.front().elastic.rows.front();
  const Real mu = young / (2 * (1 + poisson));
  const Real lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  ASSERT_EQ(m.initial_stresses[1].rows(), 8);
  const Real trace = 1e-3 - 2e-4;
  // sigma0 = -C eps_p (tensor shear components: 2 mu eps_xy), plus the given initial stress
  EXPECT_NEAR(m.initial_stresses[1](2, 0), 10.0 - (2 * mu * 1e-3 + lambda * trace), 1e-9);
  EXPECT_NEAR(m.initial_stresses[1](2, 1), -(2 * mu * -2e-4 + lambda * trace), 1e-9);
  EXPECT_NEAR(m.initial_stresses[1](2, 2), -lambda * trace, 1e-9);
  EXPECT_NEAR(m.initial_stresses[1](2, 3), -2 * mu * 4e-4, 1e-9);
  EXPECT_NEAR(m.initial_stresses[1](2, 5), 2 * mu * 1e-4, 1e-9);
  EXPECT_EQ(m.initial_stresses[1](1, 0), 0.0);
  // Materials that would need more than C at the start are refused at the card.
  std::string plastic = test::two_cubes_model();
  plastic.replace(plastic.find("*SOLID SECTION"), 0, "*PLASTIC\n300., 0.\n");
  std::string hot = test::two_cubes_model();
  const auto row = hot.find('\n', hot.find("*ELASTIC\n") + 9);
  hot.replace(row, 0, ", 20.\n100000., 0.3, 500.");
  for (const auto& [model, why] : std::vector<std::pair<std::string, std::string>>{
           {plastic, "has *PLASTIC"}, {hot, "is not isotropic with one *ELASTIC row"}}) {
    try {
      read_deck_text(model + "*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN\n"
                             "1, 1, 1e-3, 0., 0., 0., 0., 0.\n*STEP\n*STATIC\n*END STEP\n",
                     "p.inp");
      ADD_FAILURE() << "accepted: " << why;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("*INITIAL CONDITIONS"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
}

TEST(inpSteps, AmplitudesAndFreezingAtStepEnd) {
  std::string deck = test::two_cubes_model();
  deck += "*AMPLITUDE, NAME=Ramp2\n0., 0., 1., 2., 2., 2.,\n3., 4.\n"
          "*AMPLITUDE, NAME=TOT, TIME=TOTAL TIME\n0, 0, 10, 1\n"
          "*STEP\n*STATIC\n0.1, 1.\n*CLOAD, AMPLITUDE=RAMP2\n9, 1, 10.\n"
          "*CLOAD, AMPLITUDE=tot\n10, 1, 1.\n*BOUNDARY, AMPLITUDE=RAMP2\n1, 1, 1, 0.1\n*END STEP\n"
          "*STEP\n*STATIC\n*END STEP\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.amplitudes.size(), 2u);
  EXPECT_EQ(m.amplitudes[0].name, "RAMP2");
  EXPECT_FALSE(m.amplitudes[0].total_time);
  EXPECT_TRUE(m.amplitudes[1].total_time);
  EXPECT_EQ(m.amplitudes[0].points.size(), 4u);
  EXPECT_DOUBLE_EQ(m.amplitudes[0].value_at(2.5), 3.0);
  const model::Step& s0 = m.steps[0];
  ASSERT_EQ(s0.cloads.size(), 2u);
  EXPECT_EQ(s0.cloads[0].amplitude, 0);
  EXPECT_DOUBLE_EQ(s0.cloads[0].value, 10.0);
  EXPECT_EQ(s0.boundaries[0].amplitude, 0);
  // Step-time amplitude: value frozen at amplitude(period = 1) = 2; total-time kept.
  const model::Step& s1 = m.steps[1];
  EXPECT_EQ(s1.cloads[0].amplitude, -1);
  EXPECT_DOUBLE_EQ(s1.cloads[0].value, 20.0);
  EXPECT_EQ(s1.cloads[1].amplitude, 1);
  EXPECT_DOUBLE_EQ(s1.cloads[1].value, 1.0);
  EXPECT_DOUBLE_EQ(s1.boundaries[0].value, 0.2);
}

TEST(inpSteps, TimeDelayShiftsACopyOfTheAmplitude) {
  std::string deck = test::two_cubes_model();
  deck += "*AMPLITUDE, NAME=A1\n0., 1., 1., 2., 2., 3.\n"
          "*STEP\n*STATIC\n0.5, 1.5\n*CLOAD, AMPLITUDE=A1, TIME DELAY=1.\n9, 2, 1.\n"
          "*CLOAD, AMPLITUDE=A1\n10, 2, 1.\n*END STEP\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.amplitudes.size(), 2u);
  const auto& cloads = m.steps[0].cloads;
  ASSERT_EQ(cloads.size(), 2u);
  EXPECT_EQ(cloads[1].amplitude, 0);  // the undelayed card keeps the amplitude itself
  const model::Amplitude& delayed = m.amplitudes[static_cast<std::size_t>(cloads[0].amplitude)];
  EXPECT_NE(cloads[0].amplitude, 0);
  for (Real t : {0.0, 0.5, 1.2, 1.5, 2.7})  // amplitude at t is A1 at t - 1
    EXPECT_DOUBLE_EQ(delayed.value_at(t), m.amplitudes[0].value_at(t - 1)) << "t = " << t;
  EXPECT_DOUBLE_EQ(delayed.value_at(1.5), 1.5);
}

TEST(inpSteps, EquationsWithContinuation) {
  std::string deck = test::two_cubes_model();
  deck += "*EQUATION\n2\n9, 1, 1., 2, 1, -1.\n5\n10, 2, 1., 11, 2, -0.25, 12, 2, -0.25, "
          "3, 2, -0.25\n7, 2, -0.25\n";
  const Model m = read_deck_text(deck);
  ASSERT_EQ(m.equations.size(), 2u);
  ASSERT_EQ(m.equations[0].terms.size(), 2u);
  EXPECT_EQ(m.equations[0].terms[0].node, 8);
  EXPECT_EQ(m.equations[0].terms[0].dof, 0);
  EXPECT_DOUBLE_EQ(m.equations[0].terms[1].coef, -1.0);
  ASSERT_EQ(m.equations[1].terms.size(), 5u);
  EXPECT_EQ(m.equations[1].terms[4].node, 6);
  EXPECT_EQ(m.equations[1].where.line, 30);
}

TEST(inpSteps, PrintRequestsCarryOverUntilReplaced) {
  std::string deck = test::two_cubes_model();
  deck += "*STEP\n*STATIC\n*NODE PRINT, NSET=TIP, TOTALS=YES\nU, RF\n*EL PRINT, ELSET=EALL\n"
          "S, E\n*NODE FILE\nU\n*EL FILE, FREQUENCY=2\nS\n*END STEP\n"
          "*STEP\n*STATIC\n*NODE PRINT, NSET=FIX, TOTALS=ONLY, GLOBAL=YES\nRF\n*END STEP\n"
          "*STEP\n*STATIC\n*END STEP\n";
  const Model m = read_deck_text(deck);
  const auto& p0 = m.steps[0].prints;
  ASSERT_EQ(p0.size(), 2u);
  EXPECT_EQ(p0[0].kind, model::PrintRequest::Kind::Node);
  EXPECT_EQ(p0[0].totals, model::Totals::Yes);
  EXPECT_FALSE(p0[0].global);
  EXPECT_EQ(p0[0].variables, (std::vector<std::string>{"U", "RF"}));
  EXPECT_EQ(p0[1].kind, model::PrintRequest::Kind::Element);
  EXPECT_EQ(p0[1].set, "EALL");
  EXPECT_EQ(p0[1].frequency, 2);  // ccx: the last FREQUENCY applies to all outputs
  ASSERT_EQ(m.steps[0].node_files.size(), 1u);
  ASSERT_EQ(m.steps[0].element_files.size(), 1u);
  // Step 2: a new *NODE PRINT replaces the node prints; the element print carries over and,
  // as in ccx 2.20, now comes first (the new request is appended to ccx's print list).
  const auto& p1 = m.steps[1].prints;
  ASSERT_EQ(p1.size(), 2u);
  EXPECT_EQ(p1[0].set, "EALL");
  EXPECT_EQ(p1[1].set, "FIX");
  EXPECT_EQ(p1[1].totals, model::Totals::Only);
  EXPECT_TRUE(p1[1].global);
  EXPECT_EQ(m.steps[1].node_files.size(), 1u);
  EXPECT_EQ(m.steps[2].prints.size(), 2u);
  EXPECT_EQ(m.steps[2].prints[1].set, "FIX");
}

TEST(inpSteps, FileCardWithoutVariablesWipesTheSelection) {
  // ccx 2.20 (measured): an empty *NODE FILE / *EL FILE writes nothing of its kind from that
  // step on; a later step without the card keeps the empty selection.
  std::string deck = test::two_cubes_model();
  deck += "*STEP\n*STATIC\n*NODE FILE\nU\n*EL FILE\nS\n*END STEP\n"
          "*STEP\n*STATIC\n*NODE FILE\n*END STEP\n"
          "*STEP\n*STATIC\n*EL FILE\n*END STEP\n";
  const Model m = read_deck_text(deck);
  EXPECT_EQ(m.steps[0].node_files.size(), 1u);
  EXPECT_EQ(m.steps[1].node_files.size(), 0u);
  EXPECT_EQ(m.steps[1].element_files.size(), 1u);
  EXPECT_EQ(m.steps[2].node_files.size(), 0u);
  EXPECT_EQ(m.steps[2].element_files.size(), 0u);
}

TEST(inpSteps, OutputOnlyKeywordsWarn) {
  std::string deck = test::two_cubes_model();
  deck += "*STEP\n*STATIC\n*NODE FILE, OUTPUT=2D\nU\n*NODE OUTPUT\nRF\n*ELEMENT OUTPUT\nS\n"
          "*OUTPUT, FIELD, FREQUENCY=3\n*END STEP\n";
  const Model m = read_deck_text(deck);
  EXPECT_EQ(m.steps[0].node_files.size(), 2u);
  EXPECT_EQ(m.steps[0].node_files[0].frequency, 3);
  EXPECT_EQ(m.steps[0].element_files.size(), 1u);
  ASSERT_GE(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("OUTPUT= ignored"), std::string::npos);
}

}  // namespace
}  // namespace kontakt::inp

namespace kontakt::inp {
namespace {

TEST(inpSteps, ControlsSetFieldsKeepBlanksAndCarryOverUntilReset) {
  std::string deck = test::two_cubes_model();
  deck += "*STEP\n*STATIC\n*CONTROLS, PARAMETERS=TIME INCREMENTATION\n6, , , 30\n0.3, , , , , , 2.0\n"
          "*CONTROLS, PARAMETERS=FIELD\n0.001, 0.02\n*END STEP\n"
          "*STEP\n*STATIC\n*END STEP\n"
          "*STEP\n*STATIC\n*CONTROLS, RESET\n*END STEP\n";
  const model::Model m = read_deck_text(deck);
  const auto& c = m.steps[0].controls;
  EXPECT_EQ(c.divergence_check_from, 6);
  EXPECT_EQ(c.log_estimate_from, 8);  // blank: unchanged
  EXPECT_EQ(c.max_iterations, 30);
  EXPECT_DOUBLE_EQ(c.divergence_cutback, 0.3);
  EXPECT_DOUBLE_EQ(c.growth_factor, 2.0);
  EXPECT_DOUBLE_EQ(c.residual_tolerance, 0.001);
  EXPECT_DOUBLE_EQ(c.correction_tolerance, 0.02);
  EXPECT_EQ(m.steps[1].controls.max_iterations, 30);  // carried over
  EXPECT_EQ(m.steps[2].controls.max_iterations, 16);  // RESET: ccx defaults
}

TEST(inpSteps, ControlsErrorsNameTheLine) {
  std::string deck = test::two_cubes_model();
  deck += "*STEP\n*STATIC\n*CONTROLS, PARAMETERS=TIME INCREMENTATION\n4.5\n*END STEP\n";
  try {
    read_deck_text(deck, "bad.inp");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("*CONTROLS"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("whole number"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace kontakt::inp

namespace kontakt::inp {
namespace {

TEST(inpMaterial, PlasticTableIsReadAndChecked) {
  auto with_plastic = [](const std::string& lines) {
    std::string deck = test::two_cubes_model();
    const auto at = deck.find("*ELASTIC");
    deck.insert(deck.find('\n', deck.find('\n', at) + 1) + 1, "*PLASTIC" + lines + "\n");
    return deck;
  };
  const model::Model m = read_deck_text(with_plastic("\n250., 0.\n300., 0.05"));
  ASSERT_EQ(m.materials[0].plastic.curves.size(), 1u);
  const auto& curve = m.materials[0].plastic.curves[0].points;
  ASSERT_EQ(curve.size(), 2u);
  EXPECT_DOUBLE_EQ(curve[1].first, 300.0);
  EXPECT_DOUBLE_EQ(curve[1].second, 0.05);
  for (const std::string& bad : {std::string("\n250., 0.01"), std::string("\n250., 0.\n260., 0."),
                                 std::string(", HARDENING=FOO\n250., 0."),
                                 std::string("\n250., 0., 20.\n260., 0.1, 100."),
                                 std::string("\n250., 0.\n0., 1e-9")}) {  // steep softening
    try {
      read_deck_text(with_plastic(bad), "p.inp");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("*PLASTIC"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("p.inp:"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace kontakt::inp

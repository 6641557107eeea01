// The nodal temperatures a frame reports (NT in the .frd) and the distributed loads a
// small-strain step computes once.
#include "analysis/step_loads.hpp"

#include <gtest/gtest.h>

#include "cube_deck.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::analysis {
namespace {

model::Model three_nodes() {
  model::Model m;
  m.mesh.node_ids = {1, 2, 3};
  m.mesh.coords = MatX3::Zero(3, 3);
  m.steps.resize(2);
  return m;
}

TEST(NodalTemperatures, EmptyForAModelWithoutTemperatures) {
  EXPECT_EQ(nodal_temperatures(three_nodes(), VecX::Zero(3)).size(), 0);
}

TEST(NodalTemperatures, InitialPlusTheChange) {
  model::Model m = three_nodes();
  m.initial_temperatures = VecX::Constant(3, 20);
  EXPECT_EQ(nodal_temperatures(m, VecX::Zero(3)), VecX::Constant(3, 20));
  const VecX dT = (VecX(3) << 0, 50, 100).finished();
  EXPECT_EQ(nodal_temperatures(m, dT), (VecX(3) << 20, 70, 120).finished());
}

TEST(NodalTemperatures, AStepTemperatureWithoutInitialConditionsStartsFromZero) {
  model::Model m = three_nodes();
  m.steps[1].temperatures = VecX::Constant(3, 300);
  EXPECT_EQ(nodal_temperatures(m, VecX::Constant(3, 150)), VecX::Constant(3, 150));
  EXPECT_EQ(nodal_temperatures(m, VecX::Zero(3)), VecX::Zero(3));  // the first step: none yet
}

// Pressures and body loads with and without amplitudes, several cards sharing one amplitude:
// the shapes scaled by their factors must give what the per-iteration evaluation gives.
TEST(DistributedLoadShapes, EqualTheLoadsEvaluatedAtEveryTime) {
  const model::Model m = inp::read_deck_text(
      testing_decks::cube_model("*ELASTIC\n210000, 0.3\n*DENSITY\n7.8e-9\n") +
          testing_decks::kRollers + R"(*AMPLITUDE, NAME=UP
0, 0, 1, 2
*AMPLITUDE, NAME=SINE, TIME=TOTAL TIME
0, 0, 0.5, 3, 1, -1
*STEP
*STATIC
0.25, 1
*DLOAD
EALL, P2, 5
*DLOAD, AMPLITUDE=UP
EALL, P4, 7
*DLOAD, AMPLITUDE=SINE
EALL, GRAV, 9810, 0.6, 0, -0.8
EALL, CENTRIF, 1e6, 0.2, 0.1, 0, 0, 0, 1
EALL, P6, 2
*DLOAD, AMPLITUDE=UP
EALL, CENTRIF, 3e5, 0, 0, 0, 1, 0, 0
*END STEP
)",
      "cube.inp");
  const model::Step& step = m.steps.front();
  const DistributedLoadShapes shapes = distributed_load_shapes(m, step);
  EXPECT_EQ(shapes.forces.size(), 3u);  // ramp, UP, SINE
  const VecX at_rest = VecX::Zero(3 * m.n_nodes());
  for (const Real t : {0.0, 0.3, 0.7, 1.0}) {
    const Real total = 2 + t, ramp = t;
    const VecX expected = pressure_forces(m, step, t, total, ramp, m.mesh.coords) +
                          body_forces(m, step, t, total, ramp, at_rest);
    const VecX f = distributed_forces(m, shapes, t, total, ramp);
    ASSERT_GT(expected.norm(), 0) << t;
    EXPECT_LT((f - expected).norm(), 1e-12 * expected.norm()) << "t = " << t;
  }
}

}  // namespace
}  // namespace kontakt::analysis

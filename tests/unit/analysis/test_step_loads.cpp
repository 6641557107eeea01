// The nodal temperatures a frame reports (NT in the .frd).
#include "analysis/step_loads.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace kontakt::analysis

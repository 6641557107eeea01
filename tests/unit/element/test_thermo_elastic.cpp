// Temperature-dependent elasticity in every solid kernel: the constants of each integration
// point at its own temperature (initial + change), ccx's thermal strain of a secant table
// measured with ccx 2.20, consistency between the linear, total Lagrangian and plastic kernels,
// and the nonlinear tangents (hardening curves by temperature too) by finite differences and a
// Taylor test.
#include <gtest/gtest.h>

#include "element/solid_plastic.hpp"
#include "element/total_lagrangian.hpp"
#include "element/total_lagrangian_plastic.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

/// The table ccx 2.20 was run with (one C3D8 under a uniaxial 4000 load, tests/peer decks).
ThermoElastic measured_table() {
  ThermoElastic m;
  m.elastic.add(100, {200000, 0.3});
  m.elastic.add(300, {100000, 0.2});
  m.expansion.add(100, {1e-5});
  m.expansion.add(300, {3e-5});
  m.expansion_zero = 50;
  return m;
}

TEST(ThermoElastic, ConstantsAndThermalStrainAsCcx) {
  // ccx 2.20: T0 = 150 -> T = 250 gives exx 3.55e-2, eyy -3.7e-3 under sxx = 4000.
  const PointElastic p = measured_table().at(150, 100);
  EXPECT_DOUBLE_EQ(p.constants.young, 125000);
  EXPECT_DOUBLE_EQ(p.constants.poisson, 0.225);
  EXPECT_NEAR(p.thermal_strain, 3.5e-3, 1e-15);
  EXPECT_NEAR(p.thermal_strain + 4000 / p.constants.young, 3.55e-2, 1e-15);
  // Beyond both ends (T0 = 20, T = 400): the end rows, alpha(T)(T - Z) - alpha(T0)(T0 - Z);
  // ccx: exx 5.08e-2, eyy 2.8e-3.
  const PointElastic q = measured_table().at(20, 380);
  EXPECT_DOUBLE_EQ(q.constants.young, 100000);
  EXPECT_NEAR(q.thermal_strain + 4000 / q.constants.young, 5.08e-2, 1e-15);
  EXPECT_NEAR(q.thermal_strain - 0.2 * 4000 / q.constants.young, 2.8e-3, 1e-15);
}

TEST(ThermoElastic, ConstantMaterialIsAlphaDTWhateverTheInitialTemperature) {
  const ThermoElastic c(LinearElastic{1000, 0.3, 2e-5});
  const PointElastic p = c.at(700, 50);
  EXPECT_EQ(p.constants.young, 1000);
  EXPECT_DOUBLE_EQ(p.thermal_strain, 2e-5 * 50);
  EXPECT_EQ(ThermoElastic(LinearElastic{1000, 0.3, 0}).at(700, 50).thermal_strain, 0);
}

class ThermoElasticKernel : public ::testing::TestWithParam<ElementType> {
 protected:
  ElementType type() const { return GetParam(); }
  MatX3 X() const { return test::distorted_coordinates(volume_topology(type())); }
  /// A temperature field varying over the element (every point sees its own constants).
  VecX field() const {
    const MatX3 x = X();
    VecX dT(x.rows());
    for (Index a = 0; a < x.rows(); ++a) dT[a] = 120 + 60 * x(a, 0) - 35 * x(a, 2) + 10 * x(a, 1);
    return dT;
  }
  /// A table whose stiffness changes strongly over the field; initial temperatures vary too.
  ThermoElastic table(Real expansion = 0) const {
    ThermoElastic m;
    m.elastic.add(0, {1000, 0.3});
    m.elastic.add(200, {400, 0.2});
    if (expansion != 0) {
      m.expansion.add(0, {expansion});
      m.expansion.add(200, {2 * expansion});
      m.expansion_zero = 20;
    }
    const MatX3 x = X();
    m.initial_temperature.resize(x.rows());
    for (Index a = 0; a < x.rows(); ++a) m.initial_temperature[a] = 30 - 10 * x(a, 1);
    return m;
  }
  MatX3 displacement(Real scale) const {
    return test::smooth_displacement(X(), scale);
  }
};

TEST_P(ThermoElasticKernel, UniformTemperatureGivesTheConstantsAtInitialPlusChange) {
  // T0 = 50 everywhere, dT = 100: the constants of T = 150 (E 550, nu 0.225).
  ThermoElastic m = table();
  m.initial_temperature.setConstant(50);
  MatX K, K_const;
  linear_stiffness(type(), X(), m, VecX::Constant(X().rows(), 100), K);
  linear_stiffness(type(), X(), LinearElastic{550, 0.225, 0}, VecX(), K_const);
  EXPECT_LT((K - K_const).norm(), 1e-12 * K_const.norm());
}

TEST_P(ThermoElasticKernel, KernelsAgreeOnTheStiffnessOfAVaryingField) {
  // Without a thermal strain every kernel's tangent at rest is the linear stiffness, and the
  // linear recovery's forces are K u: each evaluates its points at the same temperatures.
  const ThermoElastic m = table();
  const VecX dT = field();
  MatX K;
  linear_stiffness(type(), X(), m, dT, K);
  MatX K_uniform;  // the field must matter, or this test could not fail
  linear_stiffness(type(), X(), m, VecX::Constant(X().rows(), 120), K_uniform);
  EXPECT_GT((K - K_uniform).norm(), 1e-3 * K.norm());

  const MatX3 u = displacement(1e-3);
  IpResults lin;
  recover(type(), X(), m, u, dT, lin);
  EXPECT_LT((lin.internal_force - K * Eigen::Map<const VecX>(u.data(), u.size())).norm(),
            1e-10 * lin.internal_force.norm());

  const MatX3 rest = MatX3::Zero(X().rows(), 3);
  NlgeomResult nl;
  nlgeom_element(type(), X(), m, rest, dT, true, nl);
  EXPECT_LT((nl.tangent - K).norm(), 1e-10 * K.norm());

  const material::HardeningTable hardening{{{1e6, 0.0}}};  // elastic here
  ElementState virgin;
  virgin.points.resize(static_cast<std::size_t>(traits(type()).n_ip));
  PlasticResult pl;
  plastic_element(type(), X(), m, hardening, rest, dT, virgin, true, pl);
  EXPECT_LT((pl.tangent - K).norm(), 1e-10 * K.norm());
  if (type() == ElementType::C3D8R) return;  // its plastic hourglass modulus is C_1111, not E
  NlgeomPlasticResult nlp;
  nlgeom_plastic_element(type(), X(), m, hardening, rest, dT, virgin, true, nlp,
                         PlasticTangent::exact);
  EXPECT_LT((nlp.tangent - K).norm(), 1e-8 * K.norm());
}

TEST_P(ThermoElasticKernel, ThermalLoadIsWhatRecoveryReportsAtRest) {
  // At u = 0 the element force of the recovery is minus the thermal load, stress -D eps_th.
  const ThermoElastic m = table(1e-4);
  const VecX dT = field();
  VecX f;
  thermal_load(type(), X(), m, dT, f);
  IpResults r;
  recover(type(), X(), m, MatX3::Zero(X().rows(), 3), dT, r);
  EXPECT_GT(f.norm(), 0);
  EXPECT_LT((r.internal_force + f).norm(), 1e-10 * f.norm());
}

TEST_P(ThermoElasticKernel, TotalLagrangianTangentMatchesCentralDifferences) {
  const ThermoElastic m = table(2e-4);
  const VecX dT = field();
  auto forces = [&](const MatX3& v) {
    NlgeomResult r;
    nlgeom_element(type(), X(), m, v, dT, false, r);
    return r.internal_force;
  };
  const MatX3 u = displacement(1);
  NlgeomResult r;
  nlgeom_element(type(), X(), m, u, dT, true, r);
  EXPECT_LT((test::fd_jacobian(forces, u) - r.tangent).norm(), 1e-6 * r.tangent.norm());
  for (Real order : test::taylor_orders(forces, u, r.tangent, 0.05)) EXPECT_GT(order, 1.9);
}

TEST_P(ThermoElasticKernel, PlasticTangentsMatchCentralDifferences) {
  // Yield 1.5..2 against stresses of order E * 1e-2 = 4..10: every point yields, each on the
  // hardening curve of its temperature (50..250: between and beyond the two curves).
  const ThermoElastic m = table(1e-4);
  const VecX dT = field();
  material::HardeningCurves hardening;
  hardening.temperatures = {100, 200};
  hardening.curves = {material::HardeningTable{{{2.0, 0.0}, {3.0, 0.05}}},
                      material::HardeningTable{{{1.5, 0.0}, {2.0, 0.03}, {2.2, 0.1}}}};
  ElementState virgin;
  virgin.points.resize(static_cast<std::size_t>(traits(type()).n_ip));
  const MatX3 u = displacement(0.1);
  auto small_forces = [&](const MatX3& v) {
    PlasticResult r;
    plastic_element(type(), X(), m, hardening, v, dT, virgin, false, r);
    return r.internal_force;
  };
  PlasticResult small;
  plastic_element(type(), X(), m, hardening, u, dT, virgin, true, small);
  ASSERT_GT(small.peeq.minCoeff(), 0);  // every point: no kink in the differences
  EXPECT_LT((test::fd_jacobian(small_forces, u) - small.tangent).norm(),
            1e-6 * small.tangent.norm());
  for (Real order : test::taylor_orders(small_forces, u, small.tangent, 1e-4))
    EXPECT_GT(order, 1.9);

  auto finite_forces = [&](const MatX3& v) {
    NlgeomPlasticResult r;
    nlgeom_plastic_element(type(), X(), m, hardening, v, dT, virgin, false, r,
                           PlasticTangent::exact);
    return r.internal_force;
  };
  NlgeomPlasticResult finite;
  nlgeom_plastic_element(type(), X(), m, hardening, u, dT, virgin, true, finite,
                         PlasticTangent::exact);
  ASSERT_GT(finite.peeq.minCoeff(), 0);
  EXPECT_LT((test::fd_jacobian(finite_forces, u) - finite.tangent).norm(),
            1e-6 * finite.tangent.norm());
  for (Real order : test::taylor_orders(finite_forces, u, finite.tangent, 1e-4))
    EXPECT_GT(order, 1.9);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, ThermoElasticKernel, ::testing::ValuesIn(test::kAllTypes),
                         [](const auto& info) { return std::string(traits(info.param).name); });

}  // namespace
}  // namespace kontakt::element

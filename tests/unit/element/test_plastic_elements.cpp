// Elastic-plastic element kernels, every element type: finite-strain J2 under NLGEOM
// (total_lagrangian_plastic) and small-strain J2 (solid_plastic). Tangents against central
// differences and a Taylor test in plastic loading, elastic unloading and with a thermal
// strain; the elastic limit against the linear stiffness; objectivity; C3D8I's condensed modes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "element/solid_kernels.hpp"
#include "element/solid_plastic.hpp"
#include "element/total_lagrangian.hpp"
#include "element/total_lagrangian_plastic.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

using material::HardeningTable;
using material::J2State;
using States = ElementState;

// Yield strain 2e-3 against strains of several percent: every point yields.
const LinearElastic kMat{1000.0, 0.3, 0.0};
const HardeningTable kTable{{{2.0, 0.0}, {2.5, 0.02}, {2.6, 0.2}}};

class PlasticElements : public ::testing::TestWithParam<ElementType> {
 protected:
  ElementType type() const { return GetParam(); }
  MatX3 X() const { return test::distorted_coordinates(volume_topology(type())); }
  /// A smooth displacement field with strains of a few percent, scaled by s.
  MatX3 displacement(Real s = 1) const {
    const MatX3 x = X();
    MatX3 u(x.rows(), 3);
    for (Index a = 0; a < x.rows(); ++a)
      u.row(a) << 0.04 * x(a, 1) + 0.02 * x(a, 0) * x(a, 2), -0.03 * x(a, 2) + 0.015 * x(a, 0),
          0.05 * x(a, 0) - 0.02 * x(a, 1) * x(a, 1);
    return s * u;
  }
};

/// The virgin state of an element of `type`.
States virgin(ElementType type) {
  States s;
  s.points.resize(static_cast<std::size_t>(traits(type).n_ip));
  return s;
}

/// Forces, tangent and states of the NLGEOM kernel.
NlgeomPlasticResult nlgeom(ElementType type, const MatX3& x, const MatX3& u, const States& s,
                           const VecX& dT = VecX(), const LinearElastic& mat = kMat) {
  NlgeomPlasticResult r;
  nlgeom_plastic_element(type, x, mat, kTable, u, dT, s, true, r, PlasticTangent::exact);
  return r;
}

PlasticResult small(ElementType type, const MatX3& x, const MatX3& u, const States& s) {
  PlasticResult r;
  plastic_element(type, x, kMat, kTable, u, VecX(), s, true, r);
  return r;
}

void expect_exact_tangent(const test::ForceFunction& forces, const MatX3& u, const MatX& K) {
  EXPECT_LT((test::fd_jacobian(forces, u) - K).norm(), 1e-6 * K.norm());
  for (Real order : test::taylor_orders(forces, u, K, 1e-4)) EXPECT_GT(order, 1.9);
}

/// The same where f is linear (small-strain elastic unloading): no quadratic remainder to
/// observe, so the remainder must be round-off.
void expect_exact_linear_tangent(const test::ForceFunction& forces, const MatX3& u, const MatX& K) {
  EXPECT_LT((test::fd_jacobian(forces, u) - K).norm(), 1e-6 * K.norm());
  for (Real r : test::taylor_remainders(forces, u, K, 1e-4)) EXPECT_LT(r, 1e-12 * forces(u).norm());
}

TEST_P(PlasticElements, ElasticLimitIsTheLinearStiffness) {
  const MatX3 x = X();
  const States s = virgin(type());
  MatX K;
  linear_stiffness(type(), x, kMat, VecX(), K);
  MatX K_nlgeom = K;
  if (type() == ElementType::C3D8R) {
    // ccx scales a *PLASTIC material's hourglass stiffness with C_1111 (lambda + 2 mu at
    // rest), a linear elastic one's with E.
    const Real nu = kMat.poisson, c1111 = kMat.young * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    MatX unit;
    hourglass_stiffness(x, 1.0, unit);
    K_nlgeom += (c1111 - kMat.young) * unit;
  }
  const MatX3 tiny = displacement(1e-6);  // far below yield
  const NlgeomPlasticResult r = nlgeom(type(), x, tiny, s);
  EXPECT_LT((r.tangent - K_nlgeom).norm(), 1e-5 * K.norm());
  EXPECT_EQ(r.peeq.maxCoeff(), 0.0);
  const PlasticResult q = small(type(), x, tiny, s);
  EXPECT_LT((q.tangent - K).norm(), 1e-10 * K.norm());
}

TEST_P(PlasticElements, NlgeomTangentIsExactInPlasticLoading) {
  const MatX3 x = X(), u = displacement();
  const States s = virgin(type());
  const NlgeomPlasticResult r = nlgeom(type(), x, u, s);
  ASSERT_GT(r.peeq.minCoeff(), 0.0);  // every point yields
  expect_exact_tangent([&](const MatX3& v) { return nlgeom(type(), x, v, s).internal_force; }, u,
                       r.tangent);
}

TEST_P(PlasticElements, NlgeomTangentIsExactFromAPlasticState) {
  // Commit a plastic state, then load on (plastic) and reverse a little (elastic unloading).
  const MatX3 x = X();
  const States s0 = virgin(type());
  const States committed = nlgeom(type(), x, displacement(), s0).state;
  for (Real scale : {1.15, 0.97}) {
    const MatX3 u = displacement(scale);
    const NlgeomPlasticResult r = nlgeom(type(), x, u, committed);
    const bool loading = scale > 1;
    for (Index k = 0; k < r.peeq.size(); ++k) {
      if (loading) {
        EXPECT_GT(r.peeq(k), committed.points[k].equivalent_plastic_strain);
      } else {
        EXPECT_EQ(r.peeq(k), committed.points[k].equivalent_plastic_strain);
      }
    }
    expect_exact_tangent(
        [&](const MatX3& v) { return nlgeom(type(), x, v, committed).internal_force; }, u, r.tangent);
  }
}

TEST_P(PlasticElements, NlgeomTangentIsExactWithAThermalStrain) {
  const MatX3 x = X(), u = displacement();
  VecX dT(x.rows());
  for (Index a = 0; a < x.rows(); ++a) dT[a] = 100 + 40 * x(a, 0) - 25 * x(a, 2);
  const LinearElastic heated{1000.0, 0.3, 1e-4};
  const States s = virgin(type());
  const NlgeomPlasticResult r = nlgeom(type(), x, u, s, dT, heated);
  ASSERT_GT(r.peeq.maxCoeff(), 0.0);
  expect_exact_tangent(
      [&](const MatX3& v) { return nlgeom(type(), x, v, s, dT, heated).internal_force; }, u,
      r.tangent);
}

TEST_P(PlasticElements, RotatingAPlasticStateRotatesItsCauchyStress) {
  const MatX3 x = X(), u = displacement();
  const NlgeomPlasticResult loaded = nlgeom(type(), x, u, virgin(type()));
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  MatX3 ur(x.rows(), 3);
  for (Index a = 0; a < x.rows(); ++a)
    ur.row(a) = (R * (x.row(a) + u.row(a)).transpose()).transpose() - x.row(a);
  const NlgeomPlasticResult r = nlgeom(type(), x, ur, loaded.state);  // elastic: same state
  for (Index k = 0; k < r.cauchy.rows(); ++k) {
    auto t = [](const auto& v) {
      Mat3 m;
      m << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
      return m;
    };
    const Mat3 expected = R * t(loaded.cauchy.row(k)) * R.transpose();
    EXPECT_LT((t(r.cauchy.row(k)) - expected).norm(), 1e-9 * expected.norm()) << "point " << k;
    EXPECT_EQ(r.peeq(k), loaded.peeq(k));
  }
}

TEST_P(PlasticElements, SmallStrainTangentIsExactInPlasticLoadingAndUnloading) {
  const MatX3 x = X();
  const States s0 = virgin(type());
  const PlasticResult first = small(type(), x, displacement(), s0);
  ASSERT_GT(first.peeq.minCoeff(), 0.0);
  expect_exact_tangent([&](const MatX3& v) { return small(type(), x, v, s0).internal_force; },
                       displacement(), first.tangent);
  auto forces = [&](const MatX3& v) { return small(type(), x, v, first.state).internal_force; };
  const MatX3 further = displacement(1.15), back = displacement(0.97);
  expect_exact_tangent(forces, further, small(type(), x, further, first.state).tangent);
  const PlasticResult unloading = small(type(), x, back, first.state);
  EXPECT_EQ(unloading.peeq, first.peeq);
  expect_exact_linear_tangent(forces, back, unloading.tangent);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, PlasticElements, ::testing::ValuesIn(test::kAllTypes),
                         [](const auto& info) { return std::string(traits(info.param).name); });

TEST(HourglassControlNonlinear, PlasticMaterialScalesWithItsTangentAsCcx) {
  // A unit-cube C3D8R in a pure hourglass mode u_x = a xi eta (all nodes prescribed), measured
  // with ccx 2.20 (E = 210000, nu = 0.3, a = 1e-4, NLGEOM): reaction 0.126 per node for
  // *ELASTIC, 0.1696154 with *PLASTIC (lambda + 2 mu in place of E), 0.1622 after a 1 %
  // stretch along x and 0.1007 once that stretch yields (yield 250), in the one increment.
  const MatX3 X = test::reference_coordinates(Topology::Hex8) * 0.5 + MatX3::Constant(8, 3, 0.5);
  auto reaction = [&](bool plastic, Real stretch, Real yield, Real a) {
    MatX3 u = MatX3::Zero(8, 3);
    for (Index n = 0; n < 8; ++n) {
      const Vec3 xi = reference_node(Topology::Hex8, static_cast<int>(n));
      u(n, 0) = a * xi(0) * xi(1) + stretch * X(n, 0);
    }
    const LinearElastic mat{210000.0, 0.3, 0.0};
    if (!plastic) {
      NlgeomResult r;
      nlgeom_element(ElementType::C3D8R, X, mat, u, VecX(), false, r);
      return r.internal_force[0];
    }
    NlgeomPlasticResult r;
    nlgeom_plastic_element(ElementType::C3D8R, X, mat, HardeningTable{{{yield, 0.0}}}, u, VecX(),
                           virgin(ElementType::C3D8R), false, r);
    return r.internal_force[0];
  };
  auto hourglass_part = [&](bool plastic, Real stretch, Real yield) {
    return reaction(plastic, stretch, yield, 1e-4) - reaction(plastic, stretch, yield, 0.0);
  };
  EXPECT_NEAR(hourglass_part(false, 0.0, 0), 0.126, 5e-7);
  EXPECT_NEAR(hourglass_part(true, 0.0, 1e6), 0.1696154, 5e-7);
  EXPECT_NEAR(hourglass_part(true, 0.01, 1e6), 0.1622, 5e-4);
  EXPECT_NEAR(hourglass_part(true, 0.01, 250), 0.1007, 5e-4);
}

TEST(IncompatibleModesNonlinear, CondensedModesCarryNoForce) {
  // The forces of the condensed element are those of the 33-dof element at the modes'
  // equilibrium: nodal forces balance (a free element is in equilibrium with itself) and a
  // bending field is far softer than with C3D8 (the modes' purpose).
  const MatX3 x = test::distorted_coordinates(Topology::Hex8);
  MatX3 u(8, 3);
  for (Index a = 0; a < 8; ++a)  // pure bending, below yield
    u.row(a) << 3e-5 * x(a, 0) * x(a, 1), 0.0, -1.5e-5 * x(a, 0) * x(a, 0);
  const States s = virgin(ElementType::C3D8I);
  const NlgeomPlasticResult i = nlgeom(ElementType::C3D8I, x, u, s);
  const NlgeomPlasticResult b = nlgeom(ElementType::C3D8, x, u, virgin(ElementType::C3D8));
  Vec3 sum = Vec3::Zero();
  for (Index a = 0; a < 8; ++a) sum += i.internal_force.segment<3>(3 * a);
  EXPECT_LT(sum.norm(), 1e-10 * i.internal_force.norm());
  EXPECT_LT(i.internal_force.norm(), 0.7 * b.internal_force.norm());
}

}  // namespace
}  // namespace kontakt::element

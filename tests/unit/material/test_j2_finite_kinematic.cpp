// Tests for finite-strain kinematic / combined J2 (solver/material/j2_finite_kinematic): with a
// flat kinematic curve it is the isotropic finite-strain model; in the small-strain limit the
// small-strain kinematic kernel; the Bauschinger effect of a moving yield surface; the exact
// tangent against central differences (elastic, plastic across a row, combined). Against
// ccx 2.20: the suite's beampkin, beampd and beampik in tests/peer/coverage_baseline.txt.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "material/j2_finite_kinematic.hpp"
#include "material/j2_finite_strain.hpp"
#include "material/j2_kinematic.hpp"
#include "material/symmetric_voigt.hpp"

// A namespace of its own: the helpers' names recur in the other material tests.
namespace kontakt::material::test_j2_finite_kinematic {
namespace {

constexpr Real kE = 210000.0;
constexpr Real kNu = 0.3;

const HardeningTable kKinematic{{{800.0, 0.0}, {1200.0, 0.02}, {1400.0, 0.1}}};
const HardeningTable kCyclic{{{800.0, 0.0}, {900.0, 0.05}}};

Mat3 stretch(Real axial, Real shear = 0) {
  Mat3 F = Mat3::Identity();
  F(0, 0) += axial;
  F(1, 1) -= 0.5 * axial;
  F(2, 2) -= 0.5 * axial;
  F(0, 1) = shear;
  return F;
}

Mat3 right_cauchy_green(const Mat3& F) { return F.transpose() * F; }

Mat3 perturbed(const Mat3& C, int j, Real h) {
  static constexpr int kI[6] = {0, 1, 2, 0, 0, 1}, kJ[6] = {0, 1, 2, 1, 2, 2};
  Mat3 c = C;
  if (j < 3) {
    c(j, j) += 2 * h;
  } else {
    c(kI[j], kJ[j]) += h;
    c(kJ[j], kI[j]) += h;
  }
  return c;
}

/// Cauchy xx minus yy stress of S at F: the signed von Mises stress of an axisymmetric state.
Real axial_difference(const Mat3& F, const Vec6& S) {
  Mat3 s;
  s << S[0], S[3], S[4], S[3], S[1], S[5], S[4], S[5], S[2];
  const Mat3 sigma = F * s * F.transpose() / F.determinant();
  return sigma(0, 0) - sigma(1, 1);
}

/// Commits `n` steps from the state's F to F1 (straight in F).
J2FiniteKinematicResult walk(const HardeningTable* cyclic, J2KinematicState& state, const Mat3& F0,
                             const Mat3& F1, int n) {
  J2FiniteKinematicResult r;
  for (int k = 1; k <= n; ++k) {
    const Mat3 F = F0 + (F1 - F0) * (static_cast<Real>(k) / n);
    r = j2_finite_kinematic(kE, kNu, kKinematic, cyclic, state, right_cauchy_green(F));
    state = r.state;
  }
  return r;
}

TEST(J2FiniteKinematic, AFlatKinematicCurveIsTheIsotropicModel) {
  const HardeningTable flat{{{800.0, 0.0}}};
  J2KinematicState kin;
  J2State iso;
  for (const Mat3& F : {stretch(0.01), stretch(0.02, 0.01), stretch(0.005, 0.03)}) {
    const Mat3 C = right_cauchy_green(F);
    const auto k = j2_finite_kinematic(kE, kNu, flat, nullptr, kin, C);
    const auto i = j2_finite_strain(kE, kNu, flat, iso, C);
    EXPECT_TRUE(k.yielded);
    EXPECT_NEAR((k.stress - i.stress).norm(), 0, 1e-9 * i.stress.norm());
    EXPECT_NEAR((k.state.plastic_strain - i.state.plastic_strain).norm(), 0, 1e-12);
    EXPECT_NEAR(k.state.back_stress.norm(), 0, 1e-12);
    kin = k.state;
    iso = i.state;
  }
}

TEST(J2FiniteKinematic, SmallStrainsGiveTheSmallStrainKernel) {
  J2KinematicState finite, small;
  for (const Real a : {0.003, 0.006, 0.009}) {  // yield at about 0.0038
    const Mat3 F = stretch(a, 0.3 * a);
    const Mat3 E = 0.5 * (right_cauchy_green(F) - Mat3::Identity());
    Vec6 eng;
    eng << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(0, 2), 2 * E(1, 2);
    const auto f = j2_finite_kinematic(kE, kNu, kKinematic, nullptr, finite, right_cauchy_green(F));
    const auto s = j2_kinematic_return_map(kE, kNu, kKinematic, nullptr, small, eng);
    // The deviators (the volume change of Green's strain differs from the small one by
    // O(a^2), which the bulk modulus turns into some 10 MPa of pressure at a = 0.009).
    EXPECT_NEAR((deviator(f.stress) - deviator(s.stress)).norm(), 0,
                1.5e-2 * deviator(s.stress).norm())
        << a;
    EXPECT_NEAR(f.state.equivalent_plastic_strain, s.state.equivalent_plastic_strain, 5e-5) << a;
    EXPECT_NEAR((f.state.back_stress - s.state.back_stress).norm(), 0,
                3e-2 * (1 + s.state.back_stress.norm()))
        << a;
    finite = f.state;
    small = s.state;
  }
}

TEST(J2FiniteKinematic, TheYieldSurfaceMovesReverseYieldComesEarly) {
  J2KinematicState state;
  const auto loaded = walk(nullptr, state, Mat3::Identity(), stretch(0.02), 20);
  const Real peak = axial_difference(stretch(0.02), loaded.stress);
  EXPECT_GT(peak, 900.0);  // hardened beyond the first yield of 800
  // Back along the path: the reverse yield comes when the stress has dropped by 2 x 800
  // (the surface keeps its size and moved), long before -peak.
  Real reverse_yield = 0;
  J2KinematicState s = state;
  for (int k = 1; k <= 200 && reverse_yield == 0; ++k) {
    const Mat3 F = stretch(0.02 - 0.03 * k / 200.0);
    const auto r = j2_finite_kinematic(kE, kNu, kKinematic, nullptr, s, right_cauchy_green(F));
    if (r.yielded) reverse_yield = axial_difference(F, r.stress);
    s = r.state;
  }
  EXPECT_NEAR(peak - reverse_yield, 2 * 800.0, 0.02 * 1600.0);
}

TEST(J2FiniteKinematic, TangentIsTheDerivativeOfTheStress) {
  for (const HardeningTable* cyclic : {static_cast<const HardeningTable*>(nullptr), &kCyclic}) {
    J2KinematicState state;
    walk(cyclic, state, Mat3::Identity(), stretch(0.015, 0.004), 6);
    // Elastic unloading, plastic loading, plastic loading across the row at 0.02.
    for (const Mat3& F : {stretch(0.012, 0.004), stretch(0.018, 0.006), stretch(0.04, 0.01)}) {
      const Mat3 C = right_cauchy_green(F);
      const auto r = j2_finite_kinematic(kE, kNu, kKinematic, cyclic, state, C);
      Mat6 fd;
      const Real h = 1e-8;
      for (int j = 0; j < 6; ++j)
        fd.col(j) =
            (j2_finite_kinematic(kE, kNu, kKinematic, cyclic, state, perturbed(C, j, h)).stress -
             j2_finite_kinematic(kE, kNu, kKinematic, cyclic, state, perturbed(C, j, -h)).stress) /
            (2 * h);
      EXPECT_LT((r.tangent - fd).cwiseAbs().maxCoeff(), 1e-5 * fd.cwiseAbs().maxCoeff())
          << (cyclic ? "combined" : "kinematic") << " yielded " << r.yielded;
    }
  }
}

}  // namespace
}  // namespace kontakt::material::test_j2_finite_kinematic

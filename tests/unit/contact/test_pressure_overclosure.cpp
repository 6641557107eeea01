#include <gtest/gtest.h>

#include <cmath>

#include "contact/pressure_overclosure.hpp"

using namespace kontakt;
using namespace kontakt::contact;

namespace {

model::SurfaceBehavior linear(Real K, Real sigma) {
  model::SurfaceBehavior b;
  b.stiffness = K;
  b.tension_limit = sigma;
  return b;
}

/// Central differences of pressure (-> slope) and energy (-> pressure).
void expect_consistent(const PressureLaw& law, Real d, Real h) {
  const auto r = pressure_overclosure(law, d), rp = pressure_overclosure(law, d + h),
             rm = pressure_overclosure(law, d - h);
  const Real scale = std::abs(r.pressure) + std::abs(r.slope) * h + 1e-12;
  EXPECT_NEAR((rp.pressure - rm.pressure) / (2 * h), r.slope, 1e-5 * (std::abs(r.slope) + 1))
      << "d = " << d;
  EXPECT_NEAR((rp.energy - rm.energy) / (2 * h), r.pressure, 1e-4 * scale) << "d = " << d;
}

}  // namespace

TEST(PressureOverclosure, QuasiBilinearMatchesCcxValue) {
  // ccx 2.20 on friction1: g = -1.3634e-5, K = 1e7, sigma_inf = 3 gives p = 133.35.
  const PressureLaw law = make_pressure_law(linear(1e7, 3), /*linear_variant=*/false);
  EXPECT_EQ(law.kind, PressureLaw::Kind::QuasiBilinear);
  EXPECT_NEAR(pressure_overclosure(law, 1.3634e-5).pressure, 133.35, 0.01);
  // Tension tends to -sigma_inf far from contact.
  EXPECT_NEAR(pressure_overclosure(law, -1.0).pressure, -3, 1e-3);
  for (Real d : {-1e-5, -1e-6, 0.0, 1e-7, 2e-6, 1e-4}) expect_consistent(law, d, 1e-10);
}

TEST(PressureOverclosure, LinearVariantIsTrulyLinear) {
  const PressureLaw law = make_pressure_law(linear(1e7, 3), /*linear_variant=*/true);
  EXPECT_EQ(law.kind, PressureLaw::Kind::Linear);
  EXPECT_EQ(pressure_overclosure(law, -1e-3).pressure, 0);
  EXPECT_DOUBLE_EQ(pressure_overclosure(law, 2e-5).pressure, 200);
  EXPECT_DOUBLE_EQ(pressure_overclosure(law, 2e-5).slope, 1e7);
  EXPECT_TRUE(is_active(law, 0, 0));
  EXPECT_DOUBLE_EQ(pressure_overclosure(law, 0).slope, 1e7);  // touching carries stiffness
  EXPECT_FALSE(is_active(law, -1e-12, 1.0));
}

TEST(PressureOverclosure, ExponentialTabularTied) {
  model::SurfaceBehavior e;
  e.law = model::SurfaceBehavior::Law::Exponential;
  e.exp_c0 = 1e-3;
  e.exp_p0 = 5;
  const PressureLaw ex = make_pressure_law(e, false);
  EXPECT_NEAR(pressure_overclosure(ex, 0).pressure, 5, 1e-12);
  EXPECT_NEAR(pressure_overclosure(ex, -1e-3).pressure, 0.05, 1e-12);  // 1 % at g = c0
  for (Real d : {-1e-3, 0.0, 5e-3, 0.02}) expect_consistent(ex, d, 1e-9);
  const Real big = pressure_overclosure(ex, 1.0).pressure;  // beyond the cap: finite, linear
  EXPECT_TRUE(std::isfinite(big));
  expect_consistent(ex, 1.0, 1e-7);
  EXPECT_TRUE(is_active(ex, -0.9e-3, creation_clearance(e, 1)));
  EXPECT_FALSE(is_active(ex, -1.1e-3, creation_clearance(e, 1)));

  model::SurfaceBehavior t;
  t.law = model::SurfaceBehavior::Law::Tabular;
  t.table = {{0, 0}, {1e-3, 10}, {2e-3, 30}};
  const PressureLaw tab = make_pressure_law(t, false);
  EXPECT_NEAR(pressure_overclosure(tab, 1.5e-3).pressure, 20, 1e-12);
  EXPECT_NEAR(pressure_overclosure(tab, 5e-3).pressure, 30, 1e-12);
  EXPECT_NEAR(pressure_overclosure(tab, 1.5e-3).slope, 2e4, 1e-6);
  for (Real d : {5e-4, 1.5e-3, 3e-3}) expect_consistent(tab, d, 1e-8);

  model::SurfaceBehavior tied = linear(1e6, 0);
  tied.law = model::SurfaceBehavior::Law::Tied;
  const PressureLaw ti = make_pressure_law(tied, true);
  EXPECT_DOUBLE_EQ(pressure_overclosure(ti, -1e-4).pressure, -100);
  EXPECT_TRUE(is_active(ti, -10, 0));
}

TEST(PressureOverclosure, CreationClearanceAsCcx) {
  model::SurfaceBehavior b = linear(1e7, 3);
  b.clearance_c0 = 1e-3;
  EXPECT_NEAR(creation_clearance(b, 4.0), 2e-3, 1e-15);
  EXPECT_NEAR(creation_clearance(b, 0.0), 1e-10, 1e-20);
}

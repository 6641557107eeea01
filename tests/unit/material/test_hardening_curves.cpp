// HardeningCurves: the yield stress at a given plastic strain linear in temperature between the
// neighbouring curves, the end curves beyond (ccx 2.20, measured on one C3D8 in uniaxial
// tension: a deck with the two curves below at 573 gives the same stresses to all printed
// digits as one with the single curve `expected_at_573`, and not as the row-by-row average).
#include "material/hardening_curves.hpp"

#include <gtest/gtest.h>

namespace kontakt::material {
namespace {

HardeningCurves curves() {
  HardeningCurves c;
  c.temperatures = {273, 873};
  c.curves = {HardeningTable{{{800, 0}, {900, 0.05}, {1000, 0.15}}},
              HardeningTable{{{700, 0}, {750, 0.04}, {800, 0.13}}}};
  return c;
}

TEST(HardeningCurves, InterpolatedAtTheSamePlasticStrain) {
  const HardeningTable expected_at_573{
      {{750, 0}, {815, 0.04}, {827.7777777777778, 0.05}, {890, 0.13}, {900, 0.15}}};
  HardeningTable scratch;
  const HardeningTable& at = curves().at(573, scratch);
  ASSERT_EQ(at.points.size(), expected_at_573.points.size());
  for (std::size_t k = 0; k < at.points.size(); ++k) {
    EXPECT_DOUBLE_EQ(at.points[k].first, expected_at_573.points[k].first) << k;
    EXPECT_DOUBLE_EQ(at.points[k].second, expected_at_573.points[k].second) << k;
  }
  for (Real e : {0.0, 0.01, 0.045, 0.1, 0.14, 0.3})  // linear in T at every plastic strain
    EXPECT_NEAR(at.yield(e), 0.5 * (curves().curves[0].yield(e) + curves().curves[1].yield(e)),
                1e-12)
        << e;
}

TEST(HardeningCurves, EndCurvesBeyondTheTableAndRowsExactly) {
  HardeningTable scratch;
  const HardeningCurves c = curves();
  EXPECT_EQ(&c.at(100, scratch), &c.curves[0]);  // ccx: the 273 curve at 100 (measured)
  EXPECT_EQ(&c.at(273, scratch), &c.curves[0]);
  EXPECT_EQ(&c.at(873, scratch), &c.curves[1]);
  EXPECT_EQ(&c.at(2000, scratch), &c.curves[1]);
}

TEST(HardeningCurves, OneCurveIsTheSameAtEveryTemperature) {
  const HardeningCurves c(HardeningTable{{{250, 0}, {300, 0.1}}});
  HardeningTable scratch;
  EXPECT_EQ(&c.at(-50, scratch), &c.curves[0]);
  EXPECT_EQ(&c.at(5000, scratch), &c.curves[0]);
}

}  // namespace
}  // namespace kontakt::material

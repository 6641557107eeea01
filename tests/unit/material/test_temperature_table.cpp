// TemperatureTable: linear in temperature between rows, the end rows beyond the table (what
// ccx 2.20 does, measured on one-element decks; tests/peer/make_material_decks.py).
#include "material/temperature_table.hpp"

#include <gtest/gtest.h>

namespace kontakt::material {
namespace {

TemperatureTable<2> table() {
  TemperatureTable<2> t;
  t.add(100, {200000, 0.3});
  t.add(300, {100000, 0.2});
  t.add(500, {50000, 0.2});
  return t;
}

TEST(TemperatureTable, LinearBetweenRows) {
  const auto r = table().at(250);
  EXPECT_DOUBLE_EQ(r[0], 125000);
  EXPECT_DOUBLE_EQ(r[1], 0.225);
  EXPECT_DOUBLE_EQ(table().at(400)[0], 75000);  // the second interval
}

TEST(TemperatureTable, RowsAreHitExactly) {
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(table().at(table().temperatures[k]), table().rows[k]) << k;
}

TEST(TemperatureTable, EndRowsHoldBeyondTheTable) {
  EXPECT_EQ(table().at(-1e6), table().rows.front());
  EXPECT_EQ(table().at(20), table().rows.front());
  EXPECT_EQ(table().at(900), table().rows.back());
}

TEST(TemperatureTable, OneRowIsAConstantWhateverItsTemperature) {
  TemperatureTable<1> t;
  t.add(700, {1.2e-5});
  EXPECT_EQ(t.at(-300)[0], 1.2e-5);
  EXPECT_EQ(t.at(2000)[0], 1.2e-5);
}

}  // namespace
}  // namespace kontakt::material

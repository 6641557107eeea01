// Material constants tabulated against temperature (*ELASTIC, *EXPANSION, *DENSITY with a
// temperature column), evaluated as ccx 2.20 does: linear in temperature between rows, the end
// row's values beyond either end of the table.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace kontakt::material {

/// N constants per row, one row per temperature, temperatures strictly ascending. A single row
/// is a constant (its temperature is irrelevant).
template <std::size_t N>
struct TemperatureTable {
  using Row = std::array<Real, N>;
  std::vector<Real> temperatures;
  std::vector<Row> rows;

  bool empty() const { return rows.empty(); }
  /// Appends a row; the caller (the deck reader) checks that temperatures ascend.
  void add(Real temperature, const Row& row) {
    temperatures.push_back(temperature);
    rows.push_back(row);
  }
  /// The constants at temperature T; the table must not be empty.
  Row at(Real T) const {
    if (rows.size() == 1 || T <= temperatures.front()) return rows.front();
    if (T >= temperatures.back()) return rows.back();
    std::size_t k = 1;
    while (temperatures[k] < T) ++k;
    const Real s = (T - temperatures[k - 1]) / (temperatures[k] - temperatures[k - 1]);
    Row r;
    for (std::size_t i = 0; i < N; ++i) r[i] = rows[k - 1][i] + s * (rows[k][i] - rows[k - 1][i]);
    return r;
  }
};

}  // namespace kontakt::material

#include "model/model.hpp"

#include <algorithm>

namespace kontakt::model {

Real Amplitude::value_at(Real time) const {
  if (points.empty()) return 1;
  if (time <= points.front().first) return points.front().second;
  if (time >= points.back().first) return points.back().second;
  auto hi = std::upper_bound(points.begin(), points.end(), time,
                             [](Real t, const auto& p) { return t < p.first; });
  auto lo = hi - 1;
  const Real span = hi->first - lo->first;
  if (span <= 0) return hi->second;
  return lo->second + (hi->second - lo->second) * (time - lo->first) / span;
}

}  // namespace kontakt::model

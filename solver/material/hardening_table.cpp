#include "material/hardening_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace kontakt::material {

void HardeningTable::validate() const {
  if (points.empty())
    throw std::invalid_argument("*PLASTIC: hardening table has no data lines");
  if (points.front().second != 0.0)
    throw std::invalid_argument(
        "*PLASTIC: the first data line must be at equivalent plastic strain 0 (initial yield)");
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto [s, e] = points[k];
    if (!std::isfinite(s) || !std::isfinite(e) || s < 0.0)
      throw std::invalid_argument("*PLASTIC: data line " + std::to_string(k + 1) +
                                  ": yield stress must be finite and >= 0");
    if (k > 0 && !(e > points[k - 1].second))
      throw std::invalid_argument("*PLASTIC: data line " + std::to_string(k + 1) +
                                  ": equivalent plastic strain must be strictly ascending");
  }
}

std::size_t HardeningTable::segment(Real alpha) const {
  // First row whose plastic strain exceeds alpha; the segment starts one row before.
  const auto it = std::upper_bound(points.begin(), points.end(), alpha,
                                   [](Real a, const std::pair<Real, Real>& p) { return a < p.second; });
  if (it == points.begin()) return 0;  // alpha < 0: clamp to the first segment
  return static_cast<std::size_t>(it - points.begin()) - 1;
}

HardeningPiece HardeningTable::piece(std::size_t k) const {
  if (k + 1 >= points.size()) return {points.back().first, points.back().second, 0.0};
  const auto& [y0, a0] = points[k];
  const auto& [y1, a1] = points[k + 1];
  return {y0, a0, (y1 - y0) / (a1 - a0), a1};
}

Real HardeningTable::yield(Real alpha) const {
  if (alpha <= points.front().second) return points.front().first;
  return piece(segment(alpha)).at(alpha);
}

Real HardeningTable::slope(Real alpha) const { return piece(segment(alpha)).slope; }

RadialReturn solve_radial_return(const HardeningTable& table, Real alpha_n, Real q_trial,
                                 Real shear_modulus) {
  // r(da) = q_trial - 3 G da - yield(alpha_n + da) is piecewise linear and strictly
  // decreasing (3G + H > 0 is required), so a Newton step is exact on one segment. A step that
  // leaves the current segment stops at the breakpoint and the walk continues with the next
  // segment's slope; it ends on the segment holding the unique root.
  const Real g3 = 3.0 * shear_modulus;
  std::size_t k = table.segment(alpha_n);
  Real da = 0.0;
  const Real scale = std::max(q_trial, table.yield(alpha_n));
  const int max_iter = static_cast<int>(table.points.size()) + 20;
  for (int it = 0; it < max_iter; ++it) {
    const HardeningPiece segment = table.piece(k);
    const Real h = segment.slope;
    if (!(g3 + h > 0.0))
      throw std::invalid_argument(
          "*PLASTIC: softening slope steeper than -3G makes the return mapping ill-posed");
    const Real r = q_trial - g3 * da - segment.at(alpha_n + da);
    if (std::abs(r) <= 1e-13 * scale && it > 0) return {da, h};
    const Real next = da + r / (g3 + h);
    if (k + 1 < table.points.size() && alpha_n + next > table.points[k + 1].second) {
      da = table.points[k + 1].second - alpha_n;  // stop at the breakpoint
      ++k;
      continue;
    }
    da = next;
  }
  const HardeningPiece last = table.piece(k);
  const Real r = q_trial - g3 * da - last.at(alpha_n + da);
  if (!(std::abs(r) <= 1e-10 * scale) || !(da >= 0.0))
    throw SolverError("J2 return mapping: the local iteration did not converge");
  return {da, last.slope};
}

}  // namespace kontakt::material

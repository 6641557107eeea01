#include "material/hardening_curves.hpp"

#include <algorithm>
#include <utility>

namespace kontakt::material {

HardeningCurves::HardeningCurves(HardeningTable curve) {
  temperatures.push_back(0);
  curves.push_back(std::move(curve));
}

const HardeningTable& HardeningCurves::at(Real T, HardeningTable& scratch) const {
  if (curves.size() == 1 || T <= temperatures.front()) return curves.front();
  if (T >= temperatures.back()) return curves.back();
  std::size_t k = 1;
  while (temperatures[k] < T) ++k;
  if (T == temperatures[k]) return curves[k];
  const HardeningTable &lo = curves[k - 1], &hi = curves[k];
  const Real s = (T - temperatures[k - 1]) / (temperatures[k] - temperatures[k - 1]);
  std::vector<Real> strains;
  for (const auto& p : lo.points) strains.push_back(p.second);
  for (const auto& p : hi.points) strains.push_back(p.second);
  std::sort(strains.begin(), strains.end());
  strains.erase(std::unique(strains.begin(), strains.end()), strains.end());
  scratch.points.clear();
  for (Real e : strains) scratch.points.emplace_back((1 - s) * lo.yield(e) + s * hi.yield(e), e);
  return scratch;
}

}  // namespace kontakt::material

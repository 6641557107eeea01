// The von Mises equivalent stress: the one definition the materials, drivers and writers use.
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace kontakt::material {

/// sqrt(3/2 s:s) of a stress vector (xx, yy, zz, xy, xz, yz) with tensor shear components.
inline Real von_mises(const Vec6& stress) {
  const Real a = stress(0) - stress(1), b = stress(1) - stress(2), c = stress(2) - stress(0);
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * stress.tail<3>().squaredNorm());
}

}  // namespace kontakt::material

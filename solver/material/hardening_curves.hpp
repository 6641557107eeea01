// *PLASTIC hardening curves by temperature, evaluated at a point's temperature as ccx 2.20 does
// (measured on one C3D8 under uniaxial tension): the yield stress at a given equivalent plastic
// strain is linear in temperature between the two neighbouring curves, and the first or last
// curve's beyond the table.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "material/hardening_table.hpp"

namespace kontakt::material {

/// How *PLASTIC's curve hardens: ISOTROPIC (the yield surface grows), KINEMATIC (it moves; its
/// size stays the curve's first stress), COMBINED (it moves, and grows along the *CYCLIC
/// HARDENING curve).
enum class HardeningRule { Isotropic, Kinematic, Combined };

struct HardeningCurves {
  std::vector<Real> temperatures;       ///< strictly ascending, one per curve
  std::vector<HardeningTable> curves;

  HardeningCurves() = default;
  /// One curve: the same at every temperature.
  HardeningCurves(HardeningTable curve);  // NOLINT(google-explicit-constructor)

  bool empty() const { return curves.empty(); }
  /// The curve at temperature T: a stored curve by reference where T selects one (a single
  /// curve, T on a row or beyond the ends), else the interpolated curve built in `scratch`
  /// (its breakpoints the union of both neighbours', where both are linear).
  const HardeningTable& at(Real T, HardeningTable& scratch) const;
};

}  // namespace kontakt::material

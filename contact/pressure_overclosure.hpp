// Pressure-overclosure laws of penalty contact (ccx-behaviour.md sections 1.4 and 2; thesis
// section 3.2 and figure 26). Overclosure d = -g is positive when the bodies overlap; the
// pressure is positive in compression. Pure functions of d.
#pragma once

#include <utility>
#include <vector>

#include "core/types.hpp"
#include "model/contact.hpp"

namespace kontakt::contact {

struct PressureLaw {
  enum class Kind {
    Linear,         ///< p = K d for d > 0, else 0 (the thesis' truly linear law)
    QuasiBilinear,  ///< p = K d (1/2 + atan(d / eps) / pi), eps = pi sigma_inf / K (ccx NTS)
    Exponential,    ///< p = p0 exp(beta d), beta = ln(100) / c0
    Tabular,        ///< piecewise linear in (overclosure, pressure), constant beyond the ends
    Tied,           ///< p = K d in tension and compression
  };
  Kind kind = Kind::Linear;
  Real stiffness = 0;      ///< K
  Real eps = 0;            ///< QuasiBilinear transition width
  Real p0 = 0, beta = 0;   ///< Exponential
  std::vector<std::pair<Real, Real>> table;  ///< Tabular (overclosure, pressure)
};

struct PressureResponse {
  Real pressure = 0;
  Real slope = 0;          ///< dp / dd
  Real energy = 0;         ///< integral of p from 0 to d (per unit area)
};

/// The law a pair uses: the linear variants of surface-to-surface contact take LINEAR as the
/// truly linear law, node-to-surface and the nonlinear variants the quasi-bilinear one.
PressureLaw make_pressure_law(const model::SurfaceBehavior& behavior, bool linear_variant);

PressureResponse pressure_overclosure(const PressureLaw& law, Real d);

/// Whether a point with overclosure `d` (effective, after the overlap ramp) carries force.
/// Linear: d >= 0 (touching counts); Tied: always; the other laws: d >= -c where c is the
/// creation clearance (ccx: c0 * sqrt(A) for LINEAR/TABULAR, c0 for EXPONENTIAL).
bool is_active(const PressureLaw& law, Real d, Real creation_clearance);

/// A pressure per unit overclosure that stands for the law's stiffness: K for the linear,
/// quasi-bilinear and tied laws, p0 * beta for the exponential law at zero clearance, the
/// steepest segment of a table.
Real reference_stiffness(const PressureLaw& law);

/// The creation clearance of a point that represents slave area `area`.
Real creation_clearance(const model::SurfaceBehavior& behavior, Real area);

}  // namespace kontakt::contact

// The isotropic hardening curve of *PLASTIC and the scalar radial-return equation on it, shared
// by the small-strain and the finite-strain J2 models.
#pragma once

#include <limits>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace kontakt::material {

/// One linear piece of a hardening curve: its value at `start` plus slope times the distance,
/// up to the next breakpoint `end` (infinity for the constant tail beyond the last row).
struct HardeningPiece {
  Real at_start = 0, start = 0, slope = 0, end = std::numeric_limits<Real>::infinity();
  Real at(Real alpha) const { return at_start + slope * (alpha - start); }
};

/// Isotropic hardening curve as given under ccx/Abaqus *PLASTIC (HARDENING=ISOTROPIC):
/// rows of (von Mises yield stress, equivalent plastic strain), plastic strain strictly
/// ascending, first row at plastic strain 0 (initial yield). One row = perfectly
/// plastic. Linear between rows; beyond the last row the yield stress stays at the last
/// value (slope 0) -- what ccx does (plinterpol.f: f = last stress, df = 0, with a
/// warning); the ccx manual itself does not document the extrapolation.
struct HardeningTable {
  /// (yield stress, equivalent plastic strain) pairs, in *PLASTIC column order.
  std::vector<std::pair<Real, Real>> points;

  /// Throws std::invalid_argument when empty, the first plastic strain is not 0, the
  /// plastic strains are not strictly ascending, or a yield stress is negative or
  /// not finite. The deck reader should wrap the message into an InputError.
  void validate() const;
  /// Yield stress at equivalent plastic strain alpha >= 0.
  Real yield(Real alpha) const;
  /// Right derivative d(yield)/d(alpha) at alpha (0 beyond the last row).
  Real slope(Real alpha) const;
  /// Index k of the segment [points[k], points[k+1]) containing alpha; returns
  /// points.size()-1 for the constant tail beyond the last row.
  std::size_t segment(Real alpha) const;
  /// Segment k as a linear piece (k = points.size()-1: the constant tail).
  HardeningPiece piece(std::size_t k) const;
};

/// Root of the radial-return equation and the hardening slope there.
struct RadialReturn {
  Real delta_alpha = 0;  ///< increment of equivalent plastic strain, >= 0
  Real slope = 0;        ///< d(yield)/d(alpha) of the segment holding the root
};

/// Solves  q_trial - 3 G delta_alpha = yield(alpha_n + delta_alpha)  for delta_alpha, where
/// q_trial is a von Mises trial stress above yield(alpha_n) and G > 0 the (effective) shear
/// modulus of the return. Throws std::invalid_argument when a softening slope reaches -3G (the
/// return is then ill-posed) and SolverError (the caller cuts back) if the walk fails.
RadialReturn solve_radial_return(const HardeningTable& table, Real alpha_n, Real q_trial,
                                 Real shear_modulus);

}  // namespace kontakt::material

// Symmetric 3x3 tensors in Voigt order xx yy zz xy xz yz, as the finite-strain material
// kernels (J2 at finite strain, hyperelastic) use them.
#pragma once

#include "core/types.hpp"

namespace kontakt::material {

inline constexpr int kVoigtI[6] = {0, 1, 2, 0, 0, 1};
inline constexpr int kVoigtJ[6] = {0, 1, 2, 1, 2, 2};

/// The six independent components of a symmetric tensor (no factor on the shear entries).
inline Vec6 voigt(const Mat3& t) {
  Vec6 v;
  for (int a = 0; a < 6; ++a) v[a] = t(kVoigtI[a], kVoigtJ[a]);
  return v;
}

/// Components (ij, kl) of d(C^-1)/dC = -(Ci_ik Ci_jl + Ci_il Ci_jk) / 2 for symmetric C, Ci
/// its inverse; with respect to the Green-Lagrange strain E (dC = 2 dE) it is twice this.
inline Mat6 inverse_derivative(const Mat3& Ci) {
  Mat6 m;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      const int i = kVoigtI[a], j = kVoigtJ[a], k = kVoigtI[b], l = kVoigtJ[b];
      m(a, b) = -0.5 * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
    }
  return m;
}

}  // namespace kontakt::material

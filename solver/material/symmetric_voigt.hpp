// Symmetric 3x3 tensors in Voigt order xx yy zz xy xz yz with tensor (not engineering) shear,
// as the material kernels use them.
#pragma once

#include <cmath>

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

/// Deviatoric part.
inline Vec6 deviator(const Vec6& t) {
  Vec6 d = t;
  const Real mean = (t(0) + t(1) + t(2)) / 3.0;
  d.head<3>().array() -= mean;
  return d;
}

/// Frobenius norm (the shear entries count twice).
inline Real tensor_norm(const Vec6& t) {
  return std::sqrt(t.head<3>().squaredNorm() + 2.0 * t.tail<3>().squaredNorm());
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

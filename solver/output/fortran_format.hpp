// Fortran list-free E editing (Ew.d with an optional kP scale factor) as gfortran prints it:
// the formatter behind every number in the ccx-compatible .dat file.
#pragma once

#include <string>

namespace kontakt::output {

/// Fortran `Ew.d` output of `value`, with scale factor `scale` (0 for plain E, 1 for `1P`).
/// Supported scales: 0 ("0.1234567E+01") and 1 ("1.234567E+00"). Exponents with three digits
/// drop the letter as the Fortran standard requires ("0.1234567+101"). Rounding is
/// round-half-even on the exact binary value (what gfortran does via glibc). -0.0 keeps its
/// sign. NaN/Inf print as "NaN"/"Infinity"/"-Infinity", right-justified. A field that does not
/// fit is filled with '*'.
std::string fortran_e(double value, int width, int digits, int scale);

/// ccx's value field `1P,E13.6`: " 1.234567E+00" / "-1.234567E+00".
inline std::string fortran_e13_6(double value) { return fortran_e(value, 13, 6, 1); }
/// ccx's time field `E14.7`: " 0.1000000E+01".
inline std::string fortran_e14_7(double value) { return fortran_e(value, 14, 7, 0); }

}  // namespace kontakt::output

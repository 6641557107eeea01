#include "output/fortran_format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace kontakt::output {

namespace {
std::string right_justify(const std::string& s, int width) {
  if (static_cast<int>(s.size()) > width) return std::string(static_cast<std::size_t>(width), '*');
  return std::string(static_cast<std::size_t>(width) - s.size(), ' ') + s;
}
}  // namespace

std::string fortran_e(double value, int width, int digits, int scale) {
  if (scale != 0 && scale != 1) throw std::invalid_argument("fortran_e: scale must be 0 or 1");
  if (digits < 1 || digits > 30) throw std::invalid_argument("fortran_e: bad digit count");
  if (std::isnan(value)) return right_justify("NaN", width);
  if (std::isinf(value)) return right_justify(value < 0 ? "-Infinity" : "Infinity", width);

  // Significant digits: scale 0 -> d digits (0.ddd), scale 1 -> d+1 digits (d.ddd).
  const int significant = scale == 1 ? digits + 1 : digits;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", significant - 1, value);
  // buf = [-]D.DDDDe[+-]XX
  std::string s(buf);
  const bool negative = s[0] == '-';
  if (negative) s.erase(0, 1);
  const auto epos = s.find('e');
  std::string mant = s.substr(0, epos);  // D.DDDD or D
  int exponent = std::atoi(s.c_str() + epos + 1);
  std::string mdigits;
  for (char c : mant)
    if (c != '.') mdigits += c;
  const bool zero = value == 0.0;

  std::string body;
  if (scale == 1) {
    body = mdigits.substr(0, 1) + "." + mdigits.substr(1);
  } else {
    body = "0." + mdigits;
    if (!zero) exponent += 1;
  }
  if (zero) exponent = 0;
  char ebuf[16];
  const int aexp = std::abs(exponent);
  if (aexp <= 99)
    std::snprintf(ebuf, sizeof ebuf, "E%c%02d", exponent < 0 ? '-' : '+', aexp);
  else if (aexp <= 999)
    std::snprintf(ebuf, sizeof ebuf, "%c%03d", exponent < 0 ? '-' : '+', aexp);
  else
    return std::string(static_cast<std::size_t>(width), '*');
  std::string out = (negative ? "-" : "") + body + ebuf;
  // The zero before the decimal point is optional in Fortran: dropped when the field is full.
  if (static_cast<int>(out.size()) > width && scale == 0)
    out = (negative ? "-" : "") + body.substr(1) + ebuf;
  return right_justify(out, width);
}

}  // namespace kontakt::output

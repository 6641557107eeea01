#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "output/fortran_format.hpp"

using kontakt::output::fortran_e;
using kontakt::output::fortran_e13_6;
using kontakt::output::fortran_e14_7;

// Expected strings were produced by gfortran 12 with (1p,e13.6) and (e14.7).
TEST(FortranFormat, Zero) {
  EXPECT_EQ(fortran_e13_6(0.0), " 0.000000E+00");
  EXPECT_EQ(fortran_e14_7(0.0), " 0.0000000E+00");
  EXPECT_EQ(fortran_e13_6(-0.0), "-0.000000E+00");
  EXPECT_EQ(fortran_e14_7(-0.0), "-0.0000000E+00");
}

TEST(FortranFormat, OrdinaryValues) {
  EXPECT_EQ(fortran_e13_6(1.0), " 1.000000E+00");
  EXPECT_EQ(fortran_e13_6(-1.0), "-1.000000E+00");
  EXPECT_EQ(fortran_e13_6(123.456), " 1.234560E+02");
  EXPECT_EQ(fortran_e13_6(0.5), " 5.000000E-01");
  EXPECT_EQ(fortran_e14_7(1.0), " 0.1000000E+01");
  EXPECT_EQ(fortran_e14_7(-1.0), "-0.1000000E+01");
  EXPECT_EQ(fortran_e14_7(0.5), " 0.5000000E+00");
  EXPECT_EQ(fortran_e14_7(123.456), " 0.1234560E+03");
}

TEST(FortranFormat, RoundingAndCarry) {
  // 9.9999995 is stored slightly below ...95: rounds down, as gfortran does.
  EXPECT_EQ(fortran_e13_6(9.9999995), " 9.999999E+00");
  EXPECT_EQ(fortran_e13_6(9.9999996), " 1.000000E+01");  // carry into the exponent
  EXPECT_EQ(fortran_e14_7(9.99999996), " 0.1000000E+02");
  EXPECT_EQ(fortran_e14_7(0.99999999), " 0.1000000E+01");
  // Exact ties round half to even (gfortran/glibc).
  EXPECT_EQ(fortran_e13_6(1234567.5), " 1.234568E+06");
  EXPECT_EQ(fortran_e13_6(1234568.5), " 1.234568E+06");
  EXPECT_EQ(fortran_e14_7(2.25), " 0.2250000E+01");
}

TEST(FortranFormat, ThreeDigitExponentsDropTheE) {
  EXPECT_EQ(fortran_e13_6(1e99), " 1.000000E+99");
  EXPECT_EQ(fortran_e14_7(1e99), " 0.1000000+100");
  EXPECT_EQ(fortran_e13_6(1e100), " 1.000000+100");
  EXPECT_EQ(fortran_e14_7(1e100), " 0.1000000+101");
  EXPECT_EQ(fortran_e13_6(9.9999996e99), " 1.000000+100");
  EXPECT_EQ(fortran_e13_6(-1.5e-100), "-1.500000-100");
  EXPECT_EQ(fortran_e14_7(-1.5e-100), "-0.1500000E-99");
  EXPECT_EQ(fortran_e13_6(1.234567e-300), " 1.234567-300");
  EXPECT_EQ(fortran_e14_7(1.234567e-300), " 0.1234567-299");
  EXPECT_EQ(fortran_e13_6(5e-324), " 4.940656-324");  // smallest subnormal
  EXPECT_EQ(fortran_e14_7(5e-324), " 0.4940656-323");
  EXPECT_EQ(fortran_e13_6(1e-20), " 1.000000E-20");
}

TEST(FortranFormat, NonFiniteAndOverflow) {
  EXPECT_EQ(fortran_e13_6(std::numeric_limits<double>::quiet_NaN()), "          NaN");
  EXPECT_EQ(fortran_e13_6(std::numeric_limits<double>::infinity()), "     Infinity");
  EXPECT_EQ(fortran_e13_6(-std::numeric_limits<double>::infinity()), "    -Infinity");
  EXPECT_EQ(fortran_e(-1.0, 8, 6, 1), "********");
  EXPECT_EQ(fortran_e(-1.0, 13, 7, 0), "-.1000000E+01");  // optional leading zero dropped
}

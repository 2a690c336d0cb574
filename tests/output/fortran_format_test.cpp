#include "tether/output/fortran_format.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace tether {
namespace {

TEST(FortranFormat, MatchesCalculixTimeStamps) {
  EXPECT_EQ(fortran_e(1.0, 7), "0.1000000E+01");
  EXPECT_EQ(fortran_e(0.5, 7), "0.5000000E+00");
  EXPECT_EQ(fortran_e(0.5, 6), "0.500000E+00");
  EXPECT_EQ(fortran_e(123.456, 7), "0.1234560E+03");
  EXPECT_EQ(fortran_e(-2.5e-3, 6), "-0.250000E-02");
  EXPECT_EQ(fortran_e(0.0, 7), "0.0000000E+00");
}

TEST(FortranFormat, RoundsOnceAndCarriesIntoTheExponent) {
  EXPECT_EQ(fortran_e(0.99999999, 7), "0.1000000E+01");
  EXPECT_EQ(fortran_e(1.23456789e-10, 4), "0.1235E-09");
  EXPECT_EQ(fortran_e(1e100, 3), "0.100E+101");
}

TEST(FortranFormat, NonFinite) {
  EXPECT_EQ(fortran_e(std::numeric_limits<double>::quiet_NaN(), 7), "NaN");
  EXPECT_EQ(fortran_e(-std::numeric_limits<double>::infinity(), 7), "-Infinity");
}

}  // namespace
}  // namespace tether

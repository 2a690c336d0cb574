#pragma once
/// \file Number formats of Fortran programs (CalculiX), reproduced so that
/// tether's text reports read like theirs.

#include <string>

namespace tether {

/// Fortran `Ew.d` without `1P` scale factor: mantissa in [0.1, 1) with
/// `digits` decimals, e.g. fortran_e(1.0, 7) == "0.1000000E+01",
/// fortran_e(-2.5e-3, 6) == "-0.250000E-02", fortran_e(0.0, 7) == "0.0000000E+00".
/// No padding; the exponent has at least two digits (three when needed,
/// written with its `E`, unlike Fortran, which drops it). Non-finite values
/// print as "NaN", "Infinity" or "-Infinity".
/// Precondition: 1 <= digits <= 17.
std::string fortran_e(double value, int digits);

}  // namespace tether

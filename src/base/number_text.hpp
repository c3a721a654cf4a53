#pragma once
// Numbers as text: the four ways Furrow writes a double, so every message,
// table and file says a number the same way.
//
//   shortest      the shortest text that reads back to the same double
//                 (std::to_chars): files meant to be read again, sort keys
//   general       printf "%.<digits>g": messages and labels, where a few
//                 significant digits say enough
//   fixed         printf "%.<decimals>f": tables and reports with a fixed
//                 unit step (mm to the micrometre, µm to 0.1)
//   signed_fixed  fixed with an explicit sign: deviations, "+12.3"
//
// Except in `shortest`, which must read back to the very same double, a
// value that rounds to zero is written without a sign ("0.000", never
// "-0.000"): a reader would take "-0.0 µm" for an overcut. None of these is
// meant for NaN or infinity; writers check finiteness where it matters.
#include <string>

namespace furrow {

std::string shortest(double value);
std::string general(double value, int digits = 6);
std::string fixed(double value, int decimals);
std::string signed_fixed(double value, int decimals);

}  // namespace furrow

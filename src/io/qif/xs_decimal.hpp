#pragma once
// A double as the text of an XML Schema xs:decimal (docs/qif.md "Numbers").
// QIF types its lengths and measured values (LinearValueType,
// MeasuredLinearValueType, ProbeRadius, a unit's Factor) as xs:decimal,
// whose lexical form has no exponent: "1.5e-05" is rejected by the schema,
// "0.000015" is not. Lists of xs:double (points, directions) keep
// std::to_chars' shortest text, exponent and all: the schema allows it there.
//
// The digits are the shortest that read back to the same double
// (std::to_chars), written out in positional notation with the zeros the
// exponent stood for, so strtod of the text gives the double bit for bit,
// -0 included ("-0").
//
// A validator may cap the digits of a decimal (XML Schema 1.0 Part 2, 3.2.3:
// at least 18 must be supported, the cap is the processor's); libxml2, which
// xmllint and much QIF software use, accepts 24. With `max_digits` the text
// stays within that many digits (the integer part's lone 0 not counted): a
// value whose exact text needs more - |v| below about 1e-7, where 17
// significant digits and the leading zeros exceed 24 - is rounded to
// `max_digits` decimal places (an error below 0.5e-24 of the unit), and a
// value of `max_digits` integer digits or more is std::invalid_argument,
// since rounding cannot shorten it.
//
// Precondition: v finite (std::invalid_argument otherwise: a decimal has no
// infinity and no NaN).
#include <string>

namespace furrow {

// No cap on the digits: exact for every finite double (up to about 330
// characters for 5e-324 or 1.8e308).
inline constexpr int kXsDecimalExact = 0;

// Appends the text to `out` (the writers of 100 MB documents append).
void append_xs_decimal(std::string& out, double v, int max_digits = kXsDecimalExact);

std::string xs_decimal_text(double v, int max_digits = kXsDecimalExact);

}  // namespace furrow

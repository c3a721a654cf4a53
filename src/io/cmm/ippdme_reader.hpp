#pragma once
// Strict reader of the I++ DME command files Furrow writes
// (ippdme_writer.hpp). It enforces the file layout and the command syntax
// rules that NIST's command parser checks (I++ DME spec 1.4, section on
// command syntax):
//   - every command line is `TTTTT Command(args)` + CR LF: five digits, the
//     sixth character a space, tag 00001..99999; then a line `\\` + CR LF;
//     the file ends with a line `:` + CR LF (a second one may follow);
//   - numbers: optional sign, 1 to 16 digits with at most one decimal point,
//     optional exponent of 1 to 3 digits; strings printable ASCII;
//   - spaces only next to parentheses and commas;
// and the session rules NIST's context checker enforces for these commands:
// StartSession first, Home before any motion, a tool selected before
// SetProp and PtMeas, PtMeas direction not zero, EndSession last. Beyond the
// spec it requires exactly the command sequence the writer emits, with tags
// counting up by one, so anything else is refused.
//
// Lines longer than kMaxIppdmeLine characters are refused before any
// pattern is matched (see the .cpp).
//
// Errors: InputError "name:line: what" (line of the command).
#include <string>

#include "io/cmm/probe_program.hpp"

namespace furrow {

// No command line Furrow writes comes near it (a PtMeas line is ~110
// characters); see parse_ippdme_program.
constexpr std::size_t kMaxIppdmeLine = 1000;

// Points come back in PtMeas order with order 1, 2, ..., an empty id, xyz
// and ijk (normalised); moves as written; the tool name, approach, retract,
// search and the two speeds. PtMeas commands before a second
// SetCoordSystem(PartCsy) are the alignment's (alignment_steps, with the
// GoTo moves before that command as alignment_final_moves); `alignment`
// stays unset, the file does not say which feature a point belongs to. The file does not carry a name, part, probe diameter or
// stylus length (left 0 / empty).
ProbeProgram parse_ippdme_program(const std::string& text, const std::string& name);
ProbeProgram read_ippdme_program(const std::string& path);

// True when `text` is a number by the spec's grammar (see above).
bool is_ippdme_number(const std::string& text);

}  // namespace furrow

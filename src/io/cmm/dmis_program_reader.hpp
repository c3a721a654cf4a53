#pragma once
// Strict reader of the DMIS programs Furrow writes (dmis_writer.hpp): every
// statement must be one the writer emits, in the writer's order, with the
// writer's spelling (upper case, no spaces, fixed-point numbers), so a
// program edited by hand into something else is refused rather than half
// understood. Used to round-trip programs in tests and to check a program
// before it is sent to a machine.
//
// Checked besides the syntax: DMISMN first and ENDFIL last; UNITS/MM; the
// sensor selected is the one defined; every MEAS refers to the feature
// defined just before it and holds exactly one PTMEAS equal to the nominal;
// every feature is measured and output exactly once; labels are unique and
// upper case; PLANID names the program; with a TOL/PROFP every OUTPUT also
// reports TA(PROFILE), without one none does.
// Point feature statements are parsed by the measurement reader's DMIS
// functions (dmis_results.hpp), so the results file a CMM writes for the
// program reads back with the same labels and nominals.
//
// Statements longer than kMaxDmisProgramStatement characters are refused
// before any pattern is matched (see the .cpp).
//
// Errors: InputError "name:line: what".
#include <string>

#include "io/cmm/probe_program.hpp"

namespace furrow {

// No statement Furrow writes comes near it (a point feature is ~90
// characters).
constexpr std::size_t kMaxDmisProgramStatement = 1000;

// Points come back with id (the upper-case label), order (1, 2, ... in
// program order), xyz and ijk (normalised); the probe with its label and
// diameter, the head length, speeds, part, revision and tolerance; moves as
// written. Fields the program carries only in comments (date, stylus
// length) or not at all (face, region, u, v) stay default.
ProbeProgram parse_dmis_program(const std::string& text, const std::string& name);
ProbeProgram read_dmis_program(const std::string& path);

}  // namespace furrow

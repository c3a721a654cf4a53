#pragma once
// I++ DME command file (.prg) for a probe plan: the commands a client sends
// to a CMM's I++ DME server, in the file layout of NIST's I++ DME test suite
// (checkerCmd, parserCmd), so the program can be checked before it meets a
// machine (docs/formats.md "I++ DME program", docs/cmm.md).
//
// Layout: every command is one line `TTTTT Command(args)` (a five-digit tag
// 00001..99999, one space, the command; tags count up from 00001 and wrap
// after 99999, which the spec allows once a command has completed), ended by
// CR LF and followed by a line holding two backslashes `\\` (CR LF); the file
// ends with a line `:` (CR LF), twice. Arguments are separated by ", "; numbers
// are fixed-point with at most 16 digits and no exponent; strings are
// printable ASCII in double quotes.
//
//   StartSession()
//   Home()                              (the spec requires homing before motion)
//   SetCoordSystem(PartCsy)             (the part frame, set up by the alignment)
//   ChangeTool("probe")
//   SetProp(Tool.PtMeasPar.Approach(a)) SetProp(Tool.PtMeasPar.Retract(r))
//   SetProp(Tool.PtMeasPar.Search(s))
//   SetProp(Tool.GoToPar.Speed(v))      SetProp(Tool.PtMeasPar.Speed(v))   (mm/s)
//   OnPtMeasReport(X(), Y(), Z(), IJK())
//   with an alignment: per alignment point GoTo ... PtMeas(...), GoTo(...)
//     up and over to the first point, SetCoordSystem(PartCsy) again: a
//     command file cannot compute a frame, so the client sets PartCsy from
//     the alignment points' responses (SetCsyTransformation) at this
//     command; a client that does not measures on the pre-alignment
//     (docs/cmm.md "Part alignment")
//   per point: GoTo(X(x), Y(y), Z(z)) ...  PtMeas(X(x), Y(y), Z(z), IJK(i, j, k))
//   GoTo(...) up to the clearance plane
//   EndSession()
//
// GoTo targets are ball-centre positions; PtMeas targets are nominal surface
// points with the outward normal (the server compensates the probe radius).
// Speeds are in mm/s, the spec's default units. The file carries no part
// name, revision, date or tolerance: the command set has no comment and no
// tolerance; the client keeps those (docs/cmm.md).
#include <string>

#include "io/cmm/probe_program.hpp"

namespace furrow {

constexpr int kMaxIppTag = 99999;

// Throws InputError (check_program) for something the file cannot carry.
std::string ippdme_program_text(const ProbeProgram& program);

}  // namespace furrow

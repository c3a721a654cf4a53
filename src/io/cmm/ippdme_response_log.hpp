#pragma once
// I++ DME response log (docs/formats.md "Measurements", I++ DME): what a
// CMM's I++ DME server answered while it ran a Furrow program
// (ippdme_writer.hpp), one response per line, each starting with the tag of
// the command it answers (five digits, a space):
//
//   00012 &                                       acknowledged
//   00012 # X(1.5), Y(2), Z(3), IJK(0, 0, 1)      data: the point PtMeas measured
//   00012 %                                       completed
//   00012 ! Error(2, 0500, "PtMeas", "Probe hit not detected")
//
// Responses of different commands may interleave (a server answers in the
// order it finishes). A tag is free again once its command completed and the
// client counts on after 99999 from 00001, so the n-th command with a tag in
// the log is the n-th command with that tag in the program. Lines where the
// tag is followed by a command (the client's own lines, when the log
// records both directions) are skipped, as are blank lines.
//
// Points: one per command that returned data, in the order of the data
// lines; id = the tag as written ("00012"), "00012_2" for its second use and
// so on; X, Y, Z in millimetres (the server's unit), IJK when reported.
// Given the program (.prg) the log answers, each point also gets its PtMeas
// target and direction as MeasuredPoint::nominal; a data line for a command
// that is not a PtMeas, or a PtMeas without a response, is an error.
//
// Errors: InputError "FILE:LINE: ...": a line that is not a response, a tag
// reused before its command completed, a second data line for one command,
// a data line without X, Y and Z, and any error response ("!") of a command
// that returned no point (e.g. "Probe hit not detected": the point was not
// measured and the run is incomplete; the message names the tag and the
// server's text). An error response of a command that did return a point
// keeps the point.
#include <string>
#include <string_view>

#include "io/cmm/measurement_file.hpp"
#include "io/cmm/probe_program.hpp"

namespace furrow {

// True when the first line with content is a server response: five digits,
// a space, then '#', '%', '&' or '!' (how a .res file is told from DMIS).
bool is_ippdme_response_log(std::string_view text);

// Fills set.points from `text` (no byte-order mark); `program` (may be null)
// is the program the log answers, `program_name` its file for messages.
void parse_ippdme_response_log(std::string_view text, const std::string& name, const ProbeProgram* program,
                               const std::string& program_name, MeasurementSet& set);

// A log as a server would write it for `set`: per point, in order, a PtMeas
// acknowledged, its data (X, Y, Z, IJK when the point has one; shortest exact
// numbers) and its completion, tags counting from 00001 and wrapping after
// 99999 as the client's do. CR LF line ends.
std::string ippdme_response_log_text(const MeasurementSet& set);

}  // namespace furrow

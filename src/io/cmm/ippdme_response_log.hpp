#pragma once
// I++ DME session read back (docs/formats.md "Reading any I++ DME
// session"): what a CMM's I++ DME server answered while it ran a program,
// from any client, in every layout NIST's test files show:
//
//   NIST .res        responses with a line `\\` between them, `:` at the end
//   plain log        one response per line
//   session log      `04:08:18_06:09:13 Sent: 00012 PtMeas(...)` /
//                    `... Received: 00012 # X(..), ...` (a client's log; a
//                    server's has Sent/received the other way round), blank
//                    lines between, notes such as `*********** Starting DME
//                    file ...`, `Final Tag: 09999`, `Session completed`
//
// with CR LF, LF or CR CR LF line ends. A line with the tag followed by a
// command is the command itself (a session log records both directions).
// Responses:
//
//   00012 &                                       acknowledged
//   00012 # X(1.5), Y(2), Z(3), IJK(0, 0, 1), ER(1)   data
//   00012 %                                       completed
//   00012 ! Error(2, 1006, "PtMeas", "Surface not found")
//   E0001 # ...                                   an event's data (passed over)
//
// Responses of different commands may interleave. A tag is free again once
// its command completed, so the n-th command with a tag in the log is the
// n-th command with that tag in the program.
//
// Which answers are points: the data of a PtMeas - known from the command
// in the log, else from the program (IppdmeSession) - with X(), Y() and Z().
// Answers to other commands (GetProp, EnumTools, Get ...) and events are
// passed over. Without either, a data line of X(), Y(), Z() and point items
// only (IJK, ER, Tool.A/B/C) is taken as a point: a Get(X(), Y(), Z())
// answer looks the same, give the program to tell them apart.
//
// Points: in the order of their data; id = the tag as written ("00012"),
// "00012_2" for its second use; X, Y, Z in millimetres (the server's unit)
// in the frame the PtMeas was sent in (IppdmeFrame: MachineCsy and PartCsy
// honoured, both brought into PartCsy when both occur); IJK when reported;
// ER as MeasuredPoint::effective_radius; the PtMeas target and direction,
// when known, as the nominal. Servers answer with the ball's centre.
//
// Not measured (MeasurementSet::not_measured, with the reason): a PtMeas
// answered by an error ("!") and no data, one whose data lack X, Y or Z, one
// completed without data, and a PtMeas of the program or the log without
// any answer.
//
// Errors: InputError "FILE:LINE: ...": a line that is none of the above, a
// response or an error whose syntax is not I++ DME, a tag reused before its
// command completed, a second data line of one PtMeas, a point measured in a
// coordinate system Furrow cannot place.
#include <string>
#include <string_view>

#include "io/cmm/ippdme_session.hpp"
#include "io/cmm/measurement_file.hpp"

namespace furrow {

// True when the first line with content is a server response or an I++ DME
// command, with or without a session log's time stamp (how an I++ DME
// session is told from DMIS, CSV and XYZ by content).
bool is_ippdme_response_log(std::string_view text);

// Fills set.points and set.not_measured from `text` (no byte-order mark);
// `program` (may be null) is the command file the log answers,
// `program_name` its file for messages.
void parse_ippdme_response_log(std::string_view text, const std::string& name, const IppdmeSession* program,
                               const std::string& program_name, MeasurementSet& set);

// A log as a server would write it for `set`: per point, in order, a PtMeas
// acknowledged, its data (X, Y, Z, IJK when the point has one, ER when the
// set holds centres; shortest exact numbers) and its completion, tags
// counting from 00001 and wrapping after 99999 as the client's do. CR LF
// line ends.
std::string ippdme_response_log_text(const MeasurementSet& set);

}  // namespace furrow

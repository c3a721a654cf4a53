#pragma once
// One I++ DME 1.4 command or response, split into its parts and checked
// against the spec's string grammar (docs/formats.md "I++ DME program",
// "Reading any I++ DME session"). Shared by the command-file reader of any
// client (ippdme_session.hpp) and the response-log reader
// (ippdme_response_log.hpp). A hand-written scanner: no std::regex, so a
// line of any length costs linear time and constant stack.
//
// Command: `TTTTT Name(arguments)`, the tag five digits (00001..99999) or
// `E` and four digits (E0001..E9999, an event tag, required by the event commands
// AbortE, GetErrStatusE, GetPropE and OnMoveReportE and refused for every
// other), one space, a command name of the spec, its arguments in
// parentheses and nothing after them. An argument is a number (the spec's
// grammar: optional sign, 1 to 16 digits with at most one decimal point,
// optional exponent of 1 to 3 digits), a string (printable ASCII in double
// quotes) or a keyword path `A.B.C` optionally followed by its own
// parenthesised arguments (in answers also a bare parenthesised list, as
// AlignPart's "(0.6, 0, 0.8)"). Spaces are allowed only next to parentheses and
// commas. Argument counts and kinds are checked for the commands whose
// arguments are fixed (no arguments, one string, 4/7/8/14 numbers ...,
// kIppdmeArity in the .cpp); the others are checked for syntax only, which
// is all a reader of the session needs.
//
// Errors are returned as text ("PtMeas: MUST HAVE ...", in the words of
// NIST's command parser where it has one), never thrown: a log reader
// passes over commands a server refused while a program reader refuses them.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace furrow {

struct IppdmeItem {
  enum class Kind { number, string, keyword };
  Kind kind = Kind::number;
  // Number: as written; string: without the quotes; keyword: the dotted path.
  std::string text;
  bool has_arguments = false;  // a keyword followed by (...)
  std::vector<IppdmeItem> arguments;
};

struct IppdmeCommand {
  std::string tag;     // five characters as written
  bool event = false;  // E tag
  int number = 0;      // the tag's number (without the E)
  std::string name;
  std::vector<IppdmeItem> arguments;
};

// Empty when `text` is a number by the spec's grammar, else why not
// ("BAD NUMBER MORE THAN 16 DIGITS", ...). `max_digits` is the spec's 16
// for commands; answers are read with 17 significant digits (leading zeros
// not counted), the most the shortest exact form of a double needs
// (docs/formats.md "Reading any I++ DME session").
constexpr int kIppdmeDigits = 16;
constexpr int kIppdmeAnswerDigits = 17;
std::string ippdme_number_error(std::string_view text, int max_digits = kIppdmeDigits);

// Splits `line` (no line end) into `out`; the error text, empty when the
// line is a well-formed command.
std::string parse_ippdme_command(std::string_view line, IppdmeCommand& out);

// The item list of a response's data (what follows `TTTTT # `) or of an
// error response (`TTTTT ! Error(...)`), numbers of up to
// kIppdmeAnswerDigits digits; the error text, empty when well formed.
std::string parse_ippdme_items(std::string_view text, std::vector<IppdmeItem>& out);

// What a PtMeas (its target) or a PtMeas answer carries: X(), Y(), Z(),
// IJK(i, j, k), ER(r), Tool.A(), Tool.B(), Tool.C(). `only_point_items` is
// false when another item appears (then it is not a point report).
struct IppdmePointItems {
  std::optional<double> x, y, z;
  std::optional<Eigen::Vector3d> ijk;  // as written, not normalised
  std::optional<double> er;            // effective ball radius [mm]
  std::optional<double> tool_a, tool_b, tool_c;  // head angles [deg]
  bool only_point_items = true;
  bool has_xyz() const { return x && y && z; }
};
// The items of `items` that a point carries; the error text (an item of a
// point with the wrong number or kind of arguments, an item twice), empty when
// none.
std::string ippdme_point_items(const std::vector<IppdmeItem>& items, IppdmePointItems& out);

// The same for a text that holds point items only - `X(1.5), Y(2),
// IJK(0, 0, 1)`, the arguments of a PtMeas or the data of its answer - read
// without building items: false (and `out` unspecified) for anything else,
// which the caller then reads with parse_ippdme_items / parse_ippdme_command
// for the answer or the error. What it accepts those accept too. It is what
// keeps a million-point session log inside its time (docs/formats.md
// "Measurements", Speed).
bool ippdme_point_items_fast(std::string_view text, int max_digits, IppdmePointItems& out);

}  // namespace furrow

#pragma once
// An I++ DME 1.4 command file (.prg) from any client, read for what its
// answers mean (docs/formats.md "Reading any I++ DME session"): every
// command of the spec is parsed (ippdme_command.hpp); a PtMeas is a point to
// be measured, its target the nominal and its tag the id; every other valid
// command is accepted and passed over, except the two that decide the frame
// the answers are in (IppdmeFrames below). Unlike the strict reader of
// Furrow's own files (ippdme_reader.hpp) it does not check the session's
// context (homing, tool selected...): that is NIST's context checker's job
// (docs/cmm.md "Checking programs").
//
// Layout: one command per line (CR LF or LF; CR CR LF too), optionally a
// line `\\` after each, blank lines, and `:` lines at the end. Anything else
// - a line that is not a well-formed I++ DME command - is refused.
//
// Errors: InputError "NAME:LINE: what" (the reason in NIST parser's words
// where it has one, e.g. "AbortE: MUST HAVE NO ARGUMENTS"); a line longer
// than kMaxIppdmeSessionLine is refused before it is scanned.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/cmm/ippdme_command.hpp"

namespace furrow {

constexpr std::size_t kMaxIppdmeSessionLine = 100000;

// The coordinate systems of I++ DME 1.4 a PtMeas may be measured in.
enum class IppdmeCsy { machine, moveable_machine, multiple_arm, part };
const char* to_string(IppdmeCsy csy);

// The frame state of a session, advanced command by command. The server
// answers a PtMeas in the system in force when the command was sent, the
// same as its target. Honoured: MachineCsy (the default after StartSession)
// and PartCsy, with PartCsy's placement from SetCsyTransformation(PartCsy,
// X0, Y0, Z0, Theta, Psi, Phi) as NIST's world model applies it (part =
// R(Theta, Psi, Phi) machine + (X0, Y0, Z0), angles in degrees).
// MoveableMachineCsy and MultipleArmCsy have no placement a client can know
// from the command file: a point measured there is refused
// (ippdme_to_one_frame). The transformations of JogDisplayCsy, JogMoveCsy,
// SensorCsy and the other systems move nothing a PtMeas answers in.
struct IppdmeFrame {
  IppdmeCsy csy = IppdmeCsy::machine;
  std::optional<Eigen::Isometry3d> part;  // machine -> part, when set
};
// Advances `frame` by `command` (SetCoordSystem, SetCsyTransformation;
// others leave it). Returns an error text for a coordinate system the spec
// does not name.
std::string advance_ippdme_frame(const IppdmeCommand& command, IppdmeFrame& frame);
// NIST's world model: part = R x + t.
Eigen::Isometry3d ippdme_csy_transformation(double x0, double y0, double z0, double theta, double psi, double phi);

struct IppdmePtMeas {
  std::string tag;        // as written
  int use = 1;            // 1 for the first command with this tag, 2 for the next ...
  int line = 0;
  std::optional<Eigen::Vector3d> target;  // X, Y, Z all given (a missing one is "where the probe is")
  std::optional<Eigen::Vector3d> ijk;     // unit, when given and not zero
  IppdmeFrame frame;                      // in force when sent
};

struct IppdmeSession {
  std::vector<IppdmePtMeas> ptmeas;  // in program order
  std::size_t commands = 0;
};

IppdmeSession parse_ippdme_session(std::string_view text, const std::string& name);
IppdmeSession read_ippdme_session(const std::string& path);

// True when the first line with content is an I++ DME command (how a
// command file or a session log is told from other text).
bool looks_like_ippdme_command(std::string_view line);

}  // namespace furrow

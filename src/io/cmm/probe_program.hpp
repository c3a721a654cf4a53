#pragma once
// A CMM measuring program as plain data: what the DMIS and I++ DME writers
// print and their strict readers give back (dmis_writer.hpp,
// ippdme_writer.hpp). The planner (src/planning) fills it from a plan and
// its moves; io knows nothing of how the points were chosen.
//
// Positions: `moves_before` and `final_moves` are probe-ball-centre targets
// (DMIS GOTO, I++ GoTo), part frame, mm. A step's point gives the nominal
// contact point xyz and the outward unit normal ijk; the CMM touches moving
// along -ijk from `approach` mm (ball surface to surface) and backs off
// `retract` mm, searching up to `search` mm past the nominal point.
// The last move before a point is its approach point (plan.json `approach`).
//
// Header, speeds and tolerance (docs/cmm.md "What the programs say"):
// `part`, `name`, `revision` and `date` are the program's identification;
// `date` is never read from the clock, so the same plan gives the same
// bytes — it is given (YYYY-MM-DD) or omitted. `head_length` is the SNSDEF
// length as DMIS means it: from the probe head's centre of rotation to the
// ball centre, not the stylus alone. Speeds are mm/s; the profile tolerance
// is the allowed deviation of each point along its normal, lower <= 0 <=
// upper [mm].
//
// Numbers in both programs are fixed-point: coordinates with
// kProgramDecimals decimals (1 nm, far below any CMM's resolution; at most
// 16 digits as the I++ DME spec requires for |x| < 1e9), directions with
// kDirectionDecimals.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "io/cmm/probe_head.hpp"
#include "io/plan_file.hpp"

namespace furrow {

constexpr int kProgramDecimals = 6;
constexpr int kDirectionDecimals = 9;

// The point profile tolerance written with every point (DMIS TOL/PROFP):
// the measured point may lie from `lower` to `upper` mm along the outward
// normal from its nominal.
struct PointProfileTolerance {
  double lower = 0;  // <= 0 [mm]
  double upper = 0;  // >= 0 [mm], upper - lower > 0
};

// What the plan options say about the program beyond the points
// (PlannerOptions::program, `furrow plan` --revision, --program-date,
// --head-length, --tolerance/--outside).
struct ProgramSettings {
  std::string revision;               // part revision, "" = not stated
  std::string date;                   // YYYY-MM-DD, "" = not stated
  std::optional<double> head_length;  // [mm]; default: the stylus length
  std::optional<PointProfileTolerance> tolerance;  // none: no TOL/PROFP
};

// Throws InputError naming the option: a revision that is not printable
// ASCII without quotes (or longer than 32), a date that is not a valid
// YYYY-MM-DD, a head length shorter than `stylus_length`, a tolerance that is
// not lower <= 0 <= upper with a positive width.
void validate(const ProgramSettings& settings, double stylus_length);

struct ProgramStep {
  PlannedPoint point;
  std::vector<Eigen::Vector3d> moves_before;  // GOTO targets, the last = approach point
  // Set by the I++ DME reader: the number of this step's PtMeas command in
  // the file, counting every command from 1 (its tag is (n - 1) % 99999 + 1),
  // so a response log can be matched without knowing the writer's set-up.
  long command = 0;
};

struct ProbeProgram {
  std::string name;       // program name: letters, digits, '_' and '-' (checked by the writers)
  std::string part;       // DMIS PARTID (may be empty)
  std::string revision;   // DMIS PARTRV (may be empty)
  std::string date;       // YYYY-MM-DD in a DMIS comment (may be empty)
  ProbeDefinition probe;  // probe.name is the I++ tool name; DMIS labels it in upper case
  double stylus_length = 0;  // ball centre to probe body [mm] (comment only)
  double head_length = 0;    // head rotation centre to ball centre [mm] (DMIS SNSDEF length)
  double approach = 0, retract = 0, search = 0;  // [mm], > 0
  double move_speed = 0;     // positioning [mm/s] (DMIS FEDRAT/POSVEL, I++ Tool.GoToPar.Speed)
  double measure_speed = 0;  // touch [mm/s] (DMIS FEDRAT/MESVEL, I++ Tool.PtMeasPar.Speed)
  std::optional<PointProfileTolerance> tolerance;  // DMIS only
  // The part alignment measured before the steps (docs/cmm.md "Part
  // alignment"): its features (DMIS only; the I++ DME reader cannot tell
  // them apart and leaves it unset), every alignment point in measuring
  // order with its moves, and the moves from the last one to the start of
  // the steps (the clearance plane above the first approach point).
  std::optional<PartAlignment> alignment;
  // DMIS: a program without an alignment of its own that runs in the one a
  // first program set up and saved (SAVE/DA(PART) after its datums): that
  // label, recalled at the start (RECALL/DA(label)). Empty: the operator
  // establishes the frame. furrow remeasure sets it.
  std::string recalled_alignment;
  std::vector<ProgramStep> alignment_steps;
  std::vector<Eigen::Vector3d> alignment_final_moves;
  std::vector<ProgramStep> steps;
  std::vector<Eigen::Vector3d> final_moves;
  // Indexable head (docs/cmm.md "Indexable heads"): the tips the program
  // defines, in order of first use, and the one selected at the start (it
  // measures the alignment). Empty / unset for the fixed vertical stylus;
  // then no step has a tip, else every step has one of these. A step whose
  // tip differs from the one before is preceded by the tip change: after
  // its first move when it has two or more (the rise to the clearance
  // plane), else before its moves (on the clearance plane, where the
  // alignment or the start left the probe). DMIS sensor and I++ tool of a
  // tip: the probe name, '_', tip_name() (PROBE1_A30B90, Probe1_A30B90).
  std::vector<TipAngles> tips;
  std::optional<TipAngles> start_tip;
  // Those of `tips` the head file did not list as qualified (the planner
  // chose them): the operator qualifies them before running. DMIS lists
  // every tip with its state in a comment; I++ DME has no comments.
  std::vector<TipAngles> unqualified_tips;
};

// The DMIS sensor label / I++ tool name of a tip of `program`'s probe.
std::string tip_sensor_name(const ProbeProgram& program, const TipAngles& tip);

// Fixed-point text with `decimals` digits; "-0.000" is written "0.000".
std::string fixed_number(double value, int decimals);

// The DMIS spelling of a label: upper case (S(PROBE1), F(P0001)), as CMM
// programmers write them and DMIS prints its own words.
std::string dmis_label(const std::string& label);

// The DMIS feature word a datum of this kind is defined and measured as
// (FEAT/..., MEAS/...): PLANE, LINE, POINT, and CIRCLE for a cylinder (a
// bore or boss, measured at one height).
const char* dmis_measure_word(DatumFeature::Kind kind);

// Throws InputError when a name, label or number cannot be written into a
// program: empty or non-ASCII names, ids that are not DMIS labels
// ([A-Za-z0-9_]) or that become the same label in upper case, non-finite
// numbers, non-positive distances or speeds, |coordinate| >= 1e9, header
// fields validate() refuses. `format` ("DMIS", "I++ DME") prefixes the
// message.
void check_program(const ProbeProgram& program, const std::string& format);

}  // namespace furrow

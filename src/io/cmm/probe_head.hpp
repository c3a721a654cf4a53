#pragma once
// An indexable (articulating) probe head and what hangs on it: head.json
// (`furrow plan --head`, docs/formats.md "Probe head", docs/cmm.md
// "Indexable heads").
//
// The head turns the probe about two axes in fixed steps, as a Renishaw PH10:
// A tilts the stylus away from straight down (-z), B then turns the tilted
// stylus about the machine's z axis. The stylus direction (from the head's
// centre of rotation towards the ball) is
//   t(A, B) = (sin A cos B, sin A sin B, -cos A)
// so A = 0 is the vertical stylus, A = 90, B = 0 points along +x and
// A = 90, B = 90 along +y. (CMMs differ in where they put B = 0; a machine
// whose B = 0 points elsewhere must qualify the tips under these names.)
//
// What is modelled, from the ball up, all along -t:
//   stylus     ball diameter, stem diameter, length ball centre to its end;
//   extension  optional, length and diameter;
//   probe body length and diameter (the probe, e.g. a TP20 module);
//   head       the head's housing: a vertical cylinder above the centre of
//              rotation (length, diameter), which does not tilt.
// The centre of rotation is at the end of the probe body: the DMIS SNSDEF
// length is stylus + extension + body.
//
// The CMM measures with the tip angles its operator qualified, which must
// lie on the head's grid (a range and a step per axis). The list keeps the
// file's order; the planner prefers nothing by that order (it picks by the
// surface normal). It may be empty here: the planner then chooses the tips
// itself (`--tips auto`), and refuses an empty list otherwise
// (planning/probe_planner.hpp).
//
// Errors: InputError naming the file and the field ("head.json:
// qualified[3].a: 52 is not on the A grid 0 + k * 7.5"). Units: mm, degrees.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "io/plan_point.hpp"

namespace furrow {

struct IndexAxis {
  double min = 0, max = 0, step = 0;  // [degrees], min <= max, step > 0
  // Is `degrees` min + k step for an integer k, within the range (1e-9 slack)?
  bool on_grid(double degrees) const;
};

struct ProbeHead {
  std::string type;        // free text ("PH10M"), informative
  IndexAxis a, b;          // the head's index grid
  double stylus_length = 20;        // ball centre to the stylus's end [mm], > ball radius
  double ball_diameter = 2;         // [mm] > 0
  double stem_diameter = 1;         // [mm] 0 < stem <= ball
  double extension_length = 0;      // [mm] >= 0 (0: none)
  double extension_diameter = 0;    // [mm] > 0 when there is an extension
  double body_length = 0;           // [mm] > 0
  double body_diameter = 0;         // [mm] > 0
  double head_length = 0;           // vertical housing above the centre of rotation [mm] >= 0
  double head_diameter = 0;         // [mm] > 0 when head_length > 0
  std::vector<TipAngles> qualified; // no duplicates, on the grid; may be empty (see above)

  // Centre of rotation to ball centre [mm] (the DMIS SNSDEF length).
  double reach() const { return stylus_length + extension_length + body_length; }
};

// The stylus direction t(A, B): unit, from the head towards the ball.
Eigen::Vector3d tip_direction(const TipAngles& tip);

// The tip's name in programs: "A" angle "B" angle in degrees, shortest
// decimals, '.' written 'P' and '-' written 'M' so that it is a DMIS label
// and an I++ tool name: A30B90, A7P5BM180.
std::string tip_name(const TipAngles& tip);

// A sensor / tool name "BASE_" tip_name() split into BASE and the tip;
// nullopt when the name does not end in a tip name in that exact spelling.
struct TipSensor {
  std::string base;
  TipAngles tip;
};
std::optional<TipSensor> split_tip_sensor(const std::string& name);

// An angle as programs write it: at most 6 decimals, no trailing zeros ("30", "7.5").
std::string angle_text(double degrees);

ProbeHead parse_probe_head(const std::string& text, const std::string& name);
ProbeHead read_probe_head(const std::string& path);

}  // namespace furrow

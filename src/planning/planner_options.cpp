// Validation and resolved defaults of PlannerOptions (probe_planner.hpp).
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <algorithm>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"
#include "planning/probe_planner.hpp"
#include "planning/tip_grid.hpp"

namespace furrow {

namespace {


void positive(double v, const char* option) {
  if (!std::isfinite(v) || !(v > 0)) throw InputError(std::string(option) + " must be a positive number, got " + general(v));
}

void non_negative(double v, const char* option) {
  if (!std::isfinite(v) || v < 0) throw InputError(std::string(option) + " must not be negative, got " + general(v));
}

}  // namespace

double border_clearance(const PlannerOptions& o) { return o.border.value_or(o.probe_diameter / 2 + 1); }
double search_distance(const PlannerOptions& o) { return o.search.value_or(o.approach); }

void use_head(PlannerOptions& o, const ProbeHead& head) {
  o.head = head;
  o.probe_diameter = head.ball_diameter;
  o.stylus_diameter = head.stem_diameter;
  o.stylus_length = head.stylus_length;
}

ProbeGeometry planner_probe(const PlannerOptions& o) {
  ProbeGeometry probe{o.probe_diameter / 2, o.stylus_diameter / 2, o.stylus_length};
  if (!o.head) return probe;
  if (o.head->extension_length > 0) probe.sections.push_back({o.head->extension_length, o.head->extension_diameter / 2});
  probe.sections.push_back({o.head->body_length, o.head->body_diameter / 2});
  probe.housing = {o.head->head_length, o.head->head_diameter / 2};
  return probe;
}

void validate(const PlannerOptions& o) {
  if (o.head) {
    if (o.probe_diameter != o.head->ball_diameter || o.stylus_diameter != o.head->stem_diameter ||
        o.stylus_length != o.head->stylus_length)
      throw InputError("--head gives the stylus: leave out --probe-diameter, --stylus-diameter and --stylus-length");
    if (o.program.head_length) throw InputError("--head gives the head-to-ball length: leave out --head-length");
    if (o.tips == TipChoice::qualified && o.head->qualified.empty())
      throw InputError("--head: the head file lists no qualified tip: qualify at least one, or let the planner "
                       "choose them with --tips auto");
    bool vertical = false;
    for (const TipAngles& t : o.head->qualified) vertical = vertical || t.a == 0;
    if (o.tips == TipChoice::automatic) {
      if (!vertical && !o.head->a.on_grid(0))
        throw InputError("--tips auto: the part alignment is measured with the vertical tip, and the head's A grid "
                         "does not include 0");
      const long orientations = tip_grid_size(*o.head);
      if (orientations > kMaxTipOrientations)
        throw InputError("--tips auto: the head's grid has " + std::to_string(orientations) +
                         " orientations, more than the limit of " + std::to_string(kMaxTipOrientations) +
                         " (docs/formats.md \"Limits\"): use coarser steps");
    } else if (!vertical) {
      throw InputError("--head: the part alignment is measured with the vertical tip: qualify a tip with a = 0");
    }
  } else if (o.tips == TipChoice::automatic) {
    throw InputError("--tips auto chooses among the orientations of an indexable head: give --head (in a job, plan.head)");
  }
  if (o.points && o.density) throw InputError("--points and --density exclude each other");
  if (o.points && *o.points < 1)
    throw InputError("--points must be at least 1, got " + std::to_string(*o.points) + " (a plan needs points)");
  if (o.points && *o.points > limits::kMaxPlanPoints)
    throw InputError("--points " + std::to_string(*o.points) + " is more than the limit of " +
                     std::to_string(limits::kMaxPlanPoints) + " (docs/formats.md \"Limits\")");
  if (o.density) positive(*o.density, "--density (points per cm^2)");
  if (o.min_per_region > limits::kMaxPlanPoints)
    throw InputError("--min-per-region " + std::to_string(o.min_per_region) + " is more than the limit of " +
                     std::to_string(limits::kMaxPlanPoints) + " points (docs/formats.md \"Limits\")");
  if (o.gouge_points > limits::kMaxPlanPoints)
    throw InputError("--gouge-points " + std::to_string(o.gouge_points) + " is more than the limit of " +
                     std::to_string(limits::kMaxPlanPoints) + " points (docs/formats.md \"Limits\")");
  if (o.probe_diameter < limits::kMinProbeDiameterMm || o.probe_diameter > limits::kMaxProbeDiameterMm)
    throw InputError("--probe-diameter " + general(o.probe_diameter) + " mm is outside the range " +
                     general(limits::kMinProbeDiameterMm) + " to " + general(limits::kMaxProbeDiameterMm) +
                     " mm (docs/formats.md \"Limits\")");
  if (o.min_per_region < 0) throw InputError("--min-per-region must not be negative");
  if (o.border) non_negative(*o.border, "--border (mm)");
  non_negative(o.contact.shift, "--contact-shift (mm)");
  positive(o.contact.tolerance, "contact tolerance (mm)");
  positive(o.probe_diameter, "--probe-diameter (mm)");
  positive(o.stylus_diameter, "--stylus-diameter (mm)");
  positive(o.stylus_length, "--stylus-length (mm)");
  if (o.stylus_diameter > o.probe_diameter)
    throw InputError("--stylus-diameter " + general(o.stylus_diameter) + " is larger than --probe-diameter " +
                     general(o.probe_diameter) + " (the shaft would touch before the ball)");
  if (!(o.stylus_length > o.probe_diameter / 2))
    throw InputError("--stylus-length " + general(o.stylus_length) + " must exceed the ball radius " +
                     general(o.probe_diameter / 2) + " (it is measured from the ball centre)");
  positive(o.approach, "--approach (mm)");
  positive(o.retract, "--retract (mm)");
  if (o.search) positive(*o.search, "--search (mm)");
  non_negative(o.clearance, "--clearance (mm)");
  if (!std::isfinite(o.max_tilt_degrees) || !(o.max_tilt_degrees > 0) || o.max_tilt_degrees > 180)
    throw InputError("--max-tilt must be in (0, 180] degrees, got " + general(o.max_tilt_degrees));
  positive(o.motion.move_speed, "--move-speed (mm/s)");
  positive(o.motion.touch_speed, "--touch-speed (mm/s)");
  positive(o.motion.acceleration, "--acceleration (mm/s^2)");
  non_negative(o.motion.dwell, "--dwell (s)");
  if (o.gouge_points < 1) throw InputError("--gouge-points must be at least 1");
  validate(o.program, o.stylus_length);
  for (unsigned char c : o.probe_name)
    if (!std::isalnum(c) && c != '_') throw InputError("--probe-name " + quote_field(o.probe_name) + ": use letters, digits and '_' only");
  if (o.probe_name.empty() || o.probe_name.size() > 32) throw InputError("--probe-name must have 1 to 32 characters");
  non_negative(o.weights.curvature, "curvature weight");
  non_negative(o.weights.risk, "risk weight");
  positive(o.max_move_fraction, "relocation radius fraction");
  if (o.tip_cover.exact_max_pairs < 0 || o.tip_cover.exact_max_nodes < 0)
    throw InputError("tip cover limits must not be negative");
  if (o.relocation_rings < 1 || o.relocation_directions < 1) throw InputError("relocation rings and directions must be >= 1");
  if (o.setups < 1 || o.setups > kMaxSetups)
    throw InputError("--setups must be from 1 to " + std::to_string(kMaxSetups) + ", got " + std::to_string(o.setups));
  if (!o.setup_faces.empty() && o.setups != 1 && o.setups < 1 + static_cast<int>(o.setup_faces.size()))
    throw InputError("--setup-faces names " + std::to_string(o.setup_faces.size()) + " faces for setups 2 on, but --setups is " +
                     std::to_string(o.setups) + ": raise --setups or leave it out");
  if (static_cast<int>(o.setup_faces.size()) >= kMaxSetups)
    throw InputError("--setup-faces: at most " + std::to_string(kMaxSetups - 1) + " faces (setups 2 to " +
                     std::to_string(kMaxSetups) + ")");
}

int setup_count(const PlannerOptions& o) {
  return std::max(o.setups, 1 + static_cast<int>(o.setup_faces.size()));
}

std::vector<int> parse_face_list(const std::string& text, const std::string& where) {
  std::vector<int> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    std::size_t used = 0;
    long value = -1;
    try {
      value = std::stol(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size() || value < 0 || value > std::numeric_limits<int>::max())
      throw InputError(where + ": \"" + item + "\" is not a face index (face indices from 0, comma-separated: 3,7)");
    for (int f : out)
      if (f == value) throw InputError(where + ": face " + item + " is named twice");
    out.push_back(static_cast<int>(value));
    at = comma + 1;
  }
  return out;
}

std::string face_list_text(const std::vector<int>& faces) {
  std::string out;
  for (int f : faces) out += (out.empty() ? "" : ",") + std::to_string(f);
  return out;
}

}  // namespace furrow

#include "stage/plan_options.hpp"

#include "base/error.hpp"
#include "io/cmm/probe_head.hpp"

namespace furrow {

namespace {

OptionTable<PlannerOptions> make_table() {
  using O = PlannerOptions;
  using nlohmann::json;
  OptionTable<O> t;
  t.push_back(integer_option<O>("points", "N", "total points; excludes --density",
                                [](auto& o) -> auto& { return o.points; }, 1));
  t.push_back(written_as(
      number_option<O>("density", "PER_CM2", "points per cm^2 of region area",
                       [](auto& o) -> auto& { return o.density; }),
      [](const O& o) { return json_fields::finite(o.density.value_or(o.points ? 0.0 : kDefaultDensity), "density"); },
      "1, without --points"));
  t.push_back(integer_option<O>("min_per_region", "N", "fewest points in any region",
                                [](auto& o) -> auto& { return o.min_per_region; }, 0));
  OptionSpec<O> strategy = parsed_option<O>(
      "strategy", "S",
      "sampling inside regions: hammersley, halton, stratified, grid, random, curvature or risk (at the "
      "predicted error maxima, needs the prediction); docs/cmm.md",
      [](auto& o) -> auto& { return o.strategy; }, parse_sampling_strategy,
      [](SamplingStrategy s) { return std::string(to_string(s)); }, choice_names({SamplingStrategy::hammersley, SamplingStrategy::halton, SamplingStrategy::stratified,
                    SamplingStrategy::grid, SamplingStrategy::random, SamplingStrategy::curvature,
                    SamplingStrategy::risk}));
  strategy.example = "halton";
  t.push_back(strategy);
  t.push_back(integer_option<O>("seed", "N", "random seed of the sampling", [](auto& o) -> auto& { return o.seed; },
                                0));
  t.push_back(written_as(
      number_option<O>("border", "MM", "clearance from region edges on the surface; a region too narrow for the default "
                       "takes the ball-contact rule (docs/cmm.md \"Narrow regions\")",
                       [](auto& o) -> auto& { return o.border; }, Bound::non_negative),
      [](const O& o) { return json_fields::finite(border_clearance(o), "border"); }, "probe radius + 1"));
  t.push_back(number_option<O>(
      "contact_shift", "MM",
      "in a region too narrow for the border: how far off its place the ball may be while its contact stays "
      "in the region (docs/cmm.md \"Narrow regions\")",
      [](auto& o) -> auto& { return o.contact.shift; }, Bound::non_negative));
  t.push_back(text_option<O>("probe_name", "NAME", "tool / sensor name on the CMM",
                             [](auto& o) -> auto& { return o.probe_name; }));
  t.push_back(number_option<O>("probe_diameter", "MM", "ball diameter",
                               [](auto& o) -> auto& { return o.probe_diameter; }));
  t.push_back(number_option<O>("stylus_length", "MM", "ball centre to probe body",
                               [](auto& o) -> auto& { return o.stylus_length; }));
  t.push_back(number_option<O>("stylus_diameter", "MM", "shaft diameter",
                               [](auto& o) -> auto& { return o.stylus_diameter; }));
  t.push_back(number_option<O>("approach", "MM", "the touch starts this far from the surface",
                               [](auto& o) -> auto& { return o.approach; }));
  t.push_back(number_option<O>("retract", "MM", "back-off after the touch",
                               [](auto& o) -> auto& { return o.retract; }));
  t.push_back(written_as(number_option<O>("search", "MM", "search distance past the nominal point",
                                          [](auto& o) -> auto& { return o.search; }),
                         [](const O& o) { return json_fields::finite(search_distance(o), "search"); },
                         "the approach"));
  t.push_back(number_option<O>(
      "clearance", "MM",
      "ball-to-part clearance of straight moves; the clearance plane is this far above the part",
      [](auto& o) -> auto& { return o.clearance; }, Bound::non_negative));
  t.push_back(number_option<O>(
      "max_tilt", "DEG",
      "largest angle between the surface normal and the stylus axis (vertical, or the tip's axis with a head)",
      [](auto& o) -> auto& { return o.max_tilt_degrees; }));
  t.push_back(number_option<O>("move_speed", "MM/S", "positioning speed the programs set",
                               [](auto& o) -> auto& { return o.motion.move_speed; }));
  t.push_back(number_option<O>("touch_speed", "MM/S", "measuring speed the programs set",
                               [](auto& o) -> auto& { return o.motion.touch_speed; }));
  t.push_back(number_option<O>("acceleration", "MM/S2", "CMM acceleration, for the cycle time estimate",
                               [](auto& o) -> auto& { return o.motion.acceleration; }));
  t.push_back(number_option<O>("dwell", "S", "settling time per touch, for the cycle time estimate",
                               [](auto& o) -> auto& { return o.motion.dwell; }, Bound::non_negative));
  t.push_back(integer_option<O>("gouge_points", "N", "points on each predicted gouge site",
                                [](auto& o) -> auto& { return o.gouge_points; }, 1));
  OptionSpec<O> tips = parsed_option<O>(
      "tips", "qualified|auto",
      "with --head: measure with the head file's qualified tips only, or let the planner choose among the "
      "orientations of the head's grid (already-qualified tips first, then the fewest; the new ones are listed "
      "for qualifying; docs/cmm.md \"Tips chosen by the planner\")",
      [](auto& o) -> auto& { return o.tips; }, parse_tip_choice,
      [](TipChoice c) { return std::string(to_string(c)); },
      choice_names({TipChoice::qualified, TipChoice::automatic}));
  tips.example = "auto";
  t.push_back(tips);
  OptionSpec<O> revision = text_option<O>("revision", "TEXT", "part revision stated in the DMIS program (PARTRV)",
                                          [](auto& o) -> auto& { return o.program.revision; });
  t.push_back(revision);
  OptionSpec<O> date = written_as(
      text_option<O>("program_date", "YYYY-MM-DD",
                     "date stated in the DMIS header; never taken from the clock, so the same plan gives the "
                     "same bytes on any day",
                     [](auto& o) -> auto& { return o.program.date; }),
      [](const O& o) { return o.program.date.empty() ? json(nullptr) : json(o.program.date); }, "none stated");
  date.example = "2026-11-27";
  t.push_back(date);
  t.push_back(written_as(
      number_option<O>("head_length", "MM",
                       "probe head's centre of rotation to the ball centre, the DMIS SNSDEF length",
                       [](auto& o) -> auto& { return o.program.head_length; }),
      [](const O& o) { return json_fields::finite(o.program.head_length.value_or(o.stylus_length), "head length"); },
      "the stylus length"));
  OptionSpec<O> datums = parsed_option<O>(
      "datums", "auto|A,B,C",
      "part alignment measured first (docs/cmm.md \"Part alignment\"): auto proposes the largest plane facing "
      "+z, the largest wall and the largest wall across it; or three face names; a part without them gets a "
      "manual best-fit alignment on three points",
      [](auto& o) -> auto& { return o.datums; }, parse_datum_choice,
      [](const DatumChoice& d) { return to_string(d); });
  datums.example = "top,left,front";
  t.push_back(datums);
  t.push_back(integer_option<O>(
      "setups", "N",
      "setups: what the part as imported leaves unmeasured is planned with the part resting on another stable "
      "face, one folder per setup (docs/cmm.md \"Setups\"); furrow plan only, a job refuses more than one",
      [](auto& o) -> auto& { return o.setups; }, 1));
  OptionSpec<O> faces = written_as(
      parsed_option<O>("setup_faces", "F1,F2",
                       "face indices the part rests on in setups 2, 3, ... (planar faces); unnamed setups take the "
                       "stable planar face that reaches the most unmeasured area",
                       [](auto& o) -> auto& { return o.setup_faces; }, parse_face_list, face_list_text),
      [](const O& o) { return o.setup_faces.empty() ? json(nullptr) : json(face_list_text(o.setup_faces)); },
      "chosen by the planner");
  faces.example = "3,7";
  t.push_back(faces);
  return t;
}

}  // namespace

const OptionTable<PlannerOptions>& plan_option_table() {
  static const OptionTable<PlannerOptions> table = make_table();
  return table;
}

const std::vector<std::string> kProbeMotionKeys = {"stylus_length", "stylus_diameter", "approach",
                                                   "retract",       "search",          "clearance",
                                                   "max_tilt",      "move_speed",      "touch_speed"};
const std::vector<std::string> kProgramKeys = {"revision", "program_date", "head_length"};

const HeadOptionNames kHeadFlags{"--head", "--probe-diameter, --stylus-diameter and --stylus-length", "--tips auto"};
const HeadOptionNames kHeadJobMembers{"plan.head", "probe_diameter, stylus_diameter and stylus_length",
                                      "\"tips\": \"auto\""};

bool stylus_changed(const PlannerOptions& o) {
  const PlannerOptions defaults;
  return o.probe_diameter != defaults.probe_diameter || o.stylus_diameter != defaults.stylus_diameter ||
         o.stylus_length != defaults.stylus_length;
}

void use_head_file(PlannerOptions& o, const std::string& path, bool stylus_given, const HeadOptionNames& names) {
  if (stylus_given) throw InputError(names.head + " gives the stylus: leave out " + names.stylus);
  use_head(o, read_probe_head(path));
  if (o.head->qualified.empty() && o.tips != TipChoice::automatic)
    throw InputError(path + ".qualified: no qualified tip is listed; qualify at least one, or let the planner "
                            "choose the tips with " + names.tips_auto);
}

}  // namespace furrow

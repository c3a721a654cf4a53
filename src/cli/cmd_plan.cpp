// furrow plan PART --regions REGIONS.json --out plans/NAME: probe points per
// region, collision-checked, ordered, with DMIS and I++ DME programs.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/atomic_file.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "partition/regions_file.hpp"
#include "planning/prediction_risk.hpp"
#include "stage/plan_options.hpp"
#include "stage/plan_stage.hpp"
#include "inspection/tolerance_zone.hpp"
#include "io/plan_file.hpp"
#include "io/qif/plan_qif.hpp"

namespace furrow::cli {

namespace {

// The program name: the output folder's name (stage/plan_stage.hpp).
std::string program_name(const std::string& out) {
  std::string base = std::filesystem::path(out).lexically_normal().filename().string();
  if (base.empty() || base == "." || base == "..")
    base = std::filesystem::path(out).lexically_normal().parent_path().filename().string();
  return cmm_program_name(base, "furrow_plan");
}


// The summary to stdout; uncovered regions to stderr as an error, or to
// stdout when accepted.
void print_coverage(const PlanCoverage& c, bool allowed) {
  std::cout << "coverage: " << c.regions_covered << " of " << c.regions.size()
            << " regions hold their minimum of points; " << c.planned << " of " << c.allocated
            << " allocated points planned, " << c.dropped << " dropped\n";
  const CoverageArea& a = c.area;
  std::cout << "area: " << fixed(100 * a.share_covered(), 1) << " % covered of " << fixed(a.total, 0)
            << " mm^2; reachable but not planned " << fixed(a.reachable_unplanned, 0)
            << " mm^2; unreachable " << fixed(a.unreachable_narrow + a.unreachable_access, 0) << " mm^2 ("
            << fixed(a.unreachable_narrow, 0) << " too narrow for the ball, " << fixed(a.unreachable_access, 0)
            << " out of the probe's reach)\n";
  if (c.complete()) return;
  if (allowed) {
    std::cout << "uncovered regions (accepted with --allow-uncovered):\n" << c.describe_uncovered();
    return;
  }
  const std::size_t short_count = c.regions.size() - static_cast<std::size_t>(c.regions_covered);
  std::cerr << "furrow plan: " << short_count << (short_count == 1 ? " region holds" : " regions hold")
            << " fewer points than the minimum:\n"
            << c.describe_uncovered()
            << "the plan is written, but it does not inspect these regions; lower --border or --min-per-region, "
               "use a smaller probe, or accept it with --allow-uncovered\n";
}

void print_summary(std::ostream& out, const PlanResult& r, const std::string& folder) {
  std::size_t planned_here = 0;  // regions left to another setup are not this plan's
  for (const RegionPlanSummary& s : r.regions) planned_here += !s.elsewhere;
  out << "plan: " << r.plan.points.size() << " points in " << planned_here << " regions, border "
      << fixed(r.border, 2) << " mm, probe " << r.plan.probe.name << " diameter " << fixed(r.plan.probe.diameter, 3)
      << " mm\n";
  for (const RegionPlanSummary& s : r.regions) {
    if (s.elsewhere) continue;
    char line[200];
    std::snprintf(line, sizeof line, "  region %3d  %-8s %10.1f mm^2  allocated %5d  planned %5d  moved %4d  dropped %4d%s\n",
                  s.region, to_string(s.curvature_class), s.area, s.allocated, s.planned, s.moved, s.dropped,
                  s.samplable ? (s.contact_rule ? "  (narrow: ball contact rule)" : "")
                              : "  (no point admissible: see the issues)");
    out << line;
  }
  std::size_t issues = 0;
  for (const PlanIssue& i : r.issues) issues += i.kind != PlanIssue::Kind::moved;
  out << "tour: " << fixed(r.tour.length, 1) << " mm between probe centres (nearest neighbour "
      << fixed(r.tour.nearest_neighbour_length, 1) << " mm); moves: " << r.cycle.straight_moves << " straight, "
      << r.cycle.plane_moves << " over the clearance plane z = " << fixed(r.clearance_z, 3) << "\n";
  if (!r.plan.points.empty() && r.plan.points.front().tip) {
    std::vector<std::string> used;
    for (const PlannedPoint& p : r.plan.points)
      if (used.empty() || used.back() != tip_name(*p.tip)) used.push_back(tip_name(*p.tip));
    out << "tips: " << r.tip_changes << " changes;";
    for (const std::string& t : used) out << ' ' << t;
    out << "\n";
    // What the operator qualifies before running, in the order used.
    int fresh = 0;
    out << "tips in the order used:";
    for (const PlanTip& t : r.plan.tips) {
      out << ' ' << tip_name(t.angles) << (t.qualified ? " (qualified)" : " (new)");
      fresh += !t.qualified;
    }
    out << "; " << fresh << " to qualify\n";
    if (r.tip_choice.automatic) {
      const TipCover& c = r.tip_choice.cover;
      out << "tip choice: " << r.tip_choice.orientations << " orientations, " << c.tests << " of "
          << r.tip_choice.pairs << " point-tip pairs checked; "
          << (c.optimal ? std::string("exact, optimal")
                        : (c.exact ? "exact search stopped at its node cap, " : "greedy, ") +
                              std::string("new tips within ") + fixed(c.bound, 3) + " x the fewest")
          << "\n";
    }
  }
  out << "cycle time estimate: " << fixed(r.cycle.seconds / 60, 1) << " min (" << fixed(r.cycle.positioning_length, 0)
      << " mm positioning)\n";
  for (const PlanIssue& i : r.issues)
    if (i.kind == PlanIssue::Kind::face_facing_down) out << "orientation: " << i.reason << "\n";
  if (issues > 0 || !r.issues.empty())
    out << r.issues.size() << " issues (moved or dropped points, short regions): see " << folder << "/report.json\n";
}

int run_plan(Args& args) {
  PlannerOptions o;
  const std::string regions_path = args.required_option("regions");
  const std::string out = args.required_option("out");
  const std::optional<std::string> prediction_path = args.option("prediction");
  read_option_flags(args, plan_option_table(), o);
  const std::optional<std::string> head_path = args.option("head");
  // The profile zone plan.qif states (docs/qif.md), as `furrow compare` takes it.
  const double qif_tolerance = args.positive_or("tolerance", 0.05);
  const auto qif_outside = args.number("outside");
  const bool allow_uncovered = args.flag("allow-uncovered");
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  const ToleranceZone zone = ToleranceZone::make(qif_tolerance, qif_outside.value_or(qif_tolerance / 2),
                                                 "--tolerance/--outside");
  o.program.tolerance = PointProfileTolerance{zone.lower(), zone.upper()};
  if (head_path) {
    try {
      use_head_file(o, *head_path, stylus_changed(o), kHeadFlags);
    } catch (const InputError& e) {
      args.fail(e.what());
    }
  }
  try {
    validate(o);
  } catch (const InputError& e) {
    args.fail(e.what());
  }
  if (needs_risk(o.strategy) && !prediction_path)
    args.fail(std::string("--strategy ") + to_string(o.strategy) + " needs a machining prediction (--prediction)");
  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.add_input(regions_path, "regions");
  if (prediction_path) outputs.add_input(*prediction_path, "prediction");
  if (head_path) outputs.add_input(*head_path, "head");
  outputs.will_write(out);
  o.part_name = part_path;

  const Part part = read_part(part_path);
  const RegionMap map = read_regions(regions_path);
  map.check_belongs_to(part, regions_path, part_path);
  std::optional<Prediction> prediction;
  std::optional<PredictionRiskMap> risk;
  if (prediction_path) {
    prediction = read_prediction(*prediction_path);
    risk.emplace(*prediction, part, *prediction_path, part_path);
  }

  const bool show = ::isatty(2);
  const char* shown = nullptr;
  const std::string name = program_name(out);
  const PlanStage stage = naming_inputs(part_path + " with " + regions_path, [&] {
    return plan_stage(part, map, o, risk ? &*risk : nullptr, name, regions_path, prediction_path.value_or(""),
                      [&](const char* step, std::size_t done, std::size_t total) {
                        if (!show) return;
                        std::cerr << "\rplan: " << step << " " << done << "/" << total << "        " << std::flush;
                        shown = step;
                      });
  });
  if (show && shown) std::cerr << "\n";

  const std::string staging = outputs.folder(out);
  for (const FolderFile& f : stage.files) {
    std::filesystem::create_directories(std::filesystem::path(staging + "/" + f.path).parent_path());
    write_file_atomically(staging + "/" + f.path, f.bytes);
  }
  if (stage.setups.empty()) {
    write_file_atomically(staging + "/plan.qif", plan_to_qif(parse_plan(stage.plan_json, out + "/plan.json"),
                                                             part_path, zone.width, zone.outside));
  } else {
    for (const SetupPlan& s : stage.setups)
      write_file_atomically(staging + "/" + s.folder + "/plan.qif",
                            plan_to_qif(parse_plan(s.plan_json, out + "/" + s.folder + "/plan.json"), part_path,
                                        zone.width, zone.outside));
  }
  outputs.publish();
  if (stage.setups.empty()) {
    print_summary(std::cout, stage.result, out);
    print_coverage(stage.coverage, allow_uncovered);
    std::cout << "wrote " << out << "/{plan.json, plan.csv, " << name << ".dmi, " << name << ".prg, plan.png, coverage.png, report.json, plan.qif}\n";
  } else {
    for (const SetupPlan& s : stage.setups) {
      std::cout << "setup " << s.setup.index << ": ";
      if (s.setup.resting_face)
        std::cout << "the part resting on face " << *s.setup.resting_face << " (\""
                  << part.faces[static_cast<std::size_t>(*s.setup.resting_face)].name() << "\")"
                  << (s.setup.named ? ", named" : ", chosen for " + fixed(s.estimated_area, 0) + " mm^2 it reaches")
                  << "; plans the regions still short\n";
      else
        std::cout << "the part as imported\n";
      print_summary(std::cout, s.result, out + "/" + s.folder);
      const CoverageArea& a = s.coverage.area;
      std::cout << "setup " << s.setup.index << " coverage: " << s.coverage.regions_covered << " of "
                << s.coverage.regions.size() << " regions planned here hold their minimum; "
                << fixed(a.covered, 0) << " of " << fixed(a.total, 0) << " mm^2 covered\n";
    }
    if (!stage.note.empty()) std::cout << "note: " << stage.note << "\n";
    std::cout << "combined over " << stage.setups.size() << " setups:\n";
    print_coverage(stage.coverage, allow_uncovered);
    std::cout << "wrote " << out << "/{report.json, coverage.png";
    for (const SetupPlan& s : stage.setups) std::cout << ", " << s.folder << "/";
    std::cout << "} (each setup: plan.json, plan.csv, " << name << "_S<k>.dmi, .prg, plan.png, coverage.png, report.json, plan.qif)\n";
  }
  return stage.coverage.complete() || allow_uncovered ? kExitOk : kExitFail;
}

std::string plan_options_help() { return option_help_lines(describe(plan_option_table())); }

}  // namespace

const Command kPlanCommand = {
    "plan", "probe points per region, collision-checked, DMIS and I++ DME programs",
    "usage: furrow plan PART --regions REGIONS.json --out FOLDER [--prediction PREDICTION.json]\n"
    "                   [--tolerance T] [--outside A] [--head HEAD.json] [--allow-uncovered]\n"
    "                   [plan options]\n"
    "\n"
    "Plans CMM probe points on every region of REGIONS.json (furrow partition), keeps\n"
    "them BORDER mm from the region edges, checks that a vertical stylus reaches each\n"
    "one (ball touches only there, shaft clear, tilt), moves or drops those it cannot\n"
    "(with the reason in report.json), orders them into a short tour and writes FOLDER\n"
    "with plan.json, plan.csv, NAME.dmi (DMIS), NAME.prg (I++ DME), plan.png,\n"
    "coverage.png, report.json and plan.qif (QIF 3.0, docs/qif.md), NAME being the\n"
    "folder's name (docs/cmm.md, docs/formats.md).\n"
    "The same inputs and seed give the same files.\n"
    "\n"
    "  --regions FILE       regions of PART (required)\n"
    "  --out FOLDER         output folder, replaced as a whole (required)\n"
    "  --prediction FILE    machining prediction of PART (furrow predict): more points\n"
    "                       where larger errors are predicted, points on every\n"
    "                       predicted gouge site, and --strategy risk\n"
    "  --tolerance T        profile zone width in mm stated in plan.qif and, per\n"
    "                       point, in the DMIS program (TOL/PROFP) (default 0.05)\n"
    "  --outside A          part of the zone on the + side in mm (default T/2)\n"
    "  --head FILE          indexable probe head (docs/formats.md \"Probe head\"): each\n"
    "                       point gets a qualified tip that reaches it, points are\n"
    "                       grouped by tip; the file gives the stylus, and\n"
    "                       --max-tilt is then measured from the tip's axis; with\n"
    "                       --tips auto the planner chooses the tips on the head's\n"
    "                       grid and lists those to qualify\n"
    "  --allow-uncovered    exit 0 although some region holds fewer than\n"
    "                       --min-per-region points (they are still reported, and\n"
    "                       plan.json lists them so no verdict passes them unseen)\n"
    "\n"
    "Plan options (a job file's \"plan\" members, docs/options.md):\n",
    run_plan, plan_options_help,
    "\n"
    "Exit status: 0 every region holds its minimum (or --allow-uncovered), 1 some\n"
    "region does not (named with the reason; the files are written), 2 bad input.\n"};

}  // namespace furrow::cli

#include "stage/plan_stage.hpp"

#include <cctype>
#include <chrono>

#include "base/error.hpp"
#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/plan_csv.hpp"
#include "io/plan_file.hpp"
#include "planning/coverage_image.hpp"
#include "planning/plan_image.hpp"
#include "planning/plan_report.hpp"
#include "planning/setup_choice.hpp"

namespace furrow {

std::string cmm_program_name(const std::string& text, const std::string& fallback) {
  std::string name;
  for (unsigned char c : text) name += (std::isalnum(c) || c == '_' || c == '-') ? static_cast<char>(c) : '_';
  if (name.size() > 64) name.resize(64);
  return name.empty() ? fallback : name;
}

namespace {

// One setup's plan and files (names relative to its folder). `setup`: the
// record plan.json states (none for a plan of one setup); `prefix` goes
// before every point id. The part's views are rasterized once for both
// figures (the most of their cost); `keep_views`, when given, gets them
// for a further figure of the same part.
PlanStage plan_one_setup(const Part& part, const RegionMap& map, const PlannerOptions& options, const RiskMap* risk,
                         const std::string& program, const std::string& regions_name,
                         const std::string& prediction_name, const PlanProgress& progress,
                         const std::optional<PlanSetupRecord>& setup, const std::string& prefix,
                         PartViewPanels* keep_views = nullptr) {
  PlanStage out;
  out.result = plan_probe_points(part, map, options, risk, progress);
  out.result.plan.setup = setup;
  if (!prefix.empty()) {
    for (PlannedPoint& p : out.result.plan.points) p.id = prefix + p.id;
    for (PlanIssue& i : out.result.issues)
      if (!i.point.empty()) i.point = prefix + i.point;
  }
  out.coverage = plan_coverage(out.result, options.min_per_region);
  for (const RegionCoverage& r : out.coverage.uncovered())
    out.result.plan.uncovered_regions.push_back(
        {r.region, static_cast<std::size_t>(r.face), r.planned, r.required, r.reason});
  // The alignment the programs measure first (docs/cmm.md "Part alignment").
  {
    const ClosestPointFinder finder(part);
    AccessOptions access = options.access;
    access.approach = out.result.approach;
    access.retract = out.result.retract;
    access.clearance_z = out.result.clearance_z;
    DatumOptions datum_options;
    datum_options.border = out.result.border;
    out.result.plan.alignment =
        choose_alignment(part, finder, out.result.probe, access, options.datums, datum_options);
  }
  // The vertical tip measures the alignment first: the tips in program order.
  out.result.plan.tips = tips_in_use(out.result, options);
  out.program = program;
  const ProbeProgram cmm = make_probe_program(out.result, program, options);
  out.plan_json = plan_to_json_text(out.result.plan);
  PartViewPanels views = part_view_panels(part);
  const std::vector<unsigned char> png = plan_image_png(map, out.result, views);
  const std::vector<unsigned char> coverage_png =
      keep_views ? coverage_image_png(map, out.result, out.coverage, views)
                 : coverage_image_png(map, out.result, out.coverage, std::move(views));
  if (keep_views) *keep_views = std::move(views);
  out.files = {
      {"plan.json", out.plan_json},
      {"plan.csv", plan_to_csv_text(out.result.plan)},
      {program + ".dmi", dmis_program_text(cmm)},
      {program + ".prg", ippdme_program_text(cmm)},
      {"report.json", plan_report_json(out.result, out.coverage, options, options.part_name, regions_name, prediction_name)},
      {"plan.png", std::string(png.begin(), png.end())},
      {"coverage.png", std::string(coverage_png.begin(), coverage_png.end())},
  };
  return out;
}

PlanSetupRecord setup_record(const PartSetup& s) {
  PlanSetupRecord r;
  r.index = s.index;
  if (s.resting_face) r.resting_face = static_cast<std::size_t>(*s.resting_face);
  r.rotation = s.to_setup.linear();
  r.translation = s.to_setup.translation();
  return r;
}

// Regions another setup may help: short of their minimum because the probe
// cannot reach them (a narrow region or a sparse allocation stays as it is
// whichever way the part lies).
void mark_short_for_access(const PlanCoverage& c, std::vector<char>& wanted) {
  for (const RegionCoverage& r : c.regions)
    wanted[static_cast<std::size_t>(r.region)] = !r.covered && r.state == CoverageState::unreachable_access;
}

}  // namespace

PlanStage plan_stage(const Part& part, const RegionMap& map, const PlannerOptions& options, const RiskMap* risk,
                     const std::string& program, const std::string& regions_name,
                     const std::string& prediction_name, const PlanProgress& progress) {
  validate(options);
  const int count = setup_count(options);
  if (count == 1) return plan_one_setup(part, map, options, risk, program, regions_name, prediction_name, progress, {}, "");
  // The named faces are checked before anything is planned.
  std::vector<RestingFace> named;
  for (int f : options.setup_faces) named.push_back(named_resting_face(part, map, f, "--setup-faces"));

  PlanStage out;
  out.program = program;
  std::vector<char> wanted(map.regions.size(), 0);
  std::vector<int> used;
  std::vector<PlanCoverage> coverages;
  std::vector<SetupSummary> summaries;
  PartViewPanels part_views;  // setup 1's, of the part as imported: for the combined figure
  for (int k = 1; k <= count; ++k) {
    PartSetup setup;
    double estimate = 0;
    const auto chosen_from = std::chrono::steady_clock::now();
    // With several setups the part of setup 1 stands on the table too: its
    // lowest point (of the control box, which contains it) is the fixture
    // plane, so nothing is planned from below it.
    if (k == 1) setup.fixture_z = part.control_box().min().z();
    if (k > 1) {
      bool any = false;
      for (char w : wanted) any = any || w;
      if (!any && static_cast<std::size_t>(k - 2) >= named.size()) {
        out.note = "setup " + std::to_string(k) + " not made: no region is left short for want of access";
        break;
      }
      if (static_cast<std::size_t>(k - 2) < named.size()) {
        const RestingFace& f = named[static_cast<std::size_t>(k - 2)];
        setup = resting_setup(f, k, true);
        estimate = score_setup(part, map, options, f, wanted).reachable_area;
      } else {
        const std::optional<SetupScore> best = best_next_setup(part, map, options, wanted, used);
        if (!best) {
          out.note = "setup " + std::to_string(k) +
                     " not made: on no further stable planar face does the probe reach a region still short";
          break;
        }
        setup = resting_setup(best->face, k, false);
        estimate = best->reachable_area;
      }
      used.push_back(*setup.resting_face);
    }
    const double choice_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - chosen_from).count();
    const Part moved = k == 1 ? Part{} : moved_part(part, setup.to_setup);
    const RegionMap moved_map = k == 1 ? RegionMap{} : moved_regions(map, setup.to_setup);
    PlannerOptions o = options;
    o.access.fixture_z = setup.fixture_z;
    if (k > 1) {
      o.planned_elsewhere.assign(map.regions.size(), 0);
      for (std::size_t r = 0; r < wanted.size(); ++r) o.planned_elsewhere[r] = !wanted[r];
    }
    const std::string folder = "setup" + std::to_string(k);
    PlanStage one;
    try {
      one = plan_one_setup(k == 1 ? part : moved, k == 1 ? map : moved_map, o, risk, program + "_S" + std::to_string(k),
                           regions_name, prediction_name, progress, setup_record(setup),
                           k == 1 ? "" : "S" + std::to_string(k) + "_", k == 1 ? &part_views : nullptr);
    } catch (const InputError& e) {
      if (k == 1) throw;
      // Nothing the probe can take in this setup (all of it blocked).
      out.note = "setup " + std::to_string(k) + " (resting on face " + std::to_string(*setup.resting_face) +
                 ") not made: " + e.what();
      break;
    }
    mark_short_for_access(one.coverage, wanted);
    coverages.push_back(one.coverage);
    for (FolderFile& f : one.files) out.files.push_back({folder + "/" + f.path, std::move(f.bytes)});
    SetupPlan plan{setup, folder, std::move(one.result), std::move(one.coverage), std::move(one.plan_json), estimate, choice_seconds};
    out.setups.push_back(std::move(plan));
  }
  for (const SetupPlan& p : out.setups) {
    SetupSummary s;
    s.index = p.setup.index;
    s.folder = p.folder;
    s.resting_face = p.setup.resting_face;
    if (s.resting_face) s.resting_face_name = part.faces[static_cast<std::size_t>(*s.resting_face)].name();
    s.named = p.setup.named;
    s.estimated_area = p.estimated_area;
    s.to_setup = p.setup.to_setup;
    s.points = p.result.plan.points.size();
    s.tips = p.result.plan.tips;
    s.coverage = &p.coverage;
    summaries.push_back(s);
  }
  out.coverage = combine_coverage(coverages);
  std::vector<Eigen::Vector3d> points;
  for (const SetupPlan& p : out.setups)
    for (const PlannedPoint& q : p.result.plan.points)
      points.push_back(p.result.plan.setup ? p.result.plan.setup->to_part(q.xyz) : q.xyz);
  const std::vector<unsigned char> png = setups_coverage_image_png(map, out.coverage, points, std::move(part_views));
  out.files.push_back({"report.json", setups_report_json(summaries, out.coverage, options.part_name, regions_name, out.note)});
  out.files.push_back({"coverage.png", std::string(png.begin(), png.end())});
  out.result = out.setups.front().result;
  out.plan_json = out.setups.front().plan_json;
  return out;
}

}  // namespace furrow

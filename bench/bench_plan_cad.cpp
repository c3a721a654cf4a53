// Probe planning on a real-looking multi-face CAD part (target: under 10 s
// and 500 MB for the whole `furrow plan` on about 140 faces).
//
// The part is built here with OpenCASCADE, as a CAD system would model a
// fixture plate: a 220 x 150 x 25 mm plate with 20 cylindrical bosses whose
// top edges are filleted (toroidal blends), 20 blind bores and 20 spherical
// dimples on a 20 mm pitch; beside it a block with a B-spline top, a ball,
// a ring (torus) and a truncated cone: planes with many circular trims,
// cylinders, tori, spheres, a cone and a B-spline face, in five solids. It
// is written to STEP and then run through what `furrow plan PART.step` does
// (docs/cmm.md): import, partition, plan and the plan folder's files in
// memory (only writing them to disk is left out). The faces the part stands
// on (facing straight down at the lowest height) are left out, as a user
// leaves them out of an inspection: no probe reaches them on the table.
// Run three times: with the vertical stylus, with an indexable head (a PH10M
// with 21 qualified tips), and with the same head and `--tips auto` (the
// planner chooses among the head's 673 grid orientations, only A0B0
// qualified: docs/cmm.md "Tips chosen by the planner"). Prints per run the
// wall time of each stage, the points allocated and placed, the regions and
// area covered, the tips chosen and the peak resident memory. Prints
// figures; it does not pass or fail.
// Then, with `setups`, the same head with `--tips auto --setups 2` on the
// whole part (docs/cmm.md "Setups"): time, memory, tips per setup and the
// combined covered share.
//   usage: bench_plan_cad [stylus|head|auto|setups] [fixed]    (default: all four)
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Writer.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bench_clock.hpp"
#include "io/cad/cad_import.hpp"
#include "occ_booleans.hpp"
#include "io/cmm/probe_head.hpp"
#include "partition/partition.hpp"
#include "stage/plan_stage.hpp"

using namespace furrow;
using furrow::bench::peak_rss_mb;
using furrow::bench::seconds_since;

namespace {

// A boss of radius r and height h standing on z0, its top edge filleted.
TopoDS_Shape filleted_boss(double x, double y, double z0, double r, double h, double fillet) {
  const TopoDS_Shape boss = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), gp::DZ()), r, h).Shape();
  BRepFilletAPI_MakeFillet round(boss);
  for (TopExp_Explorer e(boss, TopAbs_EDGE); e.More(); e.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    if (curve.GetType() == GeomAbs_Circle && std::abs(curve.Circle().Location().Z() - (z0 + h)) < 1e-9)
      round.Add(fillet, TopoDS::Edge(e.Current()));
  }
  return round.Shape();
}

TopoDS_Shape fixture_plate() {
  TopTools_ListOfShape cutters, bosses;
  int k = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 6; ++j, ++k) {
      const double x = 20 + 20 * i, y = 25 + 20 * j;
      if (k % 3 == 0)
        bosses.Append(filleted_boss(x, y, 25, 5, 8, 1.5));
      else if (k % 3 == 1)
        cutters.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, 15), gp::DZ()), 4, 12).Shape());
      else
        cutters.Append(BRepPrimAPI_MakeSphere(gp_Pnt(x, y, 29), 6).Shape());
    }
  return furrow::bench::cut_then_fuse(BRepPrimAPI_MakeBox(220, 150, 25).Shape(), cutters, bosses);
}

TopoDS_Shape freeform_block() {
  TColgp_Array2OfPnt pts(1, 6, 1, 5);
  for (int i = 1; i <= 6; ++i)
    for (int j = 1; j <= 5; ++j)
      pts(i, j) = gp_Pnt(240 + 12 * (i - 1), 10 * (j - 1), 20 + 4 * std::sin(0.9 * i) * std::cos(0.7 * j));
  const Handle(Geom_BSplineSurface) top = GeomAPI_PointsToBSplineSurface(pts).Surface();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(top, 1e-7).Face();
  return BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, -15)).Shape();
}

TopoDS_Shape make_part() {
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  builder.Add(compound, fixture_plate());
  builder.Add(compound, freeform_block());
  builder.Add(compound, BRepPrimAPI_MakeSphere(gp_Pnt(270, 80, 15), 15).Shape());
  builder.Add(compound, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(270, 130, 8), gp::DZ()), 14, 6).Shape());
  builder.Add(compound, BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(320, 80, 0), gp::DZ()), 12, 5, 18).Shape());
  return compound;
}

// The head of docs/cmm.md's example, tips every 15 degrees of A up to 90
// and every 90 degrees of B.
const char* kHead = R"({
  "head": {"type": "PH10M", "a": {"min": 0, "max": 105, "step": 7.5}, "b": {"min": -180, "max": 180, "step": 7.5},
           "length": 30, "diameter": 24},
  "stylus": {"length": 30, "ball_diameter": 2, "stem_diameter": 1.2},
  "probe_body": {"length": 25, "diameter": 13.2},
  "qualified": [{"a": 0, "b": 0},
                {"a": 15, "b": 0}, {"a": 15, "b": 90}, {"a": 15, "b": 180}, {"a": 15, "b": -90},
                {"a": 30, "b": 0}, {"a": 30, "b": 90}, {"a": 30, "b": 180}, {"a": 30, "b": -90},
                {"a": 45, "b": 0}, {"a": 45, "b": 90}, {"a": 45, "b": 180}, {"a": 45, "b": -90},
                {"a": 60, "b": 0}, {"a": 60, "b": 90}, {"a": 60, "b": 180}, {"a": 60, "b": -90},
                {"a": 90, "b": 0}, {"a": 90, "b": 90}, {"a": 90, "b": 180}, {"a": 90, "b": -90}]
})";

// `fixed`: the border clearance for every region (--border given), as
// before the contact rule of narrow regions (docs/cmm.md "Narrow regions").
void run(const std::string& step, bool head, bool fixed, bool automatic = false) {
  const auto t0 = std::chrono::steady_clock::now();
  Part part = import_cad(step).part;
  const std::size_t imported = part.faces.size();
  part.faces.erase(std::remove_if(part.faces.begin(), part.faces.end(),
                                  [](const Face& f) {
                                    const ParameterDomain& d = f.domain();
                                    const DifferentialGeometry g =
                                        f.geometry((d.u0 + d.u1) / 2, (d.v0 + d.v1) / 2);
                                    return g.normal.z() < -0.99 && std::abs(g.point.z()) < 1e-6;
                                  }),
                   part.faces.end());
  const double t_import = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  const RegionMap map = partition_part(part, {}).map;
  const double t_partition = seconds_since(t1);
  PlannerOptions options;
  options.part_name = "fixture";
  if (head) use_head(options, parse_probe_head(kHead, "head.json"));
  if (automatic) {
    options.head->qualified = {TipAngles{0, 0}};
    options.tips = TipChoice::automatic;
  }
  if (fixed) options.border = border_clearance(options);
  const auto t2 = std::chrono::steady_clock::now();
  const PlanStage stage = plan_stage(part, map, options, nullptr, "fixture", "regions.json", "");
  const double t_plan = seconds_since(t2);
  std::size_t bytes = 0;
  for (const FolderFile& f : stage.files) bytes += f.bytes.size();
  const PlanCoverage& c = stage.coverage;
  std::printf("\n%s, %s, %d OpenMP threads\n",
              automatic ? "indexable head, --tips auto (A0B0 qualified)" : head ? "indexable head (21 tips)" : "vertical stylus",
              fixed ? "fixed border clearance" : "contact rule in narrow regions", omp_get_max_threads());
  std::printf("  faces %zu imported, %zu planned (the table side left out), %zu regions\n", imported,
              part.faces.size(), map.regions.size());
  std::printf("  import %.2f s, partition %.2f s, plan and files %.2f s: total %.2f s (target < 10 s)\n", t_import,
              t_partition, t_plan, seconds_since(t0));
  const PlanTiming& t = stage.result.timing;
  std::printf("  of the plan: regions %.2f s, sampling %.2f s, collision checks %.2f s, ordering %.2f s, moves %.2f s\n",
              t.regions_seconds, t.sampling_seconds, t.access_seconds, t.tour_seconds, t.moves_seconds);
  std::printf("  points: %ld allocated, %ld placed, %ld dropped; regions covered %d of %zu; tip changes %d\n",
              c.allocated, c.planned, c.dropped, c.regions_covered, c.regions.size(), stage.result.tip_changes);
  double area = 0, covered_area = 0;
  int narrow = 0, narrow_covered = 0, skipped = 0, warnings = 0;
  for (std::size_t r = 0; r < c.regions.size(); ++r) {
    const RegionPlanSummary& s = stage.result.regions[r];
    area += s.area;
    if (c.regions[r].covered) covered_area += s.area;
    narrow += s.contact_rule;
    narrow_covered += s.contact_rule && c.regions[r].covered;
  }
  for (const PlanIssue& i : stage.result.issues) {
    skipped += i.kind == PlanIssue::Kind::region_skipped;
    warnings += i.kind == PlanIssue::Kind::face_facing_down;
  }
  std::printf("  area covered %.0f of %.0f mm^2 (%.1f %%); regions skipped (no point admissible) %d; "
              "by the contact rule %d, of which covered %d; orientation warnings %d\n",
              covered_area, area, area > 0 ? 100 * covered_area / area : 0.0, skipped, narrow, narrow_covered, warnings);
  if (head) {
    int fresh = 0;
    std::string names;
    for (const PlanTip& tip : stage.result.plan.tips) {
      fresh += !tip.qualified;
      names += " " + tip_name(tip.angles) + (tip.qualified ? "" : "*");
    }
    std::printf("  tips used %zu (%d new, marked *):%s\n", stage.result.plan.tips.size(), fresh, names.c_str());
    const TipChoiceSummary& tc = stage.result.tip_choice;
    if (tc.automatic)
      std::printf("  tip choice: %d orientations, %ld pairs within the tilt limit, %ld checked; %s; greedy bound "
                  "H(%d) = %.3f; %zu points no orientation reaches\n",
                  tc.orientations, tc.pairs, tc.cover.tests,
                  tc.cover.optimal ? "exact, optimal" : tc.cover.exact ? "exact search capped" : "greedy",
                  tc.cover.bound_n, tc.cover.bound, tc.cover.uncoverable.size());
  }
  if (!c.complete()) std::printf("  uncovered: %s\n", c.describe_uncovered(getenv("BENCH_ALL") ? 1000 : 6).c_str());
  std::printf("  files %zu (%.1f kB); peak resident memory so far %.0f MB (target < 500 MB)\n", stage.files.size(),
              bytes / 1024.0, peak_rss_mb());
}

// `--tips auto --setups 2` on the whole part, the faces it stands on
// included: setup 2 rests on the stable planar face that brings the most
// unreachable area within reach (docs/cmm.md "Setups"). The covered share
// is the combined coverage's, as report.json states it.
void run_setups(const std::string& step) {
  const auto t0 = std::chrono::steady_clock::now();
  const Part part = import_cad(step).part;
  const RegionMap map = partition_part(part, {}).map;
  const double t_prepare = seconds_since(t0);
  PlannerOptions options;
  options.part_name = "fixture";
  use_head(options, parse_probe_head(kHead, "head.json"));
  options.head->qualified = {TipAngles{0, 0}};
  options.tips = TipChoice::automatic;
  options.setups = 2;
  const auto t1 = std::chrono::steady_clock::now();
  const PlanStage stage = plan_stage(part, map, options, nullptr, "fixture", "regions.json", "");
  const double t_plan = seconds_since(t1);
  std::printf("\nindexable head, --tips auto --setups 2, all %zu faces (the table side included), %zu regions, %d "
              "OpenMP threads\n",
              part.faces.size(), map.regions.size(), omp_get_max_threads());
  std::printf("  import and partition %.2f s; plan of the setups and their files %.2f s (target < 30 s)\n", t_prepare,
              t_plan);
  for (const SetupPlan& s : stage.setups) {
    std::string tips;
    for (const PlanTip& t : s.result.plan.tips) tips += " " + tip_name(t.angles) + (t.qualified ? "" : "*");
    const CoverageArea& a = s.coverage.area;
    std::printf("  setup %d%s: %zu points, %zu tips (new marked *):%s; covers %.0f of the %.0f mm^2 it plans "
                "(%d of %zu regions)\n",
                s.setup.index,
                s.setup.resting_face ? (" resting on face " + std::to_string(*s.setup.resting_face) + " (" +
                                        part.faces[static_cast<std::size_t>(*s.setup.resting_face)].name() + ")")
                                           .c_str()
                                     : " (as imported)",
                s.result.plan.points.size(), s.result.plan.tips.size(), tips.c_str(), a.covered, a.total,
                s.coverage.regions_covered, s.coverage.regions.size());
    const PlanTiming& t = s.result.timing;
    std::printf("    face chosen in %.2f s; plan: regions %.2f s, sampling %.2f s, collision checks and tips %.2f s, "
                "ordering %.2f s, moves %.2f s\n",
                s.choice_seconds, t.regions_seconds, t.sampling_seconds, t.access_seconds, t.tour_seconds,
                t.moves_seconds);
  }
  if (!stage.note.empty()) std::printf("  note: %s\n", stage.note.c_str());
  const CoverageArea& a = stage.coverage.area;
  std::printf("  combined: %.1f %% of %.0f mm^2 covered (goal >= 90 %%); reachable not planned %.0f, too narrow %.0f, "
              "out of reach %.0f mm^2; %d of %zu regions\n",
              100 * a.share_covered(), a.total, a.reachable_unplanned, a.unreachable_narrow, a.unreachable_access,
              stage.coverage.regions_covered, stage.coverage.regions.size());
  for (const auto& [problem, area] : a.by_access_problem)
    std::printf("    out of reach, %s: %.0f mm^2\n", to_string(problem), area);
  if (!stage.coverage.complete())
    std::printf("  uncovered: %s\n", stage.coverage.describe_uncovered(getenv("BENCH_ALL") ? 1000 : 6).c_str());
  std::printf("  total %.2f s; peak resident memory so far %.0f MB (target < 500 MB)\n", seconds_since(t0),
              peak_rss_mb());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string only = argc > 1 ? argv[1] : "";
  Message::DefaultMessenger()->ChangePrinters().Clear();
  const std::string dir = (std::filesystem::temp_directory_path() / "furrow_bench_plan_cad").string();
  std::filesystem::create_directories(dir);
  const std::string step = dir + "/fixture.step";
  const TopoDS_Shape part = make_part();
  TopTools_IndexedMapOfShape faces, solids;
  TopExp::MapShapes(part, TopAbs_FACE, faces);
  TopExp::MapShapes(part, TopAbs_SOLID, solids);
  STEPControl_Writer writer;
  writer.Transfer(part, STEPControl_AsIs);
  writer.Write(step.c_str());
  std::printf("part: %d faces in %d solids (plate with 20 filleted bosses, 20 bores, 20 dimples; B-spline block, "
              "ball, ring, cone), STEP %.1f MB\n",
              faces.Extent(), solids.Extent(), std::filesystem::file_size(step) / 1e6);
  // bench_plan_cad [stylus|head|auto|setups] [fixed]
  const bool fixed = argc > 2 && std::string(argv[2]) == "fixed";
  if (only.empty() || only == "stylus") run(step, false, fixed);
  if (only.empty() || only == "head") run(step, true, fixed);
  if (only.empty() || only == "auto") run(step, true, fixed, true);
  if (only.empty() || only == "setups") run_setups(step);
  return 0;
}

// The re-measure loop end to end (docs/verification.md "Re-measuring"): an
// INCONCLUSIVE comparison, `furrow remeasure` planning what it left open,
// the new points measured (simulated on a part whose truth the test knows),
// and `furrow compare` with both files resolving the verdict either way.
// Also the merging rule of several measurement files.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "base/json_fields.hpp"
#include "inspection/comparison_file.hpp"
#include "io/cmm/measurement_file.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

test::CliResult run(const std::vector<std::string>& args) {
  const test::CliResult r = test::run_furrow(args);
  if (r.status != 0 && r.status != 1 && r.status != 4) MESSAGE(args[0] << ": " << r.out << r.err);
  return r;
}

// The grid plan of the verdict tests (points about 8 mm apart).
InspectionPlan write_grid_plan(const std::string& path) {
  const Part part = read_part(kMould);
  InspectionPlan plan = grid_plan(part, 12, 10, {"ruby 2 mm", 2});
  plan.part = kMould;
  write_plan(plan, path);
  return read_plan(path);
}

// Every plan point lies on its face with the face's normal.
void check_on_part(const InspectionPlan& plan, const Part& part) {
  for (const PlannedPoint& p : plan.points) {
    CAPTURE(p.id);
    REQUIRE(p.face_index < part.faces.size());
    const DifferentialGeometry g = part.faces[p.face_index].geometry(p.uv.x(), p.uv.y());
    CHECK((g.point - p.xyz).norm() < 1e-9);
    CHECK((g.normal - p.ijk).norm() < 1e-9);
  }
}

}  // namespace

TEST_CASE("remeasure: a one-point dent is re-probed with a ring, the dent confirmed fails, dirt passes") {
  const std::string dir = test::scratch_dir("remeasure-dent");
  const InspectionPlan plan = write_grid_plan(dir + "/plan.json");
  const Part part = read_part(kMould);
  // The dent of test_verdict.cpp: 6 mm across, 80 um deep, centred on one
  // planned point that no neighbour sees.
  const PlannedPoint& target = plan.points[plan.points.size() / 2 + 3];
  const std::string bump = number(target.xyz.x()) + "," + number(target.xyz.y()) + "," + number(target.xyz.z()) +
                           ",3,-0.08";
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/plan.json", "--noise", "0.002", "--outliers", "0",
               "--bump", bump, "--out", dir + "/first.csv"})
              .status == 0);
  const test::CliResult first = run({"compare", kMould, "--measurements", dir + "/first.csv", "--plan",
                                     dir + "/plan.json", "--out", dir + "/first.json"});
  REQUIRE(first.status == 4);
  REQUIRE(first.out.find("re-measure point " + target.id) != std::string::npos);

  const test::CliResult rm = run({"remeasure", dir + "/first.json", "--out", dir + "/again"});
  REQUIRE(rm.status == 0);
  const std::string program = "again";
  CHECK(fs::exists(dir + "/again/" + program + ".dmi"));
  CHECK(fs::exists(dir + "/again/" + program + ".prg"));
  const InspectionPlan again = read_plan(dir + "/again/plan.json");
  check_plan_against_part(again, part, "again/plan.json");
  check_on_part(again, part);
  // The suspect's own nominal, same id, then six neighbours at 1.5 mm.
  REQUIRE(again.points.size() == 7);
  CHECK(again.points[0].id == target.id);
  CHECK(again.points[0].xyz == target.xyz);
  CHECK(again.points[0].ijk == target.ijk);
  CHECK(again.probe.diameter == plan.probe.diameter);
  for (int k = 1; k <= 6; ++k) {
    const PlannedPoint& p = again.points[static_cast<std::size_t>(k)];
    CHECK(p.id == target.id + "_R" + std::to_string(k));
    // In the tangent plane at 1.5 mm, then onto the mould (curvature radii
    // of tens of mm move it by well under 0.1 mm).
    CHECK(std::abs((p.xyz - target.xyz).norm() - 1.5) < 0.1);
  }
  // The DMIS program probes those points under those labels.
  const std::string dmis = test::slurp(dir + "/again/" + program + ".dmi");
  for (const PlannedPoint& p : again.points) CHECK(dmis.find("F(" + p.id + ")=FEAT/POINT") != std::string::npos);
  // The first plan set up no datum frame (a grid on the free-form mould),
  // so there is no saved alignment to recall.
  CHECK_FALSE((plan.alignment && plan.alignment->method == PartAlignment::Method::datums));
  CHECK(dmis.find("RECALL/DA") == std::string::npos);

  // The dent is real: the re-measure sees it at the point and its ring.
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/again/plan.json", "--noise", "0.002",
               "--outliers", "0", "--seed", "7", "--bump", bump, "--out", dir + "/dent.csv"})
              .status == 0);
  const test::CliResult dent = run({"compare", kMould, "--measurements", dir + "/first.csv", "--measurements",
                                    dir + "/dent.csv", "--plan", dir + "/plan.json", "--out", dir + "/dent.json"});
  CHECK(dent.status == 1);
  CHECK(dent.out.find("re-measured: " + target.id + " from " + dir + "/dent.csv") != std::string::npos);
  const ComparisonDocument d = read_comparison(dir + "/dent.json");
  CHECK(d.summary.verdict == Verdict::fail);
  const ComparisonDocument::Point& seen = d.points[d.points_by_id.at(target.id)];
  CHECK(seen.evaluated);
  CHECK(seen.in_tolerance == std::optional<bool>(false));
  CHECK(seen.file == 1);

  // Why 1.5 mm: a ring at 3 mm sits on the dent's rim, sees nothing, and
  // the point stays a suspected blunder however often it is re-measured.
  REQUIRE(run({"remeasure", dir + "/first.json", "--radius", "3", "--out", dir + "/rim"}).status == 0);
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/rim/plan.json", "--noise", "0.002", "--outliers",
               "0", "--seed", "7", "--bump", bump, "--out", dir + "/rim.csv"})
              .status == 0);
  const test::CliResult rim = run({"compare", kMould, "--measurements", dir + "/first.csv", "--measurements",
                                   dir + "/rim.csv", "--plan", dir + "/plan.json", "--out", dir + "/rim.json"});
  CHECK(rim.status == 4);
  CHECK(rim.out.find("re-measure point " + target.id) != std::string::npos);

  // It was dirt: the clean part re-measured passes.
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/again/plan.json", "--noise", "0.002",
               "--outliers", "0", "--seed", "7", "--out", dir + "/dirt.csv"})
              .status == 0);
  const test::CliResult dirt = run({"compare", kMould, "--measurements", dir + "/first.csv", "--measurements",
                                    dir + "/dirt.csv", "--plan", dir + "/plan.json", "--out", dir + "/dirt.json"});
  CHECK(dirt.status == 0);
  CHECK(read_comparison(dir + "/dirt.json").summary.verdict == Verdict::pass);

  // A comparison that passed leaves nothing to re-measure: said, nothing written.
  const test::CliResult none = run({"remeasure", dir + "/dirt.json", "--out", dir + "/none"});
  CHECK(none.status == 0);
  CHECK(none.out.find("nothing to re-measure") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/none"));
}

TEST_CASE("remeasure: a predicted gouge nobody measured is probed inside its extent and resolves the verdict") {
  const std::string dir = test::scratch_dir("remeasure-gouge");
  const InspectionPlan plan = write_grid_plan(dir + "/plan.json");
  const Part part = test::mould_part();
  // The site between four grid points: none lies within its box plus the
  // 1 mm margin (the grid is about 8 mm, the box 3 mm).
  std::set<double> us, vs;
  for (const PlannedPoint& p : plan.points) {
    us.insert(p.uv.x());
    vs.insert(p.uv.y());
  }
  const std::vector<double> u(us.begin(), us.end()), v(vs.begin(), vs.end());
  const Eigen::Vector2d centre((u[3] + u[4]) / 2, (v[5] + v[6]) / 2);
  auto clean_field = [](const Eigen::Vector2d& uv) { return 0.002 + 0.004 * std::sin(3 * uv.x()) * uv.y(); };
  auto cut_field = [&](const Eigen::Vector2d& uv) { return clean_field(uv) + test::dent(uv, centre, 0.03, 0.02); };
  Prediction cut = test::field_prediction(part, cut_field, 0.001);
  test::add_zmap_site(cut, part, centre, {0.015, 0.015}, 0.02);
  write_prediction(cut, dir + "/cut.json");
  write_prediction(test::field_prediction(part, clean_field, 0.001), dir + "/clean.json");

  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/plan.json", "--prediction", dir + "/cut.json",
               "--outliers", "0", "--out", dir + "/first.csv"})
              .status == 0);
  auto compare = [&](std::vector<std::string> files, const std::string& out) {
    std::vector<std::string> args = {"compare", kMould, "--plan", dir + "/plan.json", "--prediction",
                                     dir + "/cut.json", "--out", dir + "/" + out};
    for (const std::string& f : files) {
      args.push_back("--measurements");
      args.push_back(dir + "/" + f);
    }
    return run(args);
  };
  const test::CliResult first = compare({"first.csv"}, "first.json");
  REQUIRE(first.status == 4);
  REQUIRE(first.out.find("0 confirmed, 0 not confirmed, 1 not measured") != std::string::npos);

  REQUIRE(run({"remeasure", dir + "/first.json", "--out", dir + "/site"}).status == 0);
  const InspectionPlan site = read_plan(dir + "/site/plan.json");
  check_on_part(site, part);
  REQUIRE(site.points.size() == 7);
  CHECK(site.points[0].id == "G1_C");
  const ComparisonDocument c = read_comparison(dir + "/first.json");
  const Eigen::AlignedBox2d& box = c.gouges->sites[0].uv_box;
  CHECK((site.points[0].uv - box.center()).norm() < 1e-12);
  for (const PlannedPoint& p : site.points) CHECK(box.contains(p.uv));  // inside the predicted extent

  // Measured on the part with the gouge: CONFIRMED, the part fails.
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/site/plan.json", "--prediction", dir + "/cut.json",
               "--outliers", "0", "--seed", "3", "--out", dir + "/cut.csv"})
              .status == 0);
  const test::CliResult confirmed = compare({"first.csv", "cut.csv"}, "confirmed.json");
  CHECK(confirmed.status == 1);
  CHECK(confirmed.out.find("gouge sites: 1 confirmed") != std::string::npos);
  // On the part without it: NOT CONFIRMED, nothing left open, PASS.
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/site/plan.json", "--prediction",
               dir + "/clean.json", "--outliers", "0", "--seed", "3", "--out", dir + "/uncut.csv"})
              .status == 0);
  const test::CliResult uncut = compare({"first.csv", "uncut.csv"}, "uncut.json");
  CHECK(uncut.status == 0);
  CHECK(uncut.out.find("gouge sites: 0 confirmed, 1 not confirmed, 0 not measured") != std::string::npos);
}

TEST_CASE("compare with several measurement files: a later point replaces an earlier one by id") {
  const std::string dir = test::scratch_dir("remeasure-merge");
  const InspectionPlan plan = write_grid_plan(dir + "/plan.json");
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/plan.json", "--outliers", "0", "--out",
               dir + "/a.csv"})
              .status == 0);
  MeasurementReadOptions read;
  read.probe_diameter = 2;
  const MeasurementSet a = read_measurements(dir + "/a.csv", read);
  const MeasuredPoint& old = a.points[10];
  // b: point 10 again, 3 um higher along its nominal normal, and a new id.
  const Eigen::Vector3d moved = old.xyz + 0.003 * plan.points[10].ijk;
  test::write_text(dir + "/b.csv", "id,x,y,z\n" + old.id + "," + number(moved.x()) + "," + number(moved.y()) + "," +
                                       number(moved.z()) + "\nEXTRA," + number(a.points[20].xyz.x()) + "," +
                                       number(a.points[20].xyz.y()) + "," + number(a.points[20].xyz.z()) + "\n");
  const test::CliResult r = run({"compare", kMould, "--measurements", dir + "/a.csv", "--measurements",
                                 dir + "/b.csv", "--plan", dir + "/plan.json", "--out", dir + "/c.json"});
  REQUIRE(r.status == 0);
  const ComparisonDocument d = read_comparison(dir + "/c.json");
  REQUIRE(d.points.size() == a.points.size() + 1);
  CHECK(d.points[10].id == old.id);  // replaced in place
  CHECK(d.points[10].measured == moved);
  CHECK(d.points[10].file == 1);
  CHECK(d.points[9].file == 0);
  CHECK(d.points.back().id == "EXTRA");
  CHECK(d.points.back().file == 1);
  REQUIRE(d.sources.measurement_files.size() == 2);
  CHECK(d.sources.measurement_files[0].path == dir + "/a.csv");
  CHECK(d.sources.measurement_files[0].points == a.points.size());
  CHECK(d.sources.measurement_files[1].points == 2);
  REQUIRE(d.sources.replaced.size() == 1);
  CHECK(d.sources.replaced[0].id == old.id);
  CHECK(d.sources.replaced[0].file == 0);
  CHECK(d.sources.replaced[0].by_file == 1);
  CHECK(d.sources.replaced[0].was == old.xyz);
  // Both files' digests are recorded (the SHA-256 of each file's bytes differ).
  CHECK(d.sources.measurement_files[0].sha256.size() == 64);
  CHECK(d.sources.measurement_files[1].sha256.size() == 64);
  CHECK(d.sources.measurement_files[0].sha256 != d.sources.measurement_files[1].sha256);
  // The other order: a's point wins.
  REQUIRE(run({"compare", kMould, "--measurements", dir + "/b.csv", "--measurements", dir + "/a.csv", "--plan",
               dir + "/plan.json", "--out", dir + "/c2.json"})
              .status == 0);
  const ComparisonDocument d2 = read_comparison(dir + "/c2.json");
  CHECK(d2.points[d2.points_by_id.at(old.id)].measured == old.xyz);

  // Ids that a file does not carry cannot be merged by: refused, exit 2,
  // naming the file, nothing written.
  std::string xyz;
  for (const MeasuredPoint& p : a.points)
    xyz += number(p.xyz.x()) + " " + number(p.xyz.y()) + " " + number(p.xyz.z()) + "\n";
  test::write_text(dir + "/c.xyz", xyz);
  const test::CliResult mixed = run({"compare", kMould, "--measurements", dir + "/a.csv", "--measurements",
                                     dir + "/c.xyz", "--plan", dir + "/plan.json", "--out", dir + "/mixed.json"});
  CHECK(mixed.status == 2);
  CHECK(mixed.err.find(dir + "/c.xyz: its point ids are generated") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/mixed.json"));
  // One XYZ file alone is read as before.
  CHECK(run({"compare", kMould, "--measurements", dir + "/c.xyz", "--probe-diameter", "2", "--out",
             dir + "/xyz.json"})
            .status == 0);
}

TEST_CASE("remeasure bad input: exit 2, one line naming what to fix, nothing written") {
  const std::string dir = test::scratch_dir("remeasure-bad");
  write_grid_plan(dir + "/plan.json");
  REQUIRE(run({"simulate-measurement", kMould, "--plan", dir + "/plan.json", "--outliers", "1", "--out",
               dir + "/m.csv"})
              .status == 0);
  REQUIRE(run({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", dir + "/plan.json", "--out",
               dir + "/c.json"})
              .status != 2);
  auto refused = [&](const std::vector<std::string>& args, const std::string& says) {
    const test::CliResult r = test::run_furrow(args);
    INFO(r.out << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(says) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir + "/out"));
  };
  refused({"remeasure", dir + "/missing.json", "--out", dir + "/out"}, dir + "/missing.json");
  // The comparison was made on the mould, not on this part.
  refused({"remeasure", dir + "/c.json", "--part", test::source_path("examples/parts/two_face.json"),
           "--out", dir + "/out"},
          dir + "/c.json: points[0]");
  refused({"remeasure", dir + "/c.json", "--ring", "30", "--out", dir + "/out"}, "--ring");
  refused({"remeasure", dir + "/c.json", "--radius", "-1", "--out", dir + "/out"}, "--radius");
  refused({"remeasure", dir + "/c.json"}, "--out is required");
}

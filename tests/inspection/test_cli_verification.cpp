// End to end: simulate-measurement --prediction/--bump and compare
// --prediction as a user runs them. Exit status 0 on a clean part, 1 on a
// confirmed gouge, 2 on bad input with nothing written.
#include <doctest/doctest.h>

#include <filesystem>

#include "inspection/comparison_file.hpp"
#include "io/cmm/measurement_file.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");
const Eigen::Vector2d kGouge(0.3, 0.6);

double clean_field(const Eigen::Vector2d& uv) { return 0.002 + 0.004 * std::sin(3 * uv.x()) * uv.y(); }
double gouged_field(const Eigen::Vector2d& uv) { return clean_field(uv) + test::dent(uv, kGouge, 0.06, 0.02); }

struct Files {
  std::string dir, plan, clean, gouged;
  explicit Files(const std::string& name) : dir(test::scratch_dir(name)) {
    const Part part = test::mould_part();
    InspectionPlan p = grid_plan(part, 30, 24, {"ruby 2 mm", 2});
    p.part = kMould;
    plan = dir + "/plan.json";
    write_plan(p, plan);
    // Not reached where v < 0.1 (the path stopped short of that edge).
    auto reached = [](const Eigen::Vector2d& uv) { return uv.y() >= 0.1; };
    clean = dir + "/clean.json";
    write_prediction(test::field_prediction(part, clean_field, 0.001, reached), clean);
    Prediction g = test::field_prediction(part, gouged_field, 0.001, reached);
    test::add_zmap_site(g, part, kGouge, {0.03, 0.03}, 0.02);
    gouged = dir + "/gouged.json";
    write_prediction(g, gouged);
  }
  test::CliResult simulate(const std::string& prediction, const std::string& out,
                           std::vector<std::string> extra = {},
                           const std::string& misalign = "2,1,-60,30,40,-10") const {
    std::vector<std::string> args = {"simulate-measurement", kMould, "--plan", plan, "--prediction",
                                     prediction, "--misalign", misalign, "--seed", "5",
                                     "--out", dir + "/" + out};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::run_furrow(args);
  }
  test::CliResult compare(const std::string& measurements, const std::string& prediction,
                          const std::string& out) const {
    return test::run_furrow({"compare", kMould, "--measurements", dir + "/" + measurements, "--plan",
                             plan, "--prediction", prediction, "--tolerance", "0.05", "--out",
                             dir + "/" + out});
  }
};

}  // namespace

TEST_CASE("simulate-measurement --prediction probes the predicted surface exactly (noise 0)") {
  const Files f("cli-verify-simulate");
  const auto r = f.simulate(f.clean, "exact.csv", {"--noise", "0"}, "0,0,0,0,0,0");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("from " + f.clean + ": 660 points where the tool reached, 60 not reached (nominal there)") !=
        std::string::npos);
  const InspectionPlan plan = read_plan(f.plan);
  const Prediction p = read_prediction(f.clean);
  MeasurementReadOptions read;
  read.probe_diameter = 2;
  const MeasurementSet m = read_measurements(f.dir + "/exact.csv", read);
  REQUIRE(m.points.size() == plan.points.size());
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    const PlannedPoint& q = plan.points[k];
    const PredictedError e = p.predicted_error_at(q.face, q.uv.x(), q.uv.y());
    const double expected = e.reached() ? e.value : 0.0;
    CHECK(std::abs((m.points[k].xyz - q.xyz).dot(q.ijk) - 1.0 - expected) < 1e-12);
  }
  // The same seed gives the same file.
  REQUIRE(f.simulate(f.clean, "again.csv", {"--noise", "0"}, "0,0,0,0,0,0").status == 0);
  CHECK(test::slurp(f.dir + "/exact.csv") == test::slurp(f.dir + "/again.csv"));
}

TEST_CASE("compare --prediction: clean part exit 0, a bump unexplained, a confirmed gouge exit 1") {
  const Files f("cli-verify-compare");
  REQUIRE(f.simulate(f.clean, "clean.csv").status == 0);
  const auto clean = f.compare("clean.csv", f.clean, "clean_out.json");
  CAPTURE(clean.out);
  CHECK(clean.status == 0);
  CHECK(clean.out.find("-> explained") != std::string::npos);
  CHECK(clean.out.find("PASS") != std::string::npos);
  const ComparisonDocument c = read_comparison(f.dir + "/clean_out.json");
  CHECK(c.summary.pass);
  CHECK(c.prediction->overall.explained());
  CHECK(c.prediction->uncompared.not_reached == 60);  // two grid rows below v = 0.1
  CHECK(c.gouges->sites.empty());
  CHECK(c.gouges->unexplained.empty());
  CHECK(c.sources.prediction == f.clean);
  CHECK(c.options.prediction.probe_sigma == 0.002);

  // A 20 um dent of radius 8 mm at (70, 40) that nothing predicted.
  const Part part = test::mould_part();
  const Eigen::Vector3d at = part.faces[0].surface().point(0.7, 0.5);
  const std::string bump = std::to_string(at.x()) + "," + std::to_string(at.y()) + "," + std::to_string(at.z()) + ",8,-0.02";
  const auto sim = f.simulate(f.clean, "bumped.csv", {"--bump", bump, "--bump", "10,10,0,1,0.5"});
  REQUIRE(sim.status == 0);
  CHECK(sim.out.find("bump: -0.0200 mm within 8 mm") != std::string::npos);
  CHECK(sim.out.find("(10, 10, 0): 0 planned points") != std::string::npos);
  const auto bumped = f.compare("bumped.csv", f.clean, "bumped_out.json");
  CHECK(bumped.status == 0);  // in tolerance, no predicted gouge: listed, not failed
  CHECK(bumped.out.find("1 unexplained overcuts") != std::string::npos);
  const ComparisonDocument b = read_comparison(f.dir + "/bumped_out.json");
  REQUIRE(b.gouges->unexplained.size() == 1);
  CHECK((b.gouges->unexplained[0].xyz - at).norm() < 4);
  const ComparisonDocument::Point& deepest = b.points[b.gouges->unexplained[0].deepest];
  CHECK(deepest.prediction->residual < -0.01);  // the prediction does not account for it

  REQUIRE(f.simulate(f.gouged, "gouged.csv").status == 0);
  const auto gouged = f.compare("gouged.csv", f.gouged, "gouged_out.json");
  CAPTURE(gouged.out);
  CHECK(gouged.status == 1);
  CHECK(gouged.out.find("gouge sites: 1 confirmed, 0 not confirmed, 0 not measured") != std::string::npos);
  CHECK(gouged.out.find("FAIL") != std::string::npos);
  const ComparisonDocument g = read_comparison(f.dir + "/gouged_out.json");
  CHECK(g.summary.out_of_tolerance == 0);  // failed by the confirmed gouge alone
  CHECK(g.summary.confirmed_gouges == 1);
  CHECK(g.gouges->sites[0].id == "G1");
  CHECK(*g.gouges->sites[0].depth_consistent);

  // The clean part measured against the gouged prediction: not confirmed.
  const auto uncut = f.compare("clean.csv", f.gouged, "uncut_out.json");
  CHECK(uncut.status == 0);
  CHECK(uncut.out.find("gouge sites: 0 confirmed, 1 not confirmed") != std::string::npos);
}

TEST_CASE("verification bad input: exit 2, one line naming the file, nothing written") {
  const Files f("cli-verify-bad");
  REQUIRE(f.simulate(f.clean, "m.csv").status == 0);
  const std::string out = f.dir + "/out.json";
  auto refused = [&](const std::vector<std::string>& args, const std::string& message) {
    const auto r = test::run_furrow(args);
    CAPTURE(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK(test::line_count(r.err) == 1);
    CHECK_FALSE(fs::exists(out));
  };
  // A prediction of another part: two_face's faces.
  const Part other = read_part(test::source_path("examples/parts/two_face.json"));
  write_prediction(test::field_prediction(other, clean_field), f.dir + "/other.json");
  // The mould's face name, another parameter domain.
  Prediction stretched = test::field_prediction(test::mould_part(), clean_field);
  stretched.faces[0].domain.u1 = 2;
  write_prediction(stretched, f.dir + "/stretched.json");
  const std::vector<std::string> compare = {"compare", kMould, "--measurements", f.dir + "/m.csv",
                                            "--plan", f.plan, "--out", out, "--prediction"};
  auto with = [](std::vector<std::string> a, const std::string& last) {
    a.push_back(last);
    return a;
  };
  refused(with(compare, f.dir + "/other.json"),
          "other.json: faces[0]: face \"valley_wall\" is not a face of " + kMould);
  refused(with(compare, f.dir + "/stretched.json"),
          "stretched.json: faces[0]: the parameter domain of face \"mould\" differs");
  refused(with(compare, f.dir + "/missing.json"), "missing.json");
  refused({"compare", kMould, "--measurements", f.dir + "/m.csv", "--plan", f.plan, "--regions",
           f.dir + "/no_regions.json", "--prediction", f.clean, "--out", out},
          "no_regions.json");
  refused({"compare", kMould, "--measurements", f.dir + "/none.csv", "--plan", f.plan, "--prediction",
           f.clean, "--out", out},
          "none.csv");
  refused({"simulate-measurement", kMould, "--plan", f.plan, "--prediction", f.dir + "/other.json",
           "--out", f.dir + "/refused.csv"},
          "the prediction was made for another part");
  CHECK_FALSE(fs::exists(f.dir + "/refused.csv"));
  refused({"simulate-measurement", kMould, "--plan", f.plan, "--bump", "1,2,3,4", "--out", out},
          "--bump expects 5 comma-separated numbers");
  refused({"simulate-measurement", kMould, "--plan", f.plan, "--bump", "1,2,3,0,0.1", "--out", out},
          "the radius must be positive");
  refused({"compare", kMould, "--measurements", f.dir + "/m.csv", "--plan", f.plan, "--prediction",
           f.clean, "--overcut-fraction", "2", "--out", out},
          "--overcut-fraction: must lie between 0 and 1");
  refused({"compare", kMould, "--measurements", f.dir + "/m.csv", "--plan", f.plan, "--prediction",
           f.clean, "--out", f.clean},
          "clean.json");
}

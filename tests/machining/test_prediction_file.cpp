#include <doctest/doctest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "io/part_file.hpp"
#include "machining/toolpath/contact_planning.hpp"
#include "machining/prediction/path_prediction.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "machining/toolpath/toolpath_generation.hpp"

using namespace furrow;

namespace {

std::string example(const std::string& name) { return std::string(FURROW_SOURCE_DIR) + "/examples/parts/" + name; }

// A 3 x 2 grid on [0, 3] x [0, 2]: means 0.001 * (i + 10 j), band +-0.002;
// cell (2, 1) not reached.
Prediction small_prediction() {
  Prediction p;
  p.part = "part.json";
  p.toolpath = "path.nc";
  p.tool = {"BALL6", ToolType::ball, 6, 3};
  p.tolerance = 0.01;
  p.gouge_threshold = 0.02;
  p.zmap = {0.05, {0, 0}, 61, 41, 10, 2000};
  FaceGridRecord f;
  f.name = "f";
  f.domain = {0, 3, 0, 2};
  f.cells_u = 3;
  f.cells_v = 2;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const bool reached = !(i == 2 && j == 1);
      f.status.push_back(reached ? ErrorCellStatus::reached : ErrorCellStatus::not_reached);
      const double m = reached ? 0.001 * (i + 10 * j) : 0.0;
      f.mean.push_back(m);
      f.max_undercut.push_back(reached ? m + 0.002 : 0.0);
      f.max_overcut.push_back(reached ? m - 0.002 : 0.0);
    }
  p.faces.push_back(f);
  GougeSiteRecord site;
  site.id = 1;
  site.face = "f";
  site.depth = 0.03;
  site.deepest = {"f", {0.5, 0.5}, {1, 2, 3}};
  site.area = 0.5;
  site.samples = 20;
  site.centroid = {"f", {0.4, 0.6}, {1, 2, 3}};
  site.box = Eigen::AlignedBox3d(Eigen::Vector3d(0, 1, 2), Eigen::Vector3d(1, 2, 3));
  site.uv_box = Eigen::AlignedBox2d(Eigen::Vector2d(0.2, 0.2), Eigen::Vector2d(0.8, 0.9));
  p.gouge_sites.push_back(site);
  p.summary.gouge_sites = 1;
  p.has_regions = true;
  p.regions_file = "regions.json";
  RegionErrorRecord reached;
  reached.region = 0;
  reached.face = "f";
  reached.curvature_class = "convex";
  reached.samples = 40;
  reached.reached = 30;
  reached.mean = -0.002;
  reached.max_undercut = {true, 0.001, {"f", {1, 1}, {0, 0, 1}}};
  reached.max_overcut = {true, -0.004, {"f", {2, 1}, {0, 0, 2}}};
  RegionErrorRecord untouched;
  untouched.region = 1;
  untouched.face = "f";
  untouched.curvature_class = "planar";
  untouched.samples = 10;
  p.regions = {reached, untouched};
  return p;
}

std::string reader_error(const std::string& text) {
  try {
    parse_prediction_json(text, "prediction.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void replace(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("predicted_error_at: the cell's band, means interpolated over reached cells") {
  const Prediction p = small_prediction();
  // At a cell centre: that cell's mean.
  PredictedError e = p.predicted_error_at("f", 1.5, 0.5);
  CHECK(e.reached());
  CHECK(e.cell_u == 1);
  CHECK(e.cell_v == 0);
  CHECK(e.value == doctest::Approx(0.001).epsilon(1e-12));
  CHECK(e.max_undercut == doctest::Approx(0.003));
  CHECK(e.max_overcut == doctest::Approx(-0.001));
  // Half-way between four reached centres: their average.
  e = p.predicted_error_at("f", 1.0, 1.0);
  CHECK(e.value == doctest::Approx((0.0 + 0.001 + 0.010 + 0.011) / 4).epsilon(1e-12));
  // Next to the unreached cell: only reached cells weigh in.
  e = p.predicted_error_at("f", 2.0, 1.0);  // cell (2, 1) is not reached; (1,0), (2,0), (1,1) are
  CHECK(e.status == ErrorCellStatus::not_reached);
  e = p.predicted_error_at("f", 1.9, 1.1);  // in cell (1, 1)
  REQUIRE(e.reached());
  const double a = 0.4, b = 0.6;  // position between the centres (1.5, 0.5) and (2.5, 1.5)
  const double w00 = (1 - a) * (1 - b), w10 = a * (1 - b), w01 = (1 - a) * b;
  CHECK(e.value == doctest::Approx((w00 * 0.001 + w10 * 0.002 + w01 * 0.011) / (w00 + w10 + w01)).epsilon(1e-12));
  // Outside the domain, an unknown face.
  CHECK(p.predicted_error_at("f", 3.5, 1.0).status == ErrorCellStatus::outside);
  CHECK_THROWS_WITH_AS(p.predicted_error_at("g", 1, 1), doctest::Contains("no face \"g\""), InputError);
  CHECK(p.gouge_sites_at("f", 0.5, 0.5) == std::vector<int>{1});
  CHECK(p.gouge_sites_at("f", 1.5, 0.5).empty());
}

TEST_CASE("prediction.json: written, read back the same, unreached cells are null, nothing is NaN") {
  const Prediction p = small_prediction();
  const std::string text = prediction_to_json_text(p);
  CHECK(text.find("nan") == std::string::npos);
  CHECK(text.find("inf") == std::string::npos);
  CHECK(text.find("\"RRN\"") != std::string::npos);  // the status row of v cell 1
  const Prediction back = parse_prediction_json(text, "prediction.json");
  CHECK(prediction_to_json_text(back) == text);
  CHECK(back.tool.name == "BALL6");
  CHECK(back.faces[0].status[5] == ErrorCellStatus::not_reached);
  CHECK(back.faces[0].mean[4] == doctest::Approx(0.011));
  CHECK(back.predicted_error_at("f", 1.0, 1.0).value == doctest::Approx(p.predicted_error_at("f", 1.0, 1.0).value));
  CHECK(back.gouge_sites[0].uv_box.max().y() == doctest::Approx(0.9));
  REQUIRE(back.regions.size() == 2);
  CHECK(back.regions[0].max_overcut.error == doctest::Approx(-0.004));
  CHECK_FALSE(back.regions[1].max_undercut.found);  // null: nothing reached there
  // Without a regions file there is no "regions" member at all.
  Prediction plain = p;
  plain.has_regions = false;
  const std::string plain_text = prediction_to_json_text(plain);
  CHECK(plain_text.find("\"regions\"") == std::string::npos);
  CHECK_FALSE(parse_prediction_json(plain_text, "p.json").has_regions);
}

TEST_CASE("prediction.json reader: errors name the field") {
  const std::string good = prediction_to_json_text(small_prediction());
  std::string t = good;
  replace(t, "\"furrow-prediction\"", "\"furrow-plan\"");
  CHECK(reader_error(t).find("prediction.json: format: not a furrow prediction") == 0);
  t = good;
  replace(t, "\"version\": 1", "\"version\": 7");
  CHECK(reader_error(t).find("prediction.json: version: version 7 is not supported") == 0);
  t = good;
  replace(t, "\"RRN\"", "\"RRR\"");  // claims a value for the null cell
  CHECK(reader_error(t).find("faces[0].mean[5]: expected a number for a reached cell, got null") !=
        std::string::npos);
  t = good;
  replace(t, "\"RRN\"", "\"RRX\"");
  CHECK(reader_error(t).find("faces[0].status[1]: unknown cell status 'X'") != std::string::npos);
  t = good;
  replace(t, "\"RRN\"", "\"RR\"");
  CHECK(reader_error(t).find("faces[0].status[1]: expected 3 cells, got 2") != std::string::npos);
  t = good;
  replace(t, "\"tolerance\": 0.01", "\"tolerance\": -1");
  CHECK(reader_error(t).find("prediction.json: tolerance") == 0);
  CHECK(reader_error("{}").find("prediction.json: format") == 0);
  CHECK(reader_error("").find("prediction.json") == 0);
}

TEST_CASE("fuzz: z-map node counts and scallop passes are whole numbers, never converted from any double") {
  // fuzz_prediction_json under UBSan: "nodes": [1e300, 41] and "passes":
  // [1e300, 1] were read as doubles and converted to int, which is undefined
  // behaviour; 1.5 was silently truncated.
  Prediction p = small_prediction();
  ScallopRecord scallop;
  scallop.pass_a = 0;
  scallop.pass_b = 1;
  scallop.height = 0.004;
  scallop.at = {"f", {0.5, 0.5}, {1, 2, 3}};
  p.scallops.push_back(scallop);
  const std::string good = prediction_to_json_text(p);
  const Prediction back = parse_prediction_json(good, "prediction.json");
  CHECK(back.zmap.nx == 61);
  REQUIRE(back.scallops.size() == 1);
  CHECK(back.scallops[0].pass_b == 1);
  const nlohmann::json doc = nlohmann::json::parse(good);
  const struct {
    const char* pointer;  // JSON pointer of the member to spoil
    nlohmann::json value;
    const char* expected;
  } cases[] = {
      {"/zmap/nodes", {1e300, 41}, "prediction.json: zmap.nodes[0]: expected an integer"},
      {"/zmap/nodes", {61, -41}, "prediction.json: zmap.nodes[1]: must not be negative"},
      {"/zmap/nodes", {61}, "prediction.json: zmap.nodes: expected two whole numbers"},
      {"/scallops/0/passes", {1e300, 1}, "prediction.json: scallops[0].passes[0]: expected an integer"},
      {"/scallops/0/passes", {0, 1.5}, "prediction.json: scallops[0].passes[1]: expected an integer"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.value.dump());
    nlohmann::json spoilt = doc;
    spoilt[nlohmann::json::json_pointer(c.pointer)] = c.value;
    CHECK(reader_error(spoilt.dump()).find(c.expected) == 0);
  }
}

namespace {

// Passes along u over the semi-cylinder, planned to 0.01 mm per step and
// `scallop` between passes, for the 8 mm ball.
Toolpath planned_semi_cylinder_path(const Part& part, const Cutter& ball, double scallop) {
  ContactPlanOptions plan_options;
  plan_options.forward.tolerance = 0.01;
  plan_options.scallop = scallop;
  plan_options.min_normal_z = 0.8;
  Toolpath path = plan_tips(plan_contact_points(part, ball, {PassDirection::along_u, 0}, plan_options));
  path.source = "planned";
  return path;
}

}  // namespace

TEST_CASE("a planned path on the semi-cylinder: prediction within tolerance, errors queryable where they are") {
  const Part part = read_part(example("semi_cylinder.json"));
  const Cutter ball("BALL8", 4, 4);
  const Toolpath path = planned_semi_cylinder_path(part, ball, 0.01);
  PathPredictionOptions options;
  options.tolerance = 0.01;
  options.resolution = 0.1;
  const PathPrediction r = predict_path(part, ball, path, options);
  const Prediction p = make_prediction(part, r, options, "semi_cylinder.json", "planned");
  CHECK(p.summary.steps == path.move_count());
  CHECK(p.summary.steps_evaluated == p.summary.steps);
  CHECK(p.summary.steps_over_tolerance == 0);
  CHECK(p.summary.points_without_contact == 0);
  CHECK(p.summary.local_gouge_points == 0);   // a convex part never gouges locally
  CHECK(p.summary.gouge_sites == 0);
  // Convex along the passes: every step overcuts by the tolerance (up to the
  // line search's precision). Straight across: the scallop target, less
  // what the steps' own overcut takes off the ridge.
  CHECK(p.summary.max_step_error == doctest::Approx(0.01).epsilon(0.01).scale(0));
  CHECK(p.summary.max_scallop <= 0.01 * 1.001);
  CHECK(p.summary.max_scallop >= 0.01 * 0.8);
  // The z-map value at any sample lies in its cell's stored band.
  const FaceErrorMap& m = r.map.faces[0];
  int checked = 0;
  for (int j = 0; j < m.nv; j += 37)
    for (int i = 0; i < m.nu; i += 41) {
      if (m.status[m.index(i, j)] != ErrorCellStatus::reached) continue;
      const PredictedError e = p.predicted_error_at("semi_cylinder", m.u(i), m.v(j));
      REQUIRE(e.reached());
      const double z = m.error[m.index(i, j)];
      CHECK(z >= e.max_overcut - 1e-7);
      CHECK(z <= e.max_undercut + 1e-7);
      ++checked;
    }
  CHECK(checked > 20);
  // And the file carries it all.
  const Prediction back = parse_prediction_json(prediction_to_json_text(p), "p.json");
  CHECK(back.steps.size() == p.steps.size());
  CHECK(back.summary.max_scallop == doctest::Approx(p.summary.max_scallop).epsilon(1e-6));
  // The cusp of each pass pair, apart from the ridge (the semi-cylinder is
  // straight across: the cusp is the side step's, the target).
  CHECK(p.summary.max_cusp == doctest::Approx(0.01).epsilon(0.02).scale(0));
  CHECK(back.summary.max_cusp == doctest::Approx(p.summary.max_cusp).epsilon(1e-6));
  REQUIRE(back.scallops.size() == p.scallops.size());
  for (std::size_t k = 0; k < p.scallops.size(); ++k) {
    REQUIRE(p.scallops[k].has_cusp);
    CHECK(back.scallops[k].has_cusp);
    CHECK(back.scallops[k].cusp == doctest::Approx(p.scallops[k].cusp).epsilon(1e-6));
    CHECK((back.scallops[k].cusp_at.xyz - p.scallops[k].cusp_at.xyz).norm() < 1e-6);
    CHECK(back.scallops[k].cusp_at.face == p.scallops[k].cusp_at.face);
  }
}

TEST_CASE("prediction.json: a step whose search stops at its iteration cap is written not converged, never as exact") {
  const Part part = read_part(example("semi_cylinder.json"));
  const Cutter ball("BALL8", 4, 4);
  const Toolpath path = planned_semi_cylinder_path(part, ball, 0.05);
  PathPredictionOptions options;
  options.tolerance = 0.01;
  options.resolution = 0.2;
  const Prediction exact = make_prediction(part, predict_path(part, ball, path, options), options, "p.json", "planned");
  // One Brent iteration cannot place an extremum to 1e-7 mm.
  options.step.refine_iterations = 1;
  const Prediction capped = make_prediction(part, predict_path(part, ball, path, options), options, "p.json", "planned");
  REQUIRE(exact.summary.steps_evaluated > 0);
  REQUIRE(exact.summary.steps_not_converged);
  CHECK(*exact.summary.steps_not_converged == 0);
  REQUIRE(capped.summary.steps_not_converged);
  CHECK(*capped.summary.steps_not_converged == capped.summary.steps_evaluated);
  std::size_t not_converged = 0;
  for (const StepRecord& s : capped.steps)
    if (s.status == "evaluated") {
      REQUIRE(s.converged);
      if (!*s.converged) ++not_converged;
    }
  CHECK(not_converged == capped.summary.steps_evaluated);
  // Written, and read back the same.
  const std::string text = prediction_to_json_text(capped);
  const nlohmann::json doc = nlohmann::json::parse(text);
  CHECK(doc["summary"]["steps_not_converged"] == capped.summary.steps_evaluated);
  for (const nlohmann::json& s : doc["steps"])
    if (s["status"] == "evaluated") CHECK(s["converged"] == false);
  const Prediction back = parse_prediction_json(text, "p.json");
  REQUIRE(back.summary.steps_not_converged);
  CHECK(*back.summary.steps_not_converged == capped.summary.steps_evaluated);
  REQUIRE(back.steps.size() == capped.steps.size());
  for (std::size_t k = 0; k < back.steps.size(); ++k) CHECK(back.steps[k].converged == capped.steps[k].converged);
  // The summary line does not call them exact; the converged one does.
  const std::string said = describe_step_errors(back.summary);
  CHECK(said.find(std::to_string(capped.summary.steps_evaluated) + " steps did not converge: not exact") !=
        std::string::npos);
  CHECK(describe_step_errors(exact.summary).find("every step exact") != std::string::npos);
  // A file from before `converged` was written: not known, not converged.
  nlohmann::json old = nlohmann::json::parse(prediction_to_json_text(exact));
  old["summary"].erase("steps_not_converged");
  for (nlohmann::json& s : old["steps"]) s.erase("converged");
  const Prediction older = parse_prediction_json(old.dump(), "old.json");
  CHECK_FALSE(older.summary.steps_not_converged);
  for (const StepRecord& s : older.steps) CHECK_FALSE(s.converged);
  CHECK(describe_step_errors(older.summary).find("not recorded") != std::string::npos);
  CHECK(describe_step_errors(older.summary).find("exact") == std::string::npos);
  // A count that the steps do not bear out is refused.
  nlohmann::json wrong = doc;
  wrong["summary"]["steps_not_converged"] = 0;
  CHECK_THROWS_WITH_AS(parse_prediction_json(wrong.dump(), "w.json"),
                       doctest::Contains("summary.steps_not_converged: 0, but steps[] has"), InputError);
}

TEST_CASE("a 20 mm ball through the mould's dimple: local gouges at the bottom, gouge sites around it") {
  const Part part = read_part(example("mould.json"));
  const VerticalProjector projector(part);
  const Cutter ball("BALL20", 10, 10);
  Toolpath path;
  path.kind = ToolpathKind::contact_points;
  path.source = "dimple.csv";
  ToolpathPass pass;
  for (int k = 0; k <= 40; ++k) {
    const SurfacePoint s = projector.project(62 + 0.5 * k, 30);
    ToolpathPoint q;
    q.position = s.point;
    q.normal = s.normal;
    q.line = k + 1;
    q.has_uv = true;
    q.uv = s.uv;
    pass.points.push_back(q);
  }
  path.passes.push_back(pass);
  PathPredictionOptions options;
  options.tolerance = 0.01;
  options.gouge_threshold = 0.002;
  options.resolution = 0.1;
  const PathPrediction r = predict_path(part, ball, path, options);
  const Prediction p = make_prediction(part, r, options, "mould.json", "dimple.csv");
  REQUIRE(p.summary.local_gouge_points > 0);
  for (const LocalGougeRecord& g : p.local_gouges) {
    CHECK(g.status == "gouge");
    CHECK(std::fabs(g.at.xyz.x() - 72) < 1.5);  // where the concave radius is below 10 mm
    CHECK(g.max_excess > 0);
    CHECK(!g.directions_deg.empty());
  }
  REQUIRE(p.summary.gouge_sites > 0);
  for (const GougeSiteRecord& s : p.gouge_sites) {
    CHECK(s.depth > 0.002);
    CHECK(std::fabs(s.centroid.xyz.x() - 72) < 4);
    CHECK(p.gouge_sites_at(s.face, s.deepest.uv.x(), s.deepest.uv.y()).size() >= 1);
    CHECK(p.predicted_error_at(s.face, s.deepest.uv.x(), s.deepest.uv.y()).max_overcut < -0.002);
  }
}

TEST_CASE("prediction.json: rapids are written only with a finding or a stock box, and read back the same") {
  Prediction p = small_prediction();
  p.rapids.checked = 4;
  p.rapids.unchecked = 2;
  // Nothing to say: no member, the bytes of a prediction without rapids.
  CHECK(prediction_to_json_text(p) == prediction_to_json_text(small_prediction()));
  CHECK_FALSE(parse_prediction_json(prediction_to_json_text(p), "p.json").rapids.written);
  p.rapids.written = true;
  p.rapids.has_stock = true;
  p.rapids.stock = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -2, -3), Eigen::Vector3d(4, 5, 6));
  RapidGougeRecord part;
  part.line = 17;
  part.kind = "part";
  part.depth = 1.25;
  part.at = {"f", {0.5, 1.5}, {1, 2, 3}};
  RapidGougeRecord stock;
  stock.line = 30;
  stock.kind = "stock";
  stock.depth = 2.5;
  stock.at.xyz = {-1, 0, 3.5};
  p.rapids.gouges = {part, stock};
  const std::string text = prediction_to_json_text(p);
  const Prediction back = parse_prediction_json(text, "prediction.json");
  CHECK(prediction_to_json_text(back) == text);
  CHECK(back.rapids.written);
  CHECK(back.rapids.checked == 4);
  CHECK(back.rapids.unchecked == 2);
  CHECK(back.rapids.stock.max().z() == 6);
  REQUIRE(back.rapids.gouges.size() == 2);
  CHECK(back.rapids.gouges[0].at.face == "f");
  CHECK(back.rapids.gouges[1].at.face.empty());
  CHECK(back.rapids.gouges[1].depth == 2.5);
  std::string t = text;
  replace(t, "\"kind\": \"stock\"", "\"kind\": \"air\"");
  CHECK(reader_error(t).find("rapids.gouges[1].kind: expected \"part\" or \"stock\"") != std::string::npos);
  t = text;
  replace(t, "\"depth\": 2.5", "\"depth\": 0");
  CHECK(reader_error(t).find("rapids.gouges[1].depth: must be positive") != std::string::npos);
}

// RPS alignment (furrow compare --align rps): the part placement a
// reference point system fixes. Oracles: the placement planted into the
// simulated data (a 3-2-1 RPS recovers it exactly); for an over-determined
// system the weighted objective recomputed here, which every nearby motion
// must raise (first-order optimality by brute force); with every axis of
// every point fixed, the closed-form point-to-point fit (Eigen::umeyama).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "inspection/comparison.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/rps_alignment.hpp"
#include "io/part_file.hpp"
#include "stage/compare_stage.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

// A block whose bottom (z = 0, normal -z), front wall (y = 0, normal -y)
// and left wall (x = 0, normal -x) carry the RPS points, with a free-form
// (twisted bilinear) top.
Part rps_part() {
  Part part;
  part.faces.emplace_back("bottom", make_plane({0, 0, 0}, {0, 60, 0}, {100, 0, 0}));
  part.faces.emplace_back("front", make_plane({0, 0, 0}, {100, 0, 0}, {0, 0, 30}));
  part.faces.emplace_back("left", make_plane({0, 0, 0}, {0, 0, 30}, {0, 60, 0}));
  part.faces.emplace_back("top", make_bilinear({10, 10, 30}, {90, 10, 36}, {10, 50, 39}, {90, 50, 27}));
  return part;
}

ReferencePoint rp(const std::string& id, const Eigen::Vector3d& at, const Eigen::Vector3d& normal,
                  const std::string& directions, double weight = 1) {
  return {id, at, normal, directions, weight};
}

// The classic 3-2-1: three points fixing z, two fixing y, one fixing x.
ReferencePointSystem three_two_one() {
  ReferencePointSystem rps;
  rps.source = "rps.json";
  rps.points = {rp("R1", {10, 10, 0}, {0, 0, -1}, "z"),  rp("R2", {90, 10, 0}, {0, 0, -1}, "z"),
                rp("R3", {50, 55, 0}, {0, 0, -1}, "z"),  rp("R4", {15, 0, 15}, {0, -1, 0}, "y"),
                rp("R5", {85, 0, 15}, {0, -1, 0}, "y"), rp("R6", {0, 30, 15}, {-1, 0, 0}, "x")};
  return rps;
}

Eigen::Isometry3d placement() {
  Misalignment m;
  m.rotation_deg = {3.5, -2, 131};
  m.translation = {412.5, -148.25, 61.75};
  return m.part_to_cmm();
}

// Probe centres (radius r) of the RPS points, each touched `offset(k)` mm
// off its nominal along its normal, on the CMM.
template <class Offset>
MeasurementSet measure(const ReferencePointSystem& rps, const Eigen::Isometry3d& part_to_cmm, double r,
                       Offset offset) {
  MeasurementSet set;
  set.source = "measured.csv";
  set.kind = r > 0 ? ProbePointKind::probe_centre : ProbePointKind::contact;
  set.probe_radius = r;
  set.ids_from_file = true;
  for (std::size_t k = 0; k < rps.points.size(); ++k) {
    const ReferencePoint& p = rps.points[k];
    MeasuredPoint m;
    m.id = p.id;
    m.xyz = part_to_cmm * (p.nominal + (offset(k) + r) * p.normal);
    set.points.push_back(m);
  }
  return set;
}

// The objective the fit minimises, recomputed from its definition.
double objective(const ReferencePointSystem& rps, const MeasurementSet& set, const Eigen::Isometry3d& T) {
  double f = 0;
  for (std::size_t k = 0; k < rps.points.size(); ++k) {
    const ReferencePoint& p = rps.points[k];
    const Eigen::Vector3d d = T * set.points[k].xyz - set.probe_radius * p.normal - p.nominal;
    for (char a : p.directions) f += p.weight * d[a - 'x'] * d[a - 'x'];
  }
  return f;
}

std::string error_of(const ReferencePointSystem& rps, const MeasurementSet& set) {
  try {
    fit_rps_alignment(rps, set);
  } catch (const DatumFrameError& e) {
    return std::string("frame: ") + e.what();
  } catch (const InputError& e) {
    return std::string("input: ") + e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("rps: a 3-2-1 system recovers the planted placement exactly, probe centres compensated") {
  const ReferencePointSystem rps = three_two_one();
  for (const double r : {0.0, 1.5}) {
    CAPTURE(r);
    const MeasurementSet set = measure(rps, placement(), r, [](std::size_t) { return 0.0; });
    const DatumFrame f = fit_rps_alignment(rps, set);
    const Eigen::Isometry3d error = f.transform * placement();
    CHECK((error.linear() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    CHECK(error.translation().norm() < 1e-9);
    REQUIRE(f.reference_points.size() == 6);
    for (const ReferencePointFit& p : f.reference_points) {
      CHECK(p.residual.norm() < 1e-9);
      // The contact is the nominal on the CMM.
      const ReferencePoint& nominal = rps.points[&p - f.reference_points.data()];
      CHECK((p.contact - placement() * nominal.nominal).norm() < 1e-9);
    }
    CHECK(f.datums.empty());
  }
}

TEST_CASE("rps: six constraints are met exactly whatever the touch errors, and the frame follows them") {
  // A point touched 0.02 mm proud of its nominal moves the frame by exactly
  // that along its axis: the bottom's three points 0.02 high lift the part.
  const ReferencePointSystem rps = three_two_one();
  const MeasurementSet set =
      measure(rps, placement(), 1.0, [](std::size_t k) { return k < 3 ? 0.02 : 0.0; });
  const DatumFrame f = fit_rps_alignment(rps, set);
  for (const ReferencePointFit& p : f.reference_points) CHECK(p.residual.norm() < 1e-9);
  // The frame's error is the slide along the bottom's normal (-z) by 0.02.
  const Eigen::Isometry3d error = f.transform * placement();
  CHECK((error.linear() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  CHECK((error.translation() - Eigen::Vector3d(0, 0, 0.02)).norm() < 1e-9);
}

TEST_CASE("rps: an over-determined weighted system is at its least-squares minimum") {
  ReferencePointSystem rps = three_two_one();
  rps.points.push_back(rp("R7", {50, 0, 25}, {0, -1, 0}, "yz", 2.5));
  rps.points.push_back(rp("R8", {0, 50, 5}, {-1, 0, 0}, "xz", 0.5));
  rps.points.push_back(rp("R9", {70, 40, 0}, {0, 0, -1}, "xyz", 4));
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0, 0.01);
  std::vector<double> offsets;
  for (std::size_t k = 0; k < rps.points.size(); ++k) offsets.push_back(noise(rng));
  const MeasurementSet set = measure(rps, placement(), 1.0, [&](std::size_t k) { return offsets[k]; });
  const DatumFrame f = fit_rps_alignment(rps, set);
  const double best = objective(rps, set, f.transform);
  CHECK(best > 0);  // over-determined with noise: not met exactly
  // Every turn (about the points' centroid) and slide of 1e-4 mm / rad in
  // any axis direction, either sign, raises the objective.
  const Eigen::Vector3d g(50, 30, 10);
  for (int k = 0; k < 6; ++k)
    for (const double h : {-1e-4, 1e-4}) {
      Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
      if (k < 3) {
        move.linear() = Eigen::AngleAxisd(h, Eigen::Vector3d::Unit(k)).toRotationMatrix();
        move.translation() = g - move.linear() * g;
      } else {
        move.translation() = h * Eigen::Vector3d::Unit(k - 3);
      }
      CAPTURE(k);
      CHECK(objective(rps, set, move * f.transform) > best);
    }
}

TEST_CASE("rps: every axis of every point fixed, one weight: the point-to-point closed form") {
  ReferencePointSystem rps = three_two_one();
  for (ReferencePoint& p : rps.points) p.directions = "xyz";
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.02);
  MeasurementSet set = measure(rps, placement(), 0.0, [](std::size_t) { return 0.0; });
  for (MeasuredPoint& m : set.points) m.xyz += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  Eigen::Matrix3Xd from(3, 6), to(3, 6);
  for (int k = 0; k < 6; ++k) from.col(k) = set.points[k].xyz, to.col(k) = rps.points[k].nominal;
  const Eigen::Matrix4d closed = Eigen::umeyama(from, to, false);
  const DatumFrame f = fit_rps_alignment(rps, set);
  CHECK((f.transform.matrix() - closed).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("rps: points that leave the part free, lie on a line or were not measured are refused with the reason") {
  const MeasurementSet set = measure(three_two_one(), placement(), 1.0, [](std::size_t) { return 0.0; });
  ReferencePointSystem flat = three_two_one();
  for (ReferencePoint& p : flat.points) p.directions = "z";  // six z: slides in x, y and the turn about z free
  const std::string free = error_of(flat, measure(flat, placement(), 1.0, [](std::size_t) { return 0.0; }));
  CHECK(free.rfind("frame: rps.json: the RPS points do not fix the part", 0) == 0);
  CHECK(free.find("free") != std::string::npos);
  // Five points fixing y and one x: nothing stops the part along z.
  ReferencePointSystem no_z = three_two_one();
  for (int k = 0; k < 3; ++k) no_z.points[k].directions = "y";
  CHECK(error_of(no_z, set).find("a slide along (0.00, 0.00, 1.00)") != std::string::npos);
  ReferencePointSystem line = three_two_one();
  for (std::size_t k = 0; k < line.points.size(); ++k) {
    line.points[k].nominal = {10.0 + 10 * k, 0, 0};
    line.points[k].directions = "xyz";
  }
  CHECK(error_of(line, measure(line, placement(), 0.0, [](std::size_t) { return 0.0; })).find("on a line") !=
        std::string::npos);
  // Five constraints, built in code (the file reader refuses them earlier).
  ReferencePointSystem five = three_two_one();
  five.points.pop_back();
  CHECK(error_of(five, set).find("frame: rps.json: the RPS points fix 5 coordinates") == 0);
  MeasurementSet missing = set;
  missing.points.erase(missing.points.begin() + 4);
  CHECK(error_of(three_two_one(), missing) == "input: measured.csv: RPS point \"R5\" of rps.json was not measured");
  MeasurementSet anonymous = set;
  anonymous.ids_from_file = false;
  CHECK(error_of(three_two_one(), anonymous).find("carry no ids") != std::string::npos);
}

TEST_CASE("rps file: every field is checked and named") {
  const std::string good_point = R"({"id": "R1", "nominal": [0, 0, 0], "normal": [0, 0, -2], "directions": "xyz"})";
  const auto doc = [&](const std::string& extra) {
    return R"({"format": "furrow-rps", "version": 1, "points": [)" + good_point + "," +
           R"({"id": "R2", "nominal": [100, 0, 0], "normal": [0, 0, -1], "directions": "zy"},)" +
           R"({"id": "R3", "nominal": [0, 60, 0], "normal": [0, 0, -1], "directions": "z")" + extra + "}]}";
  };
  const ReferencePointSystem ok = parse_reference_points(doc(""), "rps.json");
  REQUIRE(ok.points.size() == 3);
  CHECK(ok.points[0].normal.isApprox(Eigen::Vector3d(0, 0, -1)));
  CHECK(ok.points[1].directions == "yz");
  CHECK(ok.constraints() == 6);
  const auto error = [&](const std::string& text) {
    try {
      parse_reference_points(text, "rps.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(error(doc(R"(, "weight": 0)")).find("rps.json: points[2].weight") == 0);
  CHECK(error(doc(R"(, "weight": 1e308)")).find("points[2].weight") != std::string::npos);
  CHECK(error(doc(R"(, "wieght": 1)")).find("points[2].wieght") != std::string::npos);
  CHECK(error(R"({"format": "furrow-rps", "version": 1, "points": [)" + good_point + "]}")
            .find("fix 3 coordinates") != std::string::npos);
  std::string twice = doc("");
  twice.replace(twice.find("\"zy\""), 4, "\"zz\"");
  CHECK(error(twice).find("axis z given twice") != std::string::npos);
  std::string other = doc("");
  other.replace(other.find("\"zy\""), 4, "\"zw\"");
  CHECK(error(other).find("points[1].directions") != std::string::npos);
  std::string zero = doc("");
  zero.replace(zero.find("[0, 0, -2]"), 10, "[0, 0, 0]");
  CHECK(error(zero).find("points[0].normal") != std::string::npos);
  std::string far = doc("");
  far.replace(far.find("[100, 0, 0]"), 11, "[1e308, 0, 0]");
  CHECK(error(far).find("points[1].nominal") != std::string::npos);
  std::string same = doc("");
  same.replace(same.find("\"R2\""), 4, "\"R1\"");
  CHECK(error(same).find("given twice") != std::string::npos);
}

TEST_CASE("furrow compare --align rps: a face machined 0.05 mm high shows in the RPS profile, not in the best fit") {
  const std::string dir = test::scratch_dir("cli-compare-rps");
  const Part part = rps_part();
  write_part_json(part, dir + "/part.json");
  const ReferencePointSystem rps = three_two_one();
  std::string json = R"({"format": "furrow-rps", "version": 1, "points": [)";
  for (const ReferencePoint& p : rps.points) {
    char line[300];
    std::snprintf(line, sizeof line, R"(%s{"id": "%s", "nominal": [%g, %g, %g], "normal": [%g, %g, %g], "directions": "%s"})",
                  &p == &rps.points.front() ? "" : ", ", p.id.c_str(), p.nominal.x(), p.nominal.y(), p.nominal.z(),
                  p.normal.x(), p.normal.y(), p.normal.z(), p.directions.c_str());
    json += line;
  }
  test::write_text(dir + "/rps.json", json + "]}");
  // Contact points: the RPS points as nominal, the top 0.05 mm higher along z.
  const Eigen::Vector3d shift(0, 0, 0.05);
  std::string csv = "id,x,y,z\n";
  std::vector<double> expected;
  const auto add = [&](const std::string& id, const Eigen::Vector3d& p) {
    const Eigen::Vector3d m = placement() * p;
    char line[200];
    std::snprintf(line, sizeof line, "%s,%.12f,%.12f,%.12f\n", id.c_str(), m.x(), m.y(), m.z());
    csv += line;
  };
  for (const ReferencePoint& p : rps.points) add(p.id, p.nominal);
  const Face& top = part.faces[3];
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) {
      const DifferentialGeometry g = top.geometry((i + 0.5) / 6, (j + 0.5) / 5);
      // The face machined high, touched on the normal through the nominal
      // point, shift . n off it: that offset is the deviation.
      add("T" + std::to_string(i * 5 + j), g.point + shift.dot(g.normal) * g.normal);
      expected.push_back(shift.dot(g.normal));
    }
  test::write_text(dir + "/measured.csv", csv);
  const std::vector<std::string> base = {"compare", dir + "/part.json", "--measurements", dir + "/measured.csv",
                                         "--points", "contact", "--tolerance", "0.06", "--out", dir + "/c.json"};
  std::vector<std::string> args = base;
  args.insert(args.end(), {"--align", "rps", "--rps", dir + "/rps.json"});
  const test::CliResult run = test::run_furrow(args);
  INFO(run.out << run.err);
  CHECK(run.status == 1);  // +0.05 lies outside the +-0.03 zone
  const ComparisonDocument doc = read_comparison(dir + "/c.json");
  CHECK(doc.alignment.method == "rps");
  REQUIRE(doc.alignment.datums.size() == 6);
  CHECK(doc.alignment.datums[5].kind == "rps");
  CHECK(doc.alignment.datums[5].directions == "x");
  CHECK(doc.alignment.datums[5].form_error < 1e-9);
  REQUIRE(doc.points.size() == expected.size());  // the RPS points are not evaluated
  for (std::size_t k = 0; k < expected.size(); ++k) CHECK(std::abs(doc.points[k].deviation - expected[k]) < 1e-6);
  REQUIRE(doc.alignment.bestfit_profile);
  CHECK(*doc.alignment.bestfit_profile < 0.002);
  CHECK(run.out.find("rps R6 (fixes x)") != std::string::npos);

  // --rps and --align rps go together; a file that does not fix the part is
  // a computation that did not succeed (3), a bad file bad input (2).
  std::vector<std::string> alone = base;
  alone.insert(alone.end(), {"--align", "rps"});
  CHECK(test::run_furrow(alone).status == 2);
  std::vector<std::string> stray = base;
  stray.insert(stray.end(), {"--rps", dir + "/rps.json"});
  CHECK(test::run_furrow(stray).status == 2);
  std::string loose = json;
  for (std::size_t at = loose.find("\"y\""); at != std::string::npos; at = loose.find("\"y\"")) loose.replace(at, 3, "\"z\"");
  for (std::size_t at = loose.find("\"x\""); at != std::string::npos; at = loose.find("\"x\"")) loose.replace(at, 3, "\"z\"");
  test::write_text(dir + "/loose.json", loose + "]}");
  std::vector<std::string> free = base;
  free.insert(free.end(), {"--align", "rps", "--rps", dir + "/loose.json"});
  const test::CliResult unfixed = test::run_furrow(free);
  CHECK(unfixed.status == 3);
  CHECK(unfixed.err.find("do not fix the part") != std::string::npos);
  test::write_text(dir + "/bad.json", R"({"format": "furrow-rps", "version": 1, "points": []})");
  std::vector<std::string> bad = base;
  bad.insert(bad.end(), {"--align", "rps", "--rps", dir + "/bad.json"});
  const test::CliResult refused = test::run_furrow(bad);
  CHECK(refused.status == 2);
  CHECK(refused.err.find("bad.json: points: the points fix 0 coordinates") != std::string::npos);
}

// plan.csv: one row per point in execution order; the numbers read back to
// the plan's doubles exactly.
#include <doctest/doctest.h>

#include <charconv>
#include <sstream>

#include "io/plan_csv.hpp"

using namespace furrow;

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

double number(const std::string& s) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  REQUIRE(ec == std::errc());
  REQUIRE(ptr == s.data() + s.size());
  return v;
}

}  // namespace

TEST_CASE("plan.csv lists the points in order with exact numbers") {
  InspectionPlan plan;
  plan.part = "p.json";
  plan.probe = {"Probe1", 2};
  for (int k = 0; k < 3; ++k) {
    PlannedPoint p;
    p.id = "P" + std::to_string(k);
    p.order = 3 - k;  // stored out of order
    p.face = "face,one";
    p.face_index = 0;
    if (k != 1) p.region = k;
    p.uv = {0.1 * k + 1.0 / 3, 0.7};
    p.xyz = {1.0 / 7 + k, -2.5, 1e-7};
    p.ijk = Eigen::Vector3d(0.3, -0.4, 1).normalized();
    p.approach = p.xyz + 4 * p.ijk;
    p.retract = p.xyz + 5 * p.ijk;
    plan.points.push_back(p);
  }
  std::istringstream in(plan_to_csv_text(plan));
  std::string line;
  std::getline(in, line);
  CHECK(line.rfind("# Furrow probe plan: part p.json, probe Probe1 diameter 2 mm, 3 points", 0) == 0);
  std::getline(in, line);
  CHECK(line.rfind("order,id,face,face_index,region,u,v,x,y,z,i,j,k,approach_x", 0) == 0);
  for (int row = 0; row < 3; ++row) {
    REQUIRE(std::getline(in, line));
    const PlannedPoint& p = plan.points[static_cast<std::size_t>(2 - row)];
    // The face name holds a comma, so it is quoted: "face,one" becomes two fields here.
    const std::vector<std::string> f = split(line);
    REQUIRE(f.size() == 20);
    CHECK(f[0] == std::to_string(row + 1));
    CHECK(f[1] == p.id);
    CHECK(f[2] + "," + f[3] == "\"face,one\"");
    CHECK(f[5] == (p.region ? std::to_string(*p.region) : ""));
    CHECK(number(f[6]) == p.uv.x());
    CHECK(number(f[8]) == p.xyz.x());
    CHECK(number(f[10]) == p.xyz.z());
    CHECK(number(f[12]) == p.ijk.y());
    CHECK(number(f[19]) == p.retract.z());
  }
}

TEST_CASE("plan.csv of a plan with an alignment: its points first, each row naming its feature") {
  InspectionPlan plan;
  plan.part = "box.step";
  plan.probe = {"Probe1", 2};
  auto point = [](const std::string& id, int order, double x) {
    PlannedPoint p;
    p.id = id;
    p.order = order;
    p.face = "top";
    p.uv = {x / 10, 0.5};
    p.xyz = {x, 1.0 / 3, 20};
    p.ijk = {0, 0, 1};
    p.approach = p.xyz + 5 * p.ijk;
    p.retract = p.approach;
    return p;
  };
  PartAlignment a;
  DatumFeature top;
  top.label = "A";
  top.points = {point("A1", 1, 1), point("A2", 2, 2), point("A3", 3, 3)};
  DatumFeature wall;
  wall.label = "B";
  wall.kind = DatumFeature::Kind::line;
  wall.points = {point("B1", 4, 4), point("B2", 5, 5)};
  a.datums = {top, wall};
  plan.alignment = a;
  plan.points = {point("P0002", 2, 7), point("P0001", 1, 6)};
  std::istringstream in(plan_to_csv_text(plan));
  std::string line;
  std::getline(in, line);
  CHECK(line == "# Furrow probe plan: part box.step, probe Probe1 diameter 2 mm, 2 points after 5 alignment points, "
                "units mm");
  std::getline(in, line);
  CHECK(line.size() > 8);
  CHECK(line.substr(line.size() - 8) == ",feature");
  struct Want {
    const char* id;
    const char* feature;
    int order;
    double x;
  } want[] = {{"A1", "DATUM_A", 1, 1}, {"A2", "DATUM_A", 2, 2}, {"A3", "DATUM_A", 3, 3}, {"B1", "DATUM_B", 4, 4},
              {"B2", "DATUM_B", 5, 5}, {"P0001", "FREE_FORM", 1, 6}, {"P0002", "FREE_FORM", 2, 7}};
  for (const Want& w : want) {
    REQUIRE(std::getline(in, line));
    const std::vector<std::string> f = split(line);
    REQUIRE(f.size() == 20);
    CHECK(f[0] == std::to_string(w.order));
    CHECK(f[1] == w.id);
    CHECK(f[19] == w.feature);
    CHECK(number(f[7]) == w.x);
    CHECK(number(f[8]) == 1.0 / 3);
  }
  CHECK_FALSE(std::getline(in, line));
}

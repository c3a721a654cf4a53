// What the report says about surfaces: region groups that join several
// regions are listed with the deviations of all their points together
// (oracle: deviation_statistics over exactly those points), and each face
// with points names the elementary surface it is (oracle: the radius and
// axis the face was built with).
#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "geometry/primitives.hpp"
#include "report/merged_surfaces.hpp"
#include "report/qa_report.hpp"
#include "report/report_html.hpp"
#include "report/report_json.hpp"
#include "report/verdict.hpp"
#include "report_fixture.hpp"

using namespace furrow;

namespace {

// Three regions on the fixture's one face, regions 0 and 2 grouped: the
// report's arithmetic does not care how the groups were found.
RegionMap grouped_map(const std::string& face_name) {
  RegionMap map;
  RegionFace face;
  face.name = face_name;
  face.regions = {0, 1, 2};
  map.faces.push_back(face);
  for (int id = 0; id < 3; ++id) {
    Region r;
    r.id = id;
    r.face = 0;
    r.curvature_class = id == 1 ? CurvatureClass::concave : CurvatureClass::convex;
    r.area = 100.0 + id;
    r.group = id == 2 ? 0 : id;
    map.regions.push_back(r);
  }
  map.collect_groups();
  return map;
}

}  // namespace

TEST_CASE("report: a group of regions is one surface with the deviations of all its points") {
  test::ReportFixture f = test::make_report_fixture();
  for (std::size_t k = 0; k < f.doc.points.size(); ++k) f.doc.points[k].region = static_cast<int>(k % 3);
  // The per-region table the comparison would have made from those ids.
  f.doc.summary.regions.clear();
  for (int id = 0; id < 3; ++id) {
    std::vector<double> d;
    for (const auto& p : f.doc.points)
      if (p.evaluated && *p.region == id) d.push_back(p.deviation);
    f.doc.summary.regions.push_back({id, deviation_statistics(d), 0});
  }
  const RegionMap map = grouped_map(f.part.faces[0].name());
  REQUIRE(map.groups.size() == 2);

  std::vector<double> values;
  std::size_t out = 0;
  for (const auto& p : f.doc.points)
    if (p.evaluated && *p.region != 1) {
      values.push_back(p.deviation);
      out += p.in_tolerance == false;
    }
  REQUIRE(values.size() > 50);
  const DeviationStatistics expected = deviation_statistics(values);

  const std::vector<MergedSurface> merged = merged_surfaces(f.doc, &map);
  REQUIRE(merged.size() == 1);  // the lone concave region is not a merged surface
  CHECK(merged[0].group->regions == std::vector<int>{0, 2});
  CHECK(merged[0].deviations.count == expected.count);
  CHECK(merged[0].deviations.mean == expected.mean);
  CHECK(merged[0].deviations.sigma == expected.sigma);
  CHECK(merged[0].out_of_tolerance == out);
  CHECK(merged_surfaces(f.doc, nullptr).empty());

  ReportContext context;
  context.generated = "2024-01-01T00:00:00Z";
  const auto doc = nlohmann::json::parse(report_json_text(f.doc, report_verdict(f.doc), &map, context, {}));
  REQUIRE(doc["surfaces"].size() == 1);
  const auto& s = doc["surfaces"][0];
  CHECK(s["group"] == 0);
  CHECK(s["class"] == "convex");
  CHECK(s["regions"] == nlohmann::json::array({0, 2}));
  CHECK(s["faces"] == nlohmann::json::array({f.part.faces[0].name()}));
  CHECK(s["count"] == expected.count);
  CHECK(s["area"].get<double>() == 202.0);
  for (const auto& r : doc["regions"]) CHECK(r["group"] == (r["region"] == 2 ? 0 : r["region"].get<int>()));
  const std::string html = report_html(f.doc, report_verdict(f.doc), &map, context, {});
  CHECK(html.find("Surfaces across faces") != std::string::npos);
  CHECK(html.find("R0, R2") != std::string::npos);
}

TEST_CASE("report: each measured face names its elementary surface, with the radius and axis it was built with") {
  test::ReportFixture f = test::make_report_fixture();
  // The fixture's points lie on the mould (face 0, free-form); a cylinder
  // about the y axis and a sphere join the part, with one point moved onto
  // each so that they are measured faces.
  f.part.faces.emplace_back("bore", make_cylinder(6.35, 40, 0, 3.0), Trim{}, false);
  f.part.faces.emplace_back("ball", make_sphere(12.5, 0, 6.0, -1.0, 1.0), Trim{}, true);
  f.doc.points[0].face_index = 1;
  f.doc.points[0].face = "bore";
  f.doc.points[1].face_index = 2;
  f.doc.points[1].face = "ball";
  const std::vector<std::optional<AnalyticSurface>> surfaces = face_surfaces(f.part, f.doc);
  REQUIRE(surfaces.size() == 3);
  CHECK_FALSE(surfaces[0].has_value());  // the mould is free-form
  REQUIRE(surfaces[1].has_value());
  CHECK(surfaces[1]->type == AnalyticSurface::Type::cylinder);
  CHECK(std::abs(surfaces[1]->radius - 6.35) < 1e-9);
  CHECK((surfaces[1]->axis - Eigen::Vector3d::UnitY()).norm() < 1e-9);
  REQUIRE(surfaces[2].has_value());
  CHECK(surfaces[2]->type == AnalyticSurface::Type::sphere);
  CHECK(std::abs(surfaces[2]->radius - 12.5) < 1e-9);
  CHECK(surfaces[2]->origin.norm() < 1e-9);

  ReportContext context;
  context.generated = "2024-01-01T00:00:00Z";
  context.face_surfaces = surfaces;
  const auto doc = nlohmann::json::parse(report_json_text(f.doc, report_verdict(f.doc), nullptr, context, {}));
  int seen = 0;
  for (const auto& face : doc["faces"]) {
    if (face["face"] == "bore") {
      ++seen;
      CHECK(face["surface"]["type"] == "cylinder");
      CHECK(std::abs(face["surface"]["radius"].get<double>() - 6.35) < 1e-9);
    } else if (face["face"] == "ball") {
      ++seen;
      CHECK(face["surface"]["type"] == "sphere");
    } else {
      CHECK(face["surface"].is_null());
    }
  }
  CHECK(seen == 2);
  const std::string html = report_html(f.doc, report_verdict(f.doc), nullptr, context, {});
  CHECK(html.find(describe(*surfaces[1])) != std::string::npos);
  CHECK(html.find("free-form") != std::string::npos);
}

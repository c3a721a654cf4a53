// report.json is streamed point by point (report_json.cpp); these tests
// hold it to the tree it replaced: the points as a nlohmann::json tree built
// the plain way here, and the layout of the dump-per-level oracle.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "report/report_json.hpp"
#include "report/verdict.hpp"
#include "report_fixture.hpp"
#include "support/json_layout_oracle.hpp"

using namespace furrow;
using nlohmann::json;

namespace {

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

// The points member as the tree writer built it (second implementation).
json points_tree(const ComparisonDocument& doc) {
  json out = json::array();
  for (const auto& p : doc.points) {
    json j;
    j["id"] = p.id;
    j["face"] = p.face;
    j["uv"] = json::array({p.uv.x(), p.uv.y()});
    j["foot"] = vec(p.foot);
    j["normal"] = vec(p.normal);
    j["measured"] = vec(p.measured);
    j["deviation"] = p.deviation;
    j["uncertainty"] = p.uncertainty ? json(*p.uncertainty) : json(nullptr);
    j["evaluated"] = p.evaluated;
    j["in_tolerance"] = p.in_tolerance ? json(*p.in_tolerance) : json(nullptr);
    j["in_fit"] = p.in_fit;
    j["outlier"] = p.outlier.empty() ? json(nullptr) : json(p.outlier);
    j["region"] = p.region ? json(*p.region) : json(nullptr);
    if (p.prediction) {
      const PointPrediction& q = *p.prediction;
      json r;
      r["status"] = q.face_predicted ? to_string(q.status) : "face_not_predicted";
      r["compared"] = q.compared;
      if (q.reached()) {
        r["predicted"] = q.predicted;
        r["band"] = json::array({q.band_low, q.band_high});
        r["measured"] = q.measured;
        r["residual"] = q.residual;
        r["sigma"] = q.sigma;
      }
      j["prediction"] = r;
    } else {
      j["prediction"] = nullptr;
    }
    out.push_back(j);
  }
  return out;
}

ComparisonDocument hostile_document() {
  ComparisonDocument doc = test::make_report_fixture().doc;
  REQUIRE(doc.points.size() > 5);
  auto& p = doc.points;
  p[0].id = "P\"1\\ \n\t\x01\x1f Ma\xc3\x9f \xe2\x82\xac \xf0\x9f\x94\xa7";
  p[1].id = "";
  p[1].outlier = "quote\" and \\ backslash";
  p[2].foot = {1e308, -1e-300, -0.0};
  p[2].measured = {-1e308, 4.9e-324, 1.0};
  p[2].uv = {-0.0, 1e-300};
  p[2].deviation = -0.0;
  p[2].uncertainty = 1e-300;
  p[3].uncertainty.reset();
  p[3].in_tolerance.reset();
  p[3].region = -2147483647;
  p[4].region.reset();
  PointPrediction reached;
  reached.face_predicted = true;
  reached.status = ErrorCellStatus::reached;
  reached.compared = true;
  reached.predicted = -0.0;
  reached.band_low = -1e-300;
  reached.band_high = 1e308;
  reached.measured = 123456789012345680000.0;
  reached.residual = 0.30000000000000004;
  reached.sigma = 1e-5;
  p[4].prediction = reached;
  PointPrediction outside;
  outside.face_predicted = true;
  outside.status = ErrorCellStatus::outside;
  p[5].prediction = outside;
  p[0].prediction = PointPrediction{};  // face not predicted
  return doc;
}

}  // namespace

TEST_CASE("report json stream: points equal the tree they replaced and the text its layout, on hostile values") {
  const ComparisonDocument doc = hostile_document();
  ReportContext context;
  context.title = "ti\"tle \\ \x02";
  context.generated = "2024-01-01T00:00:00Z";
  context.stages = {{"compare", 1e-300}, {"", 0.5}};
  context.total_seconds = 1e308;
  const std::string text = report_json_text(doc, report_verdict(doc), nullptr, context, {});
  const json parsed = json::parse(text);
  CHECK(parsed.at("points") == points_tree(doc));
  CHECK(parsed.at("title") == context.title);
  // Bytes: the text is what the tree writer would write for that document.
  CHECK(text == test::oracle_text(parsed));
  // Negative zero and the extremes survive as text (== cannot tell -0 from 0).
  CHECK(text.find("\"deviation\": -0.0,") != std::string::npos);
  CHECK(text.find("\"foot\": [1e+308,-1e-300,-0.0]") != std::string::npos);
  CHECK(text.find("\"id\": \"P\\\"1\\\\ \\n\\t\\u0001\\u001f Ma\xc3\x9f") != std::string::npos);
  CHECK(std::signbit(parsed.at("points")[2].at("deviation").get<double>()));
}

TEST_CASE("report json stream: an empty point list and a non-finite value") {
  ComparisonDocument doc = test::make_report_fixture().doc;
  ReportContext context;
  context.generated = "x";
  ComparisonDocument none = doc;
  none.points.clear();
  const std::string empty = report_json_text(none, report_verdict(none), nullptr, context, {});
  CHECK(empty.find("\"points\": [],\n") != std::string::npos);
  CHECK(empty == test::oracle_text(json::parse(empty)));
  doc.points[3].measured.y() = std::nan("");
  CHECK_THROWS_AS(report_json_text(doc, report_verdict(doc), nullptr, context, {}), std::logic_error);
}

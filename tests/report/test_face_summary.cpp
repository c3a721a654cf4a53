// The per-face summary of a many-face part: faces worst first, counts and
// extremes against a brute-force pass over the points.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "report/face_summary.hpp"
#include "report_fixture.hpp"

using namespace furrow;

namespace {

const test::ReportFixture& fixture() {
  static const test::ReportFixture f = test::make_report_fixture();
  return f;
}

// The fixture's points spread over 140 faces (as an imported part has),
// face k named "face_k"; a few points not evaluated.
ComparisonDocument many_faces() {
  ComparisonDocument doc = fixture().doc;
  for (std::size_t i = 0; i < doc.points.size(); ++i) {
    auto& p = doc.points[i];
    p.face_index = static_cast<int>((i * 37) % 140);
    p.face = "face_" + std::to_string(p.face_index);
  }
  return doc;
}

}  // namespace

TEST_CASE("faces are summarised worst first with the points' numbers") {
  const ComparisonDocument doc = many_faces();
  const ToleranceZone& zone = doc.options.tolerance;
  // Brute force per face.
  struct Expect {
    std::size_t points = 0, evaluated = 0, out = 0;
    double min = 1e300, max = -1e300, excess = 0, worst = -1;
  };
  std::map<int, Expect> expect;
  for (const auto& p : doc.points) {
    Expect& e = expect[p.face_index];
    ++e.points;
    if (!p.evaluated) continue;
    ++e.evaluated;
    const bool in = p.deviation >= zone.lower() && p.deviation <= zone.upper();
    e.out += !in;
    e.min = std::min(e.min, p.deviation);
    e.max = std::max(e.max, p.deviation);
    e.excess = std::max(e.excess, p.deviation > zone.upper()   ? p.deviation - zone.upper()
                                  : p.deviation < zone.lower() ? zone.lower() - p.deviation
                                                               : 0.0);
    e.worst = std::max(e.worst, std::abs(p.deviation));
  }
  const std::vector<FaceDeviationSummary> faces = face_summaries(doc);
  REQUIRE(faces.size() == expect.size());
  CHECK(faces.size() == 140);  // 192 points reach every one of 140 faces (37 is prime to 140)
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const FaceDeviationSummary& f = faces[k];
    const Expect& e = expect.at(f.face_index);
    CHECK(f.face == "face_" + std::to_string(f.face_index));
    CHECK(f.points == e.points);
    CHECK(f.evaluated == e.evaluated);
    CHECK(f.out_of_tolerance == e.out);
    if (e.evaluated) {
      CHECK(*f.min_deviation == e.min);
      CHECK(*f.max_deviation == e.max);
      CHECK(f.max_abs_deviation == e.worst);
      CHECK(f.worst_excess == doctest::Approx(e.excess).epsilon(1e-12));
    }
    if (k == 0) continue;
    // Worst first: a face never precedes one with a larger excess, nor, at
    // equal excess, one with a larger |deviation|.
    const FaceDeviationSummary& before = faces[k - 1];
    if (before.evaluated && f.evaluated) {
      CHECK(before.worst_excess >= f.worst_excess);
      if (before.worst_excess == f.worst_excess) CHECK(before.max_abs_deviation >= f.max_abs_deviation);
    }
  }
  // The first face holds the worst point of the whole part.
  double worst_excess = 0;
  for (const auto& [index, e] : expect) worst_excess = std::max(worst_excess, e.excess);
  CHECK(worst_excess > 0);
  CHECK(faces.front().worst_excess == doctest::Approx(worst_excess).epsilon(1e-12));
}

TEST_CASE("the faces section lists each face once with out-of-tolerance faces marked") {
  const ComparisonDocument doc = many_faces();
  const std::string html = face_summary_html(doc);
  std::size_t rows = 0, out_rows = 0;
  for (std::size_t at = html.find("<tr"); at != std::string::npos; at = html.find("<tr", at + 1)) {
    ++rows;
    out_rows += html.compare(at, 16, "<tr class=\"out\">") == 0;
  }
  CHECK(rows == 140 + 1);  // + header
  std::size_t bad = 0;
  for (const FaceDeviationSummary& f : face_summaries(doc)) bad += f.out_of_tolerance > 0;
  CHECK(out_rows == bad);
  CHECK(bad >= 1);
  CHECK(html.find("140 faces carry measured points; " + std::to_string(bad) + " with points out of tolerance") !=
        std::string::npos);
}

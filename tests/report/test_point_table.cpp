// The point table (points.csv and report.html) against comparison.json,
// every row: the JSON is parsed here with nlohmann, independently of the
// comparison reader, and the out-of-tolerance amounts are recomputed from
// the zone's limits.
#include <doctest/doctest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "inspection/comparison_file.hpp"
#include "report/point_table.hpp"
#include "report/point_table_html.hpp"
#include "report/points_csv.hpp"
#include "report_fixture.hpp"

using namespace furrow;
using nlohmann::json;

namespace {

const test::ReportFixture& fixture() {
  static const test::ReportFixture f = test::make_report_fixture();
  return f;
}

double parse_double(const std::string& s) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  REQUIRE(ec == std::errc());
  REQUIRE(ptr == s.data() + s.size());
  return v;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// The oracle: the amount beyond the nearer limit, 0 inside.
double expected_excess(double d, double lower, double upper) {
  if (d > upper) return d - upper;
  if (d < lower) return lower - d;
  return 0;
}

struct HtmlRow {
  std::string status;
  std::vector<std::string> values;  // data-v of each cell ("" when the cell has none)
  std::vector<std::string> texts;
};

// The rows of the point table: <tr ... data-status="S"><td data-v="v">text</td>...
std::vector<HtmlRow> html_rows(const std::string& html) {
  std::vector<HtmlRow> rows;
  const std::size_t table = html.find("id=\"point-table\"");
  REQUIRE(table != std::string::npos);
  const std::size_t body = html.find("<tbody>", table), end = html.find("</tbody>", body);
  REQUIRE(body != std::string::npos);
  for (std::size_t at = html.find("<tr", body); at != std::string::npos && at < end; at = html.find("<tr", at + 1)) {
    HtmlRow row;
    const std::size_t s = html.find("data-status=\"", at) + 13;
    row.status = html.substr(s, html.find('"', s) - s);
    const std::size_t row_end = html.find("</tr>", at);
    for (std::size_t c = html.find("<td", at); c < row_end; c = html.find("<td", c + 1)) {
      const std::size_t close = html.find('>', c);
      const std::string open = html.substr(c, close - c);
      const std::size_t v = open.find("data-v=\"");
      row.values.push_back(v == std::string::npos ? "" : open.substr(v + 8, open.find('"', v + 8) - v - 8));
      row.texts.push_back(html.substr(close + 1, html.find("</td>", close) - close - 1));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

// The fixture's comparison, and a copy with three points set aside (not
// evaluated, as the comparison writes blunders) read back through the same
// reader, so the NOT EVALUATED rows are checked too.
struct Variant {
  json comparison;
  ComparisonDocument doc;
};
std::vector<Variant> variants() {
  std::vector<Variant> v;
  v.push_back({json::parse(fixture().comparison_json), fixture().doc});
  json blunders = json::parse(fixture().comparison_json);
  for (std::size_t i : {3u, 50u, 100u}) {
    json& p = blunders["points"][i];
    p["evaluated"] = false;
    p["in_tolerance"] = nullptr;
    p["in_fit"] = false;
    p["outlier"] = {{"reason", "blunder"}, {"detail", "test"}};
  }
  v.push_back({blunders, parse_comparison(blunders.dump(), "blunders.json")});
  return v;
}

}  // namespace

TEST_CASE("points.csv carries the metrologist's columns with every row as comparison.json says") {
  for (const Variant& variant : variants()) {
    const json& comparison = variant.comparison;
    const double lower = comparison["tolerance"]["lower"], upper = comparison["tolerance"]["upper"];
    std::istringstream in(points_csv_text(variant.doc));
    std::string header;
    std::getline(in, header);
    const std::vector<std::string> columns = split(header);
    auto column = [&](const std::string& name) {
      for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i] == name) return i;
      FAIL("no column " << name);
      return std::size_t(0);
    };
    const json& points = comparison["points"];
    std::size_t row = 0, out = 0, not_evaluated = 0;
    for (std::string line; std::getline(in, line); ++row) {
      REQUIRE(row < points.size());
      const json& p = points[row];
      const std::vector<std::string> cells = split(line);
      REQUIRE(cells.size() == columns.size());
      CHECK(cells[column("id")] == p["id"].get<std::string>());
      const char* axes[] = {"x", "y", "z"};
      const char* ijk[] = {"i", "j", "k"};
      for (int k = 0; k < 3; ++k) {
        CHECK(parse_double(cells[column(std::string("foot_") + axes[k])]) == p["foot"][k].get<double>());
        CHECK(parse_double(cells[column(std::string("normal_") + ijk[k])]) == p["normal"][k].get<double>());
        CHECK(parse_double(cells[column(std::string("actual_") + axes[k])]) == p["contact"][k].get<double>());
      }
      const double d = p["deviation"];
      CHECK(parse_double(cells[column("deviation")]) == d);
      CHECK(parse_double(cells[column("lower_tolerance")]) == lower);
      CHECK(parse_double(cells[column("upper_tolerance")]) == upper);
      // The actual is the part-frame point the deviation is measured at.
      double along = 0;
      for (int k = 0; k < 3; ++k)
        along += p["normal"][k].get<double>() * (p["contact"][k].get<double>() - p["foot"][k].get<double>());
      CHECK(std::abs(along - d) < 1e-9);  // mm; coordinates of ~100 mm round at ~1e-14
      const std::string status = cells[column("status")];
      if (!p["evaluated"].get<bool>()) {
        CHECK(status == "NOT EVALUATED");
        CHECK(cells[column("out_of_tolerance")].empty());
        ++not_evaluated;
        continue;
      }
      const double excess = parse_double(cells[column("out_of_tolerance")]);
      CHECK(excess == doctest::Approx(expected_excess(d, lower, upper)).epsilon(1e-12));
      CHECK(status == (p["in_tolerance"].get<bool>() ? "IN" : "OUT"));
      CHECK((status == "OUT") == (excess > 0));
      out += status == "OUT";
    }
    CHECK(row == points.size());
    std::size_t expected_out = 0;
    for (const json& p : points)
      expected_out += p["evaluated"].get<bool>() && (p["deviation"] < lower || p["deviation"] > upper);
    CHECK(out == expected_out);
    CHECK(out >= 1);  // the fixture's 60 um dent breaks the 50 um zone
    std::size_t evaluated = 0;
    for (const json& p : points) evaluated += p["evaluated"].get<bool>();
    CHECK(not_evaluated == points.size() - evaluated);
  }
}

TEST_CASE("the HTML point table shows every point with the same numbers as comparison.json") {
  std::size_t not_evaluated = 0;
  for (const Variant& variant : variants()) {
    const json& comparison = variant.comparison;
    const double lower = comparison["tolerance"]["lower"], upper = comparison["tolerance"]["upper"];
    const std::vector<HtmlRow> rows = html_rows(point_table_html(variant.doc));
    const json& points = comparison["points"];
    REQUIRE(rows.size() == points.size());  // 192 < the cap: all of them
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const HtmlRow& r = rows[i];
      const json& p = points[i];
      REQUIRE(r.values.size() == 17);
      CHECK(parse_double(r.values[0]) == static_cast<double>(i + 1));
      CHECK(r.texts[1] == p["id"].get<std::string>());
      for (int k = 0; k < 3; ++k) {
        CHECK(parse_double(r.values[3 + k]) == p["foot"][k].get<double>());
        CHECK(parse_double(r.values[6 + k]) == p["normal"][k].get<double>());
        CHECK(parse_double(r.values[9 + k]) == p["contact"][k].get<double>());
        // The text is the value rounded to 4 decimals.
        CHECK(std::abs(parse_double(r.texts[3 + k]) - p["foot"][k].get<double>()) <= 0.5e-4 + 1e-12);
        CHECK(std::abs(parse_double(r.texts[9 + k]) - p["contact"][k].get<double>()) <= 0.5e-4 + 1e-12);
      }
      const double d = p["deviation"];
      CHECK(parse_double(r.values[12]) == d);
      CHECK(std::abs(parse_double(r.texts[12]) - d) <= 0.5e-4 + 1e-12);
      CHECK(parse_double(r.values[13]) == lower);
      CHECK(parse_double(r.values[14]) == upper);
      if (p["evaluated"].get<bool>()) {
        CHECK(parse_double(r.values[15]) == doctest::Approx(expected_excess(d, lower, upper)).epsilon(1e-12));
        CHECK(r.status == (p["in_tolerance"].get<bool>() ? "IN" : "OUT"));
        CHECK(r.texts[16].rfind(r.status, 0) == 0);
      } else {
        CHECK(r.status == "NOT EVALUATED");
        CHECK(r.texts[15] == "&ndash;");
        CHECK(r.texts[16] == "NOT EVALUATED (blunder)");
        ++not_evaluated;
      }
    }
  }
  CHECK(not_evaluated == 3);  // the second variant's
}

TEST_CASE("a large point table keeps every out-of-tolerance point and says that points.csv has the rest") {
  const ComparisonDocument& doc = fixture().doc;
  const json comparison = json::parse(fixture().comparison_json);
  const double lower = comparison["tolerance"]["lower"], upper = comparison["tolerance"]["upper"];
  // Brute force: the out-of-tolerance ids and their amounts.
  std::vector<std::pair<double, std::string>> out;
  for (const json& p : comparison["points"])
    if (p["evaluated"].get<bool>() && !p["in_tolerance"].get<bool>())
      out.push_back({expected_excess(p["deviation"], lower, upper), p["id"]});
  REQUIRE(out.size() >= 2);
  REQUIRE(out.size() < 40);

  const std::string html = point_table_html(doc, 40);
  const std::vector<HtmlRow> rows = html_rows(html);
  CHECK(rows.size() == 40);
  CHECK(html.find("40 of 192 points shown") != std::string::npos);
  std::size_t shown_out = 0;
  double previous = 0;
  for (const HtmlRow& r : rows) {
    shown_out += r.status == "OUT";
    CHECK(parse_double(r.values[0]) > previous);  // measurement order
    previous = parse_double(r.values[0]);
  }
  CHECK(shown_out == out.size());

  // Fewer rows than out-of-tolerance points: the worst ones.
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const std::vector<HtmlRow> worst = html_rows(point_table_html(doc, 2));
  REQUIRE(worst.size() == 2);
  std::vector<std::string> ids = {worst[0].texts[1], worst[1].texts[1]};
  std::sort(ids.begin(), ids.end());
  std::vector<std::string> expected = {out[0].second, out[1].second};
  std::sort(expected.begin(), expected.end());
  CHECK(ids == expected);
}

TEST_CASE("the out-of-tolerance amount is the distance beyond the nearer limit") {
  const ToleranceZone bilateral = ToleranceZone::make(0.05, 0.025, "test");
  CHECK(out_of_tolerance_amount(0.0, bilateral) == 0);
  CHECK(out_of_tolerance_amount(0.025, bilateral) == 0);  // on the limit: in
  CHECK(out_of_tolerance_amount(0.03, bilateral) == doctest::Approx(0.005));
  CHECK(out_of_tolerance_amount(-0.1, bilateral) == doctest::Approx(0.075));
  const ToleranceZone inside = ToleranceZone::make(0.05, 0, "test");  // -0.05 .. 0
  CHECK(out_of_tolerance_amount(0.01, inside) == doctest::Approx(0.01));
  CHECK(out_of_tolerance_amount(-0.06, inside) == doctest::Approx(0.01));
}

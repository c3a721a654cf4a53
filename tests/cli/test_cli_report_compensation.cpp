// The QA report's Compensation section (`furrow report --compensation
// COMP.json`): the mould measured with a planted +50 um bump (the shared
// fixture), compensated with gain 0.8, reported with and without the
// record. Oracles: the statistics recomputed here, independently, from
// the record's per-point values (RMS and worst point of the measured
// deviation, the residual and the field, per region and overall);
// python3-jsonschema for report.json; the bytes of a second run for the
// figures.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "base/number_text.hpp"
#include "mould_bump_fixture.hpp"
#include "report_checks.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::slurp;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

const test::MouldBump& measured() {
  static const test::MouldBump made = test::measured_mould_bump("cli-report-compensation", 15, 0.05, 25, 7);
  return made;
}

// COMP.json of the fixture's program compensated with gain 0.8.
const std::string& record_path() {
  static const std::string path = [] {
    const test::MouldBump& m = measured();
    const auto r = run_furrow({"compensate", m.part, "--comparison", m.comparison, "--toolpath", m.program, "--tool",
                               m.tool, "--out", m.dir + "/comp.nc", "--gain", "0.8"});
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    return m.dir + "/comp.json";
  }();
  return path;
}

struct Stats {
  std::size_t n = 0;
  double before = 0, after = 0, field = 0, largest_se = 0;
  std::string worst_before_id, worst_after_id;
  double worst_before = 0, worst_after = 0;
};

// The statistics of the record's points of `region` (null: all), computed
// here from the per-point values alone.
Stats recompute(const json& points, const json& region) {
  Stats s;
  for (const json& p : points) {
    if (!region.is_null() && p["region"] != region) continue;
    ++s.n;
    const double m = p["measured"].get<double>(), r = p["residual"].get<double>(), f = p["field"].get<double>();
    s.before += m * m;
    s.after += r * r;
    s.field += f * f;
    s.largest_se = std::max(s.largest_se, p["standard_error"].get<double>());
    if (s.worst_before_id.empty() || std::abs(m) > std::abs(s.worst_before))
      s.worst_before = m, s.worst_before_id = p["id"].get<std::string>();
    if (s.worst_after_id.empty() || std::abs(r) > std::abs(s.worst_after))
      s.worst_after = r, s.worst_after_id = p["id"].get<std::string>();
  }
  if (s.n > 0) {
    s.before = std::sqrt(s.before / double(s.n));
    s.after = std::sqrt(s.after / double(s.n));
    s.field = std::sqrt(s.field / double(s.n));
  }
  return s;
}

void check_statistics(const json& shown, const Stats& s) {
  CHECK(shown["points"].get<std::size_t>() == s.n);
  CHECK(std::abs(shown["rms_before"].get<double>() - s.before) < 1e-12);
  CHECK(std::abs(shown["rms_after"].get<double>() - s.after) < 1e-12);
  CHECK(std::abs(shown["rms_field"].get<double>() - s.field) < 1e-12);
  CHECK(std::abs(shown["largest_standard_error"].get<double>() - s.largest_se) < 1e-12);
  CHECK(shown["worst_before"]["id"] == s.worst_before_id);
  CHECK(shown["worst_before"]["value"].get<double>() == s.worst_before);
  CHECK(shown["worst_after"]["id"] == s.worst_after_id);
  CHECK(shown["worst_after"]["value"].get<double>() == s.worst_after);
}

// The HTML text of one <tr> of the section's table, from its first cell.
std::string table_row(const std::string& html, const std::string& first_cell) {
  const std::size_t section = html.find("<section id=\"compensation\">");
  REQUIRE(section != std::string::npos);
  const std::size_t at = html.find("<td>" + first_cell + "</td>", section);
  REQUIRE(at != std::string::npos);
  return html.substr(at, html.find("</tr>", at) - at);
}

}  // namespace

TEST_CASE("report compensation: the section's numbers are the record's per-point values summarised") {
  const test::MouldBump& m = measured();
  const json record = json::parse(slurp(record_path()));
  const std::string out = m.dir + "/report";
  const auto r = run_furrow({"report", m.comparison, "--compensation", record_path(), "--out", out});
  INFO(r.out << r.err);
  REQUIRE((r.status == 0 || r.status == 1));
  const json report = json::parse(slurp(out + "/report.json"));
  const json& shown = report["compensation"];
  REQUIRE(shown.is_object());
  const json& points = record["expected"]["points"];
  REQUIRE(points.size() >= 40);
  const Stats all = recompute(points, json(nullptr));
  check_statistics(shown["overall"], all);
  // The bump is taken off: the oracle's own figures say so, not only the report's.
  CHECK(all.after < 0.5 * all.before);
  REQUIRE(shown["regions"].size() == record["expected"]["regions"].size());
  REQUIRE(shown["regions"].size() > 1);
  std::size_t in_regions = 0;
  for (const json& region : shown["regions"]) {
    const Stats s = recompute(points, region["region"]);
    REQUIRE(s.n > 0);
    in_regions += s.n;
    check_statistics(region, s);
  }
  CHECK(in_regions <= all.n);
  CHECK(shown["gain"].get<double>() == 0.8);
  CHECK(shown["max_offset"].get<double>() == record["max_offset"].get<double>());
  CHECK(shown["clipped"].get<std::size_t>() == record["clipped"].size());
  CHECK(shown["gouge_clipped"].get<std::size_t>() == record["gouge_clipped"].size());
  CHECK(shown["clip_back"]["points"].get<std::size_t>() == record["clip_back"]["points"].size());
  CHECK(shown["rework"].is_null());
  CHECK(shown["record"] == record_path());

  // The page shows the same numbers (µm, one decimal) in the overall row.
  const std::string html = slurp(out + "/report.html");
  const std::string row = table_row(html, "All points");
  CHECK(row.find("<td>" + std::to_string(all.n) + "</td>") != std::string::npos);
  CHECK(row.find("<td>" + fixed(all.before * 1000, 1) + "</td>") != std::string::npos);
  CHECK(row.find("<td>" + fixed(all.after * 1000, 1) + "</td>") != std::string::npos);
  CHECK(row.find(signed_fixed(all.worst_after * 1000, 1) + " (" + all.worst_after_id + ")") != std::string::npos);
  CHECK(html.find("<a href=\"#compensation\">") != std::string::npos);
  CHECK(html.find("id=\"fig-compensation_before\"") != std::string::npos);
  CHECK(html.find("id=\"fig-compensation_after\"") != std::string::npos);
  // The record is an input of the report, with its digest.
  bool listed = false;
  for (const json& in : report["inputs"]) listed = listed || (in["role"] == "compensation" && in["path"] == record_path());
  CHECK(listed);

  const auto valid = test::validate_with_jsonschema(test::source_path("docs/report.schema.json"),
                                                    out + "/report.json", m.dir);
  INFO(valid.out);
  CHECK(valid.status == 0);
}

TEST_CASE("report compensation: the maps share one colour scale and are the same bytes run to run") {
  const test::MouldBump& m = measured();
  const std::string a = m.dir + "/report_a", b = m.dir + "/report_b";
  for (const std::string& out : {a, b}) {
    const auto r = run_furrow({"report", m.comparison, "--compensation", record_path(), "--out", out});
    INFO(r.err);
    REQUIRE((r.status == 0 || r.status == 1));
  }
  for (const char* name : {"figures/compensation_before.png", "figures/compensation_before.svg",
                           "figures/compensation_after.png", "figures/compensation_after.svg"}) {
    INFO(name);
    REQUIRE(fs::exists(a + "/" + name));
    CHECK(slurp(a + "/" + name) == slurp(b + "/" + name));
  }
  const std::string before = slurp(a + "/figures/compensation_before.svg");
  const std::string after = slurp(a + "/figures/compensation_after.svg");
  CHECK(before != after);
  // One scale: the colour bar (its ticks, from the scale's range, and the
  // zone's marks) is the last part of each drawing and reads the same.
  auto bar = [](const std::string& svg) {
    const std::size_t at = svg.rfind("+tol");
    REQUIRE(at != std::string::npos);
    return svg.substr(svg.rfind("<text", svg.rfind("<text", at) - 1));
  };
  CHECK(bar(before) == bar(after));
  // The largest |value| of either map sets the scale: the measured bump
  // (~50 um) is larger than the zone's limits (comparison default).
  const json record = json::parse(slurp(record_path()));
  CHECK(std::abs(record["expected"]["overall"]["worst_before"]["value"].get<double>()) > 0.03);
}

TEST_CASE("report compensation: without a record there is no section, and a record of another comparison is refused") {
  const test::MouldBump& m = measured();
  const std::string plain = m.dir + "/report_plain";
  const auto r = run_furrow({"report", m.comparison, "--out", plain});
  REQUIRE((r.status == 0 || r.status == 1));
  const std::string html = slurp(plain + "/report.html");
  CHECK(html.find("id=\"compensation\"") == std::string::npos);
  CHECK(html.find("#compensation") == std::string::npos);
  CHECK(json::parse(slurp(plain + "/report.json"))["compensation"].is_null());
  CHECK(!fs::exists(plain + "/figures/compensation_before.png"));
  CHECK(!fs::exists(plain + "/figures/compensation_after.png"));

  // One point's measured value changed: the record is not of this comparison.
  json record = json::parse(slurp(record_path()));
  json& p = record["expected"]["points"][3];
  p["measured"] = p["measured"].get<double>() + 0.001;
  const std::string other = m.dir + "/other_comp.json";
  test::write_text(other, record.dump(2));
  const std::string refused = m.dir + "/report_refused";
  const auto bad = run_furrow({"report", m.comparison, "--compensation", other, "--out", refused});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("other_comp.json") != std::string::npos);
  CHECK(bad.err.find(p["id"].get<std::string>()) != std::string::npos);
  CHECK(!fs::exists(refused));
  // A member the record does not have is named.
  json misspelt = json::parse(slurp(record_path()));
  misspelt["gian"] = 1;
  test::write_text(other, misspelt.dump(2));
  const auto unknown = run_furrow({"report", m.comparison, "--compensation", other, "--out", refused});
  CHECK(unknown.status == 2);
  CHECK(unknown.err.find("gian") != std::string::npos);
  CHECK(!fs::exists(refused));
}

#include <doctest/doctest.h>

#include <cmath>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "results/spc_html.hpp"
#include "results/spc_statistics.hpp"
#include "spc_batch.hpp"

using namespace furrow;

namespace {

struct Area {
  double x, y, w, h, x0, x1, y0, y1;
  // Pixel to data, the inverse of the chart's linear map; SVG coordinates
  // carry two decimals, so a value is known to 0.005 px.
  double data_x(double px) const { return x0 + (px - x) / w * (x1 - x0); }
  double data_y(double py) const { return y0 + (y + h - py) / h * (y1 - y0); }
  double tol_y() const { return 0.0051 / h * (y1 - y0); }
  double tol_x() const { return 0.0051 / w * (x1 - x0); }
};

Area area_of(const pugi::xml_node& rect) {
  return {rect.attribute("x").as_double(),       rect.attribute("y").as_double(),
          rect.attribute("width").as_double(),   rect.attribute("height").as_double(),
          rect.attribute("data-x0").as_double(), rect.attribute("data-x1").as_double(),
          rect.attribute("data-y0").as_double(), rect.attribute("data-y1").as_double()};
}

std::string classes(const pugi::xml_node& n) { return n.attribute("class").as_string(); }

}  // namespace

TEST_CASE("spc.html has one I-MR chart per characteristic, worst first, whose points map back to the values") {
  const SpcResult r = compute_spc(spc_batch());
  const std::string page = spc_html(r, {"results.sqlite", {{"last", "30"}}});
  CHECK(page == spc_html(r, {"results.sqlite", {{"last", "30"}}}));  // deterministic
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_string(page.c_str());
  REQUIRE_MESSAGE(parsed, parsed.description());
  const pugi::xpath_node_set sections = doc.select_nodes("//section[@class='characteristic']");
  REQUIRE(sections.size() == r.characteristics.size());
  const std::vector<std::size_t> order = worst_first(r);
  for (std::size_t s = 0; s < sections.size(); ++s) {
    const CharacteristicSpc& c = r.characteristics[order[s]];
    CAPTURE(c.id);
    const pugi::xml_node section = sections[s].node();
    CHECK(std::string(section.attribute("data-id").as_string()) == c.id);
    REQUIRE(section.select_nodes("svg").size() == 1);
    const pugi::xml_node svg = section.child("svg");
    std::vector<pugi::xml_node> areas;
    for (const pugi::xpath_node& a : svg.select_nodes("rect[@class='plot-area']")) areas.push_back(a.node());
    REQUIRE(areas.size() == 2);
    const Area values = area_of(areas[0]), ranges = area_of(areas[1]);
    // Individuals: every value at its part, red exactly where a violation is.
    std::vector<bool> alarm(c.n, false);
    for (const SpcViolation& v : c.violations)
      for (std::size_t i = v.index; i <= v.last; ++i) alarm[i] = true;
    std::size_t k = 0;
    for (const pugi::xpath_node& p : svg.select_nodes("circle")) {
      const pugi::xml_node dot = p.node();
      if (classes(dot).rfind("value", 0) != 0) continue;
      REQUIRE(k < c.n);
      CHECK(std::abs(values.data_y(dot.attribute("cy").as_double()) - c.values[k] * 1000) <= values.tol_y());
      CHECK(std::abs(values.data_x(dot.attribute("cx").as_double()) - static_cast<double>(c.part_index[k])) <=
            values.tol_x());
      CHECK((classes(dot) == "value alarm") == alarm[k]);
      ++k;
    }
    CHECK(k == c.n);
    // Moving ranges: |x[i] - x[i-1]| at the later part.
    std::size_t m = 0;
    for (const pugi::xpath_node& p : svg.select_nodes("circle[@class='mr']")) {
      REQUIRE(m + 1 < c.n);
      const double expected = std::abs(c.values[m + 1] - c.values[m]) * 1000;
      CHECK(std::abs(ranges.data_y(p.node().attribute("cy").as_double()) - expected) <= ranges.tol_y() + 1e-12);
      ++m;
    }
    CHECK(m == (c.n > 0 ? c.n - 1 : 0));
    // Centre line and limits of the individuals chart.
    std::vector<double> centre, limits;
    for (const pugi::xpath_node& l : svg.select_nodes("line[@class='centre' or @class='limit']")) {
      const double y = values.data_y(l.node().attribute("y1").as_double());
      if (l.node().attribute("y1").as_double() > values.y + values.h) continue;  // the MR panel's
      (classes(l.node()) == "centre" ? centre : limits).push_back(y);
    }
    if (c.mean) {
      REQUIRE(centre.size() == 1);
      CHECK(std::abs(centre[0] - *c.mean * 1000) <= values.tol_y());
    }
    if (c.cpk) {
      REQUIRE(limits.size() == 2);
      CHECK(std::abs(limits[0] - *c.ucl * 1000) <= values.tol_y());
      CHECK(std::abs(limits[1] - *c.lcl * 1000) <= values.tol_y());
    }
  }
  // The capability table in the same order, and every part's verdict.
  const pugi::xpath_node_set rows = doc.select_nodes("//table[@class='capability']/tr[@data-id]");
  REQUIRE(rows.size() == r.characteristics.size());
  for (std::size_t s = 0; s < rows.size(); ++s)
    CHECK(std::string(rows[s].node().attribute("data-id").as_string()) == r.characteristics[order[s]].id);
  const pugi::xpath_node_set parts = doc.select_nodes("//table[@class='parts']/tr[td]");
  REQUIRE(parts.size() == r.parts.size());
  CHECK(std::string(parts[29].node().select_node("td[4]").node().child_value()) == "FAIL");
}

TEST_CASE("spc.html escapes ids and serials") {
  SpcInput in = spc_batch();
  in.parts[0].serial = "<b>&\"x\"";
  in.characteristics[0].id = "A<&>";
  const std::string page = spc_html(compute_spc(in), {"db<1>", {}});
  pugi::xml_document doc;
  REQUIRE(doc.load_string(page.c_str()));
  CHECK(page.find("<b>&") == std::string::npos);
  CHECK(doc.select_nodes("//section[@data-id='A<&>']").size() == 1);
}

TEST_CASE("spc.html lists each rule's violations once with their count") {
  const SpcResult r = compute_spc(spc_batch());
  pugi::xml_document doc;
  REQUIRE(doc.load_string(spc_html(r, {"results.sqlite", {}}).c_str()));
  for (const CharacteristicSpc& c : r.characteristics) {
    std::vector<std::size_t> per_rule(9, 0);
    for (const SpcViolation& v : c.violations) ++per_rule[v.rule];
    const std::string where = "//section[@data-id='" + c.id + "']/ul/li";
    std::size_t listed = 0;
    for (const pugi::xpath_node& li : doc.select_nodes(where.c_str())) {
      const int rule = li.node().attribute("data-rule").as_int();
      REQUIRE(rule >= 1);
      REQUIRE(rule <= 8);
      CHECK(li.node().attribute("data-count").as_ullong() == per_rule[rule]);
      ++listed;
    }
    std::size_t rules = 0;
    for (std::size_t n : per_rule) rules += n > 0;
    CHECK(listed == rules);
  }
}

TEST_CASE("spc.html charts the last parts of a long batch, with the limits of all of them") {
  // 150 parts; the characteristic skips every tenth part, so the window's
  // first value and the moving range reaching into it are tested too.
  SpcInput in;
  for (std::size_t i = 0; i < 150; ++i) in.parts.push_back({"S" + std::to_string(i), "2026-11-28T00:00:00Z", "PASS"});
  CharacteristicSeries series{"P1", "point", -0.05, 0.05, {}, {}};
  const std::vector<double> noise = spc_oracle::normal_sample(7, 150, 0.001, 0.003);
  for (std::size_t i = 0; i < 150; ++i)
    if (i % 10 != 3) {
      series.part_index.push_back(i);
      series.values.push_back(noise[i]);
    }
  in.characteristics = {series};
  const SpcResult r = compute_spc(in);
  const CharacteristicSpc& c = r.characteristics[0];
  pugi::xml_document doc;
  const std::string page = spc_html(r, {"results.sqlite", {}});
  REQUIRE(doc.load_string(page.c_str()));
  const pugi::xml_node svg = doc.select_node("//section[@class='characteristic']/svg").node();
  const Area values = area_of(svg.select_node("rect[@class='plot-area']").node());
  // The window: parts 50 .. 149 (kSpcChartParts = 100), as the x range.
  CHECK(values.x0 == -0.5 + 50);
  CHECK(values.x1 == 149.5);
  // Oracle: the positions of the series whose part is in the window.
  std::vector<std::size_t> shown;
  for (std::size_t k = 0; k < c.n; ++k)
    if (c.part_index[k] >= 50) shown.push_back(k);
  const pugi::xpath_node_set dots = svg.select_nodes("circle[starts-with(@class, 'value')]");
  REQUIRE(dots.size() == shown.size());
  for (std::size_t j = 0; j < shown.size(); ++j) {
    const pugi::xml_node dot = dots[j].node();
    CHECK(std::abs(values.data_x(dot.attribute("cx").as_double()) - static_cast<double>(c.part_index[shown[j]])) <=
          values.tol_x());
    CHECK(std::abs(values.data_y(dot.attribute("cy").as_double()) - c.values[shown[j]] * 1000) <= values.tol_y());
  }
  // One moving range per value shown: the first one's partner is before the window.
  CHECK(svg.select_nodes("circle[@class='mr']").size() == shown.size());
  // The centre line is the mean over all 135 values, not over the window.
  double y_centre = 0;
  for (const pugi::xpath_node& l : svg.select_nodes("line[@class='centre']")) {
    y_centre = values.data_y(l.node().attribute("y1").as_double());
    break;
  }
  double sum = 0;
  for (double v : series.values) sum += v;
  CHECK(std::abs(y_centre - sum / static_cast<double>(series.values.size()) * 1000) <= values.tol_y());
  CHECK(page.find("the chart shows the last 100 of 150 parts") != std::string::npos);
}

// The point table's inline script in a real browser (headless Chromium):
// the status filter and sorting by a column header do what they say. The
// expected order comes from comparison.json and the zone's limits, not
// from the page.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../support/run_cli.hpp"
#include "report/point_table_html.hpp"
#include "report_fixture.hpp"

using namespace furrow;
using nlohmann::json;

namespace {

// Drives the controls the table's script created: status OUT, then two
// clicks on "Out of tol." (ascending, then descending); records the visible
// ids in order, then filters by text.
const char* kDriver =
    "<script>(function(){var t=document.getElementById('point-table');"
    "var s=document.getElementById('point-status');s.value='OUT';s.dispatchEvent(new Event('change'));"
    "var h=t.tHead.rows[0].cells[15];h.click();h.click();"
    "var ids=[],rows=t.tBodies[0].rows;for(var i=0;i<rows.length;i++)"
    "if(rows[i].style.display!=='none')ids.push(rows[i].cells[1].textContent);"
    "document.body.setAttribute('data-visible',ids.join(' '));"
    "s.value='';s.dispatchEvent(new Event('change'));"
    "var q=document.getElementById('point-filter');q.value='P00101';q.dispatchEvent(new Event('input'));"
    "document.body.setAttribute('data-filtered',document.getElementById('point-count').textContent);"
    "})();</script>";

std::string attribute(const std::string& dom, const std::string& name) {
  const std::size_t at = dom.find(name + "=\"");
  if (at == std::string::npos) return "(missing)";
  const std::size_t start = at + name.size() + 2;
  return dom.substr(start, dom.find('"', start) - start);
}

}  // namespace

TEST_CASE("the point table's filter and sort work in a browser") {
  const char* chromium = "/usr/bin/chromium";
  // Without the browser the check fails: a check that passes unrun would
  // hide a broken table script (scripts/install-deps.sh installs Chromium).
  if (!std::filesystem::exists(chromium))
    FAIL("the browser check needs /usr/bin/chromium, which is missing: run scripts/install-deps.sh");
  const test::ReportFixture f = test::make_report_fixture();
  const std::string dir = test::scratch_dir("point-table-script");
  test::write_text(dir + "/table.html", "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"></head><body>\n" +
                                            point_table_html(f.doc) + kDriver + "\n</body></html>\n");
  const std::string command = std::string("timeout 120 ") + chromium +
                              " --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking"
                              " --disable-component-update --disable-sync --user-data-dir=" +
                              test::shell_quote(dir + "/profile") + " --dump-dom " +
                              test::shell_quote("file://" + dir + "/table.html") + " > " +
                              test::shell_quote(dir + "/dom.html") + " 2> " + test::shell_quote(dir + "/log.txt");
  REQUIRE(std::system(command.c_str()) == 0);
  const std::string dom = test::slurp(dir + "/dom.html");

  // The oracle: out-of-tolerance points by their amount beyond the zone, largest first.
  const json c = json::parse(f.comparison_json);
  const double lower = c["tolerance"]["lower"], upper = c["tolerance"]["upper"];
  std::vector<std::pair<double, std::string>> out;
  for (const json& p : c["points"]) {
    const double d = p["deviation"];
    if (p["evaluated"].get<bool>() && (d < lower || d > upper))
      out.push_back({d > upper ? d - upper : lower - d, p["id"]});
  }
  REQUIRE(out.size() >= 2);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string expected;
  for (const auto& [amount, id] : out) expected += (expected.empty() ? "" : " ") + id;
  CHECK(attribute(dom, "data-visible") == expected);
  CHECK(attribute(dom, "data-filtered") == "1 of 192 rows shown");
}

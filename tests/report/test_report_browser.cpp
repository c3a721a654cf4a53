// The report in a browser: the 3D view's data (spheres coloured on the
// deviation scale, the predicted field on the surface) against independent
// oracles, the page in headless Chromium (software WebGL: loads, draws a
// non-empty canvas, no console error; without WebGL the static views), and
// report.pdf (pages, header and page number on each, no table row cut)
// checked with poppler-utils. Chromium and poppler-utils are in
// scripts/install-deps.sh: a test that needs one fails when it is missing.
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "base/error.hpp"
#include "geometry/closest_point.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/part_file.hpp"
#include "cli/report_checks.hpp"
#include "deviation_ramp.hpp"
#include "report/part_view_3d.hpp"
#include "report/pdf_print.hpp"
#include "report/qa_report.hpp"
#include "report_fixture.hpp"
#include "support/synthetic_prediction.hpp"

using namespace furrow;
using furrow::test::run_shell;
using furrow::test::shell_quote;
using furrow::test::slurp;

namespace {

const test::ReportFixture& fixture() {
  static const test::ReportFixture f = test::make_report_fixture();
  return f;
}

ReportContext context() {
  ReportContext c;
  c.title = "browser check";
  c.generated = "2024-01-01T00:00:00Z";
  c.inputs.push_back(digest_generated("comparison", "comparison.json", "{}"));
  return c;
}

std::string page(const std::vector<FolderFile>& files) {
  for (const FolderFile& f : files)
    if (f.path == "report.html") return f.bytes;
  FAIL("no report.html");
  return "";
}

nlohmann::json view_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"view3d-data\">";
  const std::size_t start = html.find(open);
  REQUIRE(start != std::string::npos);
  const std::size_t end = html.find("</script>", start);
  return nlohmann::json::parse(html.substr(start + open.size(), end - start - open.size()));
}

void require_tool(const std::string& path, const std::string& package) {
  INFO(path << " is missing: install the Debian package " << package << " (scripts/install-deps.sh)");
  REQUIRE(std::filesystem::exists(path));
}

// Headless Chromium with software WebGL (SwiftShader): the DOM after the
// page's scripts ran, and the browser's log with console messages.
struct Loaded {
  int status = -1;
  std::string dom, log;
};
Loaded load_in_chromium(const std::string& html_file, const std::string& scratch, const std::string& extra) {
  const std::string profile = scratch + "/profile";
  std::filesystem::remove_all(profile);
  const std::string command = std::string("timeout 180 ") + test::kChromium +
                              " --headless=new --no-sandbox --disable-gpu --enable-unsafe-swiftshader"
                              " --use-angle=swiftshader --no-first-run --disable-background-networking"
                              " --disable-component-update --disable-sync --enable-logging=stderr --v=0"
                              " --virtual-time-budget=15000 --window-size=1200,900 " +
                              extra + " --user-data-dir=" + shell_quote(profile) + " --dump-dom " +
                              shell_quote("file://" + std::filesystem::absolute(html_file).string());
  Loaded r;
  r.status = std::system((command + " > " + shell_quote(scratch + "/dom.html") + " 2> " +
                          shell_quote(scratch + "/chromium.log"))
                             .c_str());
  r.dom = slurp(scratch + "/dom.html");
  r.log = slurp(scratch + "/chromium.log");
  return r;
}

// Console messages of the page. Chromium logs every console message
// (console.log/warn/error, uncaught exceptions) as an INFO "CONSOLE" line
// without its level, and the page logs nothing when all is well: any such
// line counts, except the software renderer's own performance notes
// ("GL Driver Message (OpenGL, Performance, ...)" on reading pixels back).
std::vector<std::string> console_messages(const std::string& log) {
  std::vector<std::string> messages;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);)
    if (line.find(":CONSOLE") != std::string::npos && line.find("GL Driver Message (OpenGL, Performance") == std::string::npos)
      messages.push_back(line);
  return messages;
}

std::string attribute_of_view(const std::string& dom, const std::string& name) {
  const std::regex re("<section id=\"view3d\"[^>]*\\b" + name + "=\"([^\"]*)\"");
  std::smatch m;
  return std::regex_search(dom, m, re) ? m[1].str() : std::string("(absent)");
}

}  // namespace

TEST_CASE("the 3D view has a sphere per point, coloured on the deviation scale") {
  const test::ReportFixture& f = fixture();
  const std::string html = page(make_report(f.doc, f.part, nullptr, context()));
  const nlohmann::json data = view_data(html);
  const auto& xyz = data["points"]["xyz"];
  const std::string colours = data["points"]["c"];
  REQUIRE(xyz.size() == 3 * f.doc.points.size());
  REQUIRE(colours.size() == 6 * f.doc.points.size());
  // The scale's range: the larger of the zone's limits and the largest |deviation|.
  double range = std::max(std::fabs(f.doc.options.tolerance.lower()), std::fabs(f.doc.options.tolerance.upper()));
  for (const auto& p : f.doc.points)
    if (p.evaluated) range = std::max(range, std::fabs(p.deviation));
  CHECK(data["range"].get<double>() == doctest::Approx(range).epsilon(1e-6));
  for (std::size_t i = 0; i < f.doc.points.size(); ++i) {
    const auto& p = f.doc.points[i];
    for (int k = 0; k < 3; ++k) CHECK(std::fabs(xyz[3 * i + k].get<double>() - p.foot[k]) <= 0.0005 + 1e-12);
    const std::array<int, 3> want = test::deviation_ramp(p.evaluated ? p.deviation / range : std::nan(""));
    const std::array<int, 3> got = test::packed_colour(colours, i);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(got[k] - want[k]) <= 1);  // rounding of the interpolation
  }
  // The mould is one untrimmed face: a full 49 x 49 vertex grid, two triangles per cell.
  REQUIRE(data["faces"].size() == 1);
  CHECK(data["faces"][0]["v"].size() == 3 * 49 * 49);
  CHECK(data["faces"][0]["t"].size() == 3 * 2 * 48 * 48);
  CHECK(data["prediction"] == false);
  CHECK(html.find("class=\"view3d-zmap\"") == std::string::npos);  // no switch without a prediction
}

TEST_CASE("with a prediction the surface carries the predicted error on the same scale") {
  const test::ReportFixture& f = fixture();
  // A linear field: the cell means' bilinear interpolation reproduces it
  // exactly between cell centres, so the analytic value is the oracle.
  const auto field = [](const Eigen::Vector2d& uv) { return 0.03 * (uv.x() - 0.5) - 0.01 * (uv.y() - 0.5); };
  const Prediction prediction = test::field_prediction(f.part, field);
  const std::string html = page(make_report(f.doc, f.part, nullptr, context(), &prediction));
  CHECK(html.find("class=\"view3d-zmap\"") != std::string::npos);
  const nlohmann::json data = view_data(html);
  CHECK(data["prediction"] == true);
  const double range = data["range"];
  const std::string p = data["faces"][0]["p"];
  REQUIRE(p.size() == 6 * 49 * 49);
  const ParameterDomain& d = f.part.faces[0].domain();
  int checked = 0;
  for (int j = 0; j <= 48; ++j)
    for (int i = 0; i <= 48; ++i) {
      const Eigen::Vector2d uv(d.u0 + d.width_u() * i / 48, d.v0 + d.width_v() * j / 48);
      // Away from the outermost half cells (100 x 80 cells), where the interpolation holds the edge value.
      if (i < 2 || i > 46 || j < 2 || j > 46) continue;
      const std::array<int, 3> want = test::deviation_ramp(field(uv) / range);
      const std::array<int, 3> got = test::packed_colour(p, static_cast<std::size_t>(j * 49 + i));
      for (int k = 0; k < 3; ++k) CHECK(std::abs(got[k] - want[k]) <= 1);
      ++checked;
    }
  CHECK(checked == 45 * 45);
}

TEST_CASE("the report loads in headless Chromium: the 3D view draws, no console error") {
  require_tool(test::kChromium, "chromium");
  const test::ReportFixture& f = fixture();
  const std::string dir = test::scratch_dir("report-browser-3d");
  test::write_text(dir + "/report.html", page(make_report(f.doc, f.part, nullptr, context())));
  const Loaded r = load_in_chromium(dir + "/report.html", dir, "");
  INFO("chromium log: " << r.log.substr(0, 3000));
  CHECK(r.status == 0);
  const std::string drawn = attribute_of_view(r.dom, "data-view3d");
  REQUIRE(drawn.rfind("drawn:", 0) == 0);
  // A non-empty canvas: a large share of its 900 x 560 pixels differ from the background.
  CHECK(std::stol(drawn.substr(6)) > 20000);
  CHECK(attribute_of_view(r.dom, "data-view3d-spheres") == std::to_string(f.doc.points.size()));
  const std::string frame_ms = attribute_of_view(r.dom, "data-view3d-frame-ms");
  CHECK(std::regex_match(frame_ms, std::regex("\\d+")));  // a second frame was timed
  CHECK(console_messages(r.log).empty());
  // The figures' images all decoded too (the page's own marker).
  CHECK(r.dom.find("data-images-loaded=\"") != std::string::npos);
}

TEST_CASE("beyond 20 000 points the 3D view draws point sprites, still one sphere per point") {
  require_tool(test::kChromium, "chromium");
  const test::ReportFixture& f = fixture();
  // The fixture's points repeated, shifted a little, to 21 120 points.
  ComparisonDocument doc = f.doc;
  doc.points.clear();
  for (int copy = 0; copy < 110; ++copy)
    for (auto p : f.doc.points) {
      p.id += "-" + std::to_string(copy);
      p.foot.x() += 0.05 * (copy % 11);
      p.foot.y() += 0.05 * (copy / 11);
      doc.points.push_back(p);
    }
  REQUIRE(doc.points.size() > 20000);
  const std::string dir = test::scratch_dir("report-browser-sprites");
  test::write_text(dir + "/report.html", page(make_report(doc, f.part, nullptr, context())));
  const Loaded r = load_in_chromium(dir + "/report.html", dir, "");
  INFO("chromium log: " << r.log.substr(0, 3000));
  const std::string drawn = attribute_of_view(r.dom, "data-view3d");
  REQUIRE(drawn.rfind("drawn:", 0) == 0);
  CHECK(std::stol(drawn.substr(6)) > 20000);
  CHECK(attribute_of_view(r.dom, "data-view3d-spheres") == std::to_string(doc.points.size()));
  CHECK(console_messages(r.log).empty());
}

TEST_CASE("the console check sees a page's uncaught exception and console.error") {
  require_tool(test::kChromium, "chromium");
  const std::string dir = test::scratch_dir("report-browser-console");
  test::write_text(dir + "/bad.html",
                   "<html><body><section id=\"view3d\"></section><script>console.error('planted');null.x;</script>"
                   "</body></html>");
  const Loaded r = load_in_chromium(dir + "/bad.html", dir, "");
  const std::vector<std::string> messages = console_messages(r.log);
  REQUIRE(messages.size() == 2);
  CHECK(messages[0].find("planted") != std::string::npos);
  CHECK(messages[1].find("Uncaught TypeError") != std::string::npos);
}

TEST_CASE("without WebGL the 3D view falls back to the static views") {
  require_tool(test::kChromium, "chromium");
  const test::ReportFixture& f = fixture();
  const std::string dir = test::scratch_dir("report-browser-nowebgl");
  test::write_text(dir + "/report.html", page(make_report(f.doc, f.part, nullptr, context())));
  const Loaded r = load_in_chromium(dir + "/report.html", dir, "--disable-3d-apis --disable-webgl");
  INFO("chromium log: " << r.log.substr(0, 3000));
  CHECK(attribute_of_view(r.dom, "data-view3d") == "fallback:no-webgl");
  CHECK(console_messages(r.log).empty());
  // The static four views are in the section.
  CHECK(r.dom.find("id=\"fig-part_views\"") != std::string::npos);
}

TEST_CASE("report.pdf: pages with the header and page number, no table row cut, A4 and Letter") {
  require_tool(test::kChromium, "chromium");
  require_tool("/usr/bin/pdfinfo", "poppler-utils");
  require_tool("/usr/bin/pdftoppm", "poppler-utils");
  const test::ReportFixture& f = fixture();
  const std::string dir = test::scratch_dir("report-pdf");
  // With an inspection record the header names the part number and serial.
  ReportContext with_record = context();
  with_record.record = parse_inspection_record(R"({"part_number": "MOULD-100-A", "revision": "C", "serial": "SN 0042"})",
                                               "record.json");
  test::write_text(dir + "/report.html", page(make_report(f.doc, f.part, nullptr, with_record)));
  for (const std::string paper : {"a4", "letter"}) {
    CAPTURE(paper);
    const std::string pdf = dir + "/report-" + paper + ".pdf";
    print_pdf(dir + "/report.html", pdf, PdfOptions{paper});
    const test::ShellResult info = run_shell("pdfinfo " + shell_quote(pdf), dir + "/info.txt");
    REQUIRE(info.status == 0);
    std::smatch m;
    REQUIRE(std::regex_search(info.out, m, std::regex("Pages:\\s+(\\d+)")));
    const int pages = std::stoi(m[1].str());
    CHECK(pages >= 3);  // verdict and alignment, figures, 192-row point table, traceability
    CHECK(info.out.find(paper == "a4" ? "(A4)" : "(letter)") != std::string::npos);
    // Rendered to PNG: one image per page, none blank.
    std::filesystem::remove_all(dir + "/pages");
    std::filesystem::create_directories(dir + "/pages");
    REQUIRE(run_shell("pdftoppm -r 30 -png " + shell_quote(pdf) + " " + shell_quote(dir + "/pages/p"),
                      dir + "/ppm.txt")
                .status == 0);
    int images = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir + "/pages")) {
      const cv::Mat img = cv::imread(e.path().string(), cv::IMREAD_GRAYSCALE);
      REQUIRE_FALSE(img.empty());
      double lo = 0, hi = 0;
      cv::minMaxLoc(img, &lo, &hi);
      CHECK(lo < 128);  // something printed on every page
      ++images;
    }
    CHECK(images == pages);
    // Text per page: the header and "Page k of N" on each; every point's
    // row whole on one line of one page, each exactly once.
    REQUIRE(run_shell("pdftotext -layout " + shell_quote(pdf) + " " + shell_quote(dir + "/text.txt"),
                      dir + "/totext.txt")
                .status == 0);
    const std::string text = slurp(dir + "/text.txt");
    std::vector<std::string> page_texts;
    for (std::size_t start = 0;;) {
      const std::size_t ff = text.find('\f', start);
      if (ff == std::string::npos) break;
      page_texts.push_back(text.substr(start, ff - start));
      start = ff + 1;
    }
    REQUIRE(static_cast<int>(page_texts.size()) == pages);
    std::map<std::string, int> rows;
    for (int k = 0; k < pages; ++k) {
      const std::string& t = page_texts[static_cast<std::size_t>(k)];
      CAPTURE(k);
      CHECK(t.find("Part MOULD-100-A rev C") != std::string::npos);
      CHECK(t.find("QA report: browser check, serial SN 0042") != std::string::npos);
      CHECK(t.find("Page " + std::to_string(k + 1) + " of " + std::to_string(pages)) != std::string::npos);
      std::istringstream in(t);
      for (std::string line; std::getline(in, line);) {
        std::smatch row;
        // "#  Id  Face  nominal XYZ  IJK  actual XYZ  deviation ..." of the point table.
        if (!std::regex_search(line, row, std::regex("^\\s*(\\d+)\\s+(P\\d{5})\\s+mould\\s+(.*)$"))) continue;
        const std::size_t index = std::stoul(row[1].str()) - 1;
        REQUIRE(index < f.doc.points.size());
        const auto& p = f.doc.points[index];
        CHECK(row[2].str() == p.id);
        // The rest of the row on the same line: nominal x y z, i j k, actual
        // x y z, deviation, the limits, the amount out and the status.
        std::istringstream cells(row[3].str());
        std::vector<std::string> c;
        for (std::string cell; cells >> cell;) c.push_back(cell);
        REQUIRE(c.size() >= 14);
        CHECK(std::fabs(std::stod(c[0]) - p.foot.x()) <= 5e-5 + 1e-9);  // nominal x [mm], 4 decimals
        CHECK(std::fabs(std::stod(c[9]) - p.deviation) <= 5e-5 + 1e-9);  // deviation [mm], 4 decimals
        ++rows[p.id];
      }
    }
    CHECK(rows.size() == f.doc.points.size());
    for (const auto& [id, n] : rows) CHECK_MESSAGE(n == 1, id);
  }
}

TEST_CASE("report.pdf without Chromium is a clear error") {
  const std::string dir = test::scratch_dir("report-pdf-missing");
  test::write_text(dir + "/report.html", "<html><head></head><body>x</body></html>");
  PdfOptions o;
  o.chromium = dir + "/no-such-chromium";
  CHECK_THROWS_WITH_AS(print_pdf(dir + "/report.html", dir + "/report.pdf", o),
                       doctest::Contains("install the Debian package chromium"), InputError);
  CHECK_FALSE(std::filesystem::exists(dir + "/report.pdf"));
  o = {};
  o.paper = "a3";
  CHECK_THROWS_WITH_AS(print_pdf(dir + "/report.html", dir + "/report.pdf", o), doctest::Contains("a4 or letter"),
                       InputError);
}

TEST_CASE("furrow report --pdf writes report.pdf next to the page, a bad paper writes nothing") {
  require_tool(test::kChromium, "chromium");
  require_tool("/usr/bin/pdfinfo", "poppler-utils");
  // The fixture's comparison as `furrow compare` writes it, its part where it names it.
  const std::string dir = test::scratch_dir("report-pdf-cli");
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const InspectionPlan plan = grid_plan(part, 8, 6, {"ruby", 2.0});
  SimulationOptions sim;
  sim.noise_sigma = 0.001;
  sim.seed = 3;
  const SimulatedMeasurement measured = simulate_measurement(plan, sim, "grid");
  CompareOptions options;
  options.tolerance = ToleranceZone::make(0.05, 0.025, "test");
  const ClosestPointFinder finder(part);
  const Comparison c = compare_measurements(finder, measured.set, &plan, options);
  ComparisonSources sources;
  sources.part = test::source_path("examples/parts/mould.json");
  test::write_text(dir + "/grid.csv", "the report only digests the measurement file\n");
  sources.measurements = dir + "/grid.csv";
  test::write_text(dir + "/comparison.json", comparison_to_json_text(c, measured.set, part, options, sources));

  const test::CliResult ok =
      test::run_furrow({"report", dir + "/comparison.json", "--out", dir + "/out", "--pdf", "--paper", "letter"});
  INFO(ok.err);
  CHECK((ok.status == 0 || ok.status == 1));  // the verdict's status
  CHECK(ok.out.find("report.pdf") != std::string::npos);
  const test::ShellResult info = run_shell("pdfinfo " + shell_quote(dir + "/out/report.pdf"), dir + "/info.txt");
  CHECK(info.status == 0);
  CHECK(info.out.find("(letter)") != std::string::npos);
  CHECK(std::filesystem::exists(dir + "/out/report.html"));

  const test::CliResult bad =
      test::run_furrow({"report", dir + "/comparison.json", "--out", dir + "/out2", "--pdf", "--paper", "a3"});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--paper: expected a4 or letter") != std::string::npos);
  CHECK(test::line_count(bad.err) == 1);
  CHECK_FALSE(std::filesystem::exists(dir + "/out2"));
}

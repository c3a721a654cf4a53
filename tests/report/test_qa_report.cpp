#include <doctest/doctest.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <omp.h>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "base/error.hpp"
#include "report/points_csv.hpp"
#include "report/report_figures.hpp"
#include "report/report_html.hpp"
#include "report/report_json.hpp"
#include "report/report_qif.hpp"
#include "report/qa_report.hpp"
#include "report/verdict.hpp"
#include "report_fixture.hpp"

using namespace furrow;
using furrow::test::make_report_fixture;

namespace {

const test::ReportFixture& fixture() {
  static const test::ReportFixture f = make_report_fixture();
  return f;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, sep)) cells.push_back(cell);
  if (!line.empty() && line.back() == sep) cells.emplace_back();
  return cells;
}

double parse_double(const std::string& s) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  REQUIRE(ec == std::errc());
  REQUIRE(ptr == s.data() + s.size());
  return v;
}

const FolderFile& file_named(const std::vector<FolderFile>& files, const std::string& path) {
  for (const FolderFile& f : files)
    if (f.path == path) return f;
  FAIL("no file " << path);
  throw std::logic_error("unreachable");
}

// RFC 4648 decoding written here, independent of the report's encoder.
std::string base64_decode(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  int bits = 0, buffer = 0;
  for (char c : text) {
    if (c == '=') break;
    const int v = value(c);
    REQUIRE(v >= 0);
    buffer = (buffer << 6) | v;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xff);
    }
  }
  return out;
}

ReportContext context(const std::string& generated) {
  ReportContext c;
  c.title = "unit";
  c.generated = generated;
  c.inputs.push_back(digest_generated("comparison", "comparison.json", "{}"));
  return c;
}

}  // namespace

TEST_CASE("points.csv has one row per measured point with the document's numbers") {
  const ComparisonDocument& doc = fixture().doc;
  const std::string csv = points_csv_text(doc);
  std::istringstream in(csv);
  std::string header;
  std::getline(in, header);
  const std::vector<std::string> columns = split(header, ',');
  REQUIRE(columns.size() == 31);  // 24, then the point table's 7 (test_point_table.cpp)
  CHECK(columns[0] == "id");
  CHECK(columns[13] == "deviation");
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line); ++rows) {
    REQUIRE(rows < doc.points.size());
    const auto& p = doc.points[rows];
    const std::vector<std::string> cells = split(line, ',');
    REQUIRE(cells.size() == columns.size());
    CHECK(cells[0] == p.id);
    CHECK(parse_double(cells[2]) == p.uv.x());      // exact: shortest round-trip text
    CHECK(parse_double(cells[13]) == p.deviation);
    CHECK(parse_double(cells[10]) == p.measured.x());
    CHECK(cells[15] == (p.evaluated ? "true" : "false"));
    CHECK(cells[20].empty());  // no prediction in this comparison
  }
  CHECK(rows == doc.points.size());
  CHECK(rows == 192);  // 16 x 12 grid
}

TEST_CASE("points.csv quotes text cells and leaves missing values empty") {
  ComparisonDocument doc = fixture().doc;
  doc.points.resize(1);
  doc.points[0].face = "side, \"left\"";
  doc.points[0].uncertainty.reset();
  doc.points[0].region.reset();
  const std::string row = points_csv_text(doc).substr(points_csv_text(doc).find('\n') + 1);
  CHECK(row.find(",\"side, \"\"left\"\"\",") != std::string::npos);
  CHECK(row.find(",,true,") != std::string::npos);  // uncertainty empty, then evaluated
}

TEST_CASE("the verdict follows the comparison and says why a part fails") {
  ComparisonDocument doc = fixture().doc;
  // The 60 um dent is outside the +-25 um zone at several neighbouring points.
  ReportVerdict v = report_verdict(doc);
  CHECK_FALSE(v.pass);
  CHECK(v.out_of_tolerance == doc.summary.out_of_tolerance);
  CHECK(v.out_of_tolerance >= 1);
  REQUIRE(v.reasons.size() == 1);
  CHECK(v.reasons[0].find("outside the profile zone [-25.0 um, 25.0 um]") != std::string::npos);
  CHECK_FALSE(v.has_prediction);

  GougeConfirmation g;
  GougeSiteCheck confirmed;
  confirmed.id = "G1";
  confirmed.status = GougeSiteStatus::confirmed;
  confirmed.measured_depth = 0.1195;
  confirmed.predicted_depth = 0.1184;
  GougeSiteCheck unmeasured;
  unmeasured.id = "G2";
  unmeasured.status = GougeSiteStatus::not_measured;
  g.sites = {confirmed, unmeasured};
  doc.gouges = g;
  doc.registration.converged = false;
  doc.registration.status = "no convergence in 50 iterations";
  v = report_verdict(doc);
  CHECK(v.has_prediction);
  CHECK(v.sites == 2);
  CHECK(v.confirmed == 1);
  CHECK(v.not_measured == 1);
  REQUIRE(v.reasons.size() == 3);
  CHECK(v.reasons[0] == "the registration did not converge (no convergence in 50 iterations)");
  CHECK(v.reasons[2] == "predicted gouge G1 confirmed: measured depth 119.5 um, predicted 118.4 um");

  doc.summary.pass = true;
  doc.summary.verdict = Verdict::pass;
  doc.summary.out_of_tolerance = 0;
  doc.gouges.reset();
  doc.registration.converged = true;
  v = report_verdict(doc);
  CHECK(v.pass);
  CHECK(std::string(v.result()) == "PASS");
  CHECK(v.reasons.empty());
}

TEST_CASE("report.json holds the document's numbers, and only the timestamp and timing differ between runs") {
  const test::ReportFixture& f = fixture();
  ReportContext a = context("2024-01-01T00:00:00Z");
  ReportContext b = context("2025-06-30T12:00:00Z");
  b.stages = {{"compare", 0.25}};
  b.total_seconds = 0.25;
  const std::vector<FolderFile> ra = make_report(f.doc, f.part, nullptr, a);
  const std::vector<FolderFile> rb = make_report(f.doc, f.part, nullptr, b);
  nlohmann::json ja = nlohmann::json::parse(file_named(ra, "report.json").bytes);
  nlohmann::json jb = nlohmann::json::parse(file_named(rb, "report.json").bytes);
  CHECK(ja["generated"] == "2024-01-01T00:00:00Z");
  CHECK(ja["timing"].is_null());
  CHECK(jb["timing"]["stages"][0]["stage"] == "compare");
  for (nlohmann::json* j : {&ja, &jb}) {
    j->erase("generated");
    j->erase("timing");
  }
  CHECK(ja == jb);
  // Every other file is byte for byte the same (figures, CSV).
  REQUIRE(ra.size() == rb.size());
  for (std::size_t k = 0; k < ra.size(); ++k)
    if (ra[k].path != "report.json" && ra[k].path != "report.html" && ra[k].path != "results.qif")
      CHECK(ra[k].bytes == rb[k].bytes);
  // results.qif differs in its time only (docs/qif.md).
  std::string qb = file_named(rb, "results.qif").bytes;
  for (std::size_t at = qb.find("2025-06-30T12:00:00Z"); at != std::string::npos; at = qb.find("2025-06-30T12:00:00Z"))
    qb.replace(at, 20, "2024-01-01T00:00:00Z");
  CHECK(file_named(ra, "results.qif").bytes.find("<TimeCreated>2024-01-01T00:00:00Z</TimeCreated>") != std::string::npos);
  CHECK(qb == file_named(ra, "results.qif").bytes);

  CHECK(ja["verdict"]["result"] == "FAIL");
  CHECK(ja["deviations"]["profile"].get<double>() == f.doc.summary.profile);
  CHECK(ja["deviations"]["out_of_tolerance"] == f.doc.summary.out_of_tolerance);
  REQUIRE(ja["points"].size() == f.doc.points.size());
  for (std::size_t i = 0; i < f.doc.points.size(); ++i) {
    CHECK(ja["points"][i]["id"] == f.doc.points[i].id);
    CHECK(ja["points"][i]["deviation"].get<double>() == f.doc.points[i].deviation);
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      CHECK(ja["alignment"]["transform"][i][j].get<double>() == f.doc.registration.transform(i, j));
  CHECK(ja["gouges"].is_null());
  CHECK(ja["prediction"].is_null());
  CHECK(ja["inputs"][0]["sha256"] == "44136fa355b3678a1146ad16f7e8649e94fb4fc21fe77e8310c060f61caaff8a");  // sha256("{}")
}

TEST_CASE("the report folder is the same bytes whether its figures and files are drawn on one thread or several") {
  // make_report draws independent figures at once and writes the four
  // documents two at a time; the oracle is every piece made strictly one
  // after the other on one thread.
  const test::ReportFixture& f = fixture();
  ReportContext c = context("2024-01-01T00:00:00Z");
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::vector<ReportFigure> figures = make_report_figures(f.doc, f.part, nullptr);
  omp_set_num_threads(4);
  const std::vector<FolderFile> parallel = make_report(f.doc, f.part, nullptr, c);
  omp_set_num_threads(threads);
  c.face_surfaces = face_surfaces(f.part, f.doc);  // what make_report adds to the context
  const ReportVerdict verdict = report_verdict(f.doc);
  std::vector<FolderFile> serial = {
      {"report.html", report_html(f.doc, verdict, nullptr, c, figures)},
      {"report.json", report_json_text(f.doc, verdict, nullptr, c, figures)},
      {"points.csv", points_csv_text(f.doc)},
      {"results.qif", comparison_to_qif(f.doc, c.inputs, c.generated, c.record)}};
  for (const ReportFigure& fig : figures) {
    serial.push_back({fig.file, std::string(fig.png.begin(), fig.png.end())});
    if (!fig.svg.empty()) serial.push_back({fig.svg_file(), fig.svg});
  }
  REQUIRE(serial.size() == parallel.size());
  CHECK(serial.size() >= 8);  // four documents and at least four figure files
  for (std::size_t k = 0; k < serial.size(); ++k) {
    CAPTURE(serial[k].path);
    CHECK(serial[k].path == parallel[k].path);
    CHECK(serial[k].bytes == parallel[k].bytes);
  }
}

TEST_CASE("report.html is self-contained: every figure is inline SVG or an embedded PNG, the same as its file") {
  const test::ReportFixture& f = fixture();
  const std::vector<FolderFile> files = make_report(f.doc, f.part, nullptr, context("2024-01-01T00:00:00Z"));
  const std::string& html = file_named(files, "report.html").bytes;
  CHECK(html.find("<div class=\"result\" id=\"verdict-result\">FAIL</div>") != std::string::npos);
  // Nothing fetched from elsewhere: no link, import or remote src/href (URLs
  // inside three.js's text and the SVG namespace name are not fetched).
  CHECK(html.find("<link") == std::string::npos);
  CHECK(html.find("@import") == std::string::npos);
  for (const char* remote : {"src=\"http", "href=\"http", "src=\"//", "href=\"//", "url(http", "url(//"})
    CHECK_MESSAGE(html.find(remote) == std::string::npos, remote);
  // Embedded raster images, each the same bytes as its figures/*.png file.
  std::vector<std::string> embedded;
  const std::string marker = "<img ";
  for (std::size_t at = html.find(marker); at != std::string::npos; at = html.find(marker, at + 1)) {
    const std::size_t start = html.find("src=\"", at) + 5, end = html.find('"', start);
    const std::string src = html.substr(start, end - start);
    REQUIRE(src.rfind("data:image/png;base64,", 0) == 0);  // nothing external
    embedded.push_back(base64_decode(src.substr(22)));
  }
  // Inline SVG: each the same text as its figures/*.svg file.
  std::vector<std::string> inline_svg;
  for (std::size_t at = html.find("<svg "); at != std::string::npos; at = html.find("<svg ", at + 1)) {
    const std::size_t end = html.find("</svg>\n", at);
    REQUIRE(end != std::string::npos);
    inline_svg.push_back(html.substr(at, end + 7 - at));
  }
  std::vector<std::string> png_files, svg_files;
  for (const FolderFile& file : files) {
    if (file.path.rfind("figures/", 0) != 0) continue;
    (file.path.size() > 4 && file.path.compare(file.path.size() - 4, 4, ".svg") == 0 ? svg_files : png_files)
        .push_back(file.bytes);
  }
  // Top view, face (u, v), histogram (vector: 192 points) and the 3D view's
  // four views (a raster): no regions, no prediction.
  CHECK(png_files.size() == 4);
  CHECK(svg_files.size() == 3);
  REQUIRE(embedded.size() == 1);
  CHECK(std::find(png_files.begin(), png_files.end(), embedded[0]) != png_files.end());  // its file's bytes
  CHECK(inline_svg == svg_files);
  for (const std::string& png : png_files) {
    const cv::Mat img = cv::imdecode(std::vector<unsigned char>(png.begin(), png.end()), cv::IMREAD_COLOR);
    CHECK_FALSE(img.empty());
  }
  // The point table has a row per point.
  std::size_t rows = 0;
  const std::size_t table = html.find("id=\"point-table\""), end = html.find("</table>", table);
  for (std::size_t at = html.find("<tr", table); at < end; at = html.find("<tr", at + 1)) ++rows;
  CHECK(rows == f.doc.points.size() + 1);  // + header
}

TEST_CASE("a comparison of another part is refused") {
  const test::ReportFixture& f = fixture();
  ComparisonDocument doc = f.doc;
  doc.points[3].face = "lid";
  CHECK_THROWS_AS(make_report(doc, f.part, nullptr, context("x")), InputError);
  doc = f.doc;
  doc.points[0].face_index = 4;
  CHECK_THROWS_WITH_AS(check_comparison_faces(doc, f.part),
                       doctest::Contains("point P00001 lies on face 4 \"mould\""), InputError);
}

TEST_CASE("an input inside the output folder is refused before the folder is replaced") {
  const std::string dir = std::string(FURROW_BINARY_DIR) + "/test-scratch/report-inputs-inside";
  std::filesystem::create_directories(dir + "/sub");
  { std::ofstream(dir + "/sub/comparison.json") << "{}"; }
  const std::vector<InputDigest> inputs = {digest_file("comparison", dir + "/sub/comparison.json")};
  CHECK_THROWS_WITH_AS(check_inputs_outside(dir, inputs), doctest::Contains("would be deleted"), InputError);
  CHECK_THROWS_AS(check_inputs_outside(dir + "/sub", inputs), InputError);
  CHECK_NOTHROW(check_inputs_outside(dir + "/other", inputs));
  CHECK_NOTHROW(check_inputs_outside(dir + "/sub2", inputs));  // a sibling with a common prefix
  std::vector<InputDigest> generated = inputs;
  generated[0].generated = true;  // written by the same run: replaced with the folder
  CHECK_NOTHROW(check_inputs_outside(dir, generated));
}

TEST_CASE("report.html and report.json show a datum frame's profile beside the best fit's, and each datum's form") {
  const test::ReportFixture& f = fixture();
  ComparisonDocument doc = f.doc;
  doc.alignment.method = "datums";
  doc.alignment.note = "the datum frame fixes the part";
  doc.alignment.bestfit_profile = 0.01234;
  ComparisonDocument::Alignment::Datum a;
  a.label = "A";
  a.kind = "plane";
  a.points = {"A1", "A2", "A3"};
  a.form_error = 0.0045;
  doc.alignment.datums = {a};
  const std::string html = file_named(make_report(doc, f.part, nullptr, context("2024-01-01T00:00:00Z")), "report.html").bytes;
  char frame[512];
  std::snprintf(frame, sizeof frame, "%.1f &micro;m in the datum frame (form + location); 12.3 &micro;m best fit (form)",
                doc.summary.profile * 1000);
  CHECK(html.find(frame) != std::string::npos);
  CHECK(html.find("Datum A (plane, 3 points)") != std::string::npos);
  CHECK(html.find("flatness 4.5 &micro;m") != std::string::npos);
  // A best fit says nothing of it.
  const std::string plain = file_named(make_report(f.doc, f.part, nullptr, context("2024-01-01T00:00:00Z")), "report.html").bytes;
  CHECK(plain.find("best fit (form)") == std::string::npos);

  // report.json carries the same: the method, each datum, the best-fit profile.
  a.origin = Eigen::Vector3d(1.5, -2, 0.25);
  a.direction = Eigen::Vector3d(0, 0.6, 0.8);
  doc.alignment.datums = {a};
  const nlohmann::json j = nlohmann::json::parse(
      file_named(make_report(doc, f.part, nullptr, context("2024-01-01T00:00:00Z")), "report.json").bytes);
  const nlohmann::json& al = j.at("alignment");
  CHECK(al.at("method") == "datums");
  CHECK(al.at("note") == doc.alignment.note);
  CHECK(al.at("bestfit_profile").get<double>() == 0.01234);
  REQUIRE(al.at("datums").size() == 1);
  const nlohmann::json& d = al.at("datums")[0];
  CHECK(d.at("label") == "A");
  CHECK(d.at("kind") == "plane");
  CHECK(d.at("points") == nlohmann::json({"A1", "A2", "A3"}));
  CHECK(d.at("form_error").get<double>() == 0.0045);
  for (int k = 0; k < 3; ++k) {
    CHECK(d.at("origin")[k].get<double>() == a.origin[k]);
    CHECK(d.at("direction")[k].get<double>() == a.direction[k]);
  }
  const nlohmann::json best = nlohmann::json::parse(
      file_named(make_report(f.doc, f.part, nullptr, context("2024-01-01T00:00:00Z")), "report.json").bytes);
  CHECK(best.at("alignment").at("method") == "bestfit");
  CHECK_FALSE(best.at("alignment").contains("bestfit_profile"));
}

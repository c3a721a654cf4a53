// The report's vector figures: every SVG parses as XML (pugixml, another
// implementation than the writer), labels out-of-tolerance points exactly
// as the comparison says, colours points with the deviation scale, and the
// raster back end paints the same drawing.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <pugixml.hpp>
#include <set>

#include "render/drawing_raster.hpp"
#include "render/svg.hpp"
#include "report/figures.hpp"
#include "report/report_figures.hpp"
#include "deviation_ramp.hpp"
#include "report_fixture.hpp"

using namespace furrow;

namespace {

const test::ReportFixture& fixture() {
  static const test::ReportFixture f = test::make_report_fixture();
  return f;
}

const ReportFigure& figure_named(const std::vector<ReportFigure>& figures, const std::string& file) {
  for (const ReportFigure& f : figures)
    if (f.file == file) return f;
  FAIL("no figure " << file);
  throw std::logic_error("unreachable");
}

using test::deviation_ramp;

std::array<int, 3> hex_colour(const std::string& s) {
  REQUIRE(s.size() == 7);
  REQUIRE(s[0] == '#');
  return {std::stoi(s.substr(1, 2), nullptr, 16), std::stoi(s.substr(3, 2), nullptr, 16),
          std::stoi(s.substr(5, 2), nullptr, 16)};
}

}  // namespace

TEST_CASE("every vector figure of the report is well-formed SVG with a title and its size") {
  const test::ReportFixture& f = fixture();
  const std::vector<ReportFigure> figures = make_report_figures(f.doc, f.part, nullptr);
  int vector = 0;
  for (const ReportFigure& fig : figures) {
    if (fig.svg.empty()) continue;
    ++vector;
    pugi::xml_document xml;
    const pugi::xml_parse_result parsed = xml.load_string(fig.svg.c_str());
    INFO(fig.file << ": " << parsed.description() << " at " << parsed.offset);
    REQUIRE(parsed);
    const pugi::xml_node svg = xml.child("svg");
    REQUIRE(svg);
    CHECK(std::string(svg.attribute("xmlns").value()) == "http://www.w3.org/2000/svg");
    CHECK(std::string(svg.child_value("title")) == fig.title);
    CHECK(std::string(svg.attribute("viewBox").value()) == "0 0 900 640");
    // Real micro signs in the text (the raster back end cannot draw them).
    bool micro = false;
    for (const pugi::xpath_node& t : svg.select_nodes("//text"))
      micro = micro || std::string(t.node().child_value()).find("\u00b5m") != std::string::npos;
    CHECK(micro);
    // No NaN or infinity in any attribute.
    for (const pugi::xpath_node& n : svg.select_nodes("//*"))
      for (const pugi::xml_attribute& a : n.node().attributes()) {
        const std::string v = a.value();
        CHECK(v.find("nan") == std::string::npos);
        CHECK(v.find("inf") == std::string::npos);
      }
  }
  CHECK(vector == 3);  // top view, face (u, v), histogram (the 3D view's four views are a raster)
}

TEST_CASE("the top view labels exactly the out-of-tolerance points, with id and deviation") {
  const test::ReportFixture& f = fixture();
  const std::vector<ReportFigure> figures = make_report_figures(f.doc, f.part, nullptr);
  const ReportFigure& top = figure_named(figures, "figures/deviation_top.png");
  pugi::xml_document xml;
  REQUIRE(xml.load_string(top.svg.c_str()));
  std::map<std::string, double> labelled;
  for (const pugi::xpath_node& t : xml.select_nodes("//text[@class='oot-label']")) {
    const std::string id = t.node().attribute("data-id").value();
    const double value = std::stod(t.node().attribute("data-value").value());
    CHECK(labelled.emplace(id, value).second);  // each point once
    CHECK(std::string(t.node().child_value()).find(id + " ") == 0);
    CHECK(std::string(t.node().child_value()).find(" \u00b5m") != std::string::npos);
  }
  // The oracle: the comparison's own in/out decision per point.
  std::map<std::string, double> expected;
  for (const auto& p : f.doc.points)
    if (p.evaluated && p.in_tolerance && !*p.in_tolerance) expected.emplace(p.id, p.deviation * 1000.0);
  REQUIRE(expected.size() >= 1);
  REQUIRE(expected.size() <= kMaxMapLabels);
  REQUIRE(labelled.size() == expected.size());
  for (const auto& [id, um] : expected) {
    REQUIRE(labelled.count(id) == 1);
    CHECK(std::fabs(labelled[id] - um) <= 0.05 + 1e-9);  // one decimal
  }
}

TEST_CASE("point colours in the SVG are the deviation scale's, computed independently") {
  std::vector<MapPoint> pts;
  for (int k = 0; k < 21; ++k) pts.push_back({Eigen::Vector2d(k, 0), (k - 10) * 0.01, false, "P" + std::to_string(k), false});
  const ToleranceLimits tol{-0.05, 0.05};
  const std::string svg = to_svg(deviation_map_drawing("scale", pts, {}, tol, "x", "y", true), "scale");
  pugi::xml_document xml;
  REQUIRE(xml.load_string(svg.c_str()));
  // The point markers are the circles of radius 7 (21 points), in drawing
  // order: |value| ascending, stable.
  std::vector<std::array<int, 3>> fills;
  for (const pugi::xpath_node& c : xml.select_nodes("//circle[@r='7']"))
    fills.push_back(hex_colour(c.node().attribute("fill").value()));
  REQUIRE(fills.size() == 21);
  std::multiset<std::array<int, 3>> got(fills.begin(), fills.end()), want;
  for (const MapPoint& p : pts) want.insert(deviation_ramp(p.value / 0.1));  // range = max(tol, max |value|) = 0.1 mm
  CHECK(got == want);
  // Extremes: dark blue and dark red ends.
  CHECK(got.count({5, 48, 97}) == 1);
  CHECK(got.count({103, 0, 31}) == 1);
}

TEST_CASE("the PNG and the SVG of a figure come from the same drawing") {
  Drawing d(200, 100);
  d.rect({10, 10}, {60, 50}, Rgb{200, 30, 30});
  d.circle({150, 50}, 20, Rgb{30, 90, 160});
  d.text("5 \u00b5m & <ok>", {20, 90}, 14);
  const std::string svg = to_svg(d, "t");
  pugi::xml_document xml;
  REQUIRE(xml.load_string(svg.c_str()));
  CHECK(std::string(xml.child("svg").child("text").child_value()) == "5 \u00b5m & <ok>");
  const std::vector<unsigned char> png = to_png(d);
  const cv::Mat img = cv::imdecode(png, cv::IMREAD_COLOR);
  REQUIRE(img.cols == 200);
  REQUIRE(img.rows == 100);
  // The rectangle covers [10, 60) x [10, 50) in both: pixel centres inside red, outside white.
  CHECK(img.at<cv::Vec3b>(30, 35) == cv::Vec3b(30, 30, 200));
  CHECK(img.at<cv::Vec3b>(30, 62) == cv::Vec3b(255, 255, 255));
  CHECK(img.at<cv::Vec3b>(50, 150) == cv::Vec3b(160, 90, 30));  // circle centre
  CHECK(img.at<cv::Vec3b>(50, 128) == cv::Vec3b(255, 255, 255));  // outside radius 20
  CHECK(to_png(d) == png);
}

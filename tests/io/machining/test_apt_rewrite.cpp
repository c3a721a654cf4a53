// APT CL data written again with moved tool tips (io/machining/apt_rewrite.hpp).
// Oracles: the original bytes (nothing moved), a tiny file whose expected
// output is written out by hand below, and the moved tips re-read from the
// output by the APT reader (its own tests check it against the G-code
// reader and hand-computed arcs) compared with the tips asked for.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/machining/apt_reader.hpp"
#include "io/machining/apt_rewrite.hpp"
#include "support/input_error.hpp"

using namespace furrow;

namespace {

using Tips = std::vector<std::vector<Eigen::Vector3d>>;

Tips tips_of(const Toolpath& path) {
  Tips tips;
  for (const ToolpathPass& pass : path.passes) {
    tips.emplace_back();
    for (const ToolpathPoint& p : pass.points) tips.back().push_back(p.position);
  }
  return tips;
}

// Largest per-axis distance between the output's points and the tips asked
// for (same structure required).
double largest_miss(const Toolpath& got, const Tips& wanted) {
  REQUIRE(got.passes.size() == wanted.size());
  double worst = 0;
  for (std::size_t p = 0; p < wanted.size(); ++p) {
    REQUIRE(got.passes[p].points.size() == wanted[p].size());
    for (std::size_t i = 0; i < wanted[p].size(); ++i)
      worst = std::max(worst, (got.passes[p].points[i].position - wanted[p][i]).cwiseAbs().maxCoeff());
  }
  return worst;
}

// NX layout: header words, CIRCLE/ arcs, a continuation line with a
// comment, 6-value GOTOs, RAPID, FEDRAT, CRLF endings and a byte-order mark.
const std::string kNx =
    "\xEF\xBB\xBF$$ -> CLSF_STYLE,ADVANCED\r\n"
    "TOOL PATH/CONTOUR_RING,TOOL,BALL_MILL\r\n"
    "TLDATA/MILL,6.0000,3.0000,50.0000,0.0000,0.0000\r\n"
    "PARTNO RING TEST / OP 10\r\n"
    "UNITS/MM\r\n"
    "CUTTER/6.0000,3.0000,0.0000,3.0000,0.0000,0.0000,50.0000\r\n"
    "SPINDL/RPM,8000,CLW\r\n"
    "RAPID\r\n"
    "GOTO/10.0000,0.0000,30.0000\r\n"
    "RAPID\r\n"
    "GOTO/10.0000,0.0000,5.0000\r\n"
    "FEDRAT/MMPM,800.0000\r\n"
    "GOTO/10.0000,0.0000,-1.0000,0.0000000,0.0000000,1.0000000\r\n"
    "CIRCLE/0.0000,0.0000,-1.0000,0.0000000,0.0000000,1.0000000,10.0000,0.0600,0.5000,6.0000,0.0000\r\n"
    "GOTO/0.0000,10.0000,-1.0000\r\n"
    "GOTO/-5.0000,10.0000,$\r\n"
    "  -1.0000  $$ continued\r\n"
    "PPRINT/ $ not a continuation, RAPID\r\n"
    "GODLTA/0.0000,-2.0000,0.0000\r\n"
    "RAPID\r\n"
    "GODLTA/31.0000\r\n"
    "FINI\r\n";

// CATIA layout: spaced GOTOs, INDIRV + TLON,GOFWD arcs over continuation
// lines, in inches by the read option.
const std::string kCatia =
    "$$*CATIA0\n"
    "PARTNO PART1\n"
    "CUTTER/ 0.250000, 0.125000, 0.000000, 0.125000, 0.000000, 0.000000, 2.000000\n"
    "FEDRAT/  40.0000,IPM\n"
    "RAPID\n"
    "GOTO  /   0.00000,   0.00000,   0.40000, 0.000000, 0.000000, 1.000000\n"
    "GOTO  /   0.00000,   0.00000,   0.00000, 0.000000, 0.000000, 1.000000\n"
    "GOTO  /   0.40000,   0.00000,   0.00000, 0.000000, 0.000000, 1.000000\n"
    "INDIRV/ 1.000000, 0.000000, 0.000000\n"
    "TLON,GOFWD/ (CIRCLE/ 0.40000, 0.20000, 0.00000, $\n"
    " 0.20000), ON, (LINE/ 0.40000, 0.20000, 0.00000, $\n"
    " 0.40000, 0.40000, 0.00000)\n"
    "GOTO  /   0.00000,   0.40000,   0.00000, 0.000000, 0.000000, 1.000000\n"
    "RAPID\n"
    "GOTO  /   0.00000,   0.40000,   0.40000\n"
    "FINI";

ToolpathReadOptions inch() {
  ToolpathReadOptions o;
  o.units = "inch";
  return o;
}

}  // namespace

TEST_CASE("APT rewrite: tips not moved give the file back byte for byte") {
  SUBCASE("NX layout, CRLF, a byte-order mark, arcs, a continuation, GODLTA") {
    const Toolpath path = parse_apt(kNx, "ring.cls");
    const ProgramRewrite out = rewrite_apt(kNx, "ring.cls", {}, tips_of(path));
    CHECK(out.text == kNx);
    CHECK(out.lines_moved == 0);
    CHECK(out.decimals == 4);
    // Moves below half a unit of the last decimal (0.05 um) change nothing.
    Tips tips = tips_of(path);
    for (auto& pass : tips)
      for (auto& t : pass) t += Eigen::Vector3d(2e-5, -2e-5, 2e-5);
    CHECK(rewrite_apt(kNx, "ring.cls", {}, tips).text == kNx);
  }
  SUBCASE("CATIA layout in inches, TLON,GOFWD arcs, no final line ending") {
    const Toolpath path = parse_apt(kCatia, "part.apt", inch());
    const ProgramRewrite out = rewrite_apt(kCatia, "part.apt", inch(), tips_of(path));
    CHECK(out.text == kCatia);
    CHECK(out.decimals == 5);
    CHECK(out.unit_mm == 25.4);
  }
}

TEST_CASE("APT rewrite: a tiny file moved by hand, GOTO, GODLTA, a zero-length cut and the pass start") {
  const std::string file =
      "PARTNO TINY\n"                                  // 1
      "UNITS/MM\n"                                     // 2
      "CUTTER/6.0000,3.0000\n"                         // 3
      "FEDRAT/500.0000\n"                              // 4
      "RAPID\n"                                        // 5
      "GOTO/0.0000,0.0000,10.0000\n"                   // 6
      "RAPID\n"                                        // 7
      "GOTO/0.0000,0.0000,1.0000\n"                    // 8  the pass starts here
      "GOTO/0.0000,0.0000,0.0000 $$ plunge\n"          // 9
      "GOTO/10.0000,0.0000,0.0000\n"                   // 10
      "GODLTA/0.0000,5.0000,0.0000\n"                  // 11
      "GOTO/10.0000,5.0000,0.0000,0.0000000,0.0000000,1.0000000\n"  // 12 zero length
      "GOTO/20.0000, 5.0000, 0.0000\n"                 // 13
      "RAPID\n"                                        // 14
      "GODLTA/10.0000\n"                               // 15
      "FINI\n";                                        // 16
  const Toolpath path = parse_apt(file, "tiny.apt");
  REQUIRE(path.passes.size() == 1);
  REQUIRE(path.passes[0].points.size() == 5);  // (0,0,1) (0,0,0) (10,0,0) (10,5,0) (20,5,0)
  Tips tips = tips_of(path);
  tips[0][0] = {0, 0, 0.9};
  tips[0][2] = {10, 0, -0.05};
  tips[0][3] = {10, 5, -0.0523};
  tips[0][4] = {20.01, 5.00004, -0.1};
  const ProgramRewrite out = rewrite_apt(file, "tiny.apt", {}, tips);
  // By hand: absolute values where the tips now are (4 decimals, 5.00004
  // rounds to 5.0000 and is left as written); GODLTA/ from where the
  // rewritten program is, (10, 0, -0.05) to (10, 5, -0.0523); the zero-length
  // GOTO/ stays with the tool (its i,j,k kept); the last RAPID GODLTA/dz
  // must still end at (20, 5, 10) from (20.01, 5, -0.1), so it gains dx, dy.
  const std::string expected =
      "PARTNO TINY\n"
      "UNITS/MM\n"
      "CUTTER/6.0000,3.0000\n"
      "FEDRAT/500.0000\n"
      "RAPID\n"
      "GOTO/0.0000,0.0000,10.0000\n"
      "RAPID\n"
      "GOTO/0.0000,0.0000,0.9000\n"
      "GOTO/0.0000,0.0000,0.0000 $$ plunge\n"
      "GOTO/10.0000,0.0000,-0.0500\n"
      "GODLTA/0.0000,5.0000,-0.0023\n"
      "GOTO/10.0000,5.0000,-0.0523,0.0000000,0.0000000,1.0000000\n"
      "GOTO/20.0100, 5.0000, -0.1000\n"
      "RAPID\n"
      "GODLTA/-0.0100,0.0000,10.1000\n"
      "FINI\n";
  CHECK(out.text == expected);
  CHECK(out.lines_moved == 6);
  CHECK(out.words_rewritten == 7);  // z of 8, 10, 11, 12; x and z of 13; the GODLTA/ value of 15
  CHECK(out.words_added == 2);
  const Toolpath back = parse_apt(out.text, "back.apt");
  CHECK(largest_miss(back, tips) <= 0.5e-4 + 1e-12);
  CHECK(back.rapids.back().to.isApprox(Eigen::Vector3d(20, 5, 10), 1e-12));
}

TEST_CASE("APT rewrite: moved arcs become GOTO statements through the moved points, re-read as asked") {
  SUBCASE("CIRCLE/ and its GOTO/, and a moved GOTO/ over a continuation line") {
    const Toolpath path = parse_apt(kNx, "ring.cls");
    Tips tips = tips_of(path);
    // Every cutting point 30 um down and 7 um across; the pass start too.
    for (auto& pass : tips)
      for (auto& t : pass) t += Eigen::Vector3d(0.007, 0, -0.03);
    const ProgramRewrite out = rewrite_apt(kNx, "ring.cls", {}, tips);
    CHECK(out.arcs_split == 1);
    CHECK(out.lines_removed == 1);  // the CIRCLE/
    CHECK(out.text.find("CIRCLE/") == std::string::npos);
    CHECK(out.text.find("PPRINT/ $ not a continuation, RAPID\r\n") != std::string::npos);
    CHECK(out.text.find("SPINDL/RPM,8000,CLW\r\n") != std::string::npos);
    CHECK(out.text.compare(0, 3, "\xEF\xBB\xBF") == 0);
    const Toolpath back = parse_apt(out.text, "back.cls");
    CHECK(largest_miss(back, tips) <= 0.5e-4 + 1e-12);
    // The rapids outside the pass end where they did.
    REQUIRE(back.rapids.size() == path.rapids.size());
    CHECK(back.rapids.back().to.isApprox(path.rapids.back().to, 1e-12));
  }
  SUBCASE("TLON,GOFWD/ arcs in inches") {
    const Toolpath path = parse_apt(kCatia, "part.apt", inch());
    Tips tips = tips_of(path);
    for (auto& pass : tips)
      for (std::size_t i = 1; i < pass.size(); ++i) pass[i] += Eigen::Vector3d(0, 0.01, -0.02);
    const ProgramRewrite out = rewrite_apt(kCatia, "part.apt", inch(), tips);
    CHECK(out.arcs_split == 1);
    CHECK(out.text.find("TLON") == std::string::npos);
    CHECK(out.text.find("INDIRV/ 1.000000, 0.000000, 0.000000\n") != std::string::npos);
    const Toolpath back = parse_apt(out.text, "back.apt", inch());
    // Half a unit of 5 decimals of an inch: 0.127 um.
    CHECK(largest_miss(back, tips) <= 0.5e-5 * 25.4 + 1e-12);
  }
}

TEST_CASE("APT rewrite: tips of another shape are refused naming the file") {
  const Toolpath path = parse_apt(kNx, "ring.cls");
  Tips tips = tips_of(path);
  tips[0].pop_back();
  CHECK(test::input_error_of([&] { rewrite_apt(kNx, "ring.cls", {}, tips); }).find("ring.cls") == 0);
}

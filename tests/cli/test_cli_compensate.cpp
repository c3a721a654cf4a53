// `furrow compensate` in the closed loop, in simulation, through the commands
// a user runs: the mould's example program (a 6 mm ball, `furrow toolpath`),
// a plan kept to the points near a planted bump, the measurement simulated
// with that bump, compared, and compensated. Oracles: the planted bump's
// height (the tips near its centre must move down by gain x height), the
// original program's bytes (far from every measured point nothing may
// change), and the structure of the program re-read.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/machining/apt_reader.hpp"
#include "io/machining/gcode_reader.hpp"
#include "io/part_file.hpp"
#include "machining/prediction/zmap.hpp"
#include "mould_bump_fixture.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::slurp;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr double kBumpRadius = 15;   // [mm]
constexpr double kBumpHeight = 0.05;  // [mm], material left
constexpr double kKept = 30;          // [mm] plan points kept within this of the bump centre

using Loop = test::MouldBump;
using test::as_apt;
using test::lines_of;

// The measured comparison of a mould cut with a bump left on it.
const Loop& loop() {
  static const Loop made = test::measured_mould_bump("cli-compensate", kBumpRadius, kBumpHeight, kKept, 3);
  return made;
}


}  // namespace

TEST_CASE("compensate: tips near a planted bump move down by gain x its height, far lines keep their bytes") {
  const Loop& l = loop();
  const std::string out = l.dir + "/comp.nc";
  const auto r = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program, "--tool",
                             l.tool, "--out", out, "--gain", "0.8"});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const json record = json::parse(slurp(l.dir + "/comp.json"));
  CHECK(record["faces"][0]["fitted"] == true);
  CHECK(record["zmap_check"]["safe"] == true);
  const std::string before_text = slurp(l.program), after_text = slurp(out);
  const Toolpath before = parse_gcode(before_text, "before.nc"), after = parse_gcode(after_text, "after.nc");
  // The same program: passes, points, lines, feeds; no arc in it, so the
  // same lines.
  REQUIRE(after.passes.size() == before.passes.size());
  CHECK(after.rapids.size() == before.rapids.size());
  const std::vector<std::string> a = lines_of(before_text), b = lines_of(after_text);
  REQUIRE(a.size() == b.size());
  const double fade = record["faces"][0]["fade_distance"].get<double>();
  // A tip farther than this (in xy) from the bump centre has its contact
  // (within a ball radius, 3 mm, of it) beyond the fade of every sample
  // (all within kKept of the centre): the field there is exactly zero.
  const double far = kKept + fade + 3 + 1;
  std::size_t near = 0, far_lines = 0;
  double worst_near = 0;
  for (std::size_t p = 0; p < before.passes.size(); ++p) {
    REQUIRE(after.passes[p].points.size() == before.passes[p].points.size());
    for (std::size_t i = 1; i < before.passes[p].points.size(); ++i) {
      const ToolpathPoint& t0 = before.passes[p].points[i];
      const ToolpathPoint& t1 = after.passes[p].points[i];
      CHECK(t1.feed == t0.feed);
      const double d = (t0.position - l.centre).head<2>().norm();
      if (d > far) {
        ++far_lines;
        CHECK(a[static_cast<std::size_t>(t0.line - 1)] == b[static_cast<std::size_t>(t1.line - 1)]);
      }
      if (d < 2) {
        ++near;
        // Material left: the tip goes down, by 0.8 x 50 um = 40 um times the
        // bump's cosine profile at its contact (>= 0.97 within 2 + 3 mm of
        // the centre at radius 15 mm). Allowed: 15 % of the height, for
        // the smoothing GCV chooses over ~5 mm spaced samples with 1 um noise.
        const Eigen::Vector3d moved = t1.position - t0.position;
        CHECK(moved.z() < 0);
        worst_near = std::max(worst_near, std::abs(moved.norm() - 0.8 * kBumpHeight));
      }
    }
  }
  CHECK(near >= 3);
  CHECK(far_lines > 100);
  MESSAGE("near the centre: " << near << " tips, worst |move - 40 um| " << worst_near * 1000 << " um; " << far_lines
                              << " far lines");
  CHECK(worst_near < 0.15 * kBumpHeight);
}

TEST_CASE("compensate: a bad option fails with status 2 naming it, and writes nothing") {
  const Loop& l = loop();
  const std::string out = l.dir + "/bad.nc";
  const auto gain = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program, "--tool",
                                l.tool, "--out", out, "--gain", "2.5"});
  CHECK(gain.status == 2);
  CHECK(gain.err.find("--gain") != std::string::npos);
  const auto offset = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program,
                                  "--tool", l.tool, "--out", out, "--max-offset", "0"});
  CHECK(offset.status == 2);
  CHECK(offset.err.find("--max-offset") != std::string::npos);
  const auto missing = run_furrow({"compensate", l.part, "--comparison", l.dir + "/none.json", "--toolpath",
                                   l.program, "--tool", l.tool, "--out", out});
  CHECK(missing.status == 2);
  CHECK(missing.err.find("none.json") != std::string::npos);
  const auto over_input = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program,
                                      "--tool", l.tool, "--out", l.program});
  CHECK(over_input.status == 2);
  CHECK(slurp(l.program) == slurp(test::source_path("examples/toolpaths/mould_ball6.nc")));
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(l.dir + "/bad.json"));
}

TEST_CASE("compensate: an APT CL file is compensated as the G-code program, written back as APT") {
  const Loop& l = loop();
  const Toolpath gcode = parse_gcode(slurp(l.program), "path.nc");
  const std::string apt_path = l.dir + "/path.apt";
  test::write_text(apt_path, as_apt(gcode, 34.6326));  // the program's clearance height
  const std::string out = l.dir + "/comp.apt", out_nc = l.dir + "/comp_for_apt.nc";
  const auto r = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", apt_path, "--tool",
                             l.tool, "--out", out, "--gain", "0.8"});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const json record = json::parse(slurp(l.dir + "/comp.json"));
  CHECK(record["zmap_check"]["safe"] == true);
  const std::string before_text = slurp(apt_path), after_text = slurp(out);
  const Toolpath before = parse_apt(before_text, "before.apt"), after = parse_apt(after_text, "after.apt");
  // Read as the G-code program is, point for point.
  REQUIRE(before.passes.size() == gcode.passes.size());
  REQUIRE(after.passes.size() == before.passes.size());
  CHECK(after.rapids.size() == before.rapids.size());
  const std::vector<std::string> a = lines_of(before_text), b = lines_of(after_text);
  REQUIRE(a.size() == b.size());
  // The same bounds as the G-code test above: the field's fade, the bump.
  const double fade = record["faces"][0]["fade_distance"].get<double>();
  const double far = kKept + fade + 3 + 1;
  // The G-code program compensated alike: a second writer of the same tips.
  const auto g = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program, "--tool",
                             l.tool, "--out", out_nc, "--gain", "0.8"});
  REQUIRE(g.status == 0);
  const Toolpath by_gcode = parse_gcode(slurp(out_nc), "comp.nc");
  REQUIRE(by_gcode.passes.size() == after.passes.size());
  std::size_t near = 0, far_lines = 0, moved = 0;
  double worst_near = 0, worst_writers = 0;
  for (std::size_t p = 0; p < before.passes.size(); ++p) {
    REQUIRE(after.passes[p].points.size() == before.passes[p].points.size());
    REQUIRE(by_gcode.passes[p].points.size() == before.passes[p].points.size());
    for (std::size_t i = 0; i < before.passes[p].points.size(); ++i) {
      const ToolpathPoint& t0 = before.passes[p].points[i];
      const ToolpathPoint& t1 = after.passes[p].points[i];
      CHECK((t0.position - gcode.passes[p].points[i].position).norm() == 0);
      worst_writers =
          std::max(worst_writers, (t1.position - by_gcode.passes[p].points[i].position).cwiseAbs().maxCoeff());
      moved += t1.position != t0.position;
      if (i == 0) continue;
      CHECK(t1.feed == t0.feed);
      const double d = (t0.position - l.centre).head<2>().norm();
      if (d > far) {
        ++far_lines;
        CHECK(a[static_cast<std::size_t>(t0.line - 1)] == b[static_cast<std::size_t>(t1.line - 1)]);
      }
      if (d < 2) {
        ++near;
        const Eigen::Vector3d step = t1.position - t0.position;
        CHECK(step.z() < 0);
        worst_near = std::max(worst_near, std::abs(step.norm() - 0.8 * kBumpHeight));
      }
    }
  }
  MESSAGE("APT: " << moved << " tips moved, near the centre " << near << " tips, worst |move - 40 um| "
                  << worst_near * 1000 << " um; " << far_lines << " far lines; APT vs G-code writer "
                  << worst_writers * 1000 << " um");
  CHECK(near >= 3);
  CHECK(far_lines > 100);
  CHECK(moved > 0);
  CHECK(worst_near < 0.15 * kBumpHeight);
  // Both writers round the same tips to 4 decimals: identical numbers.
  CHECK(worst_writers == 0);
  // A G-code name for an APT program is refused before any work.
  const auto wrong = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", apt_path,
                                 "--tool", l.tool, "--out", l.dir + "/wrong.nc"});
  CHECK(wrong.status == 2);
  CHECK(!fs::exists(l.dir + "/wrong.nc"));
}

TEST_CASE("compensate: --prediction takes the path's own marks off a comparison made without one") {
  // The same plan and bump, but the part simulated as the program really
  // cuts it (its predicted furrows and cusps on top of the bump) and
  // compared without a prediction: fitted as they are, the deviations carry
  // the path's own mean error too. With --prediction the command takes it
  // off again. Oracle: the planted bump, as in the first test.
  const Loop& l = loop();
  const std::string prediction = l.dir + "/prediction.json";
  const auto pr = run_furrow({"predict", l.part, "--tool", l.tool, "--toolpath", l.program, "--out", prediction});
  INFO(pr.err);
  REQUIRE(pr.status == 0);
  char bump[160];
  std::snprintf(bump, sizeof bump, "%.6f,%.6f,%.6f,%g,%g", l.centre.x(), l.centre.y(), l.centre.z(), kBumpRadius,
                kBumpHeight);
  REQUIRE(run_furrow({"simulate-measurement", l.part, "--plan", l.dir + "/plan.json", "--prediction", prediction,
                      "--bump", bump, "--noise", "0.001", "--blunders", "0", "--seed", "3", "--misalign",
                      "0,0,0,0,0,0", "--out", l.dir + "/cut.csv"})
              .status == 0);
  const std::string comparison = l.dir + "/cut_comparison.json";
  run_furrow({"compare", l.part, "--measurements", l.dir + "/cut.csv", "--plan", l.dir + "/plan.json", "--align",
              "cmm", "--no-outlier-rejection", "--out", comparison});
  REQUIRE(fs::exists(comparison));
  const Toolpath before = parse_gcode(slurp(l.program), "before.nc");
  // The largest |move - 0.8 x bump| of the tips within 2 mm of the centre.
  auto worst_near = [&](const std::string& out) {
    const Toolpath after = parse_gcode(slurp(out), "after.nc");
    REQUIRE(after.passes.size() == before.passes.size());
    double worst = 0;
    std::size_t near = 0;
    for (std::size_t p = 0; p < before.passes.size(); ++p)
      for (std::size_t i = 1; i < before.passes[p].points.size(); ++i) {
        const Eigen::Vector3d& t0 = before.passes[p].points[i].position;
        if ((t0 - l.centre).head<2>().norm() >= 2) continue;
        ++near;
        worst = std::max(worst, std::abs((after.passes[p].points[i].position - t0).norm() - 0.8 * kBumpHeight));
      }
    CHECK(near >= 3);
    return worst;
  };
  const std::string with = l.dir + "/with.nc", without = l.dir + "/without.nc";
  const auto r = run_furrow({"compensate", l.part, "--comparison", comparison, "--toolpath", l.program, "--tool",
                             l.tool, "--out", with, "--gain", "0.8", "--prediction", prediction});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const json record = json::parse(slurp(l.dir + "/with.json"));
  CHECK(record["prediction"] == prediction);
  CHECK(record["prediction_removed"] == true);
  REQUIRE(run_furrow({"compensate", l.part, "--comparison", comparison, "--toolpath", l.program, "--tool", l.tool,
                      "--out", without, "--gain", "0.8"})
              .status == 0);
  const double with_prediction = worst_near(with), without_prediction = worst_near(without);
  MESSAGE("worst |move - 40 um| near the centre: " << with_prediction * 1000 << " um with --prediction, "
                                                  << without_prediction * 1000 << " um without");
  CHECK(with_prediction < 0.15 * kBumpHeight);
  CHECK(with_prediction < without_prediction);
  // A file that is not a prediction is refused before anything is written.
  const auto other = run_furrow({"compensate", l.part, "--comparison", comparison, "--toolpath", l.program,
                                 "--tool", l.tool, "--out", l.dir + "/other.nc", "--prediction", l.comparison});
  CHECK(other.status == 2);
  CHECK(!fs::exists(l.dir + "/other.nc"));
}

TEST_CASE("compensate: one pass over the bump's flank is clipped back, or refused with exit 3 when rounds run out") {
  // One pass of the example program alone, 11 mm from the planted bump's
  // centre, where the field slopes across it: the compensated ball tilts
  // with the field and its side cuts beside the pass deeper than the pass's
  // own offset allows, which no neighbouring pass covers.
  const Loop& l = loop();
  const std::string text = slurp(l.program);
  const std::vector<std::string> lines = lines_of(text);
  const Toolpath all = parse_gcode(text, "path.nc");
  std::size_t chosen = 0;
  for (std::size_t p = 1; p < all.passes.size(); ++p)
    if (std::abs(all.passes[p].points[0].position.y() - l.centre.y() - 11) <
        std::abs(all.passes[chosen].points[0].position.y() - l.centre.y() - 11))
      chosen = p;
  // Its lines: from the rapid down to its start through its last cut, then
  // up to the clearance.
  const ToolpathPass& pass = all.passes[chosen];
  std::string single = "G21 G90 G17\n";
  char rapid[96];
  std::snprintf(rapid, sizeof rapid, "G0 X%.4f Y%.4f Z34.6326\nG0 Z%.4f\n", pass.points[0].position.x(),
                pass.points[0].position.y(), pass.points[0].position.z());
  single += rapid;
  for (int k = pass.points[1].line; k <= pass.points.back().line; ++k) single += lines[std::size_t(k - 1)] + "\n";
  single += "G0 Z34.6326\nM30\n";
  const std::string program = l.dir + "/single.nc";
  test::write_text(program, single);
  const Toolpath original = parse_gcode(single, "single.nc");
  REQUIRE(original.passes.size() == 1);
  REQUIRE(original.passes[0].points.size() == pass.points.size());

  // Two rounds are not enough: exit 3, nothing written, the reason given.
  const std::string refused = l.dir + "/refused.nc";
  const auto r3 = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", program, "--tool",
                              l.tool, "--out", refused, "--clip-back", "2"});
  INFO(r3.out << r3.err);
  CHECK(r3.status == 3);
  CHECK(r3.err.find("after 2 clip-back rounds") != std::string::npos);
  CHECK(!fs::exists(refused));
  CHECK(!fs::exists(l.dir + "/refused.json"));

  // The default rounds rescue it.
  const std::string out = l.dir + "/rescued.nc";
  const auto r = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", program, "--tool",
                             l.tool, "--out", out});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const json record = json::parse(slurp(l.dir + "/rescued.json"));
  const int rounds = record["clip_back"]["rounds"].get<int>();
  CHECK(rounds > 2);
  CHECK(rounds <= 8);
  CHECK(!record["clip_back"]["points"].empty());
  for (const json& p : record["clip_back"]["points"]) {
    const double requested = p["requested"].get<double>(), applied = p["applied"].get<double>();
    CHECK(std::abs(applied - requested / std::pow(2.0, p["rounds"].get<int>())) < 1e-12);
  }
  CHECK(record["zmap_check"]["safe"] == true);
  // Oracle: z-maps the test makes of the original pass and of the program
  // written, at 0.05 mm; within 2.5 mm of the pass and where the original's
  // machined surface is flatter than n_z = 0.3 (central differences), the
  // written one may lie below it by at most the largest offset written over
  // n_z, plus 1 um and the rounding of 4 decimals.
  const Toolpath written = parse_gcode(slurp(out), "rescued.nc");
  const double largest = record["largest_offset"].get<double>();
  Eigen::AlignedBox2d box;
  for (const ToolpathPoint& t : original.passes[0].points) box.extend(t.position.head<2>());
  box.min().array() -= 4;
  box.max().array() += 4;
  const Cutter ball("ball", 3, 3);
  ZMap before(box, 0.05), after(box, 0.05);
  before.cut(ball, moves_from_toolpath(original));
  after.cut(ball, moves_from_toolpath(written));
  const std::vector<ZMapMove> moves = moves_from_toolpath(original);
  double worst = -1;
  std::size_t judged = 0;
  for (int j = 1; j + 1 < after.ny(); ++j)
    for (int i = 1; i + 1 < after.nx(); ++i) {
      const double h0 = before.node_height(i, j), h = after.node_height(i, j);
      const double xm = before.node_height(i - 1, j), xp = before.node_height(i + 1, j);
      const double ym = before.node_height(i, j - 1), yp = before.node_height(i, j + 1);
      if (!std::isfinite(h0) || !std::isfinite(h) || !std::isfinite(xm + xp + ym + yp)) continue;
      const Eigen::Vector2d at(after.x(i), after.y(j));
      double near = 1e9;
      for (const ZMapMove& m : moves) {
        const Eigen::Vector2d a = m.from.head<2>(), b = m.to.head<2>();
        const double t = std::clamp((at - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-30), 0.0, 1.0);
        near = std::min(near, (a + t * (b - a) - at).norm());
      }
      if (near > 2.5) continue;
      const double sx = (xp - xm) / 0.1, sy = (yp - ym) / 0.1;
      const double nz = 1 / std::sqrt(1 + sx * sx + sy * sy);
      if (nz < 0.3) continue;
      ++judged;
      worst = std::max(worst, (h0 - h) - (largest / nz + 1e-3 + std::sqrt(3.0) * 0.5e-4));
    }
  MESSAGE("single pass: " << rounds << " clip-back rounds, " << record["clip_back"]["points"].size()
                          << " tips reduced, largest offset " << largest * 1000 << " um; oracle: " << judged
                          << " nodes, worst excess " << worst * 1000 << " um");
  CHECK(judged > 1000);
  CHECK(worst <= 0);
}

// The clip-back of the compensation stage (stage/compensate_stage.hpp,
// docs/compensation.md "Safety"): a program the z-map check finds cutting
// deeper than its offsets has the offending moves' corrections halved,
// round after round, until the check passes or the rounds run out (then
// the program is refused: `furrow compensate` exits 3 and writes nothing).
//
// The case: one pass of a 6 mm ball along a plate, under a measured error
// that rises across the pass (50 um of material left on the pass, 30 um
// more per mm to one side). The compensated contacts tilt with the field,
// so the ball moves 3 mm x 0.03 = 90 um sideways and its side cuts the
// tilted surface, up to y x 0.03 below the pass's own offset at y mm from
// the pass: as deep as the field asks there, but deeper than any offset of
// the program (50 um) 2 mm out. The check therefore refuses it, and only
// halving the correction (offset and tilt) some seven times brings the side
// within the check's 1 um.
//
// Oracle: z-maps the test makes itself (at 0.05 mm, a quarter of the
// check's cell) of the original and of the program the stage wrote, and an
// allowance of its own: below the original by at most the largest offset
// written anywhere over n_z of the original single ball track there,
// sqrt(r^2 - y^2) / r (analytic), plus 1 um and the rounding of 4 decimals.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "geometry/primitives.hpp"
#include "io/machining/gcode_reader.hpp"
#include "machining/prediction/zmap.hpp"
#include "stage/compensate_stage.hpp"

using namespace furrow;

namespace {

constexpr double kSlope = 0.03;  // [mm/mm] of the field across the pass
constexpr double kTrack = 10;    // [mm] y of the pass
const Cutter kBall("ball", 3, 3);

double error_at(double y) { return 0.05 + kSlope * (y - kTrack); }  // [mm], + material left

Part plate() {
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 0}, {100, 0, 0}, {0, 20, 0}));
  return part;
}

// The part measured on a 5 x 2.5 mm grid, without a prediction: the
// deviations are the field (a plane: the spline's polynomial part holds it
// exactly, whatever the smoothing).
ComparisonDocument measured() {
  ComparisonDocument doc;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 8; ++j) {
      ComparisonDocument::Point p;
      const double x = 5.0 * i, y = 2.5 * j;
      p.id = "P" + std::to_string(i) + "_" + std::to_string(j);
      p.face = "plate";
      p.uv = {x / 100, y / 20};
      p.evaluated = true;
      p.deviation = error_at(y);
      doc.points.push_back(p);
    }
  return doc;
}

std::string program() {
  std::string text = "G21 G90\nG0 X20. Y10. Z5.\nG1 Z0. F500\n";
  for (int x = 22; x <= 80; x += 2) text += "G1 X" + std::to_string(x) + ".\n";
  return text + "G0 Z5.\nM30\n";
}

CompensatedProgram run(int rounds) {
  const std::string text = program();
  const Toolpath path = parse_gcode(text, "pass.nc");
  CompensateOptions options;
  options.clip_back = rounds;
  return compensate_stage(plate(), single_tool(kBall, path), text, ProgramFormat::gcode, {}, measured(), options,
                          {"plate.json", "c.json", "pass.nc", "comp.nc", ""});
}

// The largest excess [mm] of the written program's cut below the
// original's over the oracle's allowance (the header), over the nodes
// within 2.5 mm of the pass and 4 mm inside its ends.
double worst_excess(const std::string& written, double largest_offset) {
  const Toolpath a = parse_gcode(program(), "a.nc"), b = parse_gcode(written, "b.nc");
  const Eigen::AlignedBox2d box(Eigen::Vector2d(15, 5), Eigen::Vector2d(85, 15));
  ZMap before(box, 0.05), after(box, 0.05);
  before.cut(kBall, moves_from_toolpath(a));
  after.cut(kBall, moves_from_toolpath(b));
  const double tolerance = 1e-3 + std::sqrt(3.0) * 0.5e-4;
  double worst = -1;
  for (int j = 0; j < after.ny(); ++j)
    for (int i = 0; i < after.nx(); ++i) {
      const double x = after.x(i), y = after.y(j) - kTrack;
      if (x < 24 || x > 76 || std::abs(y) > 2.5) continue;
      const double nz = std::sqrt(9 - y * y) / 3;
      const double depth = before.node_height(i, j) - after.node_height(i, j);
      worst = std::max(worst, depth - (largest_offset / nz + tolerance));
    }
  return worst;
}

}  // namespace

TEST_CASE("compensation clip-back: a pass cut deeper than its offsets is clipped back until the z-map check passes") {
  const CompensatedProgram unclipped = run(0);
  const CompensatedProgram done = run(CompensateOptions{}.clip_back);
  // The correction asked for: 50 um down on every cutting point.
  CHECK(std::abs(unclipped.offset.largest_offset - 0.05) < 1e-6);
  // Refused as first written, by the stage's check and by the oracle.
  CHECK_FALSE(unclipped.check.safe());
  CHECK(unclipped.clip_back.empty());
  const double before = worst_excess(unclipped.program.text, unclipped.offset.largest_offset);
  MESSAGE("unclipped: the oracle's worst excess " << before * 1000 << " um");
  CHECK(before > 0.005);
  // Rescued within the rounds, and the oracle agrees.
  REQUIRE(done.check.safe());
  CHECK(done.clip_back_rounds >= 2);
  CHECK(done.clip_back_rounds <= CompensateOptions{}.clip_back);
  const double after = worst_excess(done.program.text, done.offset.largest_offset);
  MESSAGE("after " << done.clip_back_rounds << " rounds: the oracle's worst excess " << after * 1000 << " um");
  CHECK(after <= 0);
  // Every cutting point on the plate is listed, halved as many times as its
  // rounds say; its line is the program's.
  CHECK(done.clip_back.size() == 31);  // the plunge's end and the 30 moves after it
  for (const ClipBackPoint& p : done.clip_back) {
    CHECK(std::abs(p.requested + 0.05) < 1e-6);
    CHECK(p.rounds >= 1);
    CHECK(std::abs(p.applied - p.requested / std::pow(2.0, p.rounds)) < 1e-15);
    CHECK(p.line >= 3);
  }
  // Still compensated: every cutting tip lower than planned, by no more
  // than the correction asked for.
  const Toolpath written = parse_gcode(done.program.text, "comp.nc");
  REQUIRE(written.passes.size() == 1);
  for (std::size_t k = 1; k < written.passes[0].points.size(); ++k) {
    const double z = written.passes[0].points[k].position.z();
    CHECK(z < 0);
    CHECK(z > -0.05 - 1e-4);
  }
}

TEST_CASE("compensation clip-back: too few rounds leave the program unsafe, and it is refused") {
  const CompensatedProgram done = run(3);
  CHECK_FALSE(done.check.safe());
  CHECK(done.clip_back_rounds == 3);
  CHECK(done.check.worst_excess > 0);
  // The oracle confirms: the program the stage would not write still cuts
  // deeper than any of its offsets allows.
  const double excess = worst_excess(done.program.text, done.offset.largest_offset);
  MESSAGE("after 3 rounds: the oracle's worst excess " << excess * 1000 << " um");
  CHECK(excess > 0);
}

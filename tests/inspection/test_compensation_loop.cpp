#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "geometry/primitives.hpp"
#include "inspection/comparison_error_field.hpp"
#include "machining/compensation/path_offset.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;

// The loop in simulation, on a plate so that the normal error is the
// height: a machine that leaves m(x, y) on top of what the path cuts, the
// part cut with a ball raster and measured at 300 scattered points with
// 1 um noise, the prediction (the path's own z-map) removed, the field
// fitted, the path offset, and the part cut again with the compensated
// path on the same machine. The z-maps are the oracle of what each path
// cuts (docs/architecture.md "Machining error between contact points").

namespace {

double bumps(double x, double y) {
  auto bump = [](double dx, double dy, double r) { return std::exp(-(dx * dx + dy * dy) / (2 * r * r)); };
  return 0.08 * bump(x - 30, y - 30, 10) - 0.06 * bump(x - 70, y - 25, 8);
}
double bumps_and_tilt(double x, double y) { return bumps(x, y) + 0.0002 * (y - 30); }

Toolpath raster() {
  Toolpath path;
  for (double y = 0; y <= 60 + 1e-9; y += 0.5) {
    ToolpathPass pass;
    for (double x = 0; x <= 100 + 1e-9; x += 2) {
      ToolpathPoint p;
      p.position = {x, y, 0};  // a ball on the plane z = 0 touches under its tip
      pass.points.push_back(p);
    }
    path.passes.push_back(pass);
  }
  return path;
}

ZMap cut(const Part& part, const Cutter& cutter, const Toolpath& path) {
  ZMap zmap(part_xy_extent(part), 0.1);
  zmap.cut(cutter, moves_from_toolpath(path));
  return zmap;
}

}  // namespace

TEST_CASE("compensation loop: the machine error left after one compensated part is a fifth of it or less") {
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 0}, {100, 0, 0}, {0, 60, 0}));
  const Cutter ball("ball", 3, 3);
  const Toolpath path = raster();
  const ZMap nominal = cut(part, ball, path);
  const PathGeometry geometry = locate_path(part, ball, path);
  const double noise = 0.001;

  // The third machine leaves the bumps in proportion to the depth of cut
  // (deflection grows with engagement): 0.5 mm of stock on the first part,
  // and on the second the compensated path cuts deeper where it was moved
  // down, so its error grows by the share of the depth it added
  // (docs/compensation.md "Assumptions": one correction then leaves a
  // remainder of about m^2 / depth).
  struct Machine {
    double (*error)(double, double);
    bool grows_with_depth;
  };
  const double stock = 0.5;
  for (const Machine& machine_case : {Machine{bumps, false}, Machine{bumps_and_tilt, false}, Machine{bumps, true}}) {
    const auto machine = machine_case.error;
    CAPTURE(machine_case.grows_with_depth);
    // Part 1: measured.
    ComparisonDocument doc;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(5, 95), uy(5, 55);
    std::normal_distribution<double> gauss(0, noise);
    for (int i = 0; i < 300; ++i) {
      ComparisonDocument::Point p;
      p.id = "P" + std::to_string(i);
      p.face = "plate";
      const double x = ux(rng), y = uy(rng);
      p.uv = {x / 100, y / 60};
      p.evaluated = true;
      const double predicted = nominal.height_at(x, y);  // the path's own scallop
      p.deviation = predicted + machine(x, y) + gauss(rng);
      PointPrediction q;
      q.face_predicted = true;
      q.status = ErrorCellStatus::reached;
      q.compared = true;
      q.predicted = predicted;
      q.measured = p.deviation;
      q.residual = q.measured - q.predicted;
      p.prediction = q;
      doc.points.push_back(p);
    }
    doc.prediction = PredictionComparison{};
    const ComparisonErrorField fit = fit_error_field(doc, part, {}, "comparison.json");
    REQUIRE(fit.field.faces[0]->fitted());

    // Part 2: the compensated path on the same machine.
    const PathOffset offset = offset_path(part, single_tool(ball, path), geometry, fit.field);
    CHECK(offset.clipped.empty());
    Toolpath compensated = path;
    for (std::size_t p = 0; p < path.passes.size(); ++p)
      for (std::size_t k = 0; k < path.passes[p].points.size(); ++k)
        compensated.passes[p].points[k].position = offset.tips[p][k];
    const ZMap second = cut(part, ball, compensated);

    // The machine's share of the error, before and after, over the measured
    // area (away from its rim, where the fade begins).
    double before2 = 0, after2 = 0, worst_outside = 0;
    int inside = 0;
    for (double x = 10; x <= 90; x += 1)
      for (double y = 10; y <= 50; y += 1) {
        const double m = machine(x, y);
        const double moved = second.height_at(x, y) - nominal.height_at(x, y);
        const double m2 = machine_case.grows_with_depth ? m * (stock - moved) / stock : m;
        const double left = moved + m2;
        if (std::abs(m) > 0.005) {
          before2 += m * m, after2 += left * left, ++inside;
        } else {
          worst_outside = std::max(worst_outside, std::abs(left) - std::abs(m));
        }
      }
    REQUIRE(inside > 100);
    const double before = std::sqrt(before2 / inside), after = std::sqrt(after2 / inside);
    CAPTURE(before);
    CAPTURE(after);
    CHECK(after <= before / 5);
    // Where the machine left (almost) nothing, compensation makes no point
    // worse by more than the measurement noise.
    CHECK(worst_outside <= noise);
    MESSAGE("machine error inside the field: RMS " << 1000 * before << " um before, " << 1000 * after << " um after");
  }
}

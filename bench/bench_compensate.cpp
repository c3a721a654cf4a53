// Compensation of a large path (docs/compensation.md): a 200 x 100 mm plate,
// a 6 mm ball raster of about 100,000 moves (0.5 mm side step, 0.4 mm
// forward steps), 1,000 measured points with a planted machine error (two
// bumps, +80 um and -60 um) and 1 um noise. Prints the seconds of each step
// of the library's part of `compensate` - the field fit (thin-plate spline
// and GCV), locating the path's contacts, the offset, and the re-prediction
// of the compensated path by the z-map (0.05 mm), the expected residual at
// the measured points (COMP.json `expected`) - and the machine error's
// RMS inside the bumps before and after, and digests of the compensated
// tips and of the re-predicted z-map (heights and owners), bit for bit, so
// that a faster version can be shown to give the same results. The issue's
// target for the whole command: under 10 s on 2 cores. Prints figures; it
// does not pass or fail.
// Threads: OMP_NUM_THREADS (default all).
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

#include "bench_clock.hpp"
#include "geometry/primitives.hpp"
#include "inspection/comparison_error_field.hpp"
#include "inspection/compensation_expectation.hpp"
#include "machining/compensation/path_offset.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;
using furrow::bench::seconds_since;

namespace {

// FNV-1a over the bytes of doubles: a digest that changes with any bit of
// the results, so that a faster version can be checked to give the same
// ones (same digest before and after).
struct Digest {
  std::uint64_t h = 1469598103934665603ull;
  void add(double v) {
    unsigned char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    for (unsigned char c : b) h = (h ^ c) * 1099511628211ull;
  }
};

double machine(double x, double y) {
  auto bump = [](double dx, double dy, double r) { return std::exp(-(dx * dx + dy * dy) / (2 * r * r)); };
  return 0.08 * bump(x - 60, y - 50, 15) - 0.06 * bump(x - 140, y - 45, 12);
}

}  // namespace

int main() {
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 0}, {200, 0, 0}, {0, 100, 0}));
  const Cutter ball("ball", 3, 3);
  Toolpath path;
  for (double y = 0; y <= 100 + 1e-9; y += 0.5) {
    ToolpathPass pass;
    for (double x = 0; x <= 200 + 1e-9; x += 0.4) {
      ToolpathPoint p;
      p.position = {x, y, 0};
      pass.points.push_back(p);
    }
    path.passes.push_back(pass);
  }
  const std::vector<ZMapMove> moves = moves_from_toolpath(path);
  std::printf("plate 200 x 100 mm, ball 6 mm, %zu passes, %zu moves, %d threads\n", path.passes.size(), moves.size(),
              omp_get_max_threads());

  auto t0 = std::chrono::steady_clock::now();
  ZMap nominal(part_xy_extent(part), 0.05);
  nominal.cut(ball, moves);
  std::printf("  z-map of the path as planned: %.2f s (%zu nodes)\n", seconds_since(t0), nominal.node_count());

  ComparisonDocument doc;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> ux(5, 195), uy(5, 95);
  std::normal_distribution<double> noise(0, 0.001);
  for (int i = 0; i < 1000; ++i) {
    ComparisonDocument::Point p;
    p.id = "P" + std::to_string(i);
    p.face = "plate";
    const double x = ux(rng), y = uy(rng);
    p.uv = {x / 200, y / 100};
    p.foot = {x, y, 0};
    p.evaluated = true;
    PointPrediction q;
    q.face_predicted = true;
    q.status = ErrorCellStatus::reached;
    q.compared = true;
    q.predicted = nominal.height_at(x, y);
    q.measured = p.deviation = q.predicted + machine(x, y) + noise(rng);
    q.residual = q.measured - q.predicted;
    p.prediction = q;
    doc.points.push_back(p);
  }
  doc.prediction = PredictionComparison{};

  t0 = std::chrono::steady_clock::now();
  const ComparisonErrorField fit = fit_error_field(doc, part, {}, "bench");
  const double fitting = seconds_since(t0);
  const GcvResult& gcv = *fit.field.faces[0]->gcv();
  std::printf("  field fit, 1000 points: %.2f s (lambda %.3g, sigma %.2f um, %d Brent steps, %s)\n", fitting,
              gcv.lambda, 1000 * gcv.sigma, gcv.iterations, gcv.converged ? "converged" : "NOT converged");

  t0 = std::chrono::steady_clock::now();
  const PathGeometry geometry = locate_path(part, ball, path);
  const double locating = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const PathOffset offset = offset_path(part, single_tool(ball, path), geometry, fit.field);
  const double offsetting = seconds_since(t0);
  std::printf("  locating contacts: %.2f s; offset: %.2f s (%zu moved, %zu clipped, largest %.1f um)\n", locating,
              offsetting, offset.moved, offset.clipped.size(), 1000 * offset.largest_offset);

  t0 = std::chrono::steady_clock::now();
  const CompensationExpectation expected = expect_compensation(doc, fit.field, geometry, offset, ball.radius());
  const double expecting = seconds_since(t0);
  std::printf("  expected residual at the %zu points: %.2f s (RMS %.2f um measured, %.2f um expected after)\n",
              expected.overall.count, expecting, 1000 * expected.overall.rms_before, 1000 * expected.overall.rms_after);

  Toolpath compensated = path;
  for (std::size_t p = 0; p < path.passes.size(); ++p)
    for (std::size_t k = 0; k < path.passes[p].points.size(); ++k)
      compensated.passes[p].points[k].position = offset.tips[p][k];
  t0 = std::chrono::steady_clock::now();
  ZMap second(part_xy_extent(part), 0.05);
  second.cut(ball, moves_from_toolpath(compensated));
  const double repredicting = seconds_since(t0);
  std::printf("  re-prediction (z-map of the compensated path): %.2f s\n", repredicting);
  std::printf("  total without the nominal z-map: %.2f s\n", fitting + locating + offsetting + expecting + repredicting);
  Digest tips, heights;
  for (const auto& pass : offset.tips)
    for (const Eigen::Vector3d& t : pass) tips.add(t.x()), tips.add(t.y()), tips.add(t.z());
  for (int j = 0; j < second.ny(); ++j)
    for (int i = 0; i < second.nx(); ++i) heights.add(second.node_height(i, j)), heights.add(second.node_owner(i, j));
  std::printf("  digests: compensated tips %016llx, re-predicted z-map %016llx\n",
              static_cast<unsigned long long>(tips.h), static_cast<unsigned long long>(heights.h));

  double before2 = 0, after2 = 0;
  int inside = 0;
  for (double x = 10; x <= 190; x += 1)
    for (double y = 10; y <= 90; y += 1) {
      const double m = machine(x, y);
      if (std::abs(m) <= 0.005) continue;
      const double left = second.height_at(x, y) - nominal.height_at(x, y) + m;
      before2 += m * m, after2 += left * left, ++inside;
    }
  std::printf("  machine error inside the bumps (%d points): RMS %.2f um before, %.2f um after\n", inside,
              1000 * std::sqrt(before2 / inside), 1000 * std::sqrt(after2 / inside));
  std::printf("  peak memory: %.0f MB\n", furrow::bench::peak_rss_mb());
  return 0;
}

// What verification against a prediction adds to `furrow compare`: predicted
// vs measured with the prediction alignment, gouge confirmation, and writing
// and reading comparison.json, for 10 000 and 250 000 simulated points on
// the mould. Prints figures; it does not pass
// or fail.
//
// Data: a synthetic prediction of the mould (a smooth +-6 um error field on
// 100 x 80 cells of ~1 mm, 20 z-map gouge sites of 20 um, 400 local-gouge
// contact points in 20 clusters), measurements simulated from it on an even
// grid plan, probe 2 mm, misaligned, 2 um noise, 1 % blunders.
//
//   ./build/bench_verification
#include <chrono>
#include <cmath>
#include <cstdio>

#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/part_file.hpp"

using namespace furrow;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double dent(const Eigen::Vector2d& uv, const Eigen::Vector2d& c) {
  const double rho = (uv - c).norm() / 0.02;
  return rho < 1 ? -0.01 * (1 + std::cos(M_PI * rho)) : 0.0;
}

Eigen::Vector2d site_centre(int k) { return {0.1 + 0.2 * (k % 5), 0.15 + 0.23 * (k / 5)}; }

double field(const Eigen::Vector2d& uv) {
  double e = 0.006 * std::sin(2 * M_PI * uv.x()) * std::cos(M_PI * uv.y());
  for (int k = 0; k < 20; ++k) e += dent(uv, site_centre(k));
  return e;
}

Prediction synthetic_prediction(const Part& part) {
  Prediction p;
  p.part = "mould.json";
  p.toolpath = "bench.nc";
  p.tool = {"ball_d10", ToolType::ball, 10, 5};
  p.tolerance = p.gouge_threshold = 0.01;
  FaceGridRecord f;
  f.name = part.faces[0].name();
  f.domain = part.faces[0].domain();
  f.cells_u = 100;
  f.cells_v = 80;
  for (int j = 0; j < f.cells_v; ++j)
    for (int i = 0; i < f.cells_u; ++i) {
      const double m = field({(i + 0.5) / f.cells_u, (j + 0.5) / f.cells_v});
      f.status.push_back(ErrorCellStatus::reached);
      f.mean.push_back(m);
      f.max_undercut.push_back(m + 0.001);
      f.max_overcut.push_back(m - 0.001);
    }
  p.faces.push_back(f);
  for (int k = 0; k < 20; ++k) {
    GougeSiteRecord s;
    s.id = k + 1;
    s.face = f.name;
    s.depth = 0.02;
    s.deepest = {f.name, site_centre(k), part.faces[0].surface().point(site_centre(k).x(), site_centre(k).y())};
    s.centroid = s.deepest;
    s.uv_box = Eigen::AlignedBox2d(site_centre(k) - Eigen::Vector2d(0.015, 0.015),
                                   site_centre(k) + Eigen::Vector2d(0.015, 0.015));
    p.gouge_sites.push_back(s);
    for (int c = 0; c < 20; ++c) {
      LocalGougeRecord g;
      g.point = k * 20 + c;
      const Eigen::Vector2d uv = site_centre(k) + Eigen::Vector2d(0.001 * c, 0.0005 * c);
      g.at = {f.name, uv, part.faces[0].surface().point(uv.x(), uv.y())};
      g.status = "gouge";
      p.local_gouges.push_back(g);
    }
  }
  return p;
}

void run(const ClosestPointFinder& finder, const Prediction& prediction, int nu, int nv) {
  const InspectionPlan plan = grid_plan(finder.part(), nu, nv, {"ball 2 mm", 2});
  SimulationOptions sim;
  sim.misalignment = {{2, -3, 40}, {20, -12, 15}};
  sim.blunders = static_cast<int>(plan.points.size() / 100);
  sim.surface_offset = predicted_surface_offsets(plan, prediction).lookup(plan);
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  CompareOptions o;
  o.registration.loss_scale = o.registration.outlier_floor = 0.025;

  auto t0 = Clock::now();
  Comparison c = compare_measurements(finder, m.set, &plan, o);
  const double registration = seconds_since(t0);
  t0 = Clock::now();
  verify_prediction(c, finder.part(), m.set.probe_radius, prediction, o);
  const double verification = seconds_since(t0);
  t0 = Clock::now();
  const std::string text = comparison_to_json_text(c, m.set, finder.part(), o,
                                                   {"mould.json", "m.csv", "plan.json", "", "prediction.json", "mm"});
  const double write = seconds_since(t0);
  t0 = Clock::now();
  const ComparisonDocument d = parse_comparison(text, "comparison.json");
  const double read = seconds_since(t0);
  std::size_t confirmed = 0;
  for (const GougeSiteCheck& s : c.gouges->sites) confirmed += s.status == GougeSiteStatus::confirmed;
  std::printf(
      "%7zu points  registration %6.2f s  verification %5.2f s (alignment %d Ceres iterations)  "
      "write %5.2f s  read %5.2f s (%.1f MB)  verdict %s, %zu of %zu sites confirmed, %zu unexplained\n",
      plan.points.size(), registration, verification, c.prediction->alignment.iterations, write, read,
      text.size() / 1e6, to_string(c.prediction->overall.verdict), confirmed, c.gouges->sites.size(),
      d.gouges->unexplained.size());
}

}  // namespace

int main() {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const ClosestPointFinder finder(part);
  const Prediction prediction = synthetic_prediction(part);
  run(finder, prediction, 125, 80);   // 10 000
  run(finder, prediction, 625, 400);  // 250 000
  return 0;
}

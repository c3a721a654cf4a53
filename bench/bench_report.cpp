// Report generation for large point sets: the figures (each drawn once,
// SVG and/or PNG), the 3D view (data + inlined three.js) and the whole
// folder rendered in memory, for 10 000 and 100 000 simulated points on the
// mould with a prediction; prints wall and CPU seconds per file (median of
// 3 runs; "whole report" is make_report itself: every figure and the four
// files, on two threads where they are independent; the breakdown times
// each piece alone on one), the time to write the folder, sizes and the
// peak resident memory of the process.
// Target (docs/report.md): under 3 s for 100 000 points, the 3D view
// still interactive (instanced spheres: one draw call). Prints figures; it
// does not pass or fail.
//
// Data: a smooth +-8 um predicted error field with two 40 um dents on
// 100 x 80 cells, measurements simulated from it on an even grid plan (probe
// 2 mm, misaligned, 2 um noise), registered and written to comparison.json
// and read back as `furrow report` does (that set-up is not timed).
//
//   ./build/bench_report            both sizes
//   ./build/bench_report 100000     one size (points, rounded to the grid)
//   ./build/bench_report 100000 DIR also writes that report folder as DIR
//                                   (replaced; to open report.html, e.g. to
//                                   time the 3D view, or to compare the files)
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/part_file.hpp"
#include "report/part_view_3d.hpp"
#include "base/atomic_file.hpp"
#include "report/points_csv.hpp"
#include "report/qa_report.hpp"
#include "report/report_html.hpp"
#include "report/report_json.hpp"
#include "report/report_qif.hpp"
#include "report/verdict.hpp"

using namespace furrow;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// CPU seconds of the process: on a machine shared with other builds the
// wall time says more about the others than about the report.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double field(const Eigen::Vector2d& uv) {
  double e = 0.008 * std::sin(2 * M_PI * uv.x()) * std::cos(M_PI * uv.y());
  for (const Eigen::Vector2d& c : {Eigen::Vector2d(0.3, 0.4), Eigen::Vector2d(0.7, 0.6)}) {
    const double rho = (uv - c).norm() / 0.05;
    if (rho < 1) e -= 0.02 * (1 + std::cos(M_PI * rho));
  }
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
  return p;
}

void run(const ClosestPointFinder& finder, const Prediction& prediction, int nu, int nv,
         const std::string& html_folder = "") {
  const Part& part = finder.part();
  const InspectionPlan plan = grid_plan(part, nu, nv, {"ball 2 mm", 2});
  SimulationOptions sim;
  sim.misalignment = {{2, -3, 40}, {20, -12, 15}};
  sim.surface_offset = predicted_surface_offsets(plan, prediction).lookup(plan);
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  CompareOptions o;
  o.tolerance = ToleranceZone::make(0.05, 0.025, "bench");
  o.registration.loss_scale = o.registration.outlier_floor = 0.025;
  Comparison c = compare_measurements(finder, m.set, &plan, o);
  verify_prediction(c, part, m.set.probe_radius, prediction, o);
  const ComparisonDocument doc = parse_comparison(
      comparison_to_json_text(c, m.set, part, o, {"mould.json", "m.csv", "plan.json", "", "prediction.json", "mm"}),
      "comparison.json");

  ReportContext context;
  context.title = "bench";
  context.generated = "2024-01-01T00:00:00Z";
  // Each stage three times, the median printed, wall and CPU seconds: the
  // machine is shared.
  constexpr int kRuns = 3;
  enum Stage { figures2d_stage, view_stage, all_figures, html_file, json_file, csv_file, qif_file, writing, kStages };
  const char* names[kStages] = {"2D figures", "3D view", "every figure", "report.html",
                                "report.json", "points.csv", "results.qif", "writing the folder"};
  std::vector<double> wall[kStages], cpu[kStages], wall_total, cpu_total;
  std::vector<ReportFigure> figures2d;
  std::vector<FolderFile> files;
  std::size_t view_bytes = 0;
  const std::string scratch = html_folder.empty() ? std::filesystem::temp_directory_path().string() +
                                                        "/bench_report_" + std::to_string(::getpid())
                                                  : html_folder;
  for (int run = 0; run < kRuns; ++run) {
    auto timed = [&](Stage stage, auto&& work) {
      const auto t0 = Clock::now();
      const double c0 = cpu_seconds();
      work();
      wall[stage].push_back(seconds_since(t0));
      cpu[stage].push_back(cpu_seconds() - c0);
    };
    timed(figures2d_stage, [&] { figures2d = make_report_figures(doc, part, nullptr, &prediction, nullptr, false); });
    timed(view_stage, [&] { view_bytes = part_view_3d_figure(doc, part, &prediction).html.size(); });
    // The whole report as `furrow report` renders it (make_report: the 3D
    // view beside the 2D figures, then the files two at a time), then each
    // piece again on its own for the breakdown.
    const auto start = Clock::now();
    const double cpu_start = cpu_seconds();
    files = make_report(doc, part, nullptr, context, &prediction);
    wall_total.push_back(seconds_since(start));
    cpu_total.push_back(cpu_seconds() - cpu_start);
    std::vector<ReportFigure> figures;
    timed(all_figures, [&] { figures = make_report_figures(doc, part, nullptr, &prediction); });
    const ReportVerdict verdict = report_verdict(doc);
    timed(html_file, [&] { (void)report_html(doc, verdict, nullptr, context, figures); });
    timed(json_file, [&] { (void)report_json_text(doc, verdict, nullptr, context, figures); });
    timed(csv_file, [&] { (void)points_csv_text(doc); });
    timed(qif_file, [&] { (void)comparison_to_qif(doc, context.inputs, context.generated, context.record); });
    timed(writing, [&] {
      write_folder_atomically(scratch, [&](const std::string& staging) { write_folder_files(staging, files); });
    });
  }
  if (html_folder.empty()) std::filesystem::remove_all(scratch);
  std::size_t html = 0, svg = 0, folder = 0;
  for (const FolderFile& f : files) {
    folder += f.bytes.size();
    if (f.path == "report.html") html = f.bytes.size();
    if (f.path.size() > 4 && f.path.compare(f.path.size() - 4, 4, ".svg") == 0) svg += f.bytes.size();
  }
  std::size_t vector_figures = 0;
  for (const ReportFigure& f : figures2d) vector_figures += !f.svg.empty();
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("%7zu points  whole report %5.2f s wall, %5.2f s CPU (median of %d)  peak RSS %.0f MB\n",
              doc.points.size(), median(wall_total), median(cpu_total), kRuns, usage.ru_maxrss / 1024.0);
  for (int k = 0; k < kStages; ++k)
    std::printf("         %-20s %5.2f s wall %5.2f s CPU\n", names[k], median(wall[k]), median(cpu[k]));
  std::printf("         report.html %5.1f MB (3D section %4.1f MB)  folder %5.1f MB  %zu of %zu 2D figures vector "
              "(%.1f MB SVG)\n",
              html / 1e6, view_bytes / 1e6, folder / 1e6, vector_figures, figures2d.size(), svg / 1e6);
  std::string sizes;
  for (const FolderFile& f : files)
    if (f.bytes.size() > 5000000) sizes += "  " + f.path + " " + std::to_string(f.bytes.size() / 1000000) + " MB";
  std::printf("         files over 5 MB:%s\n", sizes.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const ClosestPointFinder finder(part);
  const Prediction prediction = synthetic_prediction(part);
  if (argc > 1) {  // an even grid of about that many points, 5:4 like the mould
    const double n = std::max(20.0, std::atof(argv[1]));
    run(finder, prediction, static_cast<int>(std::lround(std::sqrt(n * 1.25))),
        static_cast<int>(std::lround(std::sqrt(n / 1.25))), argc > 2 ? argv[2] : "");
    return 0;
  }
  run(finder, prediction, 125, 80);   // 10 000
  run(finder, prediction, 400, 250);  // 100 000
  return 0;
}

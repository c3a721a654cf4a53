#pragma once
// What the QA report of a scan shows, recorded when the scan is compared
// (docs/scan.md "In the report"), because the report must not need the raw
// scan (a million points, hundreds of MB, perhaps not archived with the
// comparison):
//
//  - the display sample: the evaluated points decimated to what a browser
//    holds, at most `cap` (kScanDisplayCap) real points of the cloud in the
//    part frame with their deviation. How they are chosen: a cubic voxel
//    grid over the evaluated points (aligned with their bounding box's
//    lowest corner), grown from a small edge until at most `cap` voxels are
//    occupied; each occupied voxel keeps its point with the largest
//    |deviation| (ties: the earlier point), so a dent or a peak narrower
//    than a voxel still shows its worst reading. When every evaluated point
//    fits under the cap all are kept (voxel 0). Points in the deviation
//    cloud's order.
//  - the histogram of the deviations of EVERY evaluated point: kScanHistogramBins
//    equal bins over the deviations and the tolerance zone's limits, padded by
//    5 % of that span; bin k counts the deviations d with
//    edges[k] <= d < edges[k + 1] (the last bin closed at its top). d is the
//    deviation as the deviation cloud stores it (a float), so the counts
//    can be recounted from that file.
//
// Units mm; frame: the part's. Deterministic (no threads, index order).
#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace furrow {

struct ScanComparison;
struct ScanCloud;

// A browser draws 50 000 point sprites interactively even in software
// WebGL (docs/report.md "Speed": 100 000 took 246 ms a frame), and the
// sample costs about 2.5 MB of comparison.json and of report.html.
inline constexpr std::size_t kScanDisplayCap = 50'000;
inline constexpr int kScanHistogramBins = 50;

struct ScanDisplay {
  std::size_t cap = kScanDisplayCap;
  double voxel = 0;                     // [mm] edge of the grid that chose the sample; 0: every evaluated point
  std::size_t grid_passes = 0;          // grids tried (each larger than the last)
  std::vector<std::size_t> index;       // vertex index in the deviation cloud (finite points in file order)
  std::vector<Eigen::Vector3d> points;  // part frame [mm], rounded to 0.1 um as written
  std::vector<float> deviation;         // [mm], as the deviation cloud stores it
};

struct ScanHistogram {
  std::vector<double> edges;         // kScanHistogramBins + 1, increasing [mm]
  std::vector<std::size_t> counts;   // per bin; they sum to the evaluated points
};

// Both from a finished comparison and the cloud it compared (the points'
// coordinates are those of the deviation cloud: transform * (p - origin)).
// Preconditions: c's per-point vectors have one entry per cloud point;
// cap >= 1. The grid grows at most 200 times (each at least by 5 %, which
// is plenty: the first grid is sized from the cloud's extent and the cap).
ScanDisplay scan_display(const ScanComparison& c, const ScanCloud& cloud, std::size_t cap = kScanDisplayCap);
ScanHistogram scan_histogram(const ScanComparison& c, int bins = kScanHistogramBins);

// Their JSON (comparison.json "display" and "histogram") is in
// scan_display_json.hpp.

}  // namespace furrow

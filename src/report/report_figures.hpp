#pragma once
// The figures of a QA report, drawn from a comparison document and the part
// (and its partition when the comparison has one), each described once
// (render/drawing.hpp) and rendered by two back ends: SVG, inline in the
// HTML and written as figures/NAME.svg, and PNG, written as figures/NAME.png.
// Raster only (no SVG) where vector graphics would be too heavy for a page:
// the region map (a painted image) and deviation maps of more than
// kVectorPointLimit points.
//
//   figures/region_map.png          the partition from above (with regions)
//   figures/deviation_top.png       deviations at the foot points, top view
//   figures/deviation_uv_<k>.png    the same on face k's (u, v) domain
//   figures/histogram.png           histogram of the evaluated deviations
//   figures/predicted_vs_measured.png  scatter with 1-sigma bars (with a prediction)
//   figures/gouge_sites.png         predicted sites by status and unexplained
//                                   overcuts, top view (with a prediction)
//   figures/compensation_before.png the measured deviations, top view, and
//   figures/compensation_after.png  the residual a compensated program is
//                                   expected to leave there (with a
//                                   compensation record), on one colour scale
// Deviation colours: colour_scale.hpp, bar in um with the zone's limits.
// Points not evaluated (blunders, beyond an edge) are grey with a ring;
// points out of tolerance get a black ring. Deterministic bytes.
#include <functional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/compensation_record.hpp"
#include "machining/prediction/prediction.hpp"
#include "partition/region_map.hpp"

namespace furrow {

struct ReportFigure {
  std::string file;     // relative to the report folder, e.g. "figures/histogram.png"
  std::string section;  // "regions", "deviations", "prediction", "gouges", "compensation"
  std::string title;
  std::string caption;
  std::vector<unsigned char> png;  // always: the raster back end
  std::string svg;                 // the vector back end; empty for a raster-only figure
  std::string html;                // an interactive section placed instead (the 3D view), may be empty
  // figures/NAME.svg for `file` figures/NAME.png.
  std::string svg_file() const { return file.substr(0, file.size() - 4) + ".svg"; }
};

// Maps of more points than this are raster only in the page.
constexpr std::size_t kVectorPointLimit = 5000;

// Figures that share nothing but the inputs they read, drawn at once, one
// per thread: at 100,000 points the figures are most of a report's time
// (docs/report.md, "Speed"). Each lands in its own slot, so the order and
// the bytes do not depend on the timing; an exception in a job is carried
// out of the parallel region and rethrown here.
std::vector<ReportFigure> draw_figures(const std::vector<std::function<ReportFigure()>>& jobs);

// `regions`, `prediction` and `compensation` may be null. Preconditions:
// doc's faces are faces of `part` (the report checks the face names first);
// the compensation record is of `doc` (check_record_against). With
// `interactive`, the last figure of the deviations is the 3D view
// (part_view_3d.hpp; section "view3d"), which needs three.js installed.
// figures/gouge_sites.png: the predicted sites of doc.gouges by status and
// its unexplained overcuts, top view, over `background` (x, y of the
// measured points; a scan's display sample), which `background_text` names
// in the caption. Shared by the probe-point and the scan report.
ReportFigure gouge_sites_figure(const ComparisonDocument& doc, const Part& part,
                                const std::vector<Eigen::Vector2d>& background, const std::string& background_text);

std::vector<ReportFigure> make_report_figures(const ComparisonDocument& doc, const Part& part,
                                              const RegionMap* regions, const Prediction* prediction = nullptr,
                                              const CompensationRecord* compensation = nullptr,
                                              bool interactive = true);

}  // namespace furrow

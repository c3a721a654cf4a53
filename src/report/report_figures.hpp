#pragma once
// The figures of a QA report, drawn from a comparison document and the part
// (and its partition when the comparison has one): PNG bytes with a file
// name inside the report folder, a title and a caption for the HTML.
//
//   figures/region_map.png          the partition from above (with regions)
//   figures/deviation_top.png       deviations at the foot points, top view
//   figures/deviation_uv_<k>.png    the same on face k's (u, v) domain
//   figures/histogram.png           histogram of the evaluated deviations
//   figures/predicted_vs_measured.png  scatter with 1-sigma bars (with a prediction)
//   figures/gouge_sites.png         predicted sites by status and unexplained
//                                   overcuts, top view (with a prediction)
// Deviation colours: colour_scale.hpp, bar in um with the zone's limits.
// Points not evaluated (blunders, beyond an edge) are grey with a ring;
// points out of tolerance get a black ring. Deterministic bytes.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "partition/region_map.hpp"

namespace furrow {

struct ReportFigure {
  std::string file;     // relative to the report folder, e.g. "figures/histogram.png"
  std::string section;  // "regions", "deviations", "prediction", "gouges"
  std::string title;
  std::string caption;
  std::vector<unsigned char> png;
};

// `regions` may be null. Precondition: doc's faces are faces of `part` (the
// report checks the face names first).
std::vector<ReportFigure> make_report_figures(const ComparisonDocument& doc, const Part& part,
                                              const RegionMap* regions);

}  // namespace furrow

#pragma once
// Per-face summary of a comparison (docs/report.md "Faces"): the report of
// an imported part with a hundred faces must say at a glance which faces are
// bad, so the faces that carry measured points are listed worst first:
// by the largest out-of-tolerance amount (point_table.hpp), then by the
// largest |deviation|, then by face index (a stable, deterministic order).
// Faces whose points were all set aside (not evaluated) come last.
//
// Only evaluated points enter the statistics (an outlier measures dust, not
// the face); `points` counts every point whose foot lies on the face.
// Lengths in mm, deviation sign as everywhere (+ material left).
#include <optional>
#include <string>
#include <vector>

#include "geometry/analytic_surface.hpp"
#include "inspection/comparison_document.hpp"

namespace furrow {

struct FaceDeviationSummary {
  int face_index = -1;
  std::string face;
  std::size_t points = 0, evaluated = 0, out_of_tolerance = 0;
  // Over the evaluated points; unset when there are none.
  std::optional<double> min_deviation, max_deviation, mean_deviation;
  double max_abs_deviation = 0;
  double worst_excess = 0;  // largest out-of-tolerance amount (0: all inside)
  std::string worst_point;  // id of the point with the largest |deviation|
};

// Worst first (see above); one entry per face that has at least one point.
std::vector<FaceDeviationSummary> face_summaries(const ComparisonDocument& doc);

// <section id="faces"> with the table; the rows of faces with points out of
// tolerance are red. `surfaces` (indexed like the part's faces, may be
// empty) gives each face's elementary surface for the "Surface" column.
std::string face_summary_html(const ComparisonDocument& doc,
                              const std::vector<std::optional<AnalyticSurface>>& surfaces = {});

}  // namespace furrow

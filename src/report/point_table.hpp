#pragma once
// The point table as metrologists read it (docs/report.md "Point table"):
// per measured point, in measurement order, the nominal (the CAD foot point
// and its outward normal), the actual (the probe-compensated contact point
// in the part frame, after registration), the signed deviation, the profile
// zone's limits, how far the deviation lies beyond the nearer limit and the
// status. points.csv and the HTML table are both written from these rows,
// so the two cannot disagree.
//
// Frames and signs (docs/architecture.md "Conventions"): everything in the
// part frame, mm; deviation = normal . (actual - nominal), + material left,
// - material removed. The actual is comparison.json's `contact`
// (registered centre - r_probe normal), for which that identity holds.
//
// Status: "IN" (evaluated, within the zone, limits included), "OUT"
// (evaluated, outside), "NOT EVALUATED" (an outlier the comparison set
// aside: a blunder, a point beyond a face edge, no foot point - its
// deviation is shown but judged by nothing). The out-of-tolerance amount is
// 0 inside the zone, d - upper above it, lower - d below it (always >= 0),
// and absent for a point not evaluated.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"

namespace furrow {

struct PointTableRow {
  std::size_t index = 0;  // into doc.points (measurement order)
  std::string id, face;
  Eigen::Vector3d nominal = Eigen::Vector3d::Zero();  // foot point [mm], part frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, out of the material
  Eigen::Vector3d actual = Eigen::Vector3d::Zero();   // measured contact point [mm], part frame
  double deviation = 0;                               // [mm]
  double lower = 0, upper = 0;                        // zone limits [mm]
  std::optional<double> out_of_tolerance;             // [mm], >= 0; none when not evaluated
  std::string status;                                 // IN, OUT, NOT EVALUATED
  std::string outlier;                                // the comparison's outlier reason, may be empty
};

// How far `deviation` lies beyond the nearer limit of `zone` (0 inside).
double out_of_tolerance_amount(double deviation, const ToleranceZone& zone);

std::vector<PointTableRow> point_table(const ComparisonDocument& doc);
// Row `i` of that table alone (i < doc.points.size()), for a writer that
// goes through the points once without holding every row.
PointTableRow point_table_row(const ComparisonDocument& doc, std::size_t i);

}  // namespace furrow

#include "report/point_table.hpp"

#include <algorithm>

namespace furrow {

double out_of_tolerance_amount(double deviation, const ToleranceZone& zone) {
  return std::max({0.0, deviation - zone.upper(), zone.lower() - deviation});
}

PointTableRow point_table_row(const ComparisonDocument& doc, std::size_t i) {
  const ToleranceZone& zone = doc.options.tolerance;
  const ComparisonDocument::Point& p = doc.points[i];
  PointTableRow r;
  r.index = i;
  r.id = p.id;
  r.face = p.face;
  r.nominal = p.foot;
  r.normal = p.normal;
  r.actual = p.contact;
  r.deviation = p.deviation;
  r.lower = zone.lower();
  r.upper = zone.upper();
  r.outlier = p.outlier;
  if (p.evaluated) {
    r.out_of_tolerance = out_of_tolerance_amount(p.deviation, zone);
    // The comparison's own judgement decides; the amount only measures it.
    r.status = p.in_tolerance.value_or(zone.contains(p.deviation)) ? "IN" : "OUT";
  } else {
    r.status = "NOT EVALUATED";
  }
  return r;
}

std::vector<PointTableRow> point_table(const ComparisonDocument& doc) {
  std::vector<PointTableRow> rows;
  rows.reserve(doc.points.size());
  for (std::size_t i = 0; i < doc.points.size(); ++i) rows.push_back(point_table_row(doc, i));
  return rows;
}

}  // namespace furrow

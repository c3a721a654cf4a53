#include "report/points_csv.hpp"

#include <charconv>
#include <sstream>
#include <stdexcept>

#include "report/point_table.hpp"

namespace furrow {

namespace {

std::string number(double v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc()) throw std::logic_error("points.csv: number not representable");
  return std::string(buf, ptr);
}

std::string text(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

const char* flag(bool b) { return b ? "true" : "false"; }

}  // namespace

std::string points_csv_text(const ComparisonDocument& doc) {
  std::ostringstream out;
  out << "id,face,u,v,foot_x,foot_y,foot_z,normal_i,normal_j,normal_k,measured_x,measured_y,measured_z,"
         "deviation,uncertainty,evaluated,in_tolerance,in_fit,outlier,region,predicted,measured_aligned,"
         "residual,sigma_total,actual_x,actual_y,actual_z,lower_tolerance,upper_tolerance,out_of_tolerance,status\n";
  const std::vector<PointTableRow> table = point_table(doc);
  for (const PointTableRow& row : table) {
    const auto& p = doc.points[row.index];
    out << text(p.id) << ',' << text(p.face) << ',' << number(p.uv.x()) << ',' << number(p.uv.y());
    for (const Eigen::Vector3d* v : {&p.foot, &p.normal, &p.measured})
      out << ',' << number(v->x()) << ',' << number(v->y()) << ',' << number(v->z());
    out << ',' << number(p.deviation) << ',' << (p.uncertainty ? number(*p.uncertainty) : "");
    out << ',' << flag(p.evaluated) << ',' << (p.in_tolerance ? flag(*p.in_tolerance) : "") << ','
        << flag(p.in_fit) << ',' << text(p.outlier) << ',' << (p.region ? std::to_string(*p.region) : "");
    if (p.prediction && p.prediction->reached())
      out << ',' << number(p.prediction->predicted) << ',' << number(p.prediction->measured) << ','
          << number(p.prediction->residual) << ',' << number(p.prediction->sigma);
    else
      out << ",,,,";
    // The metrologist's columns (point_table.hpp): nominal and normal are
    // foot_* and normal_* above.
    out << ',' << number(row.actual.x()) << ',' << number(row.actual.y()) << ',' << number(row.actual.z()) << ','
        << number(row.lower) << ',' << number(row.upper) << ','
        << (row.out_of_tolerance ? number(*row.out_of_tolerance) : "") << ',' << text(row.status);
    out << '\n';
  }
  return out.str();
}

}  // namespace furrow

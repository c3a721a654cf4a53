#include "report/points_csv.hpp"

#include <charconv>
#include <sstream>
#include <stdexcept>

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
         "residual,sigma_total\n";
  for (const auto& p : doc.points) {
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
    out << '\n';
  }
  return out.str();
}

}  // namespace furrow

#include "report/points_csv.hpp"

#include <charconv>
#include <stdexcept>

#include "report/point_table.hpp"

namespace furrow {

namespace {

// Appended straight to the file's text: no stream, no string per cell
// (100 000 points are 31 cells each), no locale.
void number(std::string& out, double v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc()) throw std::logic_error("points.csv: number not representable");
  out.append(buf, ptr);
}

void cell(std::string& out, double v) {
  out += ',';
  number(out, v);
}

void cell(std::string& out, const std::optional<double>& v) {
  out += ',';
  if (v) number(out, *v);
}

void text(std::string& out, const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) {
    out += s;
    return;
  }
  out += '"';
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

void text_cell(std::string& out, const std::string& s) {
  out += ',';
  text(out, s);
}

void flag(std::string& out, bool b) { out += b ? ",true" : ",false"; }

}  // namespace

std::string points_csv_text(const ComparisonDocument& doc) {
  std::string out =
      "id,face,u,v,foot_x,foot_y,foot_z,normal_i,normal_j,normal_k,measured_x,measured_y,measured_z,"
      "deviation,uncertainty,evaluated,in_tolerance,in_fit,outlier,region,predicted,measured_aligned,"
      "residual,sigma_total,actual_x,actual_y,actual_z,lower_tolerance,upper_tolerance,out_of_tolerance,status\n";
  out.reserve(out.size() + 480 * doc.points.size());
  for (std::size_t i = 0; i < doc.points.size(); ++i) {
    const PointTableRow row = point_table_row(doc, i);
    const auto& p = doc.points[i];
    text(out, p.id);
    text_cell(out, p.face);
    cell(out, p.uv.x());
    cell(out, p.uv.y());
    for (const Eigen::Vector3d* v : {&p.foot, &p.normal, &p.measured}) {
      cell(out, v->x());
      cell(out, v->y());
      cell(out, v->z());
    }
    cell(out, p.deviation);
    cell(out, p.uncertainty);
    flag(out, p.evaluated);
    if (p.in_tolerance)
      flag(out, *p.in_tolerance);
    else
      out += ',';
    flag(out, p.in_fit);
    text_cell(out, p.outlier);
    out += ',';
    if (p.region) {
      char buf[16];
      out.append(buf, std::to_chars(buf, buf + sizeof buf, *p.region).ptr);
    }
    if (p.prediction && p.prediction->reached()) {
      cell(out, p.prediction->predicted);
      cell(out, p.prediction->measured);
      cell(out, p.prediction->residual);
      cell(out, p.prediction->sigma);
    } else {
      out += ",,,,";
    }
    // The metrologist's columns (point_table.hpp): nominal and normal are
    // foot_* and normal_* above.
    cell(out, row.actual.x());
    cell(out, row.actual.y());
    cell(out, row.actual.z());
    cell(out, row.lower);
    cell(out, row.upper);
    cell(out, row.out_of_tolerance);
    text_cell(out, row.status);
    out += '\n';
  }
  return out;
}

}  // namespace furrow

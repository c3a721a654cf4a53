#include "io/cmm/measurement_xyz.hpp"

#include <vector>

#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace mf = measurement_fields;

void parse_measurements_xyz(std::string_view text, const std::string& name, double scale, MeasurementSet& set) {
  std::size_t columns = 0;
  int first_line = 0;
  std::vector<std::string_view> fields;
  mf::for_each_line(text, [&](int number, std::string_view line) {
    const std::string_view t = mf::trimmed(line);
    if (t.empty() || t[0] == '#') return;
    fields.clear();
    for (std::size_t p = 0; p < t.size();) {
      while (p < t.size() && (t[p] == ' ' || t[p] == '\t')) ++p;
      std::size_t q = p;
      while (q < t.size() && t[q] != ' ' && t[q] != '\t') ++q;
      if (q > p) fields.push_back(t.substr(p, q - p));
      p = q;
    }
    if (columns == 0) {
      if (fields.size() != 3 && fields.size() != 6)
        mf::fail(name, number,
                 "expected \"x y z\" or \"x y z i j k\", got " + std::to_string(fields.size()) + " fields");
      columns = fields.size();
      first_line = number;
    } else if (fields.size() != columns) {
      mf::fail(name, number,
               "expected " + std::to_string(columns) + " fields like line " + std::to_string(first_line) +
                   ", got " + std::to_string(fields.size()));
    }
    double v[6];
    for (std::size_t c = 0; c < columns; ++c)
      v[c] = mf::number(fields[c], name, number, "field " + std::to_string(c + 1));
    MeasuredPoint p;
    p.line = number;
    p.id = std::to_string(set.points.size() + 1);
    p.xyz = scale * Eigen::Vector3d(v[0], v[1], v[2]);
    if (columns == 6) p.ijk = mf::unit_direction({v[3], v[4], v[5]}, name, number, "i, j, k");
    mf::add_point(set, std::move(p), name);
  });
  set.ids_from_file = false;
}

}  // namespace furrow

#include "machining/gouge/site_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace furrow::site_json {

namespace jf = json_fields;

json rounded(double value, double quantum, const char* what) {
  jf::finite(value, what);
  // Through decimal text, so that the written number is the short decimal
  // (x / q * q in binary would print as 27.586206999999998).
  const int decimals = std::max(0, static_cast<int>(std::lround(-std::log10(quantum))));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return std::strtod(buf, nullptr) + 0.0;  // + 0.0: never "-0"
}

json rounded(const Eigen::Vector3d& v, double quantum, const char* what) {
  return json::array({rounded(v.x(), quantum, what), rounded(v.y(), quantum, what),
                      rounded(v.z(), quantum, what)});
}

json site(const Part& part, const ContactSite& s, const Eigen::Vector3d& point,
          const Eigen::Vector3d& normal, double k1, double k2) {
  json j;
  j["face"] = part.faces[s.face].name();
  j["uv"] = json::array({rounded(s.uv.x(), 1e-12, "u"), rounded(s.uv.y(), 1e-12, "v")});
  if (s.grid_i >= 0) j["grid"] = json::array({s.grid_i, s.grid_j});
  if (s.line > 0) j["line"] = s.line;
  if (!s.id.empty()) j["id"] = s.id;
  j["position"] = rounded(point, kLengthQuantum, "position");
  j["normal"] = rounded(normal, kUnitQuantum, "normal");
  j["k1"] = rounded(k1, kCurvatureQuantum, "k1");
  j["k2"] = rounded(k2, kCurvatureQuantum, "k2");
  return j;
}

json sites_source(int grid, const std::string& points_file, std::size_t count) {
  json j;
  if (points_file.empty()) {
    j["mode"] = "grid";
    j["grid"] = grid;
  } else {
    j["mode"] = "points";
    j["file"] = points_file;
  }
  j["count"] = count;
  return j;
}

}  // namespace furrow::site_json

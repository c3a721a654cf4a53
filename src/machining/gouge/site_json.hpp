#pragma once
// JSON pieces shared by the gouge and tool-selection reports: a contact
// site's fields and rounding for readable, deterministic numbers.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <Eigen/Core>
#include <string>

#include "geometry/part.hpp"
#include "base/json_fields.hpp"
#include "machining/gouge/contact_sites.hpp"

namespace furrow::site_json {

using json_fields::json;

// Rounds to the decimals of `quantum` (a power of ten): outputs carry no
// false digits; the library keeps full precision. Non-finite values are a
// bug (logic_error).
json rounded(double value, double quantum, const char* what);
json rounded(const Eigen::Vector3d& v, double quantum, const char* what);

// Output quanta.
constexpr double kLengthQuantum = 1e-6;     // mm (1 nm)
constexpr double kUnitQuantum = 1e-9;       // normals, directions
constexpr double kCurvatureQuantum = 1e-9;  // 1/mm
constexpr double kAngleQuantum = 1e-4;      // degrees

// face, uv, grid [i, j] or line (and id), position, normal, k1, k2.
json site(const Part& part, const ContactSite& site, const Eigen::Vector3d& point,
          const Eigen::Vector3d& normal, double k1, double k2);

// "grid" or "points" description of where the sites came from.
json sites_source(int grid, const std::string& points_file, std::size_t count);

}  // namespace furrow::site_json

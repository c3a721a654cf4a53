#pragma once
// A reference point system (RPS): the alignment of sheet-metal and
// cast parts by named points, each of which fixes the part along the axes
// the drawing declares for it (docs/registration.md "RPS alignment"). A
// classic 3-2-1 RPS has three points fixing z, two fixing y and one fixing
// x; points fixing more axes, or more points than six constraints with
// weights, are common too.
//
// The file (docs/formats.md "RPS file"), read with every field checked:
//   {"format": "furrow-rps", "version": 1,
//    "points": [{"id": "RPS1", "nominal": [x, y, z], "normal": [i, j, k],
//                "directions": "z", "weight": 1}, ...]}
// `nominal` is the point on the part (part frame, mm), `normal` the
// outward surface normal there (probe compensation of centre points; made
// unit), `directions` the part axes the point fixes ("x", "yz", "xyz", each
// once), `weight` (optional, > 0, default 1) its share in an over-determined
// system. The measured points are matched by id. Errors name the file and
// the field (InputError, exit 2).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace furrow {

struct ReferencePoint {
  std::string id;
  Eigen::Vector3d nominal = Eigen::Vector3d::Zero();  // part frame [mm]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, outward
  std::string directions;                             // "x", "yz", ... in x, y, z order
  double weight = 1;
};

struct ReferencePointSystem {
  std::string source;  // the file, for messages
  std::vector<ReferencePoint> points;
  // How many coordinates the points fix in all (at least 6 are needed).
  std::size_t constraints() const;
};

ReferencePointSystem parse_reference_points(const std::string& text, const std::string& name);
ReferencePointSystem read_reference_points(const std::string& path);

}  // namespace furrow

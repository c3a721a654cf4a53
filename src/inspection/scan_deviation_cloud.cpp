// The deviation cloud (contract in scan_deviation_cloud.hpp).
#include "inspection/scan_deviation_cloud.hpp"

#include <algorithm>

#include "io/ply_writer.hpp"

namespace furrow {

std::string scan_deviation_ply(const ScanComparison& c, const ScanCloud& cloud) {
  const std::size_t n = cloud.points.size();
  std::vector<PlyColumn> columns = {{"x", PlyScalar::float64, {}},
                                    {"y", PlyScalar::float64, {}},
                                    {"z", PlyScalar::float64, {}},
                                    {"deviation", PlyScalar::float32, {}},
                                    {"outlier", PlyScalar::uchar, {}}};
  for (PlyColumn& column : columns) column.values.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Relative to the local origin first, as the fit ran: no cancellation
    // for a cloud far from its scanner frame's origin.
    const Eigen::Vector3d p = c.registration.transform * (cloud.points[i] - c.pre.origin);
    for (int k = 0; k < 3; ++k) columns[static_cast<std::size_t>(k)].values.push_back(p[k]);
    columns[3].values.push_back(c.deviation[i]);
    columns[4].values.push_back(static_cast<double>(c.status[i]));
  }
  // A header comment is one line: a file name's line ends become blanks.
  std::string name = cloud.file;
  std::replace(name.begin(), name.end(), '\n', ' ');
  std::replace(name.begin(), name.end(), '\r', ' ');
  return ply_vertex_text(columns, {"furrow " FURROW_VERSION " deviation cloud of " + name +
                                   " (part frame, mm; outlier: 0 evaluated, 1 spray far, 2 spray near, 3 off part, 4 grazing)"});
}

}  // namespace furrow

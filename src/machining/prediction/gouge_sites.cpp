#include "machining/prediction/gouge_sites.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>

#include "machining/cutter/vertical_projection.hpp"

namespace furrow {

std::vector<GougeSite> find_gouge_sites(const Part& part, const ZMap& zmap, const ErrorMap& map,
                                        const GougeSiteOptions& options, const ErrorMapOptions& refine) {
  std::vector<GougeSite> sites;
  for (const FaceErrorMap& m : map.faces) {
    cv::Mat mask(m.nv, m.nu, CV_8U, cv::Scalar(0));
    for (int j = 0; j < m.nv; ++j)
      for (int i = 0; i < m.nu; ++i) {
        const std::size_t k = m.index(i, j);
        if (m.status[k] == ErrorCellStatus::reached && m.error[k] < -options.threshold) mask.at<unsigned char>(j, i) = 1;
      }
    cv::Mat labels, stats, centroids;
    const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
    if (count <= 1) continue;
    const Face& face = part.faces[m.face];
    const double du = m.domain.width_u() / m.nu, dv = m.domain.width_v() / m.nv;
    // OpenCV numbers components in raster order of their first pixel.
    std::vector<GougeSite> found(count - 1);
    std::vector<int> deepest_i(count - 1), deepest_j(count - 1);
    std::vector<double> deepest(count - 1, 0.0);
    for (int j = 0; j < m.nv; ++j)
      for (int i = 0; i < m.nu; ++i) {
        const int label = labels.at<int>(j, i);
        if (label == 0) continue;
        GougeSite& s = found[label - 1];
        const double u = m.u(i), v = m.v(j);
        const SurfaceDerivatives d = face.surface().evaluate(u, v, 1);
        const double area = d.Su.cross(d.Sv).norm() * du * dv;
        s.area += area;
        s.centroid += area * d.S;
        s.centroid_uv += area * Eigen::Vector2d(u, v);
        s.box.extend(d.S);
        s.uv_box.extend(Eigen::Vector2d(u - 0.5 * du, v - 0.5 * dv));
        s.uv_box.extend(Eigen::Vector2d(u + 0.5 * du, v + 0.5 * dv));
        ++s.samples;
        const double depth = -m.error[m.index(i, j)];
        if (depth > deepest[label - 1]) deepest[label - 1] = depth, deepest_i[label - 1] = i, deepest_j[label - 1] = j;
      }
    for (int l = 0; l < count - 1; ++l) {
      GougeSite& s = found[l];
      s.face = m.face;
      if (s.area > 0) {
        s.centroid /= s.area;
        s.centroid_uv /= s.area;
      }
      const Eigen::Vector2d start(m.u(deepest_i[l]), m.v(deepest_j[l]));
      const ErrorExtremum e = refine_error_extremum(part, zmap, m.face, start, du, dv, -1.0, refine);
      s.depth = e.found ? std::max(-e.error, deepest[l]) : deepest[l];
      s.deepest = e.found && -e.error >= deepest[l] ? e.at : surface_point(part, static_cast<int>(m.face), start);
      s.id = static_cast<int>(sites.size()) + 1;
      sites.push_back(s);
    }
  }
  return sites;
}

}  // namespace furrow

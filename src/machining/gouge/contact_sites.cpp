#include "machining/gouge/contact_sites.hpp"

#include <cmath>
#include <cstdio>

#include "base/error.hpp"
#include "machining/cutter/face_seeds.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

std::string vec_text(const Eigen::Vector3d& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return buf;
}

}  // namespace

std::vector<ContactSite> grid_sites(const Part& part, int n) {
  if (n < 2) throw InputError("grid of " + std::to_string(n) + " nodes per direction: need at least 2");
  std::vector<ContactSite> sites;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const Face& face = part.faces[f];
    const ParameterDomain& d = face.domain();
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        ContactSite s;
        s.face = f;
        s.uv = {grid_parameter(d.u0, d.u1, i, n), grid_parameter(d.v0, d.v1, j, n)};
        s.grid_i = i;
        s.grid_j = j;
        if (face.contains(s.uv.x(), s.uv.y())) sites.push_back(std::move(s));
      }
    }
  }
  return sites;
}

std::vector<ContactSite> sites_from_points(const Part& part,
                                           const std::vector<ContactPointRecord>& points,
                                           const std::string& source,
                                           const PointSiteOptions& options) {
  const ClosestPointFinder projector(part, options.projection);
  const double cos_limit = std::cos(options.max_normal_deviation_deg * kPi / 180);
  std::vector<ContactSite> sites;
  sites.reserve(points.size());
  for (const ContactPointRecord& p : points) {
    const std::string where = source + ":" + std::to_string(p.line);
    const ClosestPoint foot = projector.project(p.position);
    if (!foot.converged)
      throw InputError(where + ": no foot point on the part for " + vec_text(p.position) +
                       " (the projection did not converge)");
    if (foot.distance > options.max_distance) {
      char buf[160];
      std::snprintf(buf, sizeof buf, ": the point is %.4g mm from the part (at most %.4g allowed)",
                    foot.distance, options.max_distance);
      throw InputError(where + buf);
    }
    const Face& face = part.faces[foot.face];
    const DifferentialGeometry g = face.geometry(foot.uv.x(), foot.uv.y());
    const Eigen::Vector3d n = p.has_normal ? p.normal : g.normal;
    // n_z = 0 is a vertical wall, touched by the cutter's side
    // (cutter_location.hpp); only a normal facing down is out of reach.
    if (!(n.z() >= 0))
      throw InputError(where + ": the " + std::string(p.has_normal ? "given" : "part's") +
                       " normal " + vec_text(n) +
                       " has n_z < 0: the point is not reachable from above by a 3-axis cutter");
    if (p.has_normal && !g.degenerate && n.dot(g.normal) < cos_limit) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    ": the given normal differs from the part's %s by %.3g degrees (at most %.3g; "
                    "wrong side or reversed face?)",
                    vec_text(g.normal).c_str(),
                    std::acos(std::max(-1.0, std::min(1.0, n.dot(g.normal)))) * 180 / kPi,
                    options.max_normal_deviation_deg);
      throw InputError(where + buf);
    }
    ContactSite s;
    s.face = foot.face;
    s.uv = foot.uv;
    s.line = p.line;
    s.id = p.id;
    sites.push_back(std::move(s));
  }
  return sites;
}

std::vector<ContactSite> load_contact_sites(const Part& part, const std::string& points_file,
                                            const std::string& units, int grid,
                                            const PointSiteOptions& options) {
  if (points_file.empty()) return grid_sites(part, grid);
  return sites_from_points(part, read_contact_points(points_file, units), points_file, options);
}

}  // namespace furrow

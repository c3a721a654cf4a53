#include "inspection/gouge_confirmation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "inspection/distance_clusters.hpp"

namespace furrow {

const char* to_string(GougeSiteSource source) {
  return source == GougeSiteSource::zmap ? "zmap" : "local";
}

GougeSiteSource parse_gouge_site_source(const std::string& text, const std::string& where) {
  if (text == "zmap") return GougeSiteSource::zmap;
  if (text == "local") return GougeSiteSource::local;
  throw InputError(where + ": \"" + text + "\" is not a gouge site source (zmap, local)");
}

const char* to_string(GougeSiteStatus status) {
  switch (status) {
    case GougeSiteStatus::confirmed: return "CONFIRMED";
    case GougeSiteStatus::not_confirmed: return "NOT CONFIRMED";
    case GougeSiteStatus::not_measured: return "NOT MEASURED";
  }
  return "unknown";
}

GougeSiteStatus parse_gouge_site_status(const std::string& text, const std::string& where) {
  for (GougeSiteStatus s : {GougeSiteStatus::confirmed, GougeSiteStatus::not_confirmed,
                            GougeSiteStatus::not_measured})
    if (text == to_string(s)) return s;
  throw InputError(where + ": \"" + text +
                   "\" is not a gouge site status (CONFIRMED, NOT CONFIRMED, NOT MEASURED)");
}

std::size_t GougeConfirmation::confirmed() const {
  return static_cast<std::size_t>(std::count_if(sites.begin(), sites.end(), [](const GougeSiteCheck& s) {
    return s.status == GougeSiteStatus::confirmed;
  }));
}

double overcut_threshold(double u, double probe_sigma, const ToleranceZone& zone,
                         const GougeConfirmationOptions& o) {
  return std::max(o.overcut_sigmas * std::sqrt(u * u + probe_sigma * probe_sigma),
                  o.tolerance_fraction * std::abs(zone.lower()));
}

namespace {

void check_options(const GougeConfirmationOptions& o) {
  auto non_negative = [](double x) { return std::isfinite(x) && x >= 0; };
  if (!(std::isfinite(o.overcut_sigmas) && o.overcut_sigmas > 0))
    throw InputError("the overcut threshold's sigma factor must be positive");
  if (!(o.tolerance_fraction >= 0 && o.tolerance_fraction <= 1))
    throw InputError("the overcut threshold's tolerance fraction must lie between 0 and 1");
  if (!non_negative(o.site_margin) || !non_negative(o.contact_cluster_distance) ||
      !non_negative(o.overcut_cluster_distance))
    throw InputError("the site margin and the cluster distances must be non-negative numbers of mm");
}

// The box grown by `margin` mm on the surface (see the header), clamped to
// the face's domain.
Eigen::AlignedBox2d grow_on_surface(const Face& face, const Eigen::AlignedBox2d& box, double margin) {
  const ParameterDomain& dom = face.domain();
  double speed_u = std::numeric_limits<double>::infinity(), speed_v = speed_u;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      const Eigen::Vector2d uv = (box.min() + (box.max() - box.min()).cwiseProduct(Eigen::Vector2d(i, j) / 2))
                                     .cwiseMax(Eigen::Vector2d(dom.u0, dom.v0))
                                     .cwiseMin(Eigen::Vector2d(dom.u1, dom.v1));
      const SurfaceDerivatives d = face.surface().evaluate(uv.x(), uv.y(), 1);
      // A degenerate edge (speed 0) says nothing about the width nearby.
      if (d.Su.norm() > 1e-9) speed_u = std::min(speed_u, d.Su.norm());
      if (d.Sv.norm() > 1e-9) speed_v = std::min(speed_v, d.Sv.norm());
    }
  const Eigen::Vector2d grow(std::isfinite(speed_u) ? margin / speed_u : 0.0,
                             std::isfinite(speed_v) ? margin / speed_v : 0.0);
  const Eigen::Vector2d lo = (box.min() - grow).cwiseMax(Eigen::Vector2d(dom.u0, dom.v0));
  const Eigen::Vector2d hi = (box.max() + grow).cwiseMin(Eigen::Vector2d(dom.u1, dom.v1));
  return Eigen::AlignedBox2d(lo, hi);
}

// Deepest overcut of the reached error cells meeting `box` (none when the
// field shows no overcut there).
std::optional<double> deepest_predicted_overcut(const FaceGridRecord& g, const Eigen::AlignedBox2d& box) {
  const ParameterDomain& d = g.domain;
  const double du = d.width_u() / g.cells_u, dv = d.width_v() / g.cells_v;
  auto first = [](double x, double x0, double w, int n) {
    return std::clamp(static_cast<int>(std::floor((x - x0) / w)), 0, n - 1);
  };
  double lowest = 0;
  for (int j = first(box.min().y(), d.v0, dv, g.cells_v); j <= first(box.max().y(), d.v0, dv, g.cells_v); ++j)
    for (int i = first(box.min().x(), d.u0, du, g.cells_u); i <= first(box.max().x(), d.u0, du, g.cells_u); ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * g.cells_u + i;
      if (g.status[k] == ErrorCellStatus::reached) lowest = std::min(lowest, g.max_overcut[k]);
    }
  if (lowest < 0) return -lowest;
  return std::nullopt;
}

// Index of a face the prediction names (check_prediction_against_part
// refuses a prediction of another part up front; this keeps the library
// safe without it).
int face_index(const Part& part, const std::string& face, const std::string& what) {
  const std::optional<std::size_t> f = part.find_face(face);
  if (!f) throw InputError("prediction: " + what + " lies on face \"" + face + "\", which the part does not have");
  return static_cast<int>(*f);
}

}  // namespace

std::vector<GougeSiteCheck> predicted_gouge_sites(const Part& part, const Prediction& prediction,
                                                  const GougeConfirmationOptions& o) {
  check_options(o);
  std::vector<GougeSiteCheck> sites;
  for (const GougeSiteRecord& r : prediction.gouge_sites) {
    GougeSiteCheck s;
    s.id = "G" + std::to_string(r.id);
    s.source = GougeSiteSource::zmap;
    s.face = r.face;
    s.face_index = face_index(part, r.face, "gouge site " + s.id);
    s.uv_box = r.uv_box;
    s.uv_box.extend(r.deepest.uv);
    s.centroid = r.centroid.xyz;
    s.anchors = {r.deepest.xyz};
    s.predicted_depth = r.depth;
    sites.push_back(s);
  }
  // Local gouges, clustered per face in path order.
  std::vector<std::size_t> gouging;
  for (std::size_t k = 0; k < prediction.local_gouges.size(); ++k) {
    const std::string& status = prediction.local_gouges[k].status;
    if (status == "gouge" || status == "concave_crease") gouging.push_back(k);
  }
  struct Cluster {
    std::size_t first;
    std::vector<std::size_t> members;
  };
  std::vector<Cluster> clusters;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    std::vector<std::size_t> on_face;
    std::vector<Eigen::Vector3d> xyz;
    for (std::size_t k : gouging)
      if (prediction.local_gouges[k].at.face == part.faces[f].name()) {
        on_face.push_back(k);
        xyz.push_back(prediction.local_gouges[k].at.xyz);
      }
    for (const std::vector<std::size_t>& c : distance_clusters(xyz, o.contact_cluster_distance)) {
      Cluster cl{on_face[c.front()], {}};
      for (std::size_t m : c) cl.members.push_back(on_face[m]);
      clusters.push_back(std::move(cl));
    }
  }
  std::sort(clusters.begin(), clusters.end(), [](const Cluster& a, const Cluster& b) { return a.first < b.first; });
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    GougeSiteCheck s;
    s.id = "L" + std::to_string(c + 1);
    s.source = GougeSiteSource::local;
    const LocalGougeRecord& first = prediction.local_gouges[clusters[c].first];
    s.face = first.at.face;
    s.face_index = face_index(part, s.face, "local gouge site " + s.id);
    s.uv_box = Eigen::AlignedBox2d(first.at.uv);
    for (std::size_t m : clusters[c].members) {
      s.uv_box.extend(prediction.local_gouges[m].at.uv);
      s.centroid += prediction.local_gouges[m].at.xyz;
      s.anchors.push_back(prediction.local_gouges[m].at.xyz);
    }
    s.contacts = clusters[c].members.size();
    s.centroid /= static_cast<double>(s.contacts);
    sites.push_back(s);
  }
  for (GougeSiteCheck& s : sites) {
    s.search_box = grow_on_surface(part.faces[static_cast<std::size_t>(s.face_index)], s.uv_box, o.site_margin);
    if (s.source == GougeSiteSource::local)
      if (const FaceGridRecord* g = prediction.find_face(s.face)) s.predicted_depth = deepest_predicted_overcut(*g, s.search_box);
  }
  return sites;
}

namespace {

bool on_site(const GougeSiteCheck& s, const RegisteredPoint& p) {
  return p.evaluated && static_cast<int>(p.foot.face) == s.face_index && s.search_box.contains(p.foot.uv);
}

}  // namespace

GougeConfirmation confirm_gouges(const RegistrationResult& r, const Part& part, const ToleranceZone& zone,
                                 const Prediction& prediction, const PredictionComparison& compared,
                                 const PredictionComparisonOptions& co, const GougeConfirmationOptions& o) {
  check_options(o);
  const std::size_t n = r.points.size();
  std::vector<double> threshold(n), sigma(n);
  for (std::size_t i = 0; i < n; ++i) {
    sigma[i] = std::hypot(r.points[i].uncertainty, co.probe_sigma);
    threshold[i] = overcut_threshold(r.points[i].uncertainty, co.probe_sigma, zone, o);
  }
  auto overcut = [&](std::size_t i) { return r.points[i].deviation < -threshold[i]; };
  auto agrees = [&](std::size_t i) {
    const PointPrediction& q = compared.points[i];
    return std::abs(q.residual) <= co.within_sigmas * q.sigma;
  };

  GougeConfirmation g;
  g.sites = predicted_gouge_sites(part, prediction, o);
  std::vector<bool> on_any(n, false);
  for (GougeSiteCheck& s : g.sites) {
    for (std::size_t i = 0; i < n; ++i)
      if (on_site(s, r.points[i])) {
        s.points.push_back(i);
        on_any[i] = true;
      }
    if (s.points.empty()) continue;
    const std::size_t j = *std::min_element(s.points.begin(), s.points.end(), [&](std::size_t a, std::size_t b) {
      return r.points[a].deviation < r.points[b].deviation;
    });
    s.deepest = j;
    s.measured_depth = -r.points[j].deviation;
    s.uncertainty = sigma[j];
    s.threshold = threshold[j];
    s.status = overcut(j) ? GougeSiteStatus::confirmed : GougeSiteStatus::not_confirmed;
    if (compared.points[j].reached()) {
      s.predicted_error = compared.points[j].predicted;
      s.depth_consistent = agrees(j);
    }
  }

  std::vector<std::size_t> loose;
  std::vector<Eigen::Vector3d> feet;
  for (std::size_t i = 0; i < n; ++i)
    if (r.points[i].evaluated && overcut(i) && !on_any[i] && !(compared.points[i].reached() && agrees(i))) {
      loose.push_back(i);
      feet.push_back(r.points[i].foot.point);
    }
  for (const std::vector<std::size_t>& c : distance_clusters(feet, o.overcut_cluster_distance)) {
    OvercutCluster u;
    for (std::size_t m : c) {
      u.points.push_back(loose[m]);
      u.centroid += feet[m];
    }
    u.centroid /= static_cast<double>(c.size());
    u.deepest = *std::min_element(u.points.begin(), u.points.end(), [&](std::size_t a, std::size_t b) {
      return r.points[a].deviation < r.points[b].deviation;
    });
    const RegisteredPoint& p = r.points[u.deepest];
    u.face_index = static_cast<int>(p.foot.face);
    u.face = part.faces[p.foot.face].name();
    u.uv = p.foot.uv;
    u.xyz = p.foot.point;
    u.depth = -p.deviation;
    u.uncertainty = sigma[u.deepest];
    u.threshold = threshold[u.deepest];
    g.unexplained.push_back(std::move(u));
  }
  std::stable_sort(g.unexplained.begin(), g.unexplained.end(),
                   [](const OvercutCluster& a, const OvercutCluster& b) { return a.depth > b.depth; });
  for (std::size_t k = 0; k < g.unexplained.size(); ++k) g.unexplained[k].id = "U" + std::to_string(k + 1);
  return g;
}

}  // namespace furrow

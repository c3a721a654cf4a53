#include "planning/region_domain.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace furrow {

RegionDomain::~RegionDomain() = default;
RegionDomain::RegionDomain(RegionDomain&&) noexcept = default;
RegionDomain& RegionDomain::operator=(RegionDomain&&) noexcept = default;

namespace {

// The face's trim loops as polylines on the surface. A trim loop is already
// a fine uv polygon; each of its edges is a straight uv segment whose image
// bows away from its chord by about the midpoint's deviation d (the sagitta),
// which n chords cut to d / n^2. So each edge gets the fewest chords (at
// most `samples`) that bring the sagitta within `tolerance`: one on a plane,
// where the image is straight. Cutting every edge into the same number of
// chords made millions of pieces on a plate with dozens of holes.
std::vector<std::vector<Eigen::Vector3d>> trim_polylines(const Face& face, int samples, double tolerance) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  const ParameterDomain& d = face.domain();
  auto at = [&](const Eigen::Vector2d& uv) {
    return face.surface().point(std::clamp(uv.x(), d.u0, d.u1), std::clamp(uv.y(), d.v0, d.v1));
  };
  for (const UvLoop& loop : face.trim().loops()) {
    std::vector<Eigen::Vector3d> line;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d& a = loop[k];
      const Eigen::Vector2d& b = loop[(k + 1) % loop.size()];
      const Eigen::Vector3d pa = at(a);
      const double sagitta = (at(0.5 * (a + b)) - 0.5 * (pa + at(b))).norm();
      const int n = std::clamp(static_cast<int>(std::ceil(std::sqrt(sagitta / tolerance))), 1, samples);
      line.push_back(pa);
      for (int s = 1; s < n; ++s) line.push_back(at(a + (b - a) * (static_cast<double>(s) / n)));
    }
    out.push_back(std::move(line));
  }
  return out;
}

// The parameter rectangle's boundary on the surface, counter-clockwise.
std::vector<Eigen::Vector3d> boundary_polyline(const Face& face, int samples) {
  const ParameterDomain& d = face.domain();
  const Eigen::Vector2d corners[4] = {{d.u0, d.v0}, {d.u1, d.v0}, {d.u1, d.v1}, {d.u0, d.v1}};
  std::vector<Eigen::Vector3d> line;
  for (int side = 0; side < 4; ++side)
    for (int s = 0; s < samples; ++s) {
      const Eigen::Vector2d uv = corners[side] + (corners[(side + 1) % 4] - corners[side]) * (static_cast<double>(s) / samples);
      line.push_back(face.surface().point(uv.x(), uv.y()));
    }
  return line;
}

}  // namespace

RegionDomain::RegionDomain(const Part& part, const RegionMap& map, int region_id,
                           const RegionDomainOptions& options, const RiskMap* risk)
    : region_id_(region_id), options_(options) {
  if (region_id < 0 || region_id >= static_cast<int>(map.regions.size()))
    throw std::invalid_argument("RegionDomain: no region " + std::to_string(region_id));
  if (!(options.border >= 0) || !(options.edge_margin >= 0) || options.trim_samples_per_edge < 1 ||
      options.min_cells < 1 || options.max_cells < options.min_cells)
    throw std::invalid_argument("RegionDomain: inconsistent options");
  region_ = &map.regions[static_cast<std::size_t>(region_id)];
  if (region_->face < 0 || region_->face >= static_cast<int>(part.faces.size()))
    throw std::invalid_argument("RegionDomain: the region's face is not in the part");
  face_ = &part.faces[static_cast<std::size_t>(region_->face)];

  // Edges: every border loop of the region, and the face's trim loops.
  edges_ = std::make_unique<EdgeDistance>();
  for (const BorderLoop& loop : region_->border)
    if (loop.xyz.size() >= 2) edges_->add_polyline(loop.xyz, true);
  // The chords' sagitta takes half the margin the polylines are allowed.
  const std::vector<std::vector<Eigen::Vector3d>> trims =
      trim_polylines(*face_, options.trim_samples_per_edge, 0.5 * options.edge_margin);
  for (const auto& line : trims)
    if (line.size() >= 2) edges_->add_polyline(line, true);
  edges_->build(std::max(options.border, 0.25));
  face_edges_ = std::make_unique<EdgeDistance>();
  for (const auto& line : trims)
    if (line.size() >= 2) face_edges_->add_polyline(line, true);
  face_edges_->add_polyline(boundary_polyline(*face_, options.boundary_samples_per_side), true);
  face_edges_->build(std::max(options.border, 0.25));

  // Sample grid over the region's uv box, about as fine as the partition's.
  const RegionFace& rf = map.faces[static_cast<std::size_t>(region_->face)];
  const Eigen::AlignedBox2d& box = region_->uv_box;
  const double du = rf.domain.width_u() / std::max(1, rf.nu), dv = rf.domain.width_v() / std::max(1, rf.nv);
  const double partition_cells = (box.sizes().x() / du) * (box.sizes().y() / dv);
  grid_ = std::clamp(static_cast<int>(std::ceil(std::sqrt(std::max(partition_cells, 1.0)))), options.min_cells,
                     options.max_cells);
  const int n = grid_;
  const double cu = box.sizes().x() / n, cv = box.sizes().y() / n;
  cells_.resize(static_cast<std::size_t>(n) * n);
  std::vector<double> row_u(static_cast<std::size_t>(n), 0.0), col_v(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      DomainCell& c = cells_[static_cast<std::size_t>(i) * n + j];
      c.uv = {box.min().x() + (i + 0.5) * cu, box.min().y() + (j + 0.5) * cv};
      const DifferentialGeometry g = face_->geometry(c.uv.x(), c.uv.y());
      c.xyz = g.point;
      c.area = g.area_element * cu * cv;
      if (!g.degenerate) {
        c.k1 = g.k1;
        c.k2 = g.k2;
        c.kappa = std::max(std::abs(g.k1), std::abs(g.k2));
      }
      c.inside = inside(c.uv);
      if (risk) {
        c.risk = risk->error_magnitude(region_->face, c.uv);
        if (!std::isfinite(c.risk) || c.risk < 0)
          throw std::invalid_argument("RegionDomain: the risk map returned a negative or non-finite error");
      }
    }
  }
  // Lengths of the box on the surface: mean chord-polyline length of the
  // grid's centre rows (u) and columns (v).
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + 1 < n; ++i)
      length_u_ += (cells_[static_cast<std::size_t>(i + 1) * n + j].xyz - cells_[static_cast<std::size_t>(i) * n + j].xyz).norm();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j + 1 < n; ++j)
      length_v_ += (cells_[static_cast<std::size_t>(i) * n + j + 1].xyz - cells_[static_cast<std::size_t>(i) * n + j].xyz).norm();
  length_u_ = length_u_ / n * n / std::max(1, n - 1);
  length_v_ = length_v_ / n * n / std::max(1, n - 1);

  // Statistics over the inside cells, summed in grid order (deterministic).
  double area = 0, k1 = 0, k2 = 0, kappa = 0, risk_sum = 0;
  for (const DomainCell& c : cells_)
    if (c.inside) {
      area += c.area;
      k1 += c.area * c.k1;
      k2 += c.area * c.k2;
      kappa += c.area * c.kappa;
      risk_sum += c.area * c.risk;
    }
  stats_.area = area;
  if (area > 0) {
    const double m1 = k1 / area, m2 = k2 / area;
    double var = 0;
    for (const DomainCell& c : cells_)
      if (c.inside) var += c.area * ((c.k1 - m1) * (c.k1 - m1) + (c.k2 - m2) * (c.k2 - m2));
    stats_.curvature_spread = std::sqrt(var / area);
    stats_.mean_kappa = kappa / area;
    stats_.mean_risk = risk_sum / area;
  }
}

bool RegionDomain::inside(const Eigen::Vector2d& uv) const {
  return region_->uv_box.contains(uv) && region_->uv_outline.contains(uv) && face_->contains(uv.x(), uv.y());
}

double RegionDomain::edge_distance(const Eigen::Vector3d& xyz, double reach) const {
  return edges_->distance(xyz, reach);
}

std::optional<double> RegionDomain::admissible(const Eigen::Vector2d& uv, Eigen::Vector3d* xyz) const {
  return admissible_against(*edges_, uv, xyz);
}

double RegionDomain::face_edge_distance(const Eigen::Vector3d& xyz, double reach) const {
  return face_edges_->distance(xyz, reach);
}

std::optional<double> RegionDomain::admissible_on_site(const Eigen::Vector2d& uv, Eigen::Vector3d* xyz) const {
  return admissible_against(*face_edges_, uv, xyz);
}

std::optional<double> RegionDomain::admissible_against(const EdgeDistance& edges, const Eigen::Vector2d& uv,
                                                       Eigen::Vector3d* xyz) const {
  if (!inside(uv)) return std::nullopt;
  const Eigen::Vector3d p = face_->surface().point(uv.x(), uv.y());
  const double need = required_edge_distance();
  const double cap = need + 1;
  const double d = edges.distance(p, cap);
  if (d < need) return std::nullopt;
  if (contact_check_ && !contact_check_(uv, p)) return std::nullopt;
  if (xyz) *xyz = p;
  return std::min(d, cap);
}

AreaWarp RegionDomain::warp(double kappa_weight, double kappa_ref, double risk_weight, double risk_floor) const {
  const int n = grid_;
  const Eigen::AlignedBox2d& box = region_->uv_box;
  const double cu = box.sizes().x() / n, cv = box.sizes().y() / n;
  const double ref = kappa_ref > 0 ? kappa_ref : 1.0;
  auto factor = [&](const DomainCell& c) {
    return (1 + kappa_weight * c.kappa / ref) * (risk_weight * c.risk + risk_floor);
  };
  // Cells outside the region get the region's mean factor: their share of
  // the mass stays their share of the area, so a risk or curvature peak just
  // outside the region cannot draw the candidates away from it.
  double weighted = 0, area = 0;
  for (const DomainCell& c : cells_)
    if (c.inside) {
      weighted += c.area * factor(c);
      area += c.area;
    }
  const double outside = area > 0 ? weighted / area : 1.0;
  return AreaWarp(box, n, [&](double u, double v) {
    const int i = std::clamp(static_cast<int>((u - box.min().x()) / cu), 0, n - 1);
    const int j = std::clamp(static_cast<int>((v - box.min().y()) / cv), 0, n - 1);
    const DomainCell& c = cells_[static_cast<std::size_t>(i) * n + j];
    return c.area * (c.inside ? factor(c) : outside);
  });
}

}  // namespace furrow

#include "machining/compound_border.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "machining/face_seeds.hpp"

namespace furrow {

namespace {

// Point and derivative along a side: the side runs along v for u sides, along
// u for v sides; t is that running parameter.
struct SidePoint {
  Eigen::Vector3d C, Ct, Ctt;
};

SidePoint side_point(const Face& face, unsigned side, double t) {
  const Eigen::Vector2d uv = side_uv(face.domain(), side, t);
  const SurfaceDerivatives d = face.surface().evaluate(uv.x(), uv.y(), 2);
  const bool along_v = runs_along_v(side);
  return {d.S, along_v ? d.Sv : d.Su, along_v ? d.Svv : d.Suu};
}

}  // namespace

int inward_directions(const SurfaceDerivatives& d, const Eigen::Vector3d& normal, unsigned sides,
                      std::array<Eigen::Vector3d, 2>& out) {
  int count = 0;
  for (const unsigned side : kAllSides) {
    if (!(sides & side)) continue;
    const bool u_side = runs_along_v(side);
    const Eigen::Vector3d edge = u_side ? d.Sv : d.Su;                  // along the edge
    const Eigen::Vector3d across = (side == kSideUMin) ? d.Su          // into the face
                                   : (side == kSideUMax) ? Eigen::Vector3d(-d.Su)
                                   : (side == kSideVMin) ? d.Sv
                                                         : Eigen::Vector3d(-d.Sv);
    Eigen::Vector3d in = normal.cross(edge);
    if (!(in.norm() > 0)) continue;
    in.normalize();
    if (in.dot(across) < 0) in = -in;
    out[count++] = in;
  }
  return count;
}

BorderLocator::BorderLocator(const Part& part, const BorderOptions& options)
    : part_(part), options_(options) {
  const int n = std::max(2, options.side_samples);
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const Face& face = part.faces[f];
    const ParameterDomain& d = face.domain();
    for (const unsigned side : kAllSides) {
      const auto [lo, hi] = side_range(d, side);
      Side s{f, side, {}, 0.0};
      for (int k = 0; k < n; ++k) {
        const double t = grid_parameter(lo, hi, k, n);
        const Eigen::Vector2d uv = side_uv(d, side, t);
        s.samples.push_back({t, face.surface().point(uv.x(), uv.y())});
        if (k > 0) s.spacing = std::max(s.spacing, (s.samples[k].point - s.samples[k - 1].point).norm());
      }
      sides_.push_back(std::move(s));
    }
  }
}

BorderNeighbour BorderLocator::neighbour(std::size_t face, const Eigen::Vector3d& point) const {
  BorderNeighbour best;
  best.distance = std::numeric_limits<double>::infinity();
  for (const Side& s : sides_) {
    if (s.face == face) continue;
    std::size_t k_best = 0;
    double d_best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < s.samples.size(); ++k) {
      const double dist = (s.samples[k].point - point).norm();
      if (dist < d_best) d_best = dist, k_best = k;
    }
    // Between samples the side can be no farther than about one spacing.
    if (d_best > s.spacing + options_.distance_tolerance) continue;
    // 1-D Newton on (C(t) - Q) . C'(t) = 0, clamped to the side.
    const Face& f = part_.faces[s.face];
    const double lo = s.samples.front().t, hi = s.samples.back().t;
    double t = s.samples[k_best].t;
    bool converged = false;
    for (int it = 0; it < options_.max_iterations; ++it) {
      const SidePoint p = side_point(f, s.side, t);
      const Eigen::Vector3d r = p.C - point;
      const double g = r.dot(p.Ct), dg = p.Ct.dot(p.Ct) + r.dot(p.Ctt);
      if (!(dg > 0)) break;
      const double next = std::clamp(t - g / dg, lo, hi);
      converged = std::abs(next - t) <= 1e-14 * (hi - lo);
      t = next;
      if (converged) break;
    }
    if (!converged) best.converged = false;
    const Eigen::Vector2d uv = side_uv(f.domain(), s.side, t);
    const double dist = (f.surface().point(uv.x(), uv.y()) - point).norm();
    if (dist <= options_.distance_tolerance && dist < best.distance) {
      best.found = true;
      best.face = s.face;
      best.uv = uv;
      best.distance = dist;
    }
  }
  if (!best.found) best.distance = 0;
  return best;
}

ContactSurfaces contact_surfaces(const BorderLocator& locator, std::size_t face,
                                 const Eigen::Vector2d& uv) {
  const Part& part = locator.part();
  const BorderOptions& options = locator.options();
  ContactSurfaces c;
  c.face = face;
  c.uv = uv;
  const Face& f = part.faces[face];
  const SurfaceDerivatives d = f.surface().evaluate(uv.x(), uv.y(), 2);
  c.geometry = f.geometry(d);
  c.sides = domain_sides(f.domain(), uv, options.side_tolerance);
  if (c.sides == 0 || c.geometry.degenerate) return c;
  c.inward_count = inward_directions(d, c.geometry.normal, c.sides, c.inward);

  const BorderNeighbour nb = locator.neighbour(face, c.geometry.point);
  c.border_search_converged = nb.converged;
  if (!nb.found) return c;
  const Face& g = part.faces[nb.face];
  const SurfaceDerivatives dn = g.surface().evaluate(nb.uv.x(), nb.uv.y(), 2);
  const DifferentialGeometry gn = g.geometry(dn);
  if (gn.degenerate) return c;
  c.has_neighbour = true;
  c.neighbour_face = nb.face;
  c.neighbour_uv = nb.uv;
  c.neighbour_geometry = gn;
  c.neighbour_inward_count = inward_directions(
      dn, gn.normal, domain_sides(g.domain(), nb.uv, options.side_tolerance), c.neighbour_inward);
  c.crease_angle = std::acos(std::clamp(c.geometry.normal.dot(gn.normal), -1.0, 1.0));
  c.crease = c.crease_angle > options.crease_angle_deg * M_PI / 180;
  if (c.crease && c.neighbour_inward_count > 0)
    c.concave_crease = c.neighbour_inward[0].dot(c.geometry.normal) > 0;
  return c;
}

LocalGouge check_contact(const Cutter& cutter, const ContactSurfaces& c,
                         const GougeOptions& options) {
  std::array<SurfaceSide, 2> sides;
  sides[0].geometry = &c.geometry;
  sides[0].inward = c.inward;
  sides[0].inward_count = c.inward_count;
  std::size_t count = 1;
  Eigen::Vector3d normal = c.geometry.normal;
  if (c.has_neighbour && !c.crease) {
    sides[1].geometry = &c.neighbour_geometry;
    sides[1].inward = c.neighbour_inward;
    sides[1].inward_count = c.neighbour_inward_count;
    count = 2;
    normal = (c.geometry.normal + c.neighbour_geometry.normal).normalized();
  }
  LocalGouge result = check_local_gouge(cutter, normal, sides.data(), count, options);
  if (c.concave_crease && !c.geometry.degenerate) {
    result.status = GougeStatus::concave_crease;
    result.ranges = AngularRanges();
    return result;
  }
  // A flat bottom at a horizontal border contact: try the other placement.
  if (result.gouges() && result.cutter.flat_bottom && c.inward_count > 0) {
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    for (int i = 0; i < c.inward_count; ++i) w += c.inward[i];
    if (std::hypot(w.x(), w.y()) > 0) {
      LocalGouge best = result;
      for (const double sign : {1.0, -1.0}) {
        GougeOptions placed = options;
        placed.location.horizontal_side = sign * w;
        LocalGouge r = check_local_gouge(cutter, normal, sides.data(), count, placed);
        if (r.max_excess < best.max_excess) best = r;
      }
      return best;
    }
  }
  return result;
}

}  // namespace furrow

#include "machining/gouge/compound_border.hpp"
#include "base/numbers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace furrow {

namespace {

// Unit tangent across an edge with 3-D direction `edge`, into the face
// (on the side of `across`); false when the edge direction is degenerate.
bool inward_across(const Eigen::Vector3d& normal, const Eigen::Vector3d& edge, const Eigen::Vector3d& across,
                   Eigen::Vector3d& out) {
  Eigen::Vector3d in = normal.cross(edge);
  if (!(in.norm() > 0)) return false;
  in.normalize();
  out = in.dot(across) < 0 ? Eigen::Vector3d(-in) : in;
  return true;
}

}  // namespace

BorderDirections border_directions(const Face& face, const Eigen::Vector2d& uv, const SurfaceDerivatives& d,
                                   const Eigen::Vector3d& normal, const BorderOptions& options) {
  BorderDirections b;
  const ParameterDomain& dom = face.domain();
  const double side_tolerance = options.side_tolerance;
  b.sides = domain_sides(dom, uv, side_tolerance);
  for (const unsigned side : kAllSides) {
    if (!(b.sides & side)) continue;
    Eigen::Vector2d opposite = uv;
    if (side == kSideUMin) opposite.x() = dom.u1;
    if (side == kSideUMax) opposite.x() = dom.u0;
    if (side == kSideVMin) opposite.y() = dom.v1;
    if (side == kSideVMax) opposite.y() = dom.v0;
    if ((face.surface().point(opposite.x(), opposite.y()) - d.S).norm() <= options.distance_tolerance)
      b.sides &= ~side;  // a seam: the face goes on across it
  }
  auto add = [&](const Eigen::Vector3d& edge, const Eigen::Vector3d& across) {
    if (b.count < 2 && inward_across(normal, edge, across, b.inward[b.count])) ++b.count;
  };
  for (const unsigned side : kAllSides) {
    if (!(b.sides & side)) continue;
    const bool u_side = runs_along_v(side);
    add(u_side ? d.Sv : d.Su, side == kSideUMin   ? d.Su
                              : side == kSideUMax ? Eigen::Vector3d(-d.Su)
                              : side == kSideVMin ? d.Sv
                                                  : Eigen::Vector3d(-d.Sv));
  }
  const double width = std::max(dom.width_u(), dom.width_v());
  if (const auto e = face.trim().edge_near(uv, side_tolerance * width)) {
    b.sides |= kTrimEdge;
    // Across the loop edge, toward the side the trim keeps.
    Eigen::Vector2d across(-e->tangent.y(), e->tangent.x());
    const double probe = 1e-6 * width;
    if (!face.trim().contains(e->point + probe * across)) across = -across;
    add(d.Su * e->tangent.x() + d.Sv * e->tangent.y(), d.Su * across.x() + d.Sv * across.y());
  }
  return b;
}

BorderLocator::BorderLocator(const Part& part, const BorderOptions& options)
    : part_(part), options_(options), finder_(part, options.closest) {}

BorderNeighbour BorderLocator::neighbour(std::size_t face, const Eigen::Vector3d& point) const {
  BorderNeighbour nb;
  const std::optional<ClosestPoint> foot = finder_.project_to_other_faces(point, face);
  if (!foot) return nb;
  nb.converged = foot->converged;
  if (!(foot->distance <= options_.distance_tolerance)) return nb;
  // A touching face counts only where its own border is: an edge of this
  // face resting on the inside of another is not a shared edge.
  const Face& other = part_.faces[foot->face];
  const SurfaceDerivatives d = other.surface().evaluate(foot->uv.x(), foot->uv.y(), 1);
  if (border_directions(other, foot->uv, d, foot->normal, options_).sides == 0) return nb;
  nb.found = true;
  nb.face = foot->face;
  nb.uv = foot->uv;
  nb.distance = foot->distance;
  return nb;
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
  const BorderDirections own = border_directions(f, uv, d, c.geometry.normal, options);
  c.sides = own.sides;
  if (c.sides == 0 || c.geometry.degenerate) return c;
  c.inward = own.inward;
  c.inward_count = own.count;

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
  const BorderDirections theirs = border_directions(g, nb.uv, dn, gn.normal, options);
  c.neighbour_inward = theirs.inward;
  c.neighbour_inward_count = theirs.count;
  c.crease_angle = std::acos(std::clamp(c.geometry.normal.dot(gn.normal), -1.0, 1.0));
  c.crease = c.crease_angle > options.crease_angle_deg * kPi / 180;
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

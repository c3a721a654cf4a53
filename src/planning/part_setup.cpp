#include "planning/part_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/analytic_surface.hpp"
#include "geometry/primitives.hpp"

namespace furrow {

namespace {

// The face's outward normal at the interior point of its largest region.
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> face_point_normal(const Part& part, const RegionMap& map,
                                                                             int face) {
  const Region* best = nullptr;
  for (int id : map.faces[static_cast<std::size_t>(face)].regions) {
    const Region& r = map.regions[static_cast<std::size_t>(id)];
    if (!best || r.area > best->area) best = &r;
  }
  if (!best) return std::nullopt;
  const DifferentialGeometry g =
      part.faces[static_cast<std::size_t>(face)].geometry(best->interior_uv.x(), best->interior_uv.y());
  if (g.degenerate) return std::nullopt;
  return std::make_pair(g.point, g.normal);
}

// Every border vertex and interior point of every region at most the
// tolerance above the plane through `point` with outward normal `normal`.
bool part_below(const RegionMap& map, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  for (const Region& r : map.regions) {
    if (normal.dot(r.interior_xyz - point) > kStableTolerance) return false;
    for (const BorderLoop& loop : r.border)
      for (const Eigen::Vector3d& q : loop.xyz)
        if (normal.dot(q - point) > kStableTolerance) return false;
  }
  return true;
}

// How far the projection of `centre` along `normal` lies inside the convex
// hull of the part's points on the plane (border vertices and interior
// points within kStableTolerance of it) [mm]: the smallest distance to a
// hull edge, negative outside. -infinity when fewer than three such points
// span an area.
double balance_margin(const RegionMap& map, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                      const Eigen::Vector3d& centre) {
  const Eigen::Vector3d e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
  std::vector<Eigen::Vector2d> on;
  auto take = [&](const Eigen::Vector3d& q) {
    if (std::abs(normal.dot(q - point)) <= kStableTolerance) on.emplace_back(e1.dot(q - point), e2.dot(q - point));
  };
  for (const Region& r : map.regions) {
    take(r.interior_xyz);
    for (const BorderLoop& loop : r.border)
      for (const Eigen::Vector3d& q : loop.xyz) take(q);
  }
  // Andrew's monotone chain: the hull counter-clockwise.
  std::sort(on.begin(), on.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> hull(2 * on.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < on.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], on[i]) <= 0) --k;
    hull[k++] = on[i];
  }
  for (std::size_t i = on.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], on[i - 1]) <= 0) --k;
    hull[k++] = on[i - 1];
  }
  if (k < 4) return -std::numeric_limits<double>::infinity();  // closed chain of fewer than 3 corners
  hull.resize(k - 1);
  const Eigen::Vector2d c(e1.dot(centre - point), e2.dot(centre - point));
  double margin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    const double length = (b - a).norm();
    if (length == 0) continue;
    margin = std::min(margin, cross(a, b, c) / length);  // > 0 left of a->b: inside
  }
  return margin;
}

bool is_plane(const Face& face) {
  if (face.analytic()) return face.analytic()->type == AnalyticSurface::Type::plane;
  const std::optional<AnalyticSurface> s = recognise_analytic(face.surface());
  return s && s->type == AnalyticSurface::Type::plane;
}

}  // namespace

std::optional<RestingFace> planar_face(const Part& part, const RegionMap& map, int face) {
  return planar_face(part, map, face, solid_mass(part));
}

std::optional<RestingFace> planar_face(const Part& part, const RegionMap& map, int face, const SolidMass& mass) {
  if (face < 0 || static_cast<std::size_t>(face) >= part.faces.size() ||
      static_cast<std::size_t>(face) >= map.faces.size())
    return std::nullopt;
  if (!is_plane(part.faces[static_cast<std::size_t>(face)])) return std::nullopt;
  const auto pn = face_point_normal(part, map, face);
  if (!pn) return std::nullopt;
  RestingFace r;
  r.face = face;
  r.point = pn->first;
  r.normal = pn->second.normalized();
  for (int id : map.faces[static_cast<std::size_t>(face)].regions) r.area += map.regions[static_cast<std::size_t>(id)].area;
  r.on_hull = part_below(map, r.point, r.normal);
  r.balance_margin = mass.closed ? balance_margin(map, r.point, r.normal, mass.centroid)
                                 : std::numeric_limits<double>::infinity();
  r.stable = r.on_hull && r.balance_margin >= 0;
  return r;
}

std::vector<RestingFace> resting_candidates(const Part& part, const RegionMap& map) {
  std::vector<RestingFace> out;
  const SolidMass mass = solid_mass(part);
  for (std::size_t f = 0; f < part.faces.size(); ++f)
    if (const auto r = planar_face(part, map, static_cast<int>(f), mass); r && r->stable) out.push_back(*r);
  std::stable_sort(out.begin(), out.end(), [](const RestingFace& a, const RestingFace& b) { return a.area > b.area; });
  // Coplanar faces (the tops of bosses of one height) give one and the same
  // setup: the largest of them stands for all.
  std::vector<RestingFace> distinct;
  for (const RestingFace& f : out) {
    bool same = false;
    for (const RestingFace& d : distinct)
      same = same || (f.normal.dot(d.normal) > 1 - 1e-9 && std::abs(f.normal.dot(f.point - d.point)) <= kStableTolerance);
    if (!same) distinct.push_back(f);
  }
  return distinct;
}

PartSetup resting_setup(const RestingFace& face, int index, bool named) {
  const Eigen::Vector3d down(0, 0, -1);
  Eigen::Matrix3d rotation;
  if (face.normal.dot(down) < -1 + 1e-12) {
    // Facing +z: turned over about +x.
    rotation = Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  } else {
    rotation = Eigen::Quaterniond::FromTwoVectors(face.normal, down).toRotationMatrix();
  }
  PartSetup s;
  s.index = index;
  s.resting_face = face.face;
  s.named = named;
  s.to_setup = Eigen::Isometry3d::Identity();
  s.to_setup.linear() = rotation;
  s.to_setup.translation() = Eigen::Vector3d(0, 0, -(rotation * face.point).z());
  s.fixture_z = 0.0;
  return s;
}

RestingFace named_resting_face(const Part& part, const RegionMap& map, int face, const std::string& where) {
  const std::string name = "face " + std::to_string(face);
  if (face < 0 || static_cast<std::size_t>(face) >= part.faces.size())
    throw InputError(where + ": " + name + " is not a face of the part (it has " + std::to_string(part.faces.size()) +
                     " faces, indices 0 to " + std::to_string(part.faces.size() - 1) + ")");
  const std::string label = name + " (\"" + part.faces[static_cast<std::size_t>(face)].name() + "\")";
  const std::optional<RestingFace> r = planar_face(part, map, face);
  if (!r) throw InputError(where + ": " + label + " is not planar: the part can only rest on a plane");
  if (!r->on_hull)
    throw InputError(where + ": the part cannot rest on " + label +
                     ": some of the part stands out beyond its plane (it is not on the part's convex hull)");
  if (!r->stable) {
    char margin[64];
    std::snprintf(margin, sizeof margin, "%.3f", -r->balance_margin);
    throw InputError(where + ": the part cannot rest on " + label +
                     ": it would tip over, its centre of mass lies " +
                     (std::isfinite(r->balance_margin) ? std::string(margin) + " mm " : std::string()) +
                     "outside the face's support (the convex hull of what touches the table)");
  }
  return *r;
}

Part moved_part(const Part& part, const Eigen::Isometry3d& motion) {
  Part out;
  out.source_units = part.source_units;
  for (const Face& f : part.faces) {
    Face moved(f.name(), transformed(f.surface(), motion), f.trim(), f.reversed(), f.source_type());
    if (f.analytic()) {
      AnalyticSurface a = *f.analytic();
      a.origin = motion * a.origin;
      a.axis = motion.linear() * a.axis;
      // The convention: the axis's largest component positive (analytic_surface.hpp).
      Eigen::Index k = 0;
      a.axis.cwiseAbs().maxCoeff(&k);
      if (a.axis[k] < 0) a.axis = -a.axis;
      moved.set_analytic(a);
    }
    moved.set_orientation_established(f.orientation_established());
    out.faces.push_back(std::move(moved));
  }
  return out;
}

RegionMap moved_regions(const RegionMap& map, const Eigen::Isometry3d& motion) {
  RegionMap out = map;
  for (Region& r : out.regions) {
    r.centroid = motion * r.centroid;
    r.interior_xyz = motion * r.interior_xyz;
    Eigen::AlignedBox3d box;
    for (int k = 0; k < 8; ++k) box.extend(motion * r.xyz_box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)));
    r.xyz_box = box;
    for (BorderLoop& loop : r.border)
      for (Eigen::Vector3d& q : loop.xyz) q = motion * q;
  }
  return out;
}

}  // namespace furrow

#include "planning/datum_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/numbers.hpp"
#include "base/text_fields.hpp"
#include "planning/edge_distance.hpp"

namespace furrow {

namespace {

// A unit normal counts as along an axis when it is within this of it (the
// analytic recognition accepts 1e-7 mm deviations; CAD planes are exact).
constexpr double kAxisTolerance = 1e-6;

struct Candidate {
  Eigen::Vector2d uv;
  Eigen::Vector3d xyz, normal;
};

struct FaceInfo {
  std::size_t index = 0;
  double area = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // outward, planes only
  bool plane = false;
};

// Face edges as polylines on the surface: trim loops and the parameter
// rectangle's boundary (conservative where the trim lies inside it).
EdgeDistance face_edges(const Face& face) {
  EdgeDistance edges;
  const ParameterDomain& d = face.domain();
  const int n = 64;
  std::vector<Eigen::Vector3d> boundary;
  auto at = [&](double u, double v) { return face.surface().point(u, v); };
  for (int k = 0; k < n; ++k) boundary.push_back(at(d.u0 + d.width_u() * k / n, d.v0));
  for (int k = 0; k < n; ++k) boundary.push_back(at(d.u1, d.v0 + d.width_v() * k / n));
  for (int k = 0; k < n; ++k) boundary.push_back(at(d.u1 - d.width_u() * k / n, d.v1));
  for (int k = 0; k < n; ++k) boundary.push_back(at(d.u0, d.v1 - d.width_v() * k / n));
  edges.add_polyline(boundary, true);
  for (const UvLoop& loop : face.trim().loops()) {
    std::vector<Eigen::Vector3d> line;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d& a = loop[k];
      const Eigen::Vector2d& b = loop[(k + 1) % loop.size()];
      for (int s = 0; s < 16; ++s) {
        const Eigen::Vector2d p = a + (b - a) * (s / 16.0);
        line.push_back(at(p.x(), p.y()));
      }
    }
    if (line.size() >= 2) edges.add_polyline(line, true);
  }
  double size = 0;
  for (int k = 1; k < static_cast<int>(boundary.size()); ++k) size = std::max(size, (boundary[k] - boundary[0]).norm());
  edges.build(std::max(size / 64, 1e-3));
  return edges;
}

// Admissible, accessible candidate points of a face on a grid of cell centres.
std::vector<Candidate> candidates(const Face& face, const ClosestPointFinder& finder, const ProbeGeometry& probe,
                                  const AccessOptions& access, const DatumOptions& o) {
  const EdgeDistance edges = face_edges(face);
  const ParameterDomain& d = face.domain();
  std::vector<Candidate> out;
  for (int i = 0; i < o.grid; ++i)
    for (int j = 0; j < o.grid; ++j) {
      const double u = d.u0 + d.width_u() * (i + 0.5) / o.grid, v = d.v0 + d.width_v() * (j + 0.5) / o.grid;
      if (!face.contains(u, v)) continue;
      const DifferentialGeometry g = face.geometry(u, v);
      if (g.degenerate) continue;
      if (edges.distance(g.point, o.border + 1) < o.border) continue;
      if (!check_access(finder, g.point, g.normal, probe, access).ok()) continue;
      out.push_back({{u, v}, g.point, g.normal});
    }
  return out;
}

// Farthest-point selection: the candidate farthest from the centroid, then
// each next the farthest from those chosen. Ties keep the lower index.
std::vector<std::size_t> spread(const std::vector<Candidate>& c, int count) {
  std::vector<std::size_t> chosen;
  if (c.empty()) return chosen;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Candidate& x : c) centroid += x.xyz;
  centroid /= static_cast<double>(c.size());
  std::vector<double> nearest(c.size(), std::numeric_limits<double>::infinity());
  std::size_t next = 0;
  double best = -1;
  for (std::size_t k = 0; k < c.size(); ++k)
    if (const double dist = (c[k].xyz - centroid).norm(); dist > best + 1e-12) best = dist, next = k;
  while (static_cast<int>(chosen.size()) < count && static_cast<int>(chosen.size()) < static_cast<int>(c.size())) {
    const std::size_t taken = next;
    chosen.push_back(taken);
    best = -1;
    for (std::size_t k = 0; k < c.size(); ++k) {
      nearest[k] = std::min(nearest[k], (c[k].xyz - c[taken].xyz).norm());
      if (nearest[k] > best + 1e-12) best = nearest[k], next = k;
    }
    if (best <= 0) break;
  }
  return chosen;
}

PlannedPoint plan_point(const Part& part, std::size_t face, const Candidate& c, const std::string& id, int order,
                        const ProbeGeometry& probe, const AccessOptions& access) {
  PlannedPoint p;
  p.id = id;
  p.order = order;
  p.face = part.faces[face].name();
  p.face_index = face;
  p.uv = c.uv;
  p.xyz = c.xyz;
  p.ijk = c.normal;
  p.approach = approach_point(c.xyz, c.normal, probe, access);
  p.retract = retract_point(c.xyz, c.normal, probe, access);
  return p;
}

char horizontal_axis(const Eigen::Vector3d& n) {
  if (std::abs(n.z()) > kAxisTolerance) return 0;
  if (std::abs(std::abs(n.x()) - 1) < kAxisTolerance) return 'X';
  if (std::abs(std::abs(n.y()) - 1) < kAxisTolerance) return 'Y';
  return 0;
}

bool faces_up(const Eigen::Vector3d& n) { return std::abs(n.z() - 1) < kAxisTolerance; }

// Origins a micrometre off zero are written as 0.
std::string fmt(double v) { return general(std::abs(v) < 5e-7 ? 0.0 : v); }

struct Builder {
  const Part& part;
  const ClosestPointFinder& finder;
  const ProbeGeometry& probe;
  const AccessOptions& access;  // tilt up to 90 degrees
  const DatumOptions& o;
  int order = 0;

  // Empty when the face cannot hold the feature. `line_sets_origin`: a line
  // sets an origin (B of plane, wall, wall), or only a direction (C after a
  // bore, which sets both in-plane origins).
  std::optional<DatumFeature> feature(const FaceInfo& f, char role, DatumFeature::Kind kind, bool line_sets_origin,
                                      std::string* why) {
    const std::vector<Candidate> c = candidates(part.faces[f.index], finder, probe, access, o);
    DatumFeature d;
    d.label = std::string(1, role);
    d.kind = kind;
    d.face = part.faces[f.index].name();
    d.face_index = f.index;
    d.normal = f.normal;
    const std::string prefix = std::string("D") + role;
    auto add = [&](std::size_t k, int n) {
      d.points.push_back(plan_point(part, f.index, c[k], prefix + std::to_string(n), ++order, probe, access));
    };
    // The candidates at the height of the one nearest mid-height (a
    // horizontal line or circle where possible).
    auto one_height = [&] {
      double zmin = c[0].xyz.z(), zmax = zmin;
      for (const Candidate& x : c) zmin = std::min(zmin, x.xyz.z()), zmax = std::max(zmax, x.xyz.z());
      std::size_t mid = 0;
      for (std::size_t k = 0; k < c.size(); ++k)
        if (std::abs(c[k].xyz.z() - (zmin + zmax) / 2) < std::abs(c[mid].xyz.z() - (zmin + zmax) / 2)) mid = k;
      std::vector<std::size_t> level;
      for (std::size_t k = 0; k < c.size(); ++k)
        if (std::abs(c[k].xyz.z() - c[mid].xyz.z()) <= 1e-6) level.push_back(k);
      return level;
    };
    if (kind == DatumFeature::Kind::plane) {
      const std::vector<std::size_t> pick = spread(c, o.plane_points);
      if (static_cast<int>(pick.size()) < 3) {
        *why = "fewer than 3 admissible, reachable points";
        return std::nullopt;
      }
      int n = 0;
      for (std::size_t k : pick) add(k, ++n);
      d.origin = d.points.front().xyz;
      d.direction = f.normal;
      d.axis = 'Z';
      d.origin_axis = 'Z';
    } else if (kind == DatumFeature::Kind::line) {
      // Horizontal direction along the wall, pointing to + of its axis.
      const char wall = horizontal_axis(f.normal);
      const Eigen::Vector3d t = wall == 'X' ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
      if (c.size() < 2) {
        *why = "fewer than 2 admissible, reachable points";
        return std::nullopt;
      }
      // The pair farthest apart along the wall at one height.
      const std::vector<std::size_t> level = one_height();
      std::size_t lo = level[0], hi = level[0];
      for (std::size_t k : level) {
        if (c[k].xyz.dot(t) < c[lo].xyz.dot(t)) lo = k;
        if (c[k].xyz.dot(t) > c[hi].xyz.dot(t)) hi = k;
      }
      if (lo == hi) {
        *why = "no two admissible, reachable points at one height";
        return std::nullopt;
      }
      add(lo, 1);
      add(hi, 2);
      d.origin = d.points[0].xyz;
      d.direction = t;
      d.axis = wall == 'X' ? 'Y' : 'X';
      d.origin_axis = line_sets_origin ? wall : 0;
    } else if (kind == DatumFeature::Kind::cylinder) {
      // A bore or boss: points around the axis at one height, spread by
      // angle; the face must go most of the way round, or the circle fit
      // would be poorly conditioned.
      const AnalyticSurface& cyl = *part.faces[f.index].analytic();
      if (c.size() < 3) {
        *why = "fewer than 3 admissible, reachable points";
        return std::nullopt;
      }
      const std::vector<std::size_t> level = one_height();
      const double height = c[level[0]].xyz.z();
      const Eigen::Vector3d centre = cyl.origin + (height - cyl.origin.z()) / cyl.axis.z() * cyl.axis;
      std::vector<std::pair<double, std::size_t>> around;
      for (std::size_t k : level)
        around.push_back({std::atan2(c[k].xyz.y() - centre.y(), c[k].xyz.x() - centre.x()), k});
      std::sort(around.begin(), around.end());
      double widest_gap = 0;
      for (std::size_t k = 0; k < around.size(); ++k) {
        const double next = k + 1 < around.size() ? around[k + 1].first : around[0].first + 2 * kPi;
        widest_gap = std::max(widest_gap, next - around[k].first);
      }
      if (around.size() < 3 || widest_gap > radians(o.bore_max_gap_degrees)) {
        *why = "its reachable points do not go round the axis (a gap wider than " +
               general(o.bore_max_gap_degrees) + " degrees)";
        return std::nullopt;
      }
      // Farthest-point selection by angle, from the first.
      std::vector<std::size_t> chosen{0};
      while (static_cast<int>(chosen.size()) < o.bore_points && chosen.size() < around.size()) {
        std::size_t next = 0;
        double best = -1;
        for (std::size_t k = 0; k < around.size(); ++k) {
          double nearest = 2 * kPi;
          for (std::size_t j : chosen) {
            const double gap = std::abs(around[k].first - around[j].first);
            nearest = std::min(nearest, std::min(gap, 2 * kPi - gap));
          }
          if (nearest > best + 1e-12) best = nearest, next = k;
        }
        chosen.push_back(next);
      }
      std::sort(chosen.begin(), chosen.end());  // measured round the circle
      int n = 0;
      for (std::size_t k : chosen) add(around[k].second, ++n);
      d.origin = centre;
      d.direction = Eigen::Vector3d::UnitZ();
      d.normal = Eigen::Vector3d::UnitZ();
      d.radius = cyl.radius;
      d.axis = 0;
      d.origin_axis = 0;  // a cylinder sets both in-plane origins
    } else {
      if (c.empty()) {
        *why = "no admissible, reachable point";
        return std::nullopt;
      }
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (const Candidate& x : c) centroid += x.xyz;
      centroid /= static_cast<double>(c.size());
      std::size_t best = 0;
      for (std::size_t k = 1; k < c.size(); ++k)
        if ((c[k].xyz - centroid).norm() < (c[best].xyz - centroid).norm() - 1e-12) best = k;
      add(best, 1);
      d.origin = d.points[0].xyz;
      d.direction = f.normal;
      d.axis = 0;
      d.origin_axis = horizontal_axis(f.normal);
    }
    return d;
  }
};

// A cylinder whose axis is vertical: a bore or boss perpendicular to A.
bool vertical_cylinder(const Face& face) {
  const std::optional<AnalyticSurface>& s = face.analytic();
  return s && s->type == AnalyticSurface::Type::cylinder && std::abs(std::abs(s->axis.z()) - 1) < kAxisTolerance;
}

std::string describe_face(const Part& part, std::size_t k) {
  return "face " + std::to_string(k) + " " + quote_field(part.faces[k].name());
}

}  // namespace

DatumChoice parse_datum_choice(const std::string& text, const std::string& where) {
  DatumChoice c;
  if (text == "auto") return c;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    c.faces.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (c.faces.size() != 3 || std::any_of(c.faces.begin(), c.faces.end(), [](const std::string& s) { return s.empty(); }))
    throw InputError(where + ": expected auto or three face names PRIMARY,SECONDARY,TERTIARY, got " + quote_field(text));
  return c;
}

std::string to_string(const DatumChoice& choice) {
  if (choice.faces.empty()) return "auto";
  return choice.faces[0] + "," + choice.faces[1] + "," + choice.faces[2];
}

double face_area(const Face& face, int grid) {
  const ParameterDomain& d = face.domain();
  const double du = d.width_u() / grid, dv = d.width_v() / grid;
  double area = 0;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const double u = d.u0 + (i + 0.5) * du, v = d.v0 + (j + 0.5) * dv;
      if (face.contains(u, v)) area += face.geometry(u, v).area_element * du * dv;
    }
  return area;
}

PartAlignment choose_alignment(const Part& part, const ClosestPointFinder& finder, const ProbeGeometry& probe,
                               const AccessOptions& access_in, const DatumChoice& choice, const DatumOptions& o) {
  AccessOptions access = access_in;
  access.max_tilt = kPi / 2 + 1e-9;  // walls are touched horizontally
  std::vector<FaceInfo> faces;
  for (std::size_t k = 0; k < part.faces.size(); ++k) {
    const Face& f = part.faces[k];
    FaceInfo info;
    info.index = k;
    info.area = face_area(f, o.area_grid);
    if (f.analytic() && f.analytic()->type == AnalyticSurface::Type::plane) {
      const ParameterDomain& d = f.domain();
      const DifferentialGeometry g = f.geometry((d.u0 + d.u1) / 2, (d.v0 + d.v1) / 2);
      if (!g.degenerate) info.plane = true, info.normal = g.normal;
    }
    faces.push_back(info);
  }
  Builder b{part, finder, probe, access, o};
  PartAlignment a;
  a.method = PartAlignment::Method::datums;

  using Kind = DatumFeature::Kind;
  if (!choice.faces.empty()) {
    const char roles[3] = {'A', 'B', 'C'};
    bool bore = false;
    for (int r = 0; r < 3; ++r) {
      const std::string& name = choice.faces[static_cast<std::size_t>(r)];
      std::optional<std::size_t> index;
      for (std::size_t k = 0; k < part.faces.size(); ++k)
        if (part.faces[k].name() == name) {
          if (index) throw InputError("--datums: two faces are named " + quote_field(name));
          index = k;
        }
      if (!index) throw InputError("--datums: the part has no face named " + quote_field(name));
      const FaceInfo& f = faces[*index];
      const std::string what = "--datums: " + describe_face(part, *index);
      Kind kind = r == 0 ? Kind::plane : r == 1 ? Kind::line : Kind::point;
      if (r == 1 && vertical_cylinder(part.faces[*index])) {
        kind = Kind::cylinder;  // a bore or boss: C is then a wall giving the direction
        bore = true;
      } else if (!f.plane) {
        throw InputError(what + (r == 1 ? " is neither a plane nor a cylinder with a vertical axis"
                                        : " is not a plane (datums are planes parallel to the CAD axes)"));
      }
      if (r == 2 && bore) kind = Kind::line;
      if (r == 0 && !faces_up(f.normal)) throw InputError(what + " does not face +z (the primary datum sets z)");
      if (r > 0 && kind != Kind::cylinder && !horizontal_axis(f.normal))
        throw InputError(what + " is not a vertical plane facing ±x or ±y");
      if (r == 2 && !bore && horizontal_axis(f.normal) == a.datums[1].origin_axis)
        throw InputError(what + " is parallel to the secondary datum");
      std::string why;
      std::optional<DatumFeature> d = b.feature(f, roles[r], kind, !bore, &why);
      if (!d) throw InputError(what + ": " + why);
      a.datums.push_back(std::move(*d));
    }
    a.reason = "datums named on the command line";
  } else {
    // Largest first, ties to the lower index.
    std::vector<std::size_t> order(faces.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return faces[x].area > faces[y].area; });
    std::string missing;
    auto pick = [&](char role, Kind kind, bool sets_origin, auto&& fits) -> bool {
      for (std::size_t k : order) {
        if (!fits(faces[k])) continue;
        std::string why;
        if (std::optional<DatumFeature> d = b.feature(faces[k], role, kind, sets_origin, &why)) {
          a.datums.push_back(std::move(*d));
          return true;
        }
      }
      return false;
    };
    auto wall = [](const FaceInfo& f) { return f.plane && horizontal_axis(f.normal) != 0; };
    if (!pick('A', Kind::plane, true, [](const FaceInfo& f) { return f.plane && faces_up(f.normal); })) {
      missing = "no plane facing +z with 3 reachable points";
    } else {
      const int after_a = b.order;
      const bool walls = pick('B', Kind::line, true, wall) && pick('C', Kind::point, true, [&](const FaceInfo& f) {
                           return wall(f) && horizontal_axis(f.normal) != a.datums[1].origin_axis;
                         });
      if (walls) {
        a.reason = "largest plane facing +z, largest wall, largest wall perpendicular to it";
      } else {
        // No two perpendicular walls: a bore or boss for the in-plane
        // origin, a wall for the direction.
        a.datums.resize(1);
        b.order = after_a;
        const bool bore = pick('B', Kind::cylinder, false,
                               [&](const FaceInfo& f) { return vertical_cylinder(part.faces[f.index]); }) &&
                          pick('C', Kind::line, false, wall);
        if (bore)
          a.reason = "largest plane facing +z, largest bore or boss perpendicular to it, largest wall";
        else
          missing = "no two perpendicular walls with 2 and 1 reachable points, nor a bore or boss perpendicular to "
                    "the primary plane with a wall";
      }
    }
    if (!missing.empty()) {
      // Free-form part: three spread points on the largest face with any.
      a = PartAlignment{};
      a.method = PartAlignment::Method::free_form;
      for (std::size_t k : order) {
        const std::vector<Candidate> c = candidates(part.faces[k], finder, probe, access_in, o);
        const std::vector<std::size_t> pts = spread(c, o.manual_points);
        if (static_cast<int>(pts.size()) < o.manual_points) continue;
        int n = 0;
        for (std::size_t p : pts) {
          ++n;
          a.manual.push_back(plan_point(part, k, c[p], "M" + std::to_string(n), n, probe, access_in));
        }
        break;
      }
      if (a.manual.empty())
        throw InputError("part alignment: " + missing + ", and no face holds " + std::to_string(o.manual_points) +
                         " reachable points for a manual best-fit alignment");
      a.reason = missing + ": best fit on " + std::to_string(a.manual.size()) + " manual points of " +
                 describe_face(part, a.manual[0].face_index) + ", refined by furrow compare's registration";
      return a;
    }
  }
  for (const DatumFeature& d : a.datums) {
    if (d.kind == Kind::cylinder) a.origin.x() = d.origin.x(), a.origin.y() = d.origin.y();
    if (d.origin_axis == 'X') a.origin.x() = d.origin.x();
    if (d.origin_axis == 'Y') a.origin.y() = d.origin.y();
    if (d.origin_axis == 'Z') a.origin.z() = d.origin.z();
  }
  std::ostringstream r;
  r << a.reason << "; datum frame origin (" << fmt(a.origin.x()) << ", " << fmt(a.origin.y()) << ", "
    << fmt(a.origin.z()) << ")";
  a.reason = r.str();
  return a;
}

}  // namespace furrow

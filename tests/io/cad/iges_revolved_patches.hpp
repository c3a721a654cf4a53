#pragma once
// Patches of spheres (and, at the end, of cylinders and tori) written as
// IGES trimmed surfaces of revolution the way CATIA/NX-class systems write
// them (tests/io/cad/iges_writer.hpp): a type 144 trimmed surface of a type
// 120 surface of revolution (type 110 axis, type 100 circular arc or type
// 110 line generatrix), whose outer boundary is a type 142 curve on surface
// carrying both a parameter-space curve (B: straight pieces in the surface's
// (u, v), as type 126 B-splines or type 110 lines, in a type 102 composite)
// and a model-space curve (C: circles of latitude and longitude, rulings,
// as type 126 B-splines, rational for circles, in a type 102).
//
// Type 120 is parametrised by u, the generatrix's own parameter, and v, the
// rotation angle about the axis (right-handed about the axis line's
// direction) from the start angle SA to the terminate angle TA; a type 100
// arc's own parameter is its angle, counterclockwise from the definition
// space's x axis, the start angle taken in [0, 2 pi) (as OpenCASCADE reads
// it; the tests' centroids confirm the geometry), a type 110 line's runs
// from 0 to 1. Writers differ in what u they put in the parameter-space
// curves: the arc's angle so defined, a signed angle (the same arc taken
// from -90 to 90 degrees), or a parameter normalised to [0, 1].
#include <Eigen/Core>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "iges_writer.hpp"

namespace furrow::test {

// A circular hole in a sphere patch: the circle of angular radius `alpha`
// around the direction of rotation angle `theta` and latitude `phi` from the
// centre, written as one type 126 (a full rational circle) and given by
// that model-space curve only (type 142 PPTR 0). `reversed`: the circle runs
// the other way round.
struct SphereHole {
  double theta = 0, phi = 0, alpha = 0.5;
  bool reversed = false;
};

// How the parameter-space curves give the generatrix parameter u.
enum class ArcParameter {
  standard,    // the arc's angle as IGES defines it (start angle in [0, 2 pi))
  signed_angle,  // the angle taken in (-pi, pi]: -pi/2 .. pi/2 for the south-to-north arc
  normalised,  // (angle - start angle) / sweep, in [0, 1]
};

inline const char* name_of(ArcParameter p) {
  switch (p) {
    case ArcParameter::standard: return "arc angle";
    case ArcParameter::signed_angle: return "signed arc angle";
    case ArcParameter::normalised: return "normalised arc parameter";
  }
  return "?";
}

struct SpherePatch {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 4.75;
  // The face: rotation angle theta0..theta1 about the axis (IGES v, as the
  // file writes it: may lie outside [SA, TA] by a period when the patch
  // crosses the seam), latitude phi0..phi1 (-pi/2 south pole .. pi/2 north).
  double theta0 = 0, theta1 = M_PI, phi0 = 0, phi1 = M_PI / 2;
  // The surface's start and terminate angles.
  double start_angle = 0, end_angle = 2 * M_PI;
  // The generatrix is the half circle from the south pole to the north pole.
  // Without a transformation it is written in the x-y plane of the world
  // (arc angles 3 pi/2 .. 5 pi/2, axis +y); with one, as the arc 0 .. pi of
  // its definition space turned onto the same place by a type 124.
  bool generatrix_transformed = false;
  // Without a transformation, the generatrix may also run from the north
  // pole to the south pole on the -x side (arc angles pi/2 .. 3 pi/2), and
  // the axis line may point along -y; the file's v then runs otherwise than
  // theta (v = theta - pi, -theta or pi - theta, moved by a period into
  // [0, 2 pi)), and so do the surface's normal and the loop's sense.
  bool north_to_south = false;
  bool axis_reversed = false;
  ArcParameter parameter = ArcParameter::standard;
  bool reversed_loop = false;  // the loop's direction in (u, v)
  bool line_pcurves = false;   // B pieces as type 110 lines instead of type 126
  bool polyline_pcurves = false;  // ... or as type 106 form 11 (2-D linear paths)
  int pref = 0;                // type 142 PREF
  int crtn = 0;                // type 142 CRTN (how the curve was made)
  std::vector<SphereHole> holes;  // inner boundaries (model-space curves only)
  // Whether the parameter-space curve runs along a degenerate pole edge
  // (B then has one piece more than C, which has no curve there).
  bool pcurve_along_pole = true;
  // Meridians that cross the equator written as two pieces meeting there
  // (the report's quarter: half a great circle and two quarter circles).
  bool split_at_equator = false;
  // The boundary as model-space curves only (type 142 PPTR = 0, as the
  // report's CATIA file writes every boundary): no parameter-space curve.
  bool model_space_only = false;
  // Meridians as type 100 circular arcs placed by a type 124 (as the
  // report's file has its quarter circles) instead of type 126 B-splines.
  bool arc_meridians = false;

  // The patch less its holes (each a cap of area 2 pi R^2 (1 - cos alpha)).
  double area() const {
    double holes_area = 0;
    for (const SphereHole& h : holes) holes_area += 2 * M_PI * radius * radius * (1 - std::cos(h.alpha));
    return radius * radius * std::abs(theta1 - theta0) * (std::sin(phi1) - std::sin(phi0)) - holes_area;
  }
  // Unit direction from the centre of rotation angle theta and latitude phi.
  static Eigen::Vector3d direction(double theta, double phi) {
    return std::cos(phi) * (std::cos(theta) * Eigen::Vector3d::UnitX() - std::sin(theta) * Eigen::Vector3d::UnitZ()) +
           std::sin(phi) * Eigen::Vector3d::UnitY();
  }
  // The file's v (rotation angle of the type 120) of the angle theta.
  double file_v(double theta) const {
    const double sign = axis_reversed ? -1 : 1;
    auto raw = [&](double t) { return sign * t + (north_to_south ? -sign * M_PI : 0.0); };
    double shift = 0;
    if (north_to_south || axis_reversed) {
      const double low = std::min(raw(theta0), raw(theta1));
      while (low + shift < -1e-12) shift += 2 * M_PI;
      while (low + shift >= 2 * M_PI - 1e-12) shift -= 2 * M_PI;
    }
    return raw(theta) + shift;
  }
  // A lune from pole to pole whose meridians lie on or across the seam of
  // a whole revolution in the file's v: given by model-space curves only,
  // nothing in the face tells it from the rest of the sphere (the importer
  // goes by the loop's direction; docs/formats.md "IGES boundaries").
  bool seam_lune() const {
    const double a = std::min(file_v(theta0), file_v(theta1)), b = std::max(file_v(theta0), file_v(theta1));
    const bool whole = end_angle - start_angle >= 2 * M_PI - 1e-12;
    return phi0 <= -M_PI / 2 + 1e-12 && phi1 >= M_PI / 2 - 1e-12 && whole &&
           (a <= start_angle + 1e-12 || b >= end_angle - 1e-12);
  }
  std::string name() const {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "sphere theta %.4f..%.4f phi %.4f..%.4f SA/TA %.4f..%.4f %s%s, %s, %s pcurves, PREF %d%s",
                  theta0, theta1, phi0, phi1, start_angle, end_angle, name_of(parameter),
                  generatrix_transformed ? " (arc 0..pi, type 124)" : " (arc 3pi/2..5pi/2)",
                  reversed_loop ? "loop reversed" : "loop as built",
                  polyline_pcurves ? "type 106" : line_pcurves ? "type 110" : "type 126", pref,
                  pcurve_along_pole ? "" : ", no pcurve along the pole");
    auto append = [&](const char* text) {
      std::snprintf(buf + std::strlen(buf), sizeof buf - std::strlen(buf), "%s", text);
    };
    if (crtn != 0) append((", CRTN " + std::to_string(crtn)).c_str());
    if (model_space_only) append(", model-space curves only");
    if (!holes.empty()) append((", " + std::to_string(holes.size()) + " hole(s)").c_str());
    if (split_at_equator) append(", meridians split at the equator");
    if (north_to_south) append(", generatrix north to south");
    if (axis_reversed) append(", axis -y");
    return buf;
  }
};

// Analytic centroid of the patch (holes not taken out): over
// theta0..theta1, phi0..phi1 with the area element R^2 cos(phi), of
// c + R (cos phi (cos theta x - sin theta z) + sin phi y).
inline Eigen::Vector3d patch_centroid(const SpherePatch& p) {
  auto cos2 = [](double phi) { return phi / 2 + std::sin(2 * phi) / 4; };  // integral of cos^2
  const double measure = (p.theta1 - p.theta0) * (std::sin(p.phi1) - std::sin(p.phi0));
  const double c2 = cos2(p.phi1) - cos2(p.phi0);
  const double sc = (std::pow(std::sin(p.phi1), 2) - std::pow(std::sin(p.phi0), 2)) / 2;
  const Eigen::Vector3d mean(c2 * (std::sin(p.theta1) - std::sin(p.theta0)), sc * (p.theta1 - p.theta0),
                             c2 * (std::cos(p.theta1) - std::cos(p.theta0)));
  return p.centre + p.radius * mean / measure;
}

// Writes the patch's surface (a type 120 and its axis and generatrix) into
// `b`; returns the type 120's DE pointer and sets `arc_start`, the
// generatrix arc's IGES start angle (of the south pole, or the north pole
// when the generatrix runs north to south).
inline int write_sphere_surface(IgesBuilder& b, const SpherePatch& p, double& arc_start) {
  const Eigen::Vector3d Y = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d& c = p.centre;
  const double R = p.radius;
  // Axis +y through the centre (v turns x toward -z), or -y.
  const int axis = b.line(c, c + (p.axis_reversed ? -Y : Y));
  int generatrix;
  if (p.generatrix_transformed) {
    // Definition space: centre 0, from (R, 0) to (-R, 0) through (0, R);
    // x_def -> -y (south pole), y_def -> +x (equator), z_def -> +z.
    Eigen::Matrix3d rot;
    rot << 0, 1, 0, -1, 0, 0, 0, 0, 1;
    const int t = b.transformation(rot, c);
    generatrix = b.arc(0, {0, 0}, {R, 0}, {-R, 0}, t);
    arc_start = 0;
  } else if (p.north_to_south) {
    generatrix = b.arc(c.z(), {c.x(), c.y()}, {c.x(), c.y() + R}, {c.x(), c.y() - R});
    arc_start = 0.5 * M_PI;
  } else {
    generatrix = b.arc(c.z(), {c.x(), c.y()}, {c.x(), c.y() - R}, {c.x(), c.y() + R});
    arc_start = 1.5 * M_PI;
  }
  return b.revolution(axis, generatrix, p.start_angle, p.end_angle);
}

// A circle on the sphere of angular radius `alpha` about the unit direction
// `d` from its centre, as one closed type 126 from the point farthest from
// the axis's +y end round to it again; counterclockwise about d (seen from
// outside the sphere) unless `reversed`. Returns the curve's DE pointer.
inline int write_sphere_circle(IgesBuilder& b, const Eigen::Vector3d& centre, double radius, const Eigen::Vector3d& d,
                               double alpha, bool reversed) {
  Eigen::Vector3d e1 = -(Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitY().dot(d) * d);
  if (e1.norm() < 1e-12) e1 = Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(d) * d;
  e1.normalize();
  const Eigen::Vector3d e2 = d.cross(e1);
  return b.bspline_arc(centre + radius * std::cos(alpha) * d, e1, e2, radius * std::sin(alpha), reversed ? 2 * M_PI : 0,
                       reversed ? 0 : 2 * M_PI);
}

// Writes the patch's entities into `b`; returns the type 144's DE pointer.
inline int write_sphere_patch(IgesBuilder& b, const SpherePatch& p) {
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d& c = p.centre;
  const double R = p.radius;
  double arc_start = 0;
  const int surface = write_sphere_surface(b, p, arc_start);

  // u of latitude phi (the arc's angle is arc_start + phi + pi/2, or pi - phi
  // from the north).
  auto u_of = [&](double phi) {
    if (p.north_to_south) {
      const double angle = M_PI - phi;
      return p.parameter == ArcParameter::normalised ? (angle - arc_start) / M_PI : angle;
    }
    switch (p.parameter) {
      case ArcParameter::standard: return arc_start + phi + M_PI / 2;
      case ArcParameter::signed_angle: return arc_start == 0 ? phi + M_PI / 2 : phi;
      case ArcParameter::normalised: return (phi + M_PI / 2) / M_PI;
    }
    return 0.0;
  };
  // Corners in running order (phi, theta); the loop as built runs along
  // phi0 first (the equator of the report's quarter), then up theta1.
  struct Corner {
    double phi, theta;
  };
  std::vector<Corner> corners{{p.phi0, p.theta0}, {p.phi0, p.theta1}, {p.phi1, p.theta1}, {p.phi1, p.theta0}};
  if (p.reversed_loop) corners = {corners[0], corners[3], corners[2], corners[1]};
  auto v_of = [&](double theta) { return p.file_v(theta); };
  std::vector<int> b_pieces, c_pieces;
  auto piece = [&](const Corner& a, const Corner& e) {
    const bool pole = std::abs(a.phi - e.phi) < 1e-15 && std::abs(std::abs(a.phi) - M_PI / 2) < 1e-15;
    const Eigen::Vector3d ua(u_of(a.phi), v_of(a.theta), 0), ue(u_of(e.phi), v_of(e.theta), 0);
    if (!p.model_space_only && (!pole || p.pcurve_along_pole))
      b_pieces.push_back(p.polyline_pcurves ? b.polyline_2d({ua.head<2>(), ue.head<2>()}, IgesBuilder::kParametric)
                         : p.line_pcurves ? b.line(ua, ue, IgesBuilder::kParametric)
                                        : b.bspline_line(ua, ue, 0, 1, true, IgesBuilder::kParametric));
    if (pole) return;  // no model-space curve along a pole
    if (std::abs(a.phi - e.phi) < 1e-15) {
      // A circle of latitude: centre on the axis, angle theta.
      const Eigen::Vector3d centre = c + R * std::sin(a.phi) * Y;
      c_pieces.push_back(b.bspline_arc(centre, X, -Z, R * std::cos(a.phi), a.theta, e.theta));
    } else {
      // A meridian: angle phi in the plane of the axis and the direction theta.
      const Eigen::Vector3d d = std::cos(a.theta) * X - std::sin(a.theta) * Z;
      if (p.arc_meridians) {
        // A type 100 runs counterclockwise in its definition space: going
        // down, its y axis is -y (the angle there is -phi).
        const double s = e.phi > a.phi ? 1 : -1;
        Eigen::Matrix3d rot;
        rot.col(0) = d;
        rot.col(1) = s * Y;
        rot.col(2) = d.cross(s * Y);
        const int t = b.transformation(rot, c);
        c_pieces.push_back(b.arc(0, {0, 0}, R * Eigen::Vector2d(std::cos(s * a.phi), std::sin(s * a.phi)),
                                 R * Eigen::Vector2d(std::cos(s * e.phi), std::sin(s * e.phi)), t));
      } else {
        c_pieces.push_back(b.bspline_arc(c, d, Y, R, a.phi, e.phi));
      }
    }
  };
  for (std::size_t k = 0; k < 4; ++k) {
    const Corner& a = corners[k];
    const Corner& e = corners[(k + 1) % 4];
    if (p.split_at_equator && a.theta == e.theta && (a.phi < 0) != (e.phi < 0) && a.phi != 0 && e.phi != 0) {
      piece(a, {0, a.theta});
      piece({0, a.theta}, e);
    } else {
      piece(a, e);
    }
  }
  const int bc = p.model_space_only ? 0 : b.composite(b_pieces, IgesBuilder::kParametric);
  const int cc = b.composite(c_pieces);
  const int boundary = b.curve_on_surface(surface, bc, cc, p.pref, p.crtn);
  std::vector<int> inner;
  for (const SphereHole& h : p.holes)
    inner.push_back(b.curve_on_surface(
        surface, 0, write_sphere_circle(b, c, R, SpherePatch::direction(h.theta, h.phi), h.alpha, h.reversed), p.pref,
        p.crtn));
  return b.trimmed_surface(surface, boundary, inner);
}

}  // namespace furrow::test

namespace furrow::test {

// Patches of cylinders and tori as type 120 surfaces of revolution about the
// axis +y through `centre`: a cylinder's generatrix is a type 110 line
// parallel to the axis at distance `radius` (u in [0, 1] from its start at
// the centre's height to `height` above it, the IGES parametrisation of a
// line), a torus's a full type 100 circle of radius `radius` whose centre is
// `major` from the axis (u its angle psi, counterclockwise from the
// outermost point). The face is s0..s1 in u and theta0..theta1 in v.
struct RevolvedPatch {
  enum class Kind { cylinder, torus } kind = Kind::cylinder;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 4.75, height = 10, major = 14.25;
  double theta0 = 0, theta1 = M_PI, s0 = 0, s1 = 1;
  bool reversed_loop = false;
  int pref = 0;
  int crtn = 0;  // type 142 CRTN
  bool model_space_only = false;  // type 142 PPTR = 0: no parameter-space curve

  // Generatrix point at u = s, relative to the centre, in the x-y plane.
  Eigen::Vector2d generatrix(double s) const {
    if (kind == Kind::cylinder) return {radius, height * s};
    return {major + radius * std::cos(s), radius * std::sin(s)};
  }
  Eigen::Vector3d point(double s, double theta) const {
    const Eigen::Vector2d g = generatrix(s);
    return centre + Eigen::Vector3d(g.x() * std::cos(theta), g.y(), -g.x() * std::sin(theta));
  }
  double area() const {
    const double dt = std::abs(theta1 - theta0);
    if (kind == Kind::cylinder) return radius * dt * height * std::abs(s1 - s0);
    // Integral of radius (major + radius cos psi) dpsi dtheta.
    return radius * dt * std::abs(major * (s1 - s0) + radius * (std::sin(s1) - std::sin(s0)));
  }
  std::string name() const {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s theta %.4f..%.4f u %.4f..%.4f, %s, PREF %d, CRTN %d%s",
                  kind == Kind::cylinder ? "cylinder" : "torus", theta0, theta1, s0, s1,
                  reversed_loop ? "loop reversed" : "loop as built", pref, crtn,
                  model_space_only ? ", model-space curves only" : "");
    return buf;
  }
};

// `holes`: model-space curves already in `b` (closed, on the patch), each
// written as an inner boundary without a parameter-space curve (type 142
// PPTR 0) with the patch's PREF and CRTN.
inline int write_revolved_patch(IgesBuilder& b, const RevolvedPatch& p, const std::vector<int>& holes = {}) {
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d& c = p.centre;
  const int axis = b.line(c, c + Y);
  int generatrix;
  if (p.kind == RevolvedPatch::Kind::cylinder) {
    generatrix = b.line(c + p.radius * X, c + p.radius * X + p.height * Y);
  } else {
    const Eigen::Vector2d centre(c.x() + p.major, c.y()), start(c.x() + p.major + p.radius, c.y());
    generatrix = b.arc(c.z(), centre, start, start);
  }
  const int surface = b.revolution(axis, generatrix, 0, 2 * M_PI);
  struct Corner {
    double s, theta;
  };
  std::vector<Corner> corners{{p.s0, p.theta0}, {p.s0, p.theta1}, {p.s1, p.theta1}, {p.s1, p.theta0}};
  if (p.reversed_loop) corners = {corners[0], corners[3], corners[2], corners[1]};
  std::vector<int> b_pieces, c_pieces;
  for (std::size_t k = 0; k < 4; ++k) {
    const Corner& a = corners[k];
    const Corner& e = corners[(k + 1) % 4];
    if (!p.model_space_only)
      b_pieces.push_back(
          b.bspline_line({a.s, a.theta, 0}, {e.s, e.theta, 0}, 0, 1, true, IgesBuilder::kParametric));
    if (a.s == e.s) {  // a circle about the axis
      const Eigen::Vector2d g = p.generatrix(a.s);
      c_pieces.push_back(b.bspline_arc(c + g.y() * Y, X, -Z, g.x(), a.theta, e.theta));
    } else if (p.kind == RevolvedPatch::Kind::cylinder) {  // a ruling
      c_pieces.push_back(b.bspline_line(p.point(a.s, a.theta), p.point(e.s, e.theta), 0, 1, false));
    } else {  // a circle of the tube
      const Eigen::Vector3d d = std::cos(a.theta) * X - std::sin(a.theta) * Z;
      c_pieces.push_back(b.bspline_arc(c + p.major * d, d, Y, p.radius, a.s, e.s));
    }
  }
  const int bc = p.model_space_only ? 0 : b.composite(b_pieces, IgesBuilder::kParametric);
  const int cc = b.composite(c_pieces);
  std::vector<int> inner;
  for (const int hole : holes) inner.push_back(b.curve_on_surface(surface, 0, hole, p.pref, p.crtn));
  return b.trimmed_surface(surface, b.curve_on_surface(surface, bc, cc, p.pref, p.crtn), inner);
}

}  // namespace furrow::test

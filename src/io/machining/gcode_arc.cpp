#include "io/machining/gcode_arc.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

// In-plane axes (u, v) and the normal w, ordered so that u x v = w: then
// counter-clockwise in (u, v) is counter-clockwise seen from +w.
void plane_axes(ArcPlane plane, int& u, int& v, int& w) {
  switch (plane) {
    case ArcPlane::xy: u = 0, v = 1, w = 2; return;
    case ArcPlane::zx: u = 2, v = 0, w = 1; return;
    case ArcPlane::yz: u = 1, v = 2, w = 0; return;
  }
  u = 0, v = 1, w = 2;
}

std::string mm(double x) { return general(x) + " mm"; }

}  // namespace

std::vector<Eigen::Vector3d> flatten_arc(const ArcMove& arc, const ArcTolerances& tol) {
  int u, v, w;
  plane_axes(arc.plane, u, v, w);
  const Eigen::Vector2d s(arc.start[u], arc.start[v]);
  const Eigen::Vector2d e(arc.end[u], arc.end[v]);
  const double chord = (e - s).norm();
  const bool same = chord <= tol.same_point;

  Eigen::Vector2d c;
  if (arc.by_radius) {
    if (arc.radius == 0) throw InputError("arc radius R is zero");
    if (same)
      throw InputError("an R-format arc cannot be a full circle (start and end are the same point; give I J K)");
    const double r = std::abs(arc.radius);
    const double half = chord / 2;
    if (half - r > std::max(tol.radius_absolute, tol.radius_relative * r))
      throw InputError("arc radius R " + mm(r) + " is smaller than half the chord " + mm(half));
    const double h = std::sqrt(std::max(0.0, r * r - half * half));
    const Eigen::Vector2d left = Eigen::Vector2d(-(e - s).y(), (e - s).x()) / chord;
    // Short arc (R > 0): the centre lies to the right of the chord for G2, to
    // the left for G3; R < 0 puts it on the other side (the long arc).
    double side = arc.clockwise ? -1.0 : 1.0;
    if (arc.radius < 0) side = -side;
    c = (s + e) / 2 + side * h * left;
  } else {
    c = s + Eigen::Vector2d(arc.centre_offset[u], arc.centre_offset[v]);
  }

  const double r0 = (s - c).norm();
  const double r1 = (e - c).norm();
  if (!(r0 > 0) || !(r1 > 0)) throw InputError("arc radius is zero (the centre is on the start or end point)");
  const double allowed = std::max(tol.radius_absolute, tol.radius_relative * std::max(r0, r1));
  if (std::abs(r1 - r0) > allowed)
    throw InputError("arc start radius " + mm(r0) + " and end radius " + mm(r1) + " differ by more than " +
                     mm(allowed));

  const double a0 = std::atan2(s.y() - c.y(), s.x() - c.x());
  const double a1 = std::atan2(e.y() - c.y(), e.x() - c.x());
  double sweep;  // signed: > 0 counter-clockwise
  if (same && !arc.by_radius) {
    sweep = 2 * kPi;
  } else {
    sweep = arc.clockwise ? a0 - a1 : a1 - a0;
    if (sweep <= 0) sweep += 2 * kPi;
  }
  if (arc.clockwise) sweep = -sweep;

  const double rmax = std::max(r0, r1);
  double step = kPi / 2;
  if (tol.sag < rmax) step = std::min(step, 2 * std::acos(1 - tol.sag / rmax));
  const double segments = std::max(1.0, std::ceil(std::abs(sweep) / step));
  if (segments > static_cast<double>(limits::kMaxFilePoints))
    throw InputError("the arc needs more than " + std::to_string(limits::kMaxFilePoints) +
                     " points at the chord tolerance " + mm(tol.sag));
  const long n = static_cast<long>(segments);

  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<std::size_t>(n));
  for (long k = 1; k < n; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(n);
    const double a = a0 + sweep * t;
    const double r = r0 + (r1 - r0) * t;
    Eigen::Vector3d p;
    p[u] = c.x() + r * std::cos(a);
    p[v] = c.y() + r * std::sin(a);
    p[w] = arc.start[w] + (arc.end[w] - arc.start[w]) * t;
    points.push_back(p);
  }
  points.push_back(arc.end);  // exact, not recomputed from the angle
  return points;
}

}  // namespace furrow

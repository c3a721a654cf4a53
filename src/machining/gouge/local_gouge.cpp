#include "machining/gouge/local_gouge.hpp"
#include "base/numbers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

namespace {

constexpr double kTwoPi = 2 * kPi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// A piece of the cutting surface: its curvatures over a window of angles.
struct CutterPiece {
  AngularRange window;
  double k_max, k_min;
  bool sharp;
};

int cutter_pieces(const CutterCurvature& c, std::array<CutterPiece, 2>& pieces) {
  if (c.side) {
    // dir_max = +z at a side contact, so t . z > 0 is -90..90 degrees: the
    // cylindrical side (straight up, 1/R around); below, the corner arc.
    pieces[0] = {{1.5 * kPi, kPi}, 0.0, c.side_k_min, false};
    pieces[1] = {{0.5 * kPi, kPi}, c.k_max, c.k_min, c.sharp};
    return 2;
  }
  if (!c.flat_bottom) {
    pieces[0] = {{0.0, kTwoPi}, c.k_max, c.k_min, c.sharp};
    return 1;
  }
  // dir_max = -e at a horizontal contact, so t . e > 0 is 90..270 degrees.
  pieces[0] = {{0.5 * kPi, kPi}, 0.0, 0.0, false};
  pieces[1] = {{1.5 * kPi, kPi}, c.k_max, c.k_min, c.sharp};
  return 2;
}

// f(a) = A + D cos(2a - psi) for one surface against one cutter piece.
struct Excess {
  double A = 0, D = 0, psi = 0;
  double at(double a) const { return A + D * std::cos(2 * a - psi); }
};

// Part curvature in the cutter frame: mean, half-difference and the double
// angle of d1 from dir_max (as cos 2phi, sin 2phi).
struct PartInFrame {
  double mean, half_diff, cos2phi, sin2phi;
  double at(double a) const {  // Euler: k1 cos^2(a - phi) + k2 sin^2(a - phi)
    return mean + half_diff * (std::cos(2 * a) * cos2phi + std::sin(2 * a) * sin2phi);
  }
};

PartInFrame part_in_frame(const DifferentialGeometry& g, const CutterCurvature& c) {
  double cm = g.d1.dot(c.dir_max), cc = g.d1.dot(c.dir_min);
  const double len2 = cm * cm + cc * cc;
  PartInFrame p{0.5 * (g.k1 + g.k2), 0.5 * (g.k1 - g.k2), 1.0, 0.0};
  if (len2 > 0) {
    p.cos2phi = (cm * cm - cc * cc) / len2;
    p.sin2phi = 2 * cm * cc / len2;
  }
  return p;
}

Excess excess(const PartInFrame& p, const CutterPiece& piece) {
  Excess e;
  e.A = p.mean - 0.5 * (piece.k_max + piece.k_min);
  const double B = p.half_diff * p.cos2phi - 0.5 * (piece.k_max - piece.k_min);
  const double C = p.half_diff * p.sin2phi;
  e.D = std::sqrt(B * B + C * C);  // curvatures: no overflow to guard against
  e.psi = std::atan2(C, B);
  return e;
}

// Largest f over the arc [lo, lo + w]; `where` receives the angle.
double max_over(const Excess& f, const AngularRange& arc, double& where) {
  // The maxima of cos(2a - psi) are at a = psi/2 + k pi.
  const double t = std::fmod(wrap_angle(0.5 * f.psi - arc.start), kPi);
  if (t <= arc.width) {
    where = arc.start + t;
    return f.A + f.D;
  }
  const double lo = f.at(arc.start), hi = f.at(arc.end());
  where = lo >= hi ? arc.start : arc.end();
  return std::max(lo, hi);
}

// Arcs of the whole circle where f > tol (0, 1 = full circle, or 2 arcs).
void gouge_arcs(const Excess& f, double tol, AngularRanges& out) {
  if (!(f.D > 0)) {
    if (f.A > tol) out.add(0.0, kTwoPi);
    return;
  }
  const double c = (tol - f.A) / f.D;
  if (c >= 1) return;
  if (c < -1) {
    out.add(0.0, kTwoPi);
    return;
  }
  const double beta = std::acos(c);  // half-width in 2a
  out.add(0.5 * (f.psi - beta), beta);
  out.add(0.5 * (f.psi - beta) + kPi, beta);
}

// Windows of a side: the intersection of its half-planes, as arcs.
AngularRanges side_windows(const SurfaceSide& side, const CutterCurvature& c) {
  AngularRanges windows;
  windows.add(0.0, kTwoPi);
  for (int i = 0; i < side.inward_count; ++i) {
    const Eigen::Vector3d& in = side.inward[i];
    const double alpha = std::atan2(in.dot(c.dir_min), in.dot(c.dir_max));
    const AngularRange half{wrap_angle(alpha - 0.5 * kPi), kPi};
    AngularRanges clipped;
    for (const AngularRange& w : windows) clipped.add_clipped(w, half);
    windows = clipped;
  }
  return windows;
}

}  // namespace

const char* to_string(GougeStatus status) {
  switch (status) {
    case GougeStatus::clear: return "clear";
    case GougeStatus::gouge: return "gouge";
    case GougeStatus::unreachable: return "unreachable";
    case GougeStatus::degenerate: return "degenerate";
    case GougeStatus::concave_crease: return "concave_crease";
  }
  return "?";
}

LocalGouge check_local_gouge(const Cutter& cutter, const DifferentialGeometry& part,
                             const GougeOptions& options) {
  SurfaceSide side;
  side.geometry = &part;
  return check_local_gouge(cutter, part.normal, &side, 1, options);
}

LocalGouge check_local_gouge(const Cutter& cutter, const Eigen::Vector3d& contact_normal,
                             const SurfaceSide* sides, std::size_t side_count,
                             const GougeOptions& options) {
  LocalGouge result;
  for (std::size_t s = 0; s < side_count; ++s) {
    if (sides[s].geometry->degenerate) {
      result.status = GougeStatus::degenerate;
      return result;
    }
  }
  result.cutter = cutter_curvature(cutter, contact_normal, options.location);
  if (!result.cutter.reachable) {
    result.status = GougeStatus::unreachable;
    return result;
  }
  const double tol = options.curvature_tolerance;
  std::array<CutterPiece, 2> pieces;
  const int piece_count = cutter_pieces(result.cutter, pieces);

  if (options.quick_accept) {
    double k1 = -kInf, k_min = kInf;
    for (std::size_t s = 0; s < side_count; ++s) k1 = std::max(k1, sides[s].geometry->k1);
    // The smallest cutter curvature in any direction: a piece's k_max is its
    // curvature along dir_max, which is the smaller one on the straight side.
    for (int p = 0; p < piece_count; ++p)
      k_min = std::min({k_min, pieces[p].k_min, pieces[p].sharp ? kInf : pieces[p].k_max});
    if (k1 <= k_min + tol) {
      result.status = GougeStatus::clear;
      result.quick = true;
      result.max_excess = k1 - k_min;
      return result;
    }
  }

  double best = -kInf, best_angle = 0;
  AngularRanges ranges;
  for (std::size_t s = 0; s < side_count; ++s) {
    const PartInFrame part = part_in_frame(*sides[s].geometry, result.cutter);
    const AngularRanges windows = side_windows(sides[s], result.cutter);
    for (int p = 0; p < piece_count; ++p) {
      const CutterPiece& piece = pieces[p];
      AngularRanges compared;  // side window x piece window
      for (const AngularRange& w : windows) compared.add_clipped(w, piece.window);
      if (piece.sharp) {
        // Cutting circle: only the two circumferential directions +-dir_min.
        for (const double a : {0.5 * kPi, 1.5 * kPi}) {
          if (!compared.contains(a)) continue;
          const double f = part.at(a) - piece.k_min;
          if (f > best) best = f, best_angle = a;
          if (f > tol) ranges.add(a, 0.0);
        }
        continue;
      }
      const Excess f = excess(part, piece);
      for (const AngularRange& w : compared) {
        double where = 0;
        const double m = max_over(f, w, where);
        if (m > best) best = m, best_angle = where;
      }
      if (f.A + f.D > tol) {
        AngularRanges arcs;
        gouge_arcs(f, tol, arcs);
        for (const AngularRange& arc : arcs)
          for (const AngularRange& w : compared) ranges.add_clipped(arc, w);
        ranges.normalize();  // keeps the count within capacity as pieces add up
      }
    }
  }
  result.max_excess = best;
  result.max_excess_angle = wrap_angle(best_angle);
  if (best > tol) {
    result.status = GougeStatus::gouge;
    // The arcs and the maximum come from the same f; only a maximum within
    // rounding of tol could leave no arc: report its single direction.
    if (ranges.empty()) ranges.add(best_angle, 0.0);
    // The rim's single directions come after the last merge: a side
    // contact's lie on the ends of the side's arcs (one range, not three).
    ranges.normalize();
    result.ranges = ranges;
  } else {
    result.status = GougeStatus::clear;
  }
  return result;
}

}  // namespace furrow

#include "machining/toolpath/contact_planning.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/zmap.hpp"
#include "base/numbers.hpp"

namespace furrow {

PassDirectionSpec parse_pass_direction(const std::string& text, const std::string& where) {
  if (text == "u") return {PassDirection::along_u, 0};
  if (text == "v") return {PassDirection::along_v, 0};
  if (text.rfind("plane:", 0) == 0) {
    const std::string number = text.substr(6);
    char* end = nullptr;
    const double angle = std::strtod(number.c_str(), &end);
    if (!number.empty() && end == number.c_str() + number.size() && std::isfinite(angle))
      return {PassDirection::plane, angle};
  }
  throw InputError(where + ": " + quote_field(text) + " is not a direction (expected u, v or plane:ANGLE in degrees)");
}

std::string to_string(const PassDirectionSpec& d) {
  if (d.kind == PassDirection::along_u) return "u";
  if (d.kind == PassDirection::along_v) return "v";
  std::ostringstream s;
  s << "plane:" << d.angle_deg;
  return s.str();
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMinToleranceMm = 1e-4, kMaxToleranceMm = 10;

// One family of passes: iso-parametric on a face, or iso-planar over the
// part. A pass is a level (v, u or plane offset) and a t range along it.
struct Family {
  const Part* part = nullptr;
  const VerticalProjector* projector = nullptr;
  int face = -1;  // iso-parametric; -1 for planes
  bool along_u = true;
  Eigen::Vector2d d{1, 0}, m{0, 1};  // plane: direction along and across (xy, unit)
  double level0 = 0, level1 = 0;
  double t0 = 0, t1 = 0;
  int samples = 2;  // along a pass

  PassCurve pass(double level, double a, double b) const {
    if (face >= 0) return iso_parametric_pass(*part, face, along_u, level, a, b);
    return iso_planar_pass(*projector, level * m, d, a, b);
  }
  double t(int k) const { return t0 + (t1 - t0) * k / samples; }
};

struct Interval {
  double level, a, b;
};

bool usable(const Part& part, const SurfacePoint& p, double min_nz) {
  return p.valid && p.normal.z() >= min_nz && part.faces[p.face].contains(p.uv.x(), p.uv.y());
}

// The usable pieces of the pass at `level`, ends refined by bisection.
std::vector<Interval> usable_intervals(const Family& f, double level, double min_nz) {
  const PassCurve c = f.pass(level, f.t0, f.t1);
  std::vector<char> ok(f.samples + 1);
  for (int k = 0; k <= f.samples; ++k) ok[k] = usable(*f.part, c.at(f.t(k)), min_nz);
  auto edge = [&](double in, double out) {
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (in + out);
      (usable(*f.part, c.at(mid), min_nz) ? in : out) = mid;
    }
    return in;
  };
  std::vector<Interval> result;
  for (int k = 0; k <= f.samples;) {
    if (!ok[k]) {
      ++k;
      continue;
    }
    int e = k;
    while (e + 1 <= f.samples && ok[e + 1]) ++e;
    const double a = k > 0 ? edge(f.t(k), f.t(k - 1)) : f.t0;
    const double b = e < f.samples ? edge(f.t(e), f.t(e + 1)) : f.t1;
    if (b - a > 1e-9 * (f.t1 - f.t0)) result.push_back({level, a, b});
    k = e + 1;
  }
  return result;
}

// The side step w (arc across the pass) at a surface point whose pass runs
// along `along`, and the across direction (toward the next pass). `first`
// says where the point lies in the pair of contacts the step separates
// (cross_section_scallop.hpp): 0 on the pass the step starts from, -1 on
// the next one.
double side_step_at(const Family& f, const Cutter& cutter, const SurfacePoint& p, const ContactPlanOptions& o,
                    double flat_w, double first, Eigen::Vector3d& across) {
  const Face& face = f.part->faces[p.face];
  const DifferentialGeometry g = face.geometry(p.uv.x(), p.uv.y());
  if (g.degenerate) return kInf;
  Eigen::Vector3d along, next;  // next: toward the next pass
  if (f.face >= 0) {
    const SurfaceDerivatives sd = face.surface().evaluate(p.uv.x(), p.uv.y(), 1);
    along = (f.along_u ? sd.Su : sd.Sv).normalized();
    next = f.along_u ? sd.Sv : sd.Su;
  } else {
    along = Eigen::Vector3d(f.m.x(), f.m.y(), 0).cross(g.normal).normalized();
    if (along.head<2>().dot(f.d) < 0) along = -along;
    next = Eigen::Vector3d(f.m.x(), f.m.y(), 0);
  }
  across = g.normal.cross(along);
  if (across.dot(next) < 0) across = -across;
  const double k_across = g.normal_curvature(across);
  const Eigen::Vector2d across_h = across.head<2>();
  const double tilt =
      across_h.norm() > 1e-12 ? std::atan2(g.normal.head<2>().dot(across_h.normalized()), g.normal.z()) : 0.0;
  const SideStepResult s = cutter_side_step_for_scallop(cutter, k_across, tilt, o.scallop, o.cross_section, first);
  return s.feasible && s.side_step > 0 ? s.side_step : flat_w;
}

// Level increment from `level` to the next pass that keeps the scallop at
// the target at every usable sample: the side step from the curvature at
// both passes (`probe` is the candidate next level; NaN: this pass only),
// converted with the surface's mean rate across between them (the arc
// length across). +inf when no sample is usable.
double side_step(const Family& f, const Cutter& cutter, double level, double probe, const ContactPlanOptions& o) {
  const PassCurve here = f.pass(level, f.t0, f.t1);
  const bool two = std::isfinite(probe);
  const PassCurve there = f.pass(two ? probe : level, f.t0, f.t1);
  const double flat_w = cutter_side_step_for_scallop(cutter, 0.0, 0.0, o.scallop, o.cross_section).side_step;
  double best = kInf;
  for (int k = 0; k <= f.samples; ++k) {
    const SurfacePoint p = here.at(f.t(k));
    if (!usable(*f.part, p, o.min_normal_z)) continue;
    Eigen::Vector3d across;
    double w = side_step_at(f, cutter, p, o, flat_w, two ? 0.0 : -0.5, across);
    if (!std::isfinite(w)) continue;
    if (two) {
      const SurfacePoint q = there.at(f.t(k));
      Eigen::Vector3d unused;
      if (usable(*f.part, q, o.min_normal_z)) w = std::min(w, side_step_at(f, cutter, q, o, flat_w, -1.0, unused));
    }
    double rate;  // level units per mm across
    if (f.face >= 0) {
      // Mean rate between the two passes (composite midpoint rule: the
      // surface's speed may change slope at a knot between them).
      constexpr int kPieces = 8;
      const double span = two ? probe - level : 0.0;
      double speed = 0;
      for (int piece = 0; piece < kPieces; ++piece) {
        const double l = level + span * (piece + 0.5) / kPieces;
        const Eigen::Vector2d uv = f.along_u ? Eigen::Vector2d(p.uv.x(), l) : Eigen::Vector2d(l, p.uv.y());
        const SurfaceDerivatives sd = f.part->faces[p.face].surface().evaluate(uv.x(), uv.y(), 1);
        // The level derivative's part perpendicular to the pass direction.
        const Eigen::Vector3d along = (f.along_u ? sd.Su : sd.Sv).normalized();
        const Eigen::Vector3d level_dir = f.along_u ? sd.Sv : sd.Su;
        speed += (level_dir - level_dir.dot(along) * along).norm() / kPieces;
      }
      if (!(speed > 1e-12)) continue;
      rate = 1 / speed;
    } else {
      rate = std::fabs(across.head<2>().dot(f.m));
    }
    best = std::min(best, w * rate);
  }
  return best;
}

}  // namespace

ContactPlan plan_contact_points(const Part& part, const Cutter& cutter, const PassDirectionSpec& direction,
                                const ContactPlanOptions& options,
                                const std::function<void(std::size_t, std::size_t)>& progress) {
  if (!(options.forward.tolerance > 0) || !std::isfinite(options.forward.tolerance))
    throw InputError("toolpath: the tolerance must be a positive number of millimetres");
  if (!(options.scallop > 0) || !std::isfinite(options.scallop))
    throw InputError("toolpath: the scallop height must be a positive number of millimetres");
  if (!(options.sample_spacing > 0)) throw InputError("toolpath: the sample spacing must be positive");
  // Physical ranges (docs/formats.md "Limits"): below 0.1 um no machine cuts.
  for (const auto& [value, what] : {std::pair{options.forward.tolerance, "tolerance"},
                                    std::pair{options.scallop, "scallop height"}})
    if (value < kMinToleranceMm || value > kMaxToleranceMm) {
      std::ostringstream s;
      s << "toolpath: the " << what << " " << value << " mm is outside " << kMinToleranceMm << " to "
        << kMaxToleranceMm << " mm (docs/formats.md \"Limits\")";
      throw InputError(s.str());
    }
  const VerticalProjector projector(part);
  std::vector<Family> families;
  if (direction.kind == PassDirection::plane) {
    Family f;
    f.part = &part;
    f.projector = &projector;
    const double a = direction.angle_deg * kPi / 180;
    f.d = {std::cos(a), std::sin(a)};
    f.m = {-std::sin(a), std::cos(a)};
    const Eigen::AlignedBox2d box = part_xy_extent(part);
    double lmin = kInf, lmax = -kInf, tmin = kInf, tmax = -kInf;
    for (int corner = 0; corner < 4; ++corner) {
      const Eigen::Vector2d p = box.corner(static_cast<Eigen::AlignedBox2d::CornerType>(corner));
      lmin = std::min(lmin, p.dot(f.m)), lmax = std::max(lmax, p.dot(f.m));
      tmin = std::min(tmin, p.dot(f.d)), tmax = std::max(tmax, p.dot(f.d));
    }
    f.level0 = lmin, f.level1 = lmax, f.t0 = tmin, f.t1 = tmax;
    f.samples = std::max(8, static_cast<int>(std::ceil((tmax - tmin) / options.sample_spacing)));
    families.push_back(f);
  } else {
    for (std::size_t k = 0; k < part.faces.size(); ++k) {
      Family f;
      f.part = &part;
      f.projector = &projector;
      f.face = static_cast<int>(k);
      f.along_u = direction.kind == PassDirection::along_u;
      const ParameterDomain& d = part.faces[k].domain();
      f.level0 = f.along_u ? d.v0 : d.u0, f.level1 = f.along_u ? d.v1 : d.u1;
      f.t0 = f.along_u ? d.u0 : d.v0, f.t1 = f.along_u ? d.u1 : d.v1;
      const Eigen::Vector2d len = face_extent_lengths(part.faces[k]);
      f.samples = std::max(8, static_cast<int>(std::ceil((f.along_u ? len.x() : len.y()) / options.sample_spacing)));
      families.push_back(f);
    }
  }

  // The work before doing it (docs/formats.md "Limits"): the passes a flat
  // surface needs at the flat side step, and the samples along them.
  {
    const double flat_w =
        cutter_side_step_for_scallop(cutter, 0.0, 0.0, options.scallop, options.cross_section).side_step;
    double passes = 0, samples = 0;
    for (const Family& f : families) {
      double across = f.level1 - f.level0;  // plane: mm
      if (f.face >= 0) {
        const Eigen::Vector2d len = face_extent_lengths(part.faces[f.face]);
        across = f.along_u ? len.y() : len.x();
      }
      const double n = std::ceil(across / std::max(flat_w, 1e-300)) + 1;
      passes += n;
      samples += n * (f.samples + 1.0);
    }
    if (!(passes <= options.max_passes) || !(samples <= static_cast<double>(options.max_pass_samples))) {
      std::ostringstream s;
      s << "toolpath: a scallop height of " << options.scallop << " mm with this " << cutter.diameter()
        << " mm tool needs about " << passes << " passes (" << samples << " samples along them), more than the limit of "
        << options.max_passes << " passes and " << options.max_pass_samples
        << " samples (docs/formats.md \"Limits\"): use a larger scallop height or tool";
      throw InputError(s.str());
    }
  }

  // Levels, one after the other (each placed from the previous one).
  std::vector<Interval> pieces;
  std::vector<int> piece_face;
  for (const Family& f : families) {
    const double span = f.level1 - f.level0;
    // Fallback increment where nothing is usable: the flat side step over
    // the typical rate (a level with nothing on it costs nothing).
    const double flat_w = cutter_side_step_for_scallop(cutter, 0.0, 0.0, options.scallop, options.cross_section).side_step;
    double fallback = flat_w;
    if (f.face >= 0) {
      const Eigen::Vector2d len = face_extent_lengths(part.faces[f.face]);
      fallback = flat_w / std::max(f.along_u ? len.y() : len.x(), 1e-9) * span;
    }
    double level = f.level0;
    for (int count = 0;; ++count) {
      if (count >= options.max_passes)
        throw InputError("toolpath: more than " + std::to_string(options.max_passes) +
                         " passes (scallop height too small for this part?)");
      for (const Interval& i : usable_intervals(f, level, options.min_normal_z)) {
        pieces.push_back(i);
        piece_face.push_back(f.face);
      }
      if (level >= f.level1) break;
      // From this pass alone, then twice from both passes (the next one may
      // be tighter, and the rate across is taken between them).
      double step = side_step(f, cutter, level, NAN, options);
      if (!std::isfinite(step)) step = fallback;
      for (int it = 0; it < 2; ++it) {
        const double again = side_step(f, cutter, level, std::min(f.level1, level + step), options);
        if (std::isfinite(again)) step = again;
      }
      step = std::max(step, 1e-9 * std::max(span, 1.0));
      level = std::min(f.level1, level + step);
    }
  }
  if (pieces.empty()) throw InputError("toolpath: no part of the surface can be machined from above in this direction");

  ContactPlan plan;
  plan.direction = direction;
  plan.passes.resize(pieces.size());
  std::vector<int> capped(pieces.size(), 0), evaluations(pieces.size(), 0);
  std::atomic<std::size_t> done{0};
  std::atomic<bool> truncated{false};
  std::atomic<long> points_so_far{0};
  ContactPlanOptions bounded = options;
  bounded.forward.max_points = std::min(options.forward.max_points, options.max_points);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Interval& i = pieces[k];
    const Family& f = families[piece_face[k] >= 0 ? piece_face[k] : 0];
    const PassCurve c = f.pass(i.level, i.a, i.b);
    if (truncated || points_so_far > options.max_points) continue;  // failing anyway (below)
    const ForwardSteps steps = place_contact_points(part, c, cutter, bounded.forward);
    PlannedPass& pass = plan.passes[k];
    pass.face = piece_face[k];
    pass.level = i.level;
    for (double t : steps.params) {
      PlannedContact p;
      p.at = c.at(t);
      // An end found by bisection lies within rounding of the face's edge,
      // where the projection may land either side: step inward rather than
      // lose the end (and with it, on a short piece, the whole pass).
      for (double inward = 1e-9; !p.at.valid && (t == i.a || t == i.b) && inward < 1e-4; inward *= 100)
        p.at = c.at(t == i.a ? t + inward * (i.b - i.a) : t - inward * (i.b - i.a));
      if (!p.at.valid) continue;
      const CutterLocation loc = cutter_location(cutter, p.at.point, p.at.normal, options.forward.predictor.location);
      if (!loc.reachable) continue;
      p.tip = loc.tip;
      pass.points.push_back(p);
    }
    if (k % 2 == 1) std::reverse(pass.points.begin(), pass.points.end());  // zig-zag
    capped[k] = steps.capped;
    if (steps.truncated) truncated = true;
    points_so_far += static_cast<long>(steps.params.size());
    evaluations[k] = steps.evaluations;
    const std::size_t d = ++done;
    if (progress && omp_get_thread_num() == 0) progress(d, pieces.size());
  }
  if (truncated || points_so_far > options.max_points) {
    std::ostringstream s;
    s << "toolpath: the tolerance " << options.forward.tolerance << " mm needs more than " << options.max_points
      << " contact points (docs/formats.md \"Limits\"): use a larger tolerance";
    throw InputError(s.str());
  }
  if (progress) progress(pieces.size(), pieces.size());
  std::vector<PlannedPass> kept;
  for (std::size_t k = 0; k < plan.passes.size(); ++k) {
    plan.capped_searches += capped[k];
    plan.evaluations += evaluations[k];
    if (plan.passes[k].points.size() >= 2) {
      plan.points += plan.passes[k].points.size();
      kept.push_back(std::move(plan.passes[k]));
    }
  }
  plan.passes = std::move(kept);
  return plan;
}

}  // namespace furrow

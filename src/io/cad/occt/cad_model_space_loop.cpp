// A face's outer loop built from its boundary's 3-D curves (contract in
// cad_model_space_loop.hpp).
#include "io/cad/occt/cad_model_space_loop.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace furrow::cad {

namespace {

constexpr int kMaxPoles = 5;    // pole passages tried (3^5 candidates at most)
constexpr int kSamples = 32;    // points per piece for the enclosed area
constexpr double kRelative = 1e-6;  // closure and span tolerance, as a fraction of the period

// A candidate loop: the whole-period shift of each piece, its signed area
// (twice, positive counterclockwise) and its (u,v) box {u0, v0, u1, v1}.
struct Candidate {
  std::vector<Eigen::Vector2d> shifts;
  double twice_area = 0;
  Eigen::Vector4d box;
  std::vector<Eigen::Vector2d> polygon;  // the loop's samples, shifts applied
};

// One piece of the loop: an edge with a 3-D curve, sampled in running order.
struct Piece {
  std::size_t edge;  // index in the wire
  std::vector<Eigen::Vector2d> points;
  bool pole_before = false;  // meets the previous piece at a pole
};

// Whether `q`, moved by any whole number of periods (up to two either way,
// enough for a loop that spans at most one period), lies inside `polygon`
// (even-odd rule).
bool holds(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& q, const Eigen::Vector2d& period) {
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      if ((i != 0 && period.x() == 0) || (j != 0 && period.y() == 0)) continue;
      const Eigen::Vector2d p = q + Eigen::Vector2d(i * period.x(), j * period.y());
      bool inside = false;
      for (std::size_t k = 0, l = polygon.size() - 1; k < polygon.size(); l = k++) {
        const Eigen::Vector2d& a = polygon[k];
        const Eigen::Vector2d& b = polygon[l];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
          inside = !inside;
      }
      if (inside) return true;
    }
  return false;
}

}  // namespace

bool model_space_loop(WireUse& wire, const Handle(Geom_Surface)& surface, const Periods& periods,
                      const FileBoundary& file, bool face_reversed, const std::vector<Eigen::Vector2d>& holes,
                      bool& turned) {
  const Eigen::Vector2d period(periods.u ? periods.du : 0.0, periods.v ? periods.dv : 0.0);
  std::vector<Piece> pieces;
  bool pole_pending = false;  // a degenerate edge since the last piece
  for (std::size_t k = 0; k < wire.edges.size(); ++k) {
    const EdgeUse& e = wire.edges[k];
    if (!e.degenerate && !e.projected) return false;
    if (e.degenerate || e.projected->collapsed()) {  // a point at a pole
      pole_pending = true;
      continue;
    }
    Piece p;
    p.edge = k;
    for (int i = 0; i <= kSamples; ++i) p.points.push_back(e.projected->uv(e.from + (e.to - e.from) * i / kSamples));
    p.pole_before = pole_pending || e.projected->starts_at_pole() ||
                    (!pieces.empty() && wire.edges[pieces.back().edge].projected->ends_at_pole());
    pole_pending = false;
    pieces.push_back(std::move(p));
  }
  if (pieces.empty()) return false;
  // The closing junction (last piece to the first).
  pieces.front().pole_before = pieces.front().pole_before || pole_pending ||
                               wire.edges[pieces.back().edge].projected->ends_at_pole();
  std::vector<std::size_t> free;  // junctions before pieces 1.. at a pole
  for (std::size_t i = 1; i < pieces.size(); ++i)
    if (pieces[i].pole_before) free.push_back(i);
  if (free.size() > static_cast<std::size_t>(kMaxPoles)) return false;
  // Which parameter a pole leaves free: the periodic one whose circle shrinks.
  const int pole_axis = periods.u ? 0 : 1;

  std::vector<Candidate> candidates;
  int combinations = 1;
  for (std::size_t i = 0; i < free.size(); ++i) combinations *= 3;
  for (int code = 0; code < combinations; ++code) {
    Candidate c;
    c.shifts.assign(pieces.size(), Eigen::Vector2d::Zero());
    int digits = code;
    for (std::size_t i = 1; i < pieces.size(); ++i) {
      const Eigen::Vector2d gap = pieces[i - 1].points.back() + c.shifts[i - 1] - pieces[i].points.front();
      for (int d = 0; d < 2; ++d)
        if (period[d] > 0) c.shifts[i][d] = std::round(gap[d] / period[d]) * period[d];
      if (pieces[i].pole_before) {
        c.shifts[i][pole_axis] += (digits % 3 - 1) * period[pole_axis];
        digits /= 3;
      }
    }
    // The loop must close where its ends do not meet at a pole, and meet
    // across the pole line where they do.
    const Eigen::Vector2d gap = pieces.back().points.back() + c.shifts.back() - pieces.front().points.front();
    bool closes = true;
    for (int d = 0; d < 2; ++d) {
      if (pieces.front().pole_before && d == pole_axis) continue;
      const double scale = period[d] > 0 ? period[d] : 1.0;
      if (std::abs(gap[d]) > kRelative * scale) closes = false;
    }
    if (!closes) continue;
    c.box << 1e300, 1e300, -1e300, -1e300;
    std::vector<Eigen::Vector2d> points;
    for (std::size_t i = 0; i < pieces.size(); ++i)
      for (const Eigen::Vector2d& q : pieces[i].points) points.push_back(q + c.shifts[i]);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector2d& a = points[k];
      const Eigen::Vector2d& b = points[(k + 1) % points.size()];
      c.twice_area += a.x() * b.y() - b.x() * a.y();
      c.box.head<2>() = c.box.head<2>().cwiseMin(a);
      c.box.tail<2>() = c.box.tail<2>().cwiseMax(a);
    }
    bool spans = true;
    for (int d = 0; d < 2; ++d)
      if (period[d] > 0 && c.box[d + 2] - c.box[d] > period[d] * (1 + kRelative)) spans = false;
    const double extent = (c.box[2] - c.box[0]) * (c.box[3] - c.box[1]);
    c.polygon = std::move(points);
    if (spans && std::abs(c.twice_area) > 1e-9 * extent) candidates.push_back(std::move(c));
  }
  if (candidates.empty()) return false;
  // A face holds its holes: of several candidates (a lune and the rest of
  // the sphere) keep those that hold every hole, when any does.
  if (candidates.size() > 1 && !holes.empty()) {
    std::vector<Candidate> holding;
    for (const Candidate& c : candidates)
      if (std::all_of(holes.begin(), holes.end(), [&](const Eigen::Vector2d& q) { return holds(c.polygon, q, period); }))
        holding.push_back(c);
    if (!holding.empty()) candidates = std::move(holding);
  }

  const Candidate* chosen = candidates.size() == 1 ? &candidates.front() : nullptr;
  if (!chosen) {
    // Within the file's rectangle: the surface's first angle and the
    // file's range of angles (the whole period where the file gives none).
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    const double start = pole_axis == 0 ? u0 : v0;
    const double p = period[pole_axis];
    const double width = file.surface_rotation > 0 ? std::min(file.surface_rotation, p) : p;
    std::vector<const Candidate*> inside;
    for (const Candidate& c : candidates) {
      const double lo = c.box[pole_axis], hi = c.box[pole_axis + 2];
      const double m = std::ceil((start - lo) / p - kRelative);  // whole periods to move it by
      if (lo + m * p >= start - kRelative * p && hi + m * p <= start + width + kRelative * p) inside.push_back(&c);
    }
    if (inside.size() == 1) chosen = inside.front();
    // The file's loop runs counterclockwise around the face (walked on a
    // reversed face, clockwise).
    const double sense = face_reversed ? -1.0 : 1.0;
    if (inside.empty())
      for (const Candidate& c : candidates) inside.push_back(&c);
    for (const Candidate* c : inside)
      if (!chosen && c->twice_area * sense > 0) chosen = c;
    if (!chosen) chosen = inside.front();
  }

  for (std::size_t i = 0; i < pieces.size(); ++i) wire.edges[pieces[i].edge].shift = chosen->shifts[i];
  const std::size_t n = wire.edges.size();
  for (std::size_t k = 0; k < n; ++k) {
    EdgeUse& e = wire.edges[k];
    if (!e.degenerate && !e.projected->collapsed()) continue;
    const EdgeUse& before = wire.edges[(k + n - 1) % n];
    const EdgeUse& after = wire.edges[(k + 1) % n];
    e.bridge_from = before.uv(before.to);
    e.bridge_to = after.uv(after.from);
    e.bridged = true;
  }
  turned = (chosen->twice_area > 0) == face_reversed;
  return true;
}

}  // namespace furrow::cad

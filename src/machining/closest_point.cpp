#include "machining/closest_point.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

namespace {

struct Start {
  double distance;
  std::size_t face;
  Eigen::Vector2d uv;
};

// Newton on |S(u,v) - q|^2 / 2 from `uv`, bound-constrained to the
// parameter rectangle: a coordinate at a bound whose gradient pushes outward
// is held there (active set), the others take the Newton step. Returns
// whether it converged (a step below tolerance, or a constrained minimum).
bool newton_foot(const Face& face, const Eigen::Vector3d& q, Eigen::Vector2d& uv,
                 const ClosestPointOptions& options) {
  const ParameterDomain& dom = face.domain();
  const Eigen::Vector2d lo(dom.u0, dom.v0), hi(dom.u1, dom.v1);
  const double tol = options.parameter_tolerance * std::max(dom.width_u(), dom.width_v());
  for (int it = 0; it < options.max_iterations; ++it) {
    const SurfaceDerivatives d = face.surface().evaluate(uv.x(), uv.y(), 2);
    const Eigen::Vector3d r = d.S - q;
    const Eigen::Vector2d grad(r.dot(d.Su), r.dot(d.Sv));
    Eigen::Matrix2d H;
    H << d.Su.dot(d.Su) + r.dot(d.Suu), d.Su.dot(d.Sv) + r.dot(d.Suv),
        d.Su.dot(d.Sv) + r.dot(d.Suv), d.Sv.dot(d.Sv) + r.dot(d.Svv);
    if (!(H(0, 0) > 0 && H.determinant() > 0)) {  // not convex here: Gauss-Newton
      H << d.Su.dot(d.Su), d.Su.dot(d.Sv), d.Su.dot(d.Sv), d.Sv.dot(d.Sv);
      H.diagonal() *= 1 + 1e-12;
    }
    bool active[2];
    for (int i = 0; i < 2; ++i)
      active[i] = (uv(i) <= lo(i) && grad(i) > 0) || (uv(i) >= hi(i) && grad(i) < 0);
    Eigen::Vector2d step = Eigen::Vector2d::Zero();
    if (active[0] && active[1]) return true;  // a corner minimum
    if (active[0] || active[1]) {
      const int i = active[0] ? 1 : 0;
      step(i) = -grad(i) / H(i, i);
    } else {
      step = -H.ldlt().solve(grad);
    }
    if (!step.allFinite()) return false;
    const double dist2 = r.squaredNorm();
    bool decreased = false;
    Eigen::Vector2d next = uv;
    for (int halving = 0; halving < 40 && !decreased; ++halving, step *= 0.5) {
      next = uv + step;
      next = next.cwiseMax(lo).cwiseMin(hi);
      decreased = (face.surface().point(next.x(), next.y()) - q).squaredNorm() <= dist2;
    }
    // A descent step that cannot decrease the distance any more: we are at
    // the minimum to rounding.
    if (!decreased) return true;
    const double moved = (next - uv).norm();
    uv = next;
    if (moved <= tol) return true;
  }
  return false;
}

}  // namespace

PartProjector::PartProjector(const Part& part, const ClosestPointOptions& options)
    : part_(part), options_(options) {
  for (const Face& face : part.faces) seeds_.push_back(make_face_seeds(face, options.seed_grid));
}

FootPoint PartProjector::project(const Eigen::Vector3d& q) const {
  // The nearest few seeds over all faces start Newton.
  std::vector<Start> starts;
  for (std::size_t f = 0; f < seeds_.size(); ++f)
    for (const FaceSeed& s : seeds_[f].seeds)
      starts.push_back({(s.point - q).norm(), f, s.uv});
  const std::size_t count = std::min<std::size_t>(starts.size(), std::max(1, options_.max_starts));
  std::partial_sort(starts.begin(), starts.begin() + count, starts.end(),
                    [](const Start& a, const Start& b) {
                      return a.distance < b.distance ||
                             (a.distance == b.distance && a.face < b.face);
                    });
  FootPoint best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < count; ++k) {
    const Face& face = part_.faces[starts[k].face];
    Eigen::Vector2d uv = starts[k].uv;
    ++best.starts;
    if (!newton_foot(face, q, uv, options_)) {
      ++best.failed_starts;
      continue;
    }
    if (!face.contains(uv.x(), uv.y())) continue;
    const Eigen::Vector3d p = face.surface().point(uv.x(), uv.y());
    const double dist = (p - q).norm();
    if (dist < best.distance) {
      best.found = true;
      best.face = starts[k].face;
      best.uv = uv;
      best.point = p;
      best.distance = dist;
    }
  }
  if (!best.found) best.distance = 0;
  return best;
}

}  // namespace furrow

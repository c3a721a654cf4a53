#include "io/cad/cad_trim_polygon.hpp"

#include <algorithm>
#include <cmath>

namespace furrow {

namespace {

// Coarse pass: polygon edges per curve from which the final count is estimated.
constexpr int kCoarseEdges = 8;
// Safety factor on the estimated count (the sag of a coarse edge is a little
// less than count^2 times the sag of its parts).
constexpr double kCountMargin = 1.05;

// Drops vertices lying on the segment between their neighbours: straight
// curves were sampled like any other.
void drop_collinear(UvLoop& loop, const Eigen::Array2d& scale) {
  if (loop.size() < 4) return;
  UvLoop kept;
  const std::size_t n = loop.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& prev = kept.empty() ? loop[n - 1] : kept.back();
    const Eigen::Vector2d& cur = loop[k];
    const Eigen::Vector2d& next = loop[(k + 1) % n];
    const Eigen::Vector2d ab = ((next - prev).array() / scale).matrix();
    const Eigen::Vector2d ac = ((cur - prev).array() / scale).matrix();
    const double cross = ab.x() * ac.y() - ab.y() * ac.x();
    const double along = ab.squaredNorm() > 0 ? ac.dot(ab) / ab.squaredNorm() : -1;
    const bool between = along > 0 && along < 1;
    if (!(between && std::abs(cross) <= 1e-13 * ab.norm())) kept.push_back(cur);
  }
  if (kept.size() >= 3) loop = std::move(kept);
}

}  // namespace

TrimPolygonBuilder::TrimPolygonBuilder(const NurbsSurface& surface, const TrimPolygonOptions& options)
    : surface_(surface), options_(options) {
  const ParameterDomain& d = surface.domain();
  scale_ = {d.width_u(), d.width_v()};
}

bool TrimPolygonBuilder::same(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  return std::abs(a.x() - b.x()) <= 1e-12 * scale_.x() && std::abs(a.y() - b.y()) <= 1e-12 * scale_.y();
}

void TrimPolygonBuilder::push(const Eigen::Vector2d& st, const Eigen::Vector2d& sag) {
  if (!vertices_.empty() && same(vertices_.back(), st)) return;
  vertices_.push_back(st);
  sags_.push_back(sag);
}

TrimPolygonBuilder::Sag TrimPolygonBuilder::measure(const BoundaryCurve& c, const Sample& a,
                                                    const Sample& b, Sample& mid) const {
  mid.x = 0.5 * (a.x + b.x);
  mid.st = c.st(mid.x);
  const Eigen::Vector2d ab = b.st - a.st;
  const double len2 = ab.squaredNorm();
  const double lambda = len2 > 0 ? std::clamp((mid.st - a.st).dot(ab) / len2, 0.0, 1.0) : 0.0;
  const Eigen::Vector2d foot = a.st + lambda * ab;
  Sag sag;
  sag.vector = mid.st - foot;
  sag.uv = (sag.vector.array() / scale_).abs().maxCoeff();
  sag.mm = (surface_.point(foot.x(), foot.y()) - surface_.point(mid.st.x(), mid.st.y())).norm();
  return sag;
}

void TrimPolygonBuilder::refine(const BoundaryCurve& c, const Sample& a, const Sample& b, int depth) {
  Sample mid;
  const Sag sag = measure(c, a, b, mid);
  if (sag.mm > options_.chord_tolerance || sag.uv > options_.uv_tolerance) {
    if (depth < options_.max_subdivisions) {
      refine(c, a, mid, depth + 1);
      refine(c, mid, b, depth + 1);
      return;
    }
    met_ = false;
  }
  worst_sag_ = std::max(worst_sag_, sag.mm);
  push(b.st, sag.vector);
}

UvLoop TrimPolygonBuilder::loop(const std::vector<BoundaryCurve>& wire) {
  vertices_.clear();
  sags_.clear();
  const double max_count = std::ldexp(1.0, options_.max_subdivisions);
  for (const BoundaryCurve& c : wire) {
    const int coarse = c.collapsed ? 1 : kCoarseEdges;
    std::vector<Sample> nodes;
    for (int k = 0; k <= coarse; ++k) {
      const double x = c.from + (c.to - c.from) * k / coarse;
      nodes.push_back({x, c.st(x)});
    }
    push(nodes.front().st, Eigen::Vector2d::Zero());
    for (int k = 0; k < coarse; ++k) {
      Sample mid;
      const Sag sag = measure(c, nodes[k], nodes[k + 1], mid);
      const double ratio =
          std::max(sag.mm / options_.chord_tolerance, sag.uv / options_.uv_tolerance);
      const double estimate = ratio > 1 ? std::ceil(kCountMargin * std::sqrt(ratio)) : 1.0;
      const int count = static_cast<int>(std::min(estimate, max_count));
      Sample a = nodes[k];
      for (int j = 1; j <= count; ++j) {
        const double x = nodes[k].x + (nodes[k + 1].x - nodes[k].x) * j / count;
        const Sample b = j == count ? nodes[k + 1] : Sample{x, c.st(x)};
        refine(c, a, b, 0);
        a = b;
      }
    }
  }
  if (vertices_.size() > 1 && same(vertices_.back(), vertices_.front())) {
    sags_.front() = sags_.back();  // the closing edge ends at the first vertex
    vertices_.pop_back();
    sags_.pop_back();
  }

  // Balance: move each vertex by 2/3 of the length-weighted sag of its edges.
  const std::size_t n = vertices_.size();
  UvLoop balanced = vertices_;
  if (n >= 3) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
      const double in = (vertices_[i] - vertices_[prev]).norm();
      const double out = (vertices_[next] - vertices_[i]).norm();
      if (in + out > 0)
        balanced[i] += (2.0 / 3.0) * (in * sags_[i] + out * sags_[next]) / (in + out);
    }
  }
  drop_collinear(balanced, scale_);
  return balanced;
}

bool is_domain_rectangle(const std::vector<UvLoop>& loops, const ParameterDomain& d) {
  if (loops.size() != 1) return false;
  const double eu = 1e-12 * d.width_u(), ev = 1e-12 * d.width_v();
  double twice_area = 0;
  const UvLoop& loop = loops[0];
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Eigen::Vector2d& p = loop[k];
    const Eigen::Vector2d& q = loop[(k + 1) % loop.size()];
    const bool on_edge = std::abs(p.x() - d.u0) <= eu || std::abs(p.x() - d.u1) <= eu ||
                         std::abs(p.y() - d.v0) <= ev || std::abs(p.y() - d.v1) <= ev;
    if (!on_edge) return false;
    twice_area += p.x() * q.y() - q.x() * p.y();
  }
  return std::abs(twice_area) / 2 >= (1 - 1e-9) * d.width_u() * d.width_v();
}

}  // namespace furrow

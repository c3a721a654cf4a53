#include "machining/cutter/drop_cutter.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "geometry/bspline_basis.hpp"

namespace furrow {

namespace {

// Blossom (polar form) of the degree-p B-spline curve with control points
// P[0..p] (those of knot span k) at the arguments t[0..p-1]: de Boor's
// algorithm with one argument per level. The Bezier points of the span
// [a, b] are the blossoms at (a,..,a, b,..,b).
Eigen::Vector4d blossom(const std::vector<double>& knots, int p, int k,
                        std::vector<Eigen::Vector4d> d, const std::vector<double>& t) {
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = k - p + j;
      const double denom = knots[i + p + 1 - r] - knots[i];
      const double alpha = denom > 0 ? (t[r - 1] - knots[i]) / denom : 0.0;
      d[j] = (1 - alpha) * d[j - 1] + alpha * d[j];
    }
  return d[p];
}

// Bezier points of the span [knots[k], knots[k+1]] from its p + 1 control points.
std::vector<Eigen::Vector4d> bezier_of_span(const std::vector<double>& knots, int p, int k,
                                            const std::vector<Eigen::Vector4d>& P) {
  const double a = knots[k], b = knots[k + 1];
  std::vector<Eigen::Vector4d> out(p + 1);
  std::vector<double> t(p);
  for (int j = 0; j <= p; ++j) {
    for (int s = 0; s < p; ++s) t[s] = s < p - j ? a : b;
    out[j] = blossom(knots, p, k, P, t);
  }
  return out;
}

// Spans k with a non-empty interval inside the domain [knots[p], knots[n]].
std::vector<int> spans(const std::vector<double>& knots, int p, int n) {
  std::vector<int> out;
  for (int k = p; k < n; ++k)
    if (knots[k + 1] > knots[k]) out.push_back(k);
  return out;
}

Eigen::Vector3d project(const Eigen::Vector4d& h) { return h.head<3>() / h.w(); }

// Halves a (p+1) x (q+1) net (row-major, i along u) along u (dir 0) or v
// (dir 1) by de Casteljau at 1/2 into `lo` and `hi` (same layout).
void halve(const Eigen::Vector4d* net, int p, int q, int dir, Eigen::Vector4d* lo, Eigen::Vector4d* hi) {
  const int n = dir == 0 ? p : q;          // degree along the split
  const int m = dir == 0 ? q + 1 : p + 1;  // lines across it
  auto index = [&](int along, int line) { return dir == 0 ? along * (q + 1) + line : line * (q + 1) + along; };
  Eigen::Vector4d w[kMaxDegree + 1];
  for (int line = 0; line < m; ++line) {
    for (int i = 0; i <= n; ++i) w[i] = net[index(i, line)];
    lo[index(0, line)] = w[0];
    hi[index(n, line)] = w[n];
    for (int r = 1; r <= n; ++r) {
      for (int i = 0; i + r <= n; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
      lo[index(r, line)] = w[0];
      hi[index(n - r, line)] = w[n - r];
    }
  }
}

Eigen::AlignedBox3d hull_box(const DropCutter::Cell& c) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector4d& h : c.net) box.extend(project(h));
  return box;
}

}  // namespace

DropCutter::DropCutter(const Part& part, const Cutter& cutter, const DropCutterOptions& options)
    : part_(part), cutter_(cutter), options_(options) {
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const NurbsSurface& s = part.faces[f].surface();
    const int p = s.degree_u(), q = s.degree_v();
    const std::vector<double>&U = s.knots_u(), &V = s.knots_v();
    for (const int ku : spans(U, p, s.num_u())) {
      // Along u first: for every control column j, the span's Bezier points.
      std::vector<std::vector<Eigen::Vector4d>> rows(p + 1, std::vector<Eigen::Vector4d>(s.num_v()));
      for (int j = 0; j < s.num_v(); ++j) {
        std::vector<Eigen::Vector4d> P(p + 1);
        for (int i = 0; i <= p; ++i) {
          const int ii = ku - p + i;
          const double w = s.weight(ii, j);
          P[i] << w * s.control_point(ii, j), w;
        }
        const std::vector<Eigen::Vector4d> b = bezier_of_span(U, p, ku, P);
        for (int i = 0; i <= p; ++i) rows[i][j] = b[i];
      }
      for (const int kv : spans(V, q, s.num_v())) {
        Cell cell;
        cell.face = f;
        cell.p = p;
        cell.q = q;
        cell.u0 = U[ku];
        cell.u1 = U[ku + 1];
        cell.v0 = V[kv];
        cell.v1 = V[kv + 1];
        cell.net.resize(static_cast<std::size_t>((p + 1) * (q + 1)));
        for (int i = 0; i <= p; ++i) {
          const std::vector<Eigen::Vector4d> P(rows[i].begin() + (kv - q), rows[i].begin() + kv + 1);
          const std::vector<Eigen::Vector4d> b = bezier_of_span(V, q, kv, P);
          for (int j = 0; j <= q; ++j) cell.net[i * (q + 1) + j] = b[j];
        }
        boxes_.push_back(hull_box(cell));
        patches_.push_back(std::move(cell));
      }
    }
  }
}

DropCutterResult DropCutter::drop(const Eigen::Vector2d& xy, double known) const {
  return search(xy, known, false);
}

DropCutterResult DropCutter::rests_above(const Eigen::Vector2d& xy, double height) const {
  return search(xy, height, true);
}

DropCutterResult DropCutter::search(const Eigen::Vector2d& xy, double known, bool first_above) const {
  DropCutterResult result;
  const double R = cutter_.radius();
  const double hold = R - options_.radial_tolerance;  // beyond: grazing (the header)
  auto box_distance = [&](const Eigen::AlignedBox3d& box) {
    const double dx = std::max({box.min().x() - xy.x(), 0.0, xy.x() - box.max().x()});
    const double dy = std::max({box.min().y() - xy.y(), 0.0, xy.y() - box.max().y()});
    return std::sqrt(dx * dx + dy * dy);
  };
  const double start = known;
  double best = known;
  // Per-cell scratch, reused: the projected control points and the bound's lines.
  std::vector<Eigen::Vector3d> pts;
  std::vector<double> a, b;
  // Lower bound from the cell's corners (surface points, when the trim keeps them).
  auto corners = [&](const Piece& c) {
    const Face& face = part_.faces[c.face];
    const int corner_index[4][2] = {{0, 0}, {c.p, 0}, {0, c.q}, {c.p, c.q}};
    for (const auto& ij : corner_index) {
      const Eigen::Vector3d& p = pts[ij[0] * (c.q + 1) + ij[1]];
      const double rho = (p.head<2>() - xy).norm();
      if (!(rho < hold)) continue;
      const double phi = p.z() - cutter_.height_at(rho);
      if (phi <= result.tip_z) continue;
      const Eigen::Vector2d uv(ij[0] == 0 ? c.u0 : c.u1, ij[1] == 0 ? c.v0 : c.v1);
      if (!face.contains(uv.x(), uv.y())) continue;
      result.any = true;
      result.tip_z = phi;
      result.face = c.face;
      result.uv = uv;
      result.point = p;
      best = std::max(best, phi);
    }
  };
  // Upper bound of phi over the cell (the header), -infinity when out of reach.
  auto upper = [&]() {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : pts) box.extend(p);
    const double d = box_distance(box);
    if (!(d < hold)) return -std::numeric_limits<double>::infinity();
    double bound = box.max().z() - cutter_.height_at(d);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : pts) centre += p;
    centre /= static_cast<double>(pts.size());
    const Eigen::Vector2d radial = centre.head<2>() - xy;
    const double rho = radial.norm();
    if (!(rho > 0)) return bound;
    // Tangent bound of psi = z - Hx(rho) + lambda (hold - rho) >= phi on the
    // disc (the header), Hx the envelope up to rho1 continued by its tangent
    // line (convex, finite, below the envelope).
    const double rho1 = std::min(rho, R - 1e-3 * std::max(cutter_.corner_radius(), 1e-3 * R));
    const double slope = cutter_.slope_at(rho1);
    const double envelope = cutter_.height_at(rho1) + slope * std::max(0.0, rho - rho1);
    const Eigen::Vector2d e = radial / rho;
    // Over the net: psi's linearization at the centroid is a_i + b_i lambda.
    const std::size_t n = pts.size();
    a.resize(n);
    b.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d p = pts[i] - centre;
      const double out = e.dot(p.head<2>());
      a[i] = p.z() - slope * out;
      b[i] = (hold - rho) - out;
    }
    // min over lambda >= 0 of max_i (a_i + b_i lambda), a convex polyline:
    // walk right along it from 0 while it descends.
    double lambda = 0, best_value = 0;
    for (int step = 0; step <= static_cast<int>(n); ++step) {
      std::size_t top = 0;
      for (std::size_t i = 1; i < n; ++i) {
        const double vi = a[i] + b[i] * lambda, vt = a[top] + b[top] * lambda;
        if (vi > vt || (vi == vt && b[i] > b[top])) top = i;
      }
      best_value = a[top] + b[top] * lambda;
      if (b[top] >= 0) break;
      double next = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < n; ++j)
        if (b[j] > b[top]) {
          const double at = (a[top] - a[j]) / (b[j] - b[top]);
          if (at > lambda && at < next) next = at;
        }
      if (!std::isfinite(next)) break;  // cannot happen with an edge ahead; kept for safety
      lambda = next;
    }
    bound = std::min(bound, centre.z() - envelope + best_value);
    return bound;
  };

  // Cells waiting to be halved: their nets live in one arena (no allocation
  // per cell), `net` indexing its first control point.
  std::vector<Piece> pool;
  std::vector<Eigen::Vector4d> arena;
  using Entry = std::pair<double, std::size_t>;  // (upper bound, index into pool)
  std::priority_queue<Entry> open;
  const auto found_above = [&] { return first_above && result.tip_z > start; };
  // `net` must not point into the arena (it may grow).
  auto consider = [&](Piece c, const Eigen::Vector4d* net) {
    ++result.cells;
    const std::size_t size = static_cast<std::size_t>((c.p + 1) * (c.q + 1));
    pts.resize(size);
    for (std::size_t i = 0; i < size; ++i) pts[i] = project(net[i]);
    corners(c);
    const double ub = upper();
    if (!(ub > best + options_.height_tolerance)) return;
    c.net = arena.size();
    arena.insert(arena.end(), net, net + size);
    pool.push_back(c);
    open.push({ub, pool.size() - 1});
  };
  for (std::size_t k = 0; k < patches_.size() && !found_above(); ++k)
    if (box_distance(boxes_[k]) < hold) {
      const Cell& patch = patches_[k];
      consider(Piece{patch.face, patch.p, patch.q, patch.u0, patch.u1, patch.v0, patch.v1, 0},
               patch.net.data());
    }
  const int cap = std::max(1, options_.max_cells);
  std::vector<Eigen::Vector4d> parent, halves[2], quarters[4];
  while (!open.empty() && !found_above()) {
    const auto [ub, index] = open.top();
    if (!(ub > best + options_.height_tolerance)) break;  // nothing left can beat it
    if (result.cells + 4 > cap) {
      result.complete = false;
      result.unresolved = ub;
      break;
    }
    open.pop();
    const Piece cell = pool[index];
    const std::size_t size = static_cast<std::size_t>((cell.p + 1) * (cell.q + 1));
    parent.assign(arena.begin() + static_cast<std::ptrdiff_t>(cell.net),
                  arena.begin() + static_cast<std::ptrdiff_t>(cell.net + size));
    for (auto& h : halves) h.resize(size);
    for (auto& q : quarters) q.resize(size);
    halve(parent.data(), cell.p, cell.q, 0, halves[0].data(), halves[1].data());
    for (int i = 0; i < 2; ++i)
      halve(halves[i].data(), cell.p, cell.q, 1, quarters[2 * i].data(), quarters[2 * i + 1].data());
    const double umid = 0.5 * (cell.u0 + cell.u1), vmid = 0.5 * (cell.v0 + cell.v1);
    for (int i = 0; i < 4; ++i) {
      Piece part = cell;
      (i < 2 ? part.u1 : part.u0) = umid;
      (i % 2 == 0 ? part.v1 : part.v0) = vmid;
      consider(part, quarters[i].data());
    }
  }
  return result;
}

}  // namespace furrow

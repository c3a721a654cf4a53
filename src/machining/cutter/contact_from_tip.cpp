#include "machining/cutter/contact_from_tip.hpp"

#include "base/scalar_search.hpp"
#include "geometry/domain_sides.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

const char* to_string(ContactKind kind) {
  switch (kind) {
    case ContactKind::corner: return "corner";
    case ContactKind::flat_bottom: return "flat_bottom";
    case ContactKind::edge: return "edge";
  }
  return "?";
}

const char* to_string(TipContactStatus status) {
  switch (status) {
    case TipContactStatus::found: return "found";
    case TipContactStatus::not_converged: return "not_converged";
    case TipContactStatus::no_contact: return "no_contact";
  }
  return "?";
}

namespace {

struct Evaluation {
  SurfaceDerivatives d;
  DifferentialGeometry g;
};

Evaluation evaluate(const Face& face, const Eigen::Vector2d& uv) {
  Evaluation e;
  e.d = face.surface().evaluate(uv.x(), uv.y(), 2);
  e.g = face.geometry(e.d);
  return e;
}

// Derivatives of the unit normal (Weingarten equations).
void normal_derivatives(const Evaluation& e, Eigen::Vector3d& n_u, Eigen::Vector3d& n_v) {
  const DifferentialGeometry& g = e.g;
  const double det = g.E * g.G - g.F * g.F;
  n_u = ((g.M * g.F - g.L * g.G) * e.d.Su + (g.L * g.F - g.M * g.E) * e.d.Sv) / det;
  n_v = ((g.N * g.F - g.M * g.G) * e.d.Su + (g.M * g.F - g.N * g.E) * e.d.Sv) / det;
}

Eigen::Vector2d clamp_uv(const ParameterDomain& d, const Eigen::Vector2d& uv) {
  return {std::clamp(uv.x(), d.u0, d.u1), std::clamp(uv.y(), d.v0, d.v1)};
}

bool on_domain_edge(const ParameterDomain& d, const Eigen::Vector2d& uv) {
  return uv.x() <= d.u0 || uv.x() >= d.u1 || uv.y() <= d.v0 || uv.y() >= d.v1;
}

// Damped Newton on a 2-D residual: `residual(uv, ev, F)` evaluates and
// returns false where the residual is undefined (degenerate, facing down);
// `jacobian(ev)` gives dF/d(u,v). Returns iterations used, -1 when it
// stalls or hits the cap, -2 when it stalls on the domain edge (the root
// lies beyond the face: not a failure, there is no contact on this face).
template <class Residual, class Jacobian, class Done>
int damped_newton(const Face& face, Eigen::Vector2d& uv, int max_iterations, Residual residual,
                  Jacobian jacobian, Done done) {
  const ParameterDomain& dom = face.domain();
  Evaluation ev;
  Eigen::Vector2d F;
  if (!residual(uv, ev, F)) return -1;
  for (int it = 0; it < max_iterations; ++it) {
    if (done(ev, F)) return it;
    const Eigen::Matrix2d J = jacobian(ev);
    Eigen::Vector2d step = -J.fullPivLu().solve(F);
    if (!step.allFinite()) return -1;
    bool accepted = false;
    for (int halving = 0; halving < 40 && !accepted; ++halving, step *= 0.5) {
      const Eigen::Vector2d next = clamp_uv(dom, uv + step);
      Evaluation ev_next;
      Eigen::Vector2d F_next;
      if (residual(next, ev_next, F_next) && F_next.norm() < F.norm()) {
        uv = next;
        ev = ev_next;
        F = F_next;
        accepted = true;
      }
    }
    if (!accepted) return done(ev, F) ? it : on_domain_edge(dom, uv) ? -2 : -1;
  }
  return done(ev, F) ? max_iterations : on_domain_edge(dom, uv) ? -2 : -1;
}

}  // namespace

TipContactFinder::TipContactFinder(const Part& part, const Cutter& cutter,
                                   const TipContactOptions& options)
    : part_(part), cutter_(cutter), options_(options), drop_(part, cutter, options.bound) {
  const int n = std::max(2, options.seed_grid);
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const FaceSeedGrid grid = make_face_seeds(part.faces[f], n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const FaceSeed& s = grid.seeds[static_cast<std::size_t>(i) * n + j];
        if (i + 1 < n)
          seed_spacing_ = std::max(seed_spacing_, (grid.seeds[(i + 1) * n + j].point - s.point).norm());
        if (j + 1 < n)
          seed_spacing_ = std::max(seed_spacing_, (grid.seeds[i * n + j + 1].point - s.point).norm());
        if (!s.valid) continue;
        Seed seed{f, s.uv, s.point, s.point.head<2>(), s.normal.z() > options.location.vertical_tolerance};
        if (seed.corner)
          seed.offset_xy += tip_offset(cutter, s.normal, options.location).head<2>();
        seeds_.push_back(seed);
      }
    }
    const Face& face = part.faces[f];
    const int m = std::max(3, options.edge_samples);
    for (const unsigned side : kAllSides) {
      const auto [lo, hi] = side_range(face.domain(), side);
      Edge edge{f, side, {}};
      for (int k = 0; k < m; ++k) {
        const double t = grid_parameter(lo, hi, k, m);
        const Eigen::Vector2d uv = side_uv(face.domain(), side, t);
        edge.samples.push_back({t, face.surface().point(uv.x(), uv.y())});
      }
      edges_.push_back(std::move(edge));
    }
  }
}

TipContactResult TipContactFinder::find(const Eigen::Vector3d& tip) const {
  TipContactResult result;
  const Eigen::Vector2d txy = tip.head<2>();
  const CutterLocationOptions& loc = options_.location;
  const double rho0 = cutter_.flat_radius(), r = cutter_.corner_radius();
  std::vector<TipContact> found;
  const double R = cutter_.radius();
  const std::size_t wanted = static_cast<std::size_t>(std::max(1, options_.max_starts));

  // One pass over the seeds gathers the candidates for every kind of start:
  // corner seeds by the distance of their axis position from the tip
  // (tangencies of this very cutter location) and by how far they stick up
  // into the lowered cutter (where it rests: largest S_z - envelope height);
  // flat-bottom seeds under the bottom disc by height.
  std::vector<std::pair<double, std::size_t>> nearest, highest, flat;
  bool under = false;
  // Squared distances first: most seeds are far from the cutter.
  const double reach2 = (R + seed_spacing_) * (R + seed_spacing_);
  const double flat2 = (rho0 + seed_spacing_) * (rho0 + seed_spacing_);
  const double near2 = 4 * seed_spacing_ * seed_spacing_;
  for (std::size_t k = 0; k < seeds_.size(); ++k) {
    const Seed& seed = seeds_[k];
    const double offset2 = (seed.offset_xy - txy).squaredNorm();
    if (seed.corner && (offset2 <= near2 || nearest.size() < wanted))
      nearest.push_back({std::sqrt(offset2), k});
    const double rho2 = (seed.point.head<2>() - txy).squaredNorm();
    if (rho2 > reach2) continue;
    under = true;
    if (rho0 > 0 && rho2 <= flat2) flat.push_back({-seed.point.z(), k});
    const double rho = std::sqrt(rho2);
    if (seed.corner && rho <= R) highest.push_back({cutter_.height_at(rho) - seed.point.z(), k});
  }
  // Nothing near the cutter: no Newton starts (the bounded search below still looks).
  if (!under) nearest.clear();
  // The best few of a list, skipping seeds next to one already taken (they
  // would converge to the same contact).
  auto pick = [&](std::vector<std::pair<double, std::size_t>>& list, std::vector<std::size_t>& out) {
    std::sort(list.begin(), list.end());
    std::size_t taken = 0;
    for (const auto& [value, k] : list) {
      if (taken == wanted) break;
      bool near = false;
      for (const std::size_t o : out)
        near |= seeds_[o].face == seeds_[k].face &&
                (seeds_[o].point - seeds_[k].point).norm() < 1.5 * seed_spacing_;
      if (near) continue;
      out.push_back(k);
      ++taken;
    }
  };
  std::vector<std::size_t> starts, flat_starts;
  pick(nearest, starts);
  pick(highest, starts);
  pick(flat, flat_starts);

  auto keep = [&](std::size_t face, const Eigen::Vector2d& uv, const Evaluation& ev,
                  ContactKind kind, int iterations) {
    const Face& f = part_.faces[face];
    // A wall touched by the side (n_z = 0, the header) does not hold the cutter up.
    if (!f.contains(uv.x(), uv.y()) || ev.g.degenerate || !(ev.g.normal.z() > loc.vertical_tolerance)) return;
    TipContact c;
    c.face = face;
    c.uv = uv;
    c.point = ev.g.point;
    c.normal = ev.g.normal;
    c.kind = kind;
    c.iterations = iterations;
    c.tip_z = kind == ContactKind::corner ? (c.point + tip_offset(cutter_, c.normal, loc)).z()
                                          : c.point.z();
    for (const TipContact& other : found)
      if (other.kind == kind && (other.point - c.point).norm() <= options_.duplicate_distance) return;
    found.push_back(c);
  };

  // Corner contacts: Newton from (face, uv); false when it stalls or runs off the face.
  auto corner_from = [&](std::size_t face_index, Eigen::Vector2d uv) {
    const Face& face = part_.faces[face_index];
    auto residual = [&](const Eigen::Vector2d& p, Evaluation& ev, Eigen::Vector2d& F) {
      ev = evaluate(face, p);
      if (ev.g.degenerate || !(ev.g.normal.z() > 0)) return false;
      F = ev.g.point.head<2>() + tip_offset(cutter_, ev.g.normal, loc).head<2>() - txy;
      return true;
    };
    auto jacobian = [&](const Evaluation& ev) {
      Eigen::Vector3d n_u, n_v;
      normal_derivatives(ev, n_u, n_v);
      bool horizontal = false;
      const Eigen::Vector3d e = axis_side(ev.g.normal, loc, &horizontal);
      const double nxy = std::sqrt(ev.g.normal.x() * ev.g.normal.x() + ev.g.normal.y() * ev.g.normal.y());
      auto column = [&](const Eigen::Vector3d& Sx, const Eigen::Vector3d& dn) {
        Eigen::Vector2d c = Sx.head<2>() + r * dn.head<2>();
        if (!horizontal && rho0 > 0) {  // d e = (dn_xy - e (e . dn_xy)) / |n_xy|
          const Eigen::Vector2d dxy = dn.head<2>();
          c += rho0 * (dxy - e.head<2>() * e.head<2>().dot(dxy)) / nxy;
        }
        return c;
      };
      Eigen::Matrix2d J;
      J.col(0) = column(ev.d.Su, n_u);
      J.col(1) = column(ev.d.Sv, n_v);
      return J;
    };
    auto done = [&](const Evaluation&, const Eigen::Vector2d& F) { return F.norm() <= options_.tolerance; };
    ++result.starts;
    const int iterations = damped_newton(face, uv, options_.max_iterations, residual, jacobian, done);
    if (iterations < 0) {
      result.failed_starts += iterations == -1;
      return false;
    }
    keep(face_index, uv, evaluate(face, uv), ContactKind::corner, iterations);
    return true;
  };
  for (const std::size_t start : starts) corner_from(seeds_[start].face, seeds_[start].uv);

  // Flat-bottom contacts: horizontal tangent planes under the bottom disc.
  if (rho0 > 0) {
    for (const std::size_t start : flat_starts) {
      const Seed& seed = seeds_[start];
      const Face& face = part_.faces[seed.face];
      Eigen::Vector2d uv = seed.uv;
      auto residual = [&](const Eigen::Vector2d& p, Evaluation& ev, Eigen::Vector2d& F) {
        ev = evaluate(face, p);
        if (ev.g.degenerate) return false;
        F = Eigen::Vector2d(ev.d.Su.z(), ev.d.Sv.z());  // horizontal tangent plane
        return true;
      };
      auto jacobian = [&](const Evaluation& ev) {
        Eigen::Matrix2d J;
        J << ev.d.Suu.z(), ev.d.Suv.z(), ev.d.Suv.z(), ev.d.Svv.z();
        return J;
      };
      auto done = [&](const Evaluation& ev, const Eigen::Vector2d&) {
        return std::hypot(ev.g.normal.x(), ev.g.normal.y()) <= loc.horizontal_tolerance;
      };
      ++result.starts;
      const int iterations = damped_newton(face, uv, options_.max_iterations, residual, jacobian, done);
      if (iterations < 0) {
        result.failed_starts += iterations == -1;
        continue;
      }
      const Evaluation ev = evaluate(face, uv);
      if ((ev.g.point.head<2>() - txy).norm() <= rho0 + options_.tolerance)
        keep(seed.face, uv, ev, ContactKind::flat_bottom, iterations);
    }
  }

  // Edge contacts: along each side, the local maxima (among its samples under
  // the cutter) of how far the side sticks up into the lowered cutter,
  // refined by a bracketed search (base/scalar_search.hpp) between the
  // neighbouring samples.
  // Where an edge holds the cutter: under it, except at rho = R within
  // rounding of the distance, where the vertical side (or, for a flat end
  // mill, the rim tangent to the edge) only grazes it (the header). An edge
  // that crosses into the disc holds the cutter just inside, at the same
  // height to first order.
  const double hold = R * (1 - 1e-9);
  for (const Edge& edge : edges_) {
    const Face& face = part_.faces[edge.face];
    auto rise = [&](double t) {  // side height minus envelope height: the tip height
      const Eigen::Vector2d uv = side_uv(face.domain(), edge.side, t);
      const Eigen::Vector3d p = face.surface().point(uv.x(), uv.y());
      const double rho = (p.head<2>() - txy).norm();
      return rho <= hold ? p.z() - cutter_.height_at(rho) : -std::numeric_limits<double>::infinity();
    };
    const std::vector<EdgeSample>& smp = edge.samples;
    std::vector<double> value(smp.size());
    bool any = false;
    for (std::size_t k = 0; k < smp.size(); ++k) {
      const double rho2 = (smp[k].point.head<2>() - txy).squaredNorm();
      any |= rho2 <= hold * hold;
      value[k] = rho2 <= hold * hold ? smp[k].point.z() - cutter_.height_at(std::sqrt(rho2))
                               : -std::numeric_limits<double>::infinity();
    }
    if (!any) continue;
    for (std::size_t k = 0; k < smp.size(); ++k) {
      const double left = k > 0 ? value[k - 1] : -std::numeric_limits<double>::infinity();
      const double right = k + 1 < smp.size() ? value[k + 1] : -std::numeric_limits<double>::infinity();
      if (!std::isfinite(value[k]) || value[k] < left || value[k] <= right) continue;
      const double a = smp[k > 0 ? k - 1 : k].t, b = smp[k + 1 < smp.size() ? k + 1 : k].t;
      ScalarSearchOptions search;
      search.tolerance = options_.edge_tolerance * std::abs(smp.back().t - smp.front().t);
      const ScalarSearchResult peak = minimize_unimodal([&](double t) { return -rise(t); }, std::min(a, b),
                                                        std::max(a, b), search);
      // The sample itself may be the maximum (an end of the side).
      double t = peak.x, best = -peak.value;
      if (value[k] > best) t = smp[k].t, best = value[k];
      const Eigen::Vector2d uv = side_uv(face.domain(), edge.side, t);
      if (!face.contains(uv.x(), uv.y())) continue;
      TipContact contact;
      contact.face = edge.face;
      contact.uv = uv;
      const DifferentialGeometry geom = face.geometry(uv.x(), uv.y());
      contact.point = geom.point;
      contact.normal = geom.normal;
      contact.kind = ContactKind::edge;
      contact.tip_z = best;
      bool duplicate = false;
      for (const TipContact& other : found)
        duplicate |= (other.point - contact.point).norm() <= options_.duplicate_distance &&
                     std::abs(other.tip_z - contact.tip_z) <= options_.duplicate_distance;
      if (!duplicate) found.push_back(contact);
    }
  }

  // The bounded search (drop_cutter.hpp): proves that nothing rests the
  // cutter higher than the best contact so far, or finds the point that
  // does; a corner Newton from there polishes it to its tangency, else (an
  // edge or trim point, a flat bottom, a stalled start) the point itself is
  // kept with its exact height.
  double known = -std::numeric_limits<double>::infinity();
  for (const TipContact& c : found) known = std::max(known, c.tip_z);
  const DropCutterResult bound = drop_.drop(txy, known);
  result.cells = bound.cells;
  result.complete = bound.complete;
  result.unresolved = bound.unresolved;
  if (bound.any && bound.tip_z > known) {
    const Face& face = part_.faces[bound.face];
    const std::size_t before = found.size();
    const bool interior = !on_domain_edge(face.domain(), bound.uv);
    if (interior) corner_from(bound.face, bound.uv);
    double polished = -std::numeric_limits<double>::infinity();
    for (std::size_t k = before; k < found.size(); ++k) polished = std::max(polished, found[k].tip_z);
    if (!(polished >= bound.tip_z)) {
      const DifferentialGeometry geom = face.geometry(bound.uv.x(), bound.uv.y());
      TipContact c;
      c.face = bound.face;
      c.uv = bound.uv;
      c.point = bound.point;
      c.normal = geom.normal;
      const double rho = (bound.point.head<2>() - txy).norm();
      c.kind = !interior ? ContactKind::edge : rho <= rho0 ? ContactKind::flat_bottom : ContactKind::corner;
      c.tip_z = bound.tip_z;
      found.push_back(c);
    }
  }

  std::sort(found.begin(), found.end(), [](const TipContact& a, const TipContact& b) {
    if (a.tip_z != b.tip_z) return a.tip_z > b.tip_z;
    if (a.face != b.face) return a.face < b.face;
    return a.uv.x() < b.uv.x() || (a.uv.x() == b.uv.x() && a.uv.y() < b.uv.y());
  });
  result.contacts = std::move(found);
  if (!result.contacts.empty()) {
    result.status = TipContactStatus::found;
    result.gap = tip.z() - result.contacts[0].tip_z;
  } else {
    result.status = result.failed_starts > 0 ? TipContactStatus::not_converged
                                             : TipContactStatus::no_contact;
  }
  return result;
}

}  // namespace furrow

#include "inspection/datum_frame.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "base/error.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

// Below this share of the largest spread a direction counts as absent:
// points that far from spanning a plane (or a line) carry no orientation
// that survives probing noise.
constexpr double kDegenerate = 1e-6;

Eigen::Vector3d centroid_of(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) c += p;
  return c / static_cast<double>(points.size());
}

// Singular values (descending) and right singular vectors of the centred
// points: the principal directions of the point cloud.
Eigen::JacobiSVD<Eigen::MatrixXd> principal(const std::vector<Eigen::Vector3d>& points,
                                            const Eigen::Vector3d& centre) {
  Eigen::MatrixXd m(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = (points[i] - centre).transpose();
  return Eigen::JacobiSVD<Eigen::MatrixXd>(m, Eigen::ComputeFullV);
}

double spread(const std::vector<double>& v) {
  if (v.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

Eigen::Isometry3d frame(const Eigen::Vector3d& origin, const Eigen::Vector3d& x, const Eigen::Vector3d& z) {
  Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
  f.linear().col(0) = x;
  f.linear().col(1) = z.cross(x);
  f.linear().col(2) = z;
  f.translation() = origin;
  return f;
}

// The in-plane unit direction of `d` (plane normal z), or why there is none.
Eigen::Vector3d in_plane(const Eigen::Vector3d& d, const Eigen::Vector3d& z, const std::string& what) {
  const Eigen::Vector3d p = d - d.dot(z) * z;
  if (!(p.norm() > kDegenerate * d.norm()))
    throw DatumFrameError(what + " runs along the primary plane's normal: it fixes no direction in the plane");
  return p.normalized();
}

// The least-squares circle through points of a plane (2-D coordinates):
// the algebraic fit as the start, then Gauss-Newton on the distances to the
// circle. Throws DatumFrameError (naming `what`) for fewer than 3 points or
// collinear ones.
struct CircleFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0;
  double roundness = 0;  // max - min of the radial residuals [mm]
};

CircleFit fit_circle(const std::vector<Eigen::Vector2d>& q, const std::string& what) {
  constexpr int kMaxIterations = 50;
  constexpr double kStep = 1e-12;  // [mm] a step below this has converged
  const auto n = static_cast<Eigen::Index>(q.size());
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : q) mean += p;
  mean /= static_cast<double>(q.size());
  // x^2 + y^2 + D x + E y + F = 0 about the mean (better conditioned).
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  double reach = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d p = q[i] - mean;
    A.row(i) << p.x(), p.y(), 1;
    b(i) = -p.squaredNorm();
    reach = std::max(reach, p.norm());
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> algebraic(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd sv = algebraic.singularValues();
  if (n < 3 || !(reach > 0) || !(sv(2) > kDegenerate * sv(0)))
    throw DatumFrameError(what + ": its points do not span a circle (fewer than 3, or collinear in the primary "
                                 "plane)");
  const Eigen::Vector3d def = algebraic.solve(b);
  CircleFit c;
  c.centre = -0.5 * def.head<2>();
  c.radius = std::sqrt(std::max(0.0, c.centre.squaredNorm() - def(2)));
  bool converged = false;
  for (int iteration = 0; iteration < kMaxIterations && !converged; ++iteration) {
    Eigen::MatrixXd J(n, 3);
    Eigen::VectorXd r(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector2d d = q[i] - mean - c.centre;
      const double len = d.norm();
      if (!(len > 0)) throw DatumFrameError(what + ": a point lies on the fitted axis");
      J.row(i) << -d.x() / len, -d.y() / len, -1;
      r(i) = len - c.radius;
    }
    const Eigen::Vector3d step = J.colPivHouseholderQr().solve(-r);
    c.centre += step.head<2>();
    c.radius += step(2);
    converged = step.norm() <= kStep * (1 + reach);
  }
  if (!converged)
    throw DatumFrameError(what + ": the circle fit did not converge in " + std::to_string(kMaxIterations) +
                          " iterations");
  std::vector<double> radial;
  for (const Eigen::Vector2d& p : q) radial.push_back((p - mean - c.centre).norm() - c.radius);
  c.roundness = spread(radial);
  c.centre += mean;
  if (!c.centre.allFinite() || !std::isfinite(c.radius)) throw DatumFrameError(what + ": the circle fit failed");
  return c;
}

// The frame of a plane A, a cylinder B perpendicular to it and a point C
// (docs/registration.md "The 3-2-1 construction"): z = A's normal, the
// origin where B's axis meets A, x toward C. `ids` are the datums' point ids.
// A datum line's points seen along z (the primary plane's normal through
// `ca`): the least-squares line, its direction oriented by the order the
// plan lists the points in (first to last along the nominal direction, the
// order the program measures them: a placement cannot reverse it).
struct PlaneLine {
  Eigen::Vector3d point, direction;
  std::vector<double> across;  // each point's offset across the line
};
PlaneLine fit_line_in_plane(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& ca,
                            const Eigen::Vector3d& z, const std::string& label, const std::string& primary) {
  std::vector<Eigen::Vector3d> q;
  for (const Eigen::Vector3d& p : points) q.push_back(p - (p - ca).dot(z) * z);
  PlaneLine out;
  out.point = centroid_of(q);
  const auto svd = principal(q, out.point);
  double reach = 0;
  for (const Eigen::Vector3d& p : points) reach = std::max(reach, (p - centroid_of(points)).norm());
  if (!(svd.singularValues()(0) > kDegenerate * std::max(reach, 1.0)))
    throw DatumFrameError("datum " + label + ": its points coincide once projected into datum " + primary +
                          " (the line runs along the primary plane's normal), so it fixes no direction");
  out.direction = in_plane(svd.matrixV().col(0), z, "datum " + label);
  if ((q.back() - q.front()).dot(out.direction) < 0) out.direction = -out.direction;
  for (const Eigen::Vector3d& p : q) out.across.push_back((p - out.point).dot(z.cross(out.direction)));
  return out;
}

DatumFrame bore_frame(const std::vector<DatumFeature>& d, const std::vector<Eigen::Vector3d>& a,
                      const std::vector<Eigen::Vector3d>& b, const std::vector<Eigen::Vector3d>& c_points, double r,
                      const std::string& where) {
  const Eigen::Vector3d zn = d[0].normal.normalized();
  if (!(std::abs(d[1].direction.normalized().dot(zn)) >= std::cos(kPi / 180)))
    throw InputError(where + ": datum " + d[1].label + " is a cylinder whose axis is not perpendicular to datum " +
                     d[0].label + " (within 1 degree)");
  // Nominal frame: where B's axis meets plane A, x toward C (a point) or
  // along C (a line on a wall).
  const Eigen::Vector3d on = d[1].origin - (d[1].origin - d[0].origin).dot(zn) * zn;
  const bool c_line = d[2].kind == DatumFeature::Kind::line;
  Eigen::Vector3d to_c = c_line ? d[2].direction : Eigen::Vector3d(d[2].origin - on);
  to_c -= to_c.dot(zn) * zn;
  if (!(to_c.norm() > 1e-3))
    throw InputError(where + ": datum " + d[2].label +
                     (c_line ? " runs along the primary plane's normal, so it fixes no turn"
                             : " lies on the axis of datum " + d[1].label + ", so it fixes no turn about it"));
  DatumFrame out;
  out.nominal = frame(on, to_c.normalized(), zn);
  const Eigen::Vector3d c = c_points[0];

  const PlaneFit pa = fit_plane(a, zn, "datum " + d[0].label);
  const Eigen::Vector3d z = pa.normal, ca = pa.centroid - r * z;
  // B's points seen along z: a circle whose centre is the axis (the same for
  // centres and contacts: compensation only changes the radius).
  const Eigen::Vector3d e1 = (std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
                                 .cross(z)
                                 .normalized();
  const Eigen::Vector3d e2 = z.cross(e1);
  std::vector<Eigen::Vector2d> q;
  for (const Eigen::Vector3d& p : b) q.emplace_back((p - ca).dot(e1), (p - ca).dot(e2));
  const CircleFit circle = fit_circle(q, "datum " + d[1].label);
  const Eigen::Vector3d o = ca + circle.centre.x() * e1 + circle.centre.y() * e2;
  // C: a line's direction sets x (compensation moves the line sideways,
  // never turns it), or a point's direction from the axis does.
  Eigen::Vector3d x, c_at, c_direction;
  double c_form = 0;
  if (c_line) {
    const PlaneLine line = fit_line_in_plane(c_points, ca, z, d[2].label, d[0].label);
    x = c_direction = line.direction;
    c_at = line.point;
    c_form = spread(line.across);
  } else {
    // C is compensated along its nominal normal turned into the CMM frame,
    // and that turn is the one C itself fixes: a few rounds settle it (the
    // compensation moves C by r, mostly across x).
    Eigen::Vector3d cp = c, nc = Eigen::Vector3d::UnitZ();
    x = Eigen::Vector3d::UnitX();
    for (int round = 0; round < 20; ++round) {
      Eigen::Vector3d in_a = cp - o;
      in_a -= in_a.dot(z) * z;
      if (!(in_a.norm() > 1e-3))
        throw DatumFrameError("datum " + d[2].label + " was measured on the axis of datum " + d[1].label +
                              ", so it fixes no turn about it");
      x = in_a.normalized();
      const Eigen::Matrix3d rel = frame(Eigen::Vector3d::Zero(), x, z).linear() * out.nominal.linear().transpose();
      nc = rel * d[2].normal.normalized();
      const Eigen::Vector3d next = c - r * nc;
      const bool settled = (next - cp).norm() <= 1e-13 * (1 + cp.norm());
      cp = next;
      if (settled) break;
    }
    c_at = cp;
    c_direction = nc;
  }
  out.measured = frame(o, x, z);
  out.transform = out.nominal * out.measured.inverse();
  std::vector<std::string> ids[3];
  for (int k = 0; k < 3; ++k)
    for (const PlannedPoint& p : d[k].points) ids[k].push_back(p.id);
  out.datums.push_back({d[0].label, d[0].kind, ids[0], ca, z, pa.flatness});
  out.datums.push_back({d[1].label, d[1].kind, ids[1], o, z, circle.roundness});
  out.datums.push_back({d[2].label, d[2].kind, ids[2], c_at, c_direction, c_form});
  if (!out.transform.matrix().allFinite()) throw DatumFrameError("the datum frame is not finite");
  return out;
}

}  // namespace

PlaneFit fit_plane(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& orientation,
                   const std::string& what) {
  if (points.size() < 3)
    throw DatumFrameError(what + ": " + std::to_string(points.size()) + " points cannot fix a plane (3 needed)");
  PlaneFit f;
  f.centroid = centroid_of(points);
  const auto svd = principal(points, f.centroid);
  const Eigen::Vector3d s = svd.singularValues();
  if (!(s(0) > 0) || !(s(1) > kDegenerate * s(0)))
    throw DatumFrameError(what + ": the points are collinear, they fix no plane");
  f.normal = svd.matrixV().col(2);
  if (f.normal.dot(orientation) < 0) f.normal = -f.normal;
  std::vector<double> r;
  for (const Eigen::Vector3d& p : points) r.push_back((p - f.centroid).dot(f.normal));
  f.flatness = spread(r);
  return f;
}

DatumFrame fit_datum_frame(const PartAlignment& alignment, const MeasurementSet& set, const std::string& where) {
  if (alignment.method != PartAlignment::Method::datums)
    throw InputError(where + ": alignment method is " + to_string(alignment.method) +
                     ", --align datums needs a datums alignment");
  const std::vector<DatumFeature>& d = alignment.datums;
  using Kind = DatumFeature::Kind;
  if (d.size() != 3 || d[0].kind != Kind::plane || (d[1].kind != Kind::line && d[1].kind != Kind::cylinder) ||
      !(d[2].kind == Kind::point || (d[1].kind == Kind::cylinder && d[2].kind == Kind::line)))
    throw InputError(where + ": alignment.datums must be a plane, a line and a point, or a plane, a cylinder and "
                     "a point or a line (3-2-1)");
  if (!set.ids_from_file)
    throw InputError(set.source + ": the points carry no ids, so the datum points cannot be found");
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < set.points.size(); ++i) index.emplace(set.points[i].id, i);
  auto measured = [&](const DatumFeature& f) {
    std::vector<Eigen::Vector3d> out;
    for (const PlannedPoint& p : f.points) {
      const auto k = index.find(p.id);
      if (k == index.end())
        throw InputError(set.source + ": datum " + f.label + " point " + p.id + " (" + where +
                         " alignment) is not among the measured points");
      out.push_back(set.points[k->second].xyz);
    }
    return out;
  };
  const std::vector<Eigen::Vector3d> a = measured(d[0]), b = measured(d[1]), c = measured(d[2]);
  const double r = set.probe_radius;
  if (d[1].kind == Kind::cylinder) return bore_frame(d, a, b, c, r, where);
  if (b.size() < 2) throw DatumFrameError("datum " + d[1].label + ": a line needs 2 points");

  // The nominal frame first: its directions orient the measured ones.
  const Eigen::Vector3d zn = d[0].normal.normalized();
  const Eigen::Vector3d xn = in_plane(d[1].direction, zn, "nominal datum " + d[1].label);
  if (std::abs(d[2].normal.normalized().dot(xn)) < 0.1)
    throw DatumFrameError("datum " + d[2].label + ": its face does not face along datum " + d[1].label +
                          ", so the point fixes no origin along it");
  const Eigen::Vector3d bn = d[1].origin - (d[1].origin - d[0].origin).dot(zn) * zn;
  DatumFrame out;
  out.nominal = frame(bn + (d[2].origin - bn).dot(xn) * xn, xn, zn);

  // Primary: the plane, moved back by the probe radius for centre points.
  const PlaneFit pa = fit_plane(a, zn, "datum " + d[0].label);
  const Eigen::Vector3d z = pa.normal, ca = pa.centroid - r * z;
  // Secondary: its points in plane A, the least-squares line.
  const PlaneLine line = fit_line_in_plane(b, ca, z, d[1].label, d[0].label);
  const Eigen::Vector3d x = line.direction, qc = line.point;
  // Rotation taking part directions to CMM directions: where B's and C's
  // outward normals point on the CMM, for the probe compensation.
  const Eigen::Matrix3d rel = frame(Eigen::Vector3d::Zero(), x, z).linear() * out.nominal.linear().transpose();
  const Eigen::Vector3d nb = rel * d[1].normal.normalized(), nc = rel * d[2].normal.normalized();
  const Eigen::Vector3d nb_plane = nb - nb.dot(z) * z;
  const Eigen::Vector3d line_point = qc - r * nb_plane;
  // Tertiary: the point, moved back by the radius along its normal.
  const Eigen::Vector3d cp = c[0] - r * nc;
  out.measured = frame(line_point + (cp - line_point).dot(x) * x, x, z);
  out.transform = out.nominal * out.measured.inverse();

  std::vector<std::string> ids[3];
  for (int k = 0; k < 3; ++k)
    for (const PlannedPoint& p : d[k].points) ids[k].push_back(p.id);
  out.datums.push_back({d[0].label, d[0].kind, ids[0], ca, z, pa.flatness});
  out.datums.push_back({d[1].label, d[1].kind, ids[1], line_point, x, spread(line.across)});
  out.datums.push_back({d[2].label, d[2].kind, ids[2], cp, nc, 0.0});
  const Eigen::Matrix4d m = out.transform.matrix();
  if (!m.allFinite()) throw DatumFrameError("the datum frame is not finite");
  return out;
}

MeasurementSet without_points(const MeasurementSet& set, const std::set<std::string>& ids) {
  MeasurementSet out = set;
  out.points.clear();
  for (const MeasuredPoint& p : set.points)
    if (!ids.count(p.id)) out.points.push_back(p);
  return out;
}

MeasurementSet without_datum_points(const MeasurementSet& set, const PartAlignment& alignment) {
  std::set<std::string> datum_ids;
  for (const DatumFeature& f : alignment.datums)
    for (const PlannedPoint& p : f.points) datum_ids.insert(p.id);
  return without_points(set, datum_ids);
}

}  // namespace furrow

#pragma once
// Brute-force oracle for probe collisions with an indexable head: the probe
// assembly built from the head's numbers by the documented convention
// (docs/cmm.md "Indexable heads"), written here again on purpose, and the
// exact distance from a point to a capsule's axis swept along a straight
// motion (a parallelogram). Sampled part points within `radius` of the swept
// axis are collisions. Independent of the planner's sphere tracing.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace furrow::test {

// Distance from p to the segment [a, b].
inline double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// Distance from p to the parallelogram a + u (b - a) + w m, u, w in [0, 1]:
// the interior minimum of the convex quadratic if it lies inside, else the
// nearest of the four edges.
inline double point_parallelogram_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                           const Eigen::Vector3d& m) {
  const Eigen::Vector3d e = b - a, q = p - a;
  const double ee = e.dot(e), em = e.dot(m), mm = m.dot(m), det = ee * mm - em * em;
  if (det > 1e-12 * std::max(1.0, ee * mm)) {
    const double u = (q.dot(e) * mm - q.dot(m) * em) / det, w = (q.dot(m) * ee - q.dot(e) * em) / det;
    if (u >= 0 && u <= 1 && w >= 0 && w <= 1) return (a + u * e + w * m - p).norm();
  }
  return std::min({point_segment_distance(p, a, b), point_segment_distance(p, a + m, b + m),
                   point_segment_distance(p, a, a + m), point_segment_distance(p, b, b + m)});
}

struct OracleCapsule {
  Eigen::Vector3d a, b;  // axis with the ball centre at the origin
  double radius;
};

struct OracleHead {
  double ball_radius, stem_radius, stylus_length, body_length, body_radius, housing_length, housing_radius;
};

// Stylus direction from the head to the ball: A tilts from -z, B turns about z.
inline Eigen::Vector3d oracle_tip_direction(double a_degrees, double b_degrees) {
  const double pi = 3.14159265358979323846;
  const double a = a_degrees * pi / 180, b = b_degrees * pi / 180;
  return {std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), -std::cos(a)};
}

// Ball (as a zero-length capsule), shaft from the ball centre, probe body,
// vertical housing above the centre of rotation; relative to the ball centre.
inline std::vector<OracleCapsule> oracle_capsules(const OracleHead& h, double a_degrees, double b_degrees) {
  const Eigen::Vector3d axis = -oracle_tip_direction(a_degrees, b_degrees);
  const double reach = h.stylus_length + h.body_length;
  std::vector<OracleCapsule> out;
  out.push_back({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), h.ball_radius});
  // The shaft leaves the ball where its surface meets the ball.
  const double leave = std::sqrt(h.ball_radius * h.ball_radius - h.stem_radius * h.stem_radius);
  out.push_back({leave * axis, h.stylus_length * axis, h.stem_radius});
  out.push_back({h.stylus_length * axis, reach * axis, h.body_radius});
  if (h.housing_length > 0)
    out.push_back({reach * axis, reach * axis + Eigen::Vector3d(0, 0, h.housing_length), h.housing_radius});
  return out;
}

// Smallest (distance - radius) over the samples and the capsules, the ball
// centre moving straight from `from` to `to`; only samples in the swept box
// are looked at.
inline double swept_clearance(const std::vector<Eigen::Vector3d>& samples, const std::vector<OracleCapsule>& capsules,
                              const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  double best = std::numeric_limits<double>::infinity();
  for (const OracleCapsule& c : capsules) {
    const Eigen::Vector3d a = from + c.a, b = from + c.b, m = to - from;
    Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(a + m).cwiseMin(b + m);
    Eigen::Vector3d hi = a.cwiseMax(b).cwiseMax(a + m).cwiseMax(b + m);
    const double reach = c.radius + 1;  // look a little beyond the radius
    lo.array() -= reach;
    hi.array() += reach;
    for (const Eigen::Vector3d& s : samples) {
      if ((s.array() < lo.array()).any() || (s.array() > hi.array()).any()) continue;
      best = std::min(best, point_parallelogram_distance(s, a, b, m) - c.radius);
    }
  }
  return best;
}

}  // namespace furrow::test

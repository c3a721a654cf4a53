// Weakly constrained directions of a rigid fit, against the analytic answer
// of each shape (a plane leaves two slides and the turn about its normal, a
// cylinder the slide along and the turn about its axis, a sphere the three
// turns about its centre) and against a brute-force search over motions.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "inspection/observability.hpp"

using namespace furrow;

namespace {

struct Cloud {
  std::vector<Eigen::Vector3d> x, n;
  void add(const Eigen::Vector3d& p, const Eigen::Vector3d& normal) {
    x.push_back(p);
    n.push_back(normal.normalized());
  }
};

const MotionBasis kAll = free_parameter_basis({true, true, true, true, true, true});

// Distance from `p` to the line through `a` along unit `d`.
double line_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& d) {
  return (p - a).cross(d).norm();
}

// The share of a motion's displacement that shows along the normals: the
// quantity whose extremes the analysis finds, computed directly.
double share(const Cloud& c, const Eigen::Matrix<double, 6, 1>& p) {
  double h = 0, g = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    const Eigen::Vector3d d = p.head<3>().cross(c.x[i]) + p.tail<3>();
    h += std::pow(c.n[i].dot(d), 2);
    g += d.squaredNorm();
  }
  return h / g;
}

Cloud plane_patch(const Eigen::Vector3d& origin) {
  Cloud c;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 6; ++j) c.add(origin + Eigen::Vector3d(11.0 * i, 9.0 * j, 0), Eigen::Vector3d::UnitZ());
  return c;
}

}  // namespace

TEST_CASE("observability: a plane leaves the two slides in it and the turn about its normal") {
  for (const Eigen::Vector3d& origin : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1000, -2000, 500)}) {
    CAPTURE(origin.transpose());
    const Cloud c = plane_patch(origin);
    const Observability o = analyse_observability(c.x, c.n, kAll, 1e-3);
    REQUIRE(o.weak.size() == 3);
    CHECK(o.constrained.cols() == 3);
    int translations = 0;
    for (const WeakDirection& d : o.weak) {
      CHECK(d.ratio < 1e-9);
      CHECK(d.information < 1e-9);
      if (d.translation) {
        ++translations;
        CHECK(std::abs(d.direction.z()) < 1e-9);  // in the plane
      } else {
        CHECK(std::abs(d.direction.z()) == doctest::Approx(1).epsilon(1e-9));
        // About the normal through the points' centroid: (49.5, 22.5) from the origin.
        CHECK(d.axis_point.x() == doctest::Approx(origin.x() + 49.5).epsilon(1e-9));
        CHECK(d.axis_point.y() == doctest::Approx(origin.y() + 22.5).epsilon(1e-9));
        CHECK(std::abs(d.pitch) < 1e-9);
        CHECK(d.describe().find("rotation about the axis through") == 0);
      }
      // Each reported motion really is invisible to the residuals.
      CHECK(share(c, d.parameters) < 1e-12);
    }
    CHECK(translations == 2);
    // The constrained directions are tilts and the lift: their shares are large.
    for (Eigen::Index k = 0; k < o.constrained.cols(); ++k) CHECK(share(c, o.constrained.col(k)) > 0.01);
  }
}

TEST_CASE("observability: a cylinder leaves the slide along and the turn about its axis") {
  const Eigen::Vector3d axis_point(0, 5, 7), axis = Eigen::Vector3d(1, 2, 2).normalized();
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  Cloud c;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 8; ++j) {
      const double a = 2.1 * i / 11, s = 60.0 * j / 7;  // 120 degrees of arc, 60 mm long
      const Eigen::Vector3d radial = std::cos(a) * e1 + std::sin(a) * e2;
      c.add(axis_point + s * axis + 20 * radial, radial);
    }
  const Observability o = analyse_observability(c.x, c.n, kAll, 1e-3);
  REQUIRE(o.weak.size() == 2);
  int rotations = 0;
  for (const WeakDirection& d : o.weak) {
    CHECK(std::abs(d.direction.dot(axis)) == doctest::Approx(1).epsilon(1e-9));
    if (!d.translation) {
      ++rotations;
      CHECK(line_distance(d.axis_point, axis_point, axis) < 1e-7);
      CHECK(std::abs(d.pitch) < 1e-7);
    }
    CHECK(share(c, d.parameters) < 1e-12);
  }
  CHECK(rotations == 1);
}

TEST_CASE("observability: a sphere cap leaves the three turns about its centre") {
  const Eigen::Vector3d centre(1, 2, 3);
  Cloud c;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 12; ++j) {
      const double lat = 0.3 + 0.12 * i, lon = 0.5 * j;
      const Eigen::Vector3d r(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
      c.add(centre + 30 * r, r);
    }
  const Observability o = analyse_observability(c.x, c.n, kAll, 1e-3);
  REQUIRE(o.weak.size() == 3);
  for (const WeakDirection& d : o.weak) {
    CHECK_FALSE(d.translation);
    CHECK(line_distance(centre, d.axis_point, d.direction) < 1e-7);
    CHECK(share(c, d.parameters) < 1e-12);
  }
}

TEST_CASE("observability: a wavy patch fixes all six, the extremes bound every motion (brute force)") {
  // z = 8 sin(x/12) cos(y/9) over 60 x 40 mm: bumps and hollows, no motion
  // slides along it.
  Cloud c;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 7; ++j) {
      const double x = -30 + 7.5 * i, y = -20 + 6.5 * j;
      const double zx = 8.0 / 12 * std::cos(x / 12) * std::cos(y / 9), zy = -8.0 / 9 * std::sin(x / 12) * std::sin(y / 9);
      c.add({x, y, 8 * std::sin(x / 12) * std::cos(y / 9)}, Eigen::Vector3d(-zx, -zy, 1));
    }
  const Observability o = analyse_observability(c.x, c.n, kAll, 1e-3);
  CHECK(o.weak.empty());
  CHECK(o.constrained.cols() == 6);
  REQUIRE(o.ratios.size() == 6);
  CHECK(o.ratios.back() == doctest::Approx(1));
  // No motion shows a smaller or larger share than the extreme eigenvalues:
  // 20000 random motions, and the share of each is within [min, max].
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  double lo = 1e9, hi = 0, largest = 0;
  Eigen::Matrix<double, 6, 1> best;
  for (int k = 0; k < 6; ++k) largest = std::max(largest, share(c, o.constrained.col(k)));
  for (int k = 0; k < 20000; ++k) {
    Eigen::Matrix<double, 6, 1> p;
    for (int m = 0; m < 6; ++m) p(m) = g(rng) * (m < 3 ? 0.02 : 1.0);
    const double s = share(c, p);
    if (s < lo) best = p;
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  CHECK(hi <= largest * (1 + 1e-9));
  CHECK(lo / largest >= o.ratios.front() * (1 - 1e-9));
  // A random descent from the best sample (a second, brute-force minimiser)
  // ends on the smallest share the analysis reports.
  double step = 0.1;
  for (int k = 0; k < 60000 && step > 1e-9; ++k) {
    Eigen::Matrix<double, 6, 1> p = best;
    for (int m = 0; m < 6; ++m) p(m) += g(rng) * step * best.norm() * (m < 3 ? 0.02 : 1.0);
    const double s = share(c, p);
    if (s < lo) {  // the one-fifth success rule of evolution strategies
      lo = s;
      best = p;
      step *= 1.3;
    } else {
      step *= 0.94;
    }
  }
  CHECK(lo / largest == doctest::Approx(o.ratios.front()).epsilon(1e-3).scale(0));
}

TEST_CASE("observability: locked degrees of freedom are not analysed, the free ones are") {
  const Cloud c = plane_patch(Eigen::Vector3d(5, 5, 0));
  // Only tz, rx, ry free: the plane fixes them all.
  const Observability o = analyse_observability(c.x, c.n, free_parameter_basis({true, true, false, false, false, true}), 1e-3);
  CHECK(o.weak.empty());
  CHECK(o.constrained.cols() == 3);
  // tx, tz free: tx is a slide in the plane.
  const Observability s = analyse_observability(c.x, c.n, free_parameter_basis({false, false, false, true, false, true}), 1e-3);
  REQUIRE(s.weak.size() == 1);
  CHECK(s.weak[0].translation);
  CHECK(std::abs(s.weak[0].direction.x()) == doctest::Approx(1));
}

TEST_CASE("observability: weak only because of the points, told apart from the surface's own") {
  // A grid over the plane z = 0 and, on it, points along one line y = 3.
  Cloud surface = plane_patch(Eigen::Vector3d(0, 0, 0));
  Cloud line;
  for (int i = 0; i < 15; ++i) line.add({4.0 * i, 3, 0}, Eigen::Vector3d::UnitZ());
  Observability o = analyse_observability(line.x, line.n, kAll, 1e-3);
  // The plane's three, plus the turn about the line itself.
  REQUIRE(o.weak.size() == 4);
  mark_weak_by_points(o, line.x, line.n, surface.x, surface.n);
  REQUIRE(o.weak.size() == 4);
  int from_points = 0;
  for (const WeakDirection& d : o.weak)
    if (d.from_points) {
      ++from_points;
      // The turn about the line of points: the plane would fix it.
      CHECK_FALSE(d.translation);
      CHECK(std::abs(d.direction.x()) == doctest::Approx(1).epsilon(1e-9));
      CHECK(line_distance({0, 3, 0}, d.axis_point, d.direction) < 1e-7);
    }
  CHECK(from_points == 1);
  // Points spread over the plane: weak only as the plane itself is.
  Observability spread = analyse_observability(surface.x, surface.n, kAll, 1e-3);
  mark_weak_by_points(spread, surface.x, surface.n, surface.x, surface.n);
  for (const WeakDirection& d : spread.weak) CHECK_FALSE(d.from_points);
  CHECK(spread.weak.size() == 3);
}

TEST_CASE("observability: identical points fix only the motion along their normal") {
  Cloud same;
  for (int i = 0; i < 40; ++i) same.add({3, 4, 5}, Eigen::Vector3d(0, 0.6, 0.8));
  const Observability o = analyse_observability(same.x, same.n, kAll, 1e-3);
  CHECK(o.weak.size() == 5);
  REQUIRE(o.constrained.cols() == 1);
  const Eigen::Matrix<double, 6, 1> p = o.constrained.col(0);
  // The one constrained motion moves the point along (0, 0.6, 0.8).
  const Eigen::Vector3d d = p.head<3>().cross(Eigen::Vector3d(3, 4, 5)) + p.tail<3>();
  CHECK(std::abs(d.normalized().dot(Eigen::Vector3d(0, 0.6, 0.8))) == doctest::Approx(1).epsilon(1e-9));
}

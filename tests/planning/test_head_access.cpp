// Access checks with an indexable head: the tilted stylus, probe body and
// head housing against a floor and a wall, compared with brute force (dense
// samples of both faces against the swept capsules, support/capsule_oracle.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "geometry/primitives.hpp"
#include "io/cmm/probe_head.hpp"
#include "planning/accessibility.hpp"
#include "plan_fixtures.hpp"
#include "support/capsule_oracle.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// Floor z = 0 over x in [-20, 5], y in [-10, 10]; a wall x = 5 facing -x,
// z in [0, 30].
Part floor_and_wall() { return test::floor_and_wall(-20, 10, 30); }

std::vector<Eigen::Vector3d> floor_and_wall_samples(double h) { return test::floor_and_wall_samples(h, -20, 10, 30); }

const OracleHead kHead{1, 0.5, 20, 25, 6.5, 30, 12};

ProbeGeometry head_probe(double a, double b) {
  ProbeGeometry g{kHead.ball_radius, kHead.stem_radius, kHead.stylus_length};
  g.sections = {{kHead.body_length, kHead.body_radius}};
  g.housing = {kHead.housing_length, kHead.housing_radius};
  g.axis = -tip_direction({a, b});
  return g;
}

}  // namespace

TEST_CASE("tip direction: A tilts from -z, B turns about z (analytic)") {
  CHECK((tip_direction({0, 0}) - Eigen::Vector3d(0, 0, -1)).norm() < 1e-15);
  CHECK((tip_direction({90, 0}) - Eigen::Vector3d(1, 0, 0)).norm() < 1e-15);
  CHECK((tip_direction({90, 90}) - Eigen::Vector3d(0, 1, 0)).norm() < 1e-15);
  for (double a : {7.5, 30.0, 52.5, 105.0})
    for (double b : {-180.0, -37.5, 0.0, 120.0}) {
      const Eigen::Vector3d t = tip_direction({a, b});
      CHECK(std::abs(t.norm() - 1) < 1e-15);
      CHECK(std::abs(std::acos(-t.z()) * 180 / kPi - a) < 1e-9);                       // tilt from -z
      if (a > 0) CHECK(std::abs(std::remainder(std::atan2(t.y(), t.x()) * 180 / kPi - b, 360)) < 1e-9);  // about z
    }
}

TEST_CASE("head access: near a wall the tip facing away reaches, the one facing the wall does not") {
  const Part part = floor_and_wall();
  const ClosestPointFinder finder(part);
  AccessOptions o;
  o.clearance_z = 60;
  const Eigen::Vector3d p(2, 0, 0), n(0, 0, 1);
  // B = 0 points the stylus tip to +x: the body leans back to -x, away from the wall.
  CHECK(check_access(finder, p, n, head_probe(45, 0), o).ok());
  const AccessResult toward = check_access(finder, p, n, head_probe(45, 180), o);
  CHECK(toward.problem == AccessProblem::stylus);
  // The same point, vertical tip: the shaft rises 3 mm from the wall, clear;
  // the body (radius 6.5) comes within 3 mm of the wall.
  CHECK(check_access(finder, p, n, head_probe(0, 0), o).problem == AccessProblem::probe_body);
  // The wall itself: the vertical tip is 90 degrees off its normal, a
  // horizontal tip pointing at it (A90 B0: stylus along +x) takes it.
  const Eigen::Vector3d w(5, 0, 15), wn(-1, 0, 0);
  CHECK(check_access(finder, w, wn, head_probe(0, 0), o).problem == AccessProblem::tilt);
  CHECK(check_access(finder, w, wn, head_probe(90, 0), o).ok());
}

TEST_CASE("head access agrees with brute force on a floor and a wall") {
  const Part part = floor_and_wall();
  const ClosestPointFinder finder(part);
  AccessOptions o;
  o.clearance_z = 70;
  const double h = 0.2;
  const std::vector<Eigen::Vector3d> samples = floor_and_wall_samples(h);
  // Sampling error: a sampled grid overestimates the distance to a plane by
  // at most h^2 / (4 d) for d >= the smallest radius (0.5).
  const double sampling = h * h / (4 * 0.5) + 1e-6;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> fx(-15, 4), fy(-6, 6), fz(2, 25);
  const double tips[][2] = {{0, 0}, {30, 0}, {30, 180}, {45, 90}, {60, 0}, {60, 180}, {90, 0}, {90, 90}, {90, 180}};
  int ok = 0, blocked = 0, compared = 0;
  for (int k = 0; k < 160; ++k) {
    const bool on_wall = k % 3 == 0;
    const Eigen::Vector3d p = on_wall ? Eigen::Vector3d(5, fy(rng), fz(rng)) : Eigen::Vector3d(fx(rng), fy(rng), 0);
    const Eigen::Vector3d n = on_wall ? Eigen::Vector3d(-1, 0, 0) : Eigen::Vector3d(0, 0, 1);
    const double* tip = tips[k % 9];
    const ProbeGeometry probe = head_probe(tip[0], tip[1]);
    const AccessResult got = check_access(finder, p, n, probe, o);
    // Oracle: tilt, then every capsule along the touch and both vertical legs.
    const std::vector<OracleCapsule> caps = oracle_capsules(kHead, tip[0], tip[1]);
    const double tilt = std::acos(std::clamp(n.dot(-oracle_tip_direction(tip[0], tip[1])), -1.0, 1.0));
    const Eigen::Vector3d c = p + n, out = p + 4 * n;
    // The ball touches at p by design: it is checked on the vertical legs
    // only; the rest of the assembly along the touch too.
    // `margin`: the same less each capsule's documented conservatism (a
    // quarter of its radius, accessibility.hpp).
    const Eigen::Vector3d top(out.x(), out.y(), o.clearance_z);
    double clearance = std::numeric_limits<double>::infinity(), margin = clearance;
    for (std::size_t i = 0; i < caps.size(); ++i) {
      const std::vector<OracleCapsule> one{caps[i]};
      double d = swept_clearance(samples, one, out, top);
      if (i > 0) d = std::min(d, swept_clearance(samples, one, c, out));
      clearance = std::min(clearance, d);
      margin = std::min(margin, d - (i > 0 ? caps[i].radius / 4 : 0.0));
    }
    CAPTURE(k);
    CAPTURE(p.transpose());
    CAPTURE(tip[0]);
    CAPTURE(tip[1]);
    CAPTURE(clearance);
    CAPTURE(to_string(got.problem));
    if (tilt > o.max_tilt + 1e-12) {
      CHECK(got.problem == AccessProblem::tilt);
      continue;
    }
    // Accepted: nothing of the assembly comes into the part (the ball may
    // touch at p: clearance 0 there).
    if (got.ok()) {
      CHECK(clearance >= -1e-6);
      ++ok;
    } else {
      ++blocked;
    }
    // Clearly clear (beyond the check's documented conservatism): accepted.
    if (margin > sampling + 0.02) {
      CHECK(got.ok());
      ++compared;
    }
    // Clearly colliding: refused.
    if (clearance < -sampling) CHECK(!got.ok());
  }
  CHECK(ok >= 20);
  CHECK(blocked >= 20);
  CHECK(compared >= 20);
}

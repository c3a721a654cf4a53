#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "io/part_file.hpp"
#include "machining/cutter/contact_from_tip.hpp"
#include "cutter_reference.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

// The mould is a height field: its control points sit at the Greville
// abscissae, so x = 100 u and y = 80 v exactly and z(x, y) = S(x/100, y/80).z
// over [0, 100] x [0, 80] (no surface outside).
double mould_height(const Face& mould, double x, double y) {
  if (x < 0 || x > 100 || y < 0 || y > 80) return -1e300;
  return mould.surface().point(x / 100, y / 80).z();
}

// Brute-force drop cutter: the tip height at which the cutter, lowered at
// (x, y), first touches the height field, its edges included.
double drop_cutter(const Face& mould, const Cutter& cutter, double x, double y) {
  auto value = [&](double rho, double phi) {
    return mould_height(mould, x + rho * std::cos(phi), y + rho * std::sin(phi)) - cutter.height_at(rho);
  };
  double best = test::maximize_over_disc(cutter.radius(), value, 120, 360);
  // The part's edges, where a cutter hanging over them rests: each edge line
  // sampled densely, then zoomed into.
  for (int e = 0; e < 4; ++e) {
    auto point = [&](double s) -> Eigen::Vector2d {
      return e == 0 ? Eigen::Vector2d(0, s) : e == 1 ? Eigen::Vector2d(100, s)
           : e == 2 ? Eigen::Vector2d(s, 0) : Eigen::Vector2d(s, 80);
    };
    const double length = e < 2 ? 80 : 100;
    auto edge_value = [&](double s) {
      const Eigen::Vector2d p = point(std::clamp(s, 0.0, length));
      const double rho = std::hypot(p.x() - x, p.y() - y);
      return rho > cutter.radius() ? -1e300 : mould_height(mould, p.x(), p.y()) - cutter.height_at(rho);
    };
    double s_best = 0, v_best = -1e300;
    for (int k = 0; k <= 4000; ++k) {
      const double v = edge_value(length * k / 4000);
      if (v > v_best) v_best = v, s_best = length * k / 4000;
    }
    for (double half = length / 4000; half > 1e-13; half *= 0.3)
      for (int k = -10; k <= 10; ++k) {
        const double v = edge_value(s_best + half * k / 10);
        if (v > v_best) v_best = v, s_best = std::clamp(s_best + half * k / 10, 0.0, length);
      }
    best = std::max(best, v_best);
  }
  return best;
}

}  // namespace

TEST_CASE("contact from tip: inverts cutter location on the mould and agrees with a brute-force drop cutter") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const Face& mould = part.faces[0];
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(0.15, 0.85);
  int resting = 0;
  for (const Cutter& cutter : {Cutter("ball", 3, 3), Cutter("bull", 4, 1), Cutter("flat", 2.5, 0)}) {
    const TipContactFinder finder(part, cutter);
    for (int k = 0; k < 12; ++k) {
      CAPTURE(cutter.name());
      CAPTURE(k);
      const Eigen::Vector2d uv(unit(rng), unit(rng));
      const DifferentialGeometry g = mould.geometry(uv.x(), uv.y());
      const CutterLocation loc = cutter_location(cutter, g.point, g.normal);
      REQUIRE(loc.reachable);
      const TipContactResult result = finder.find(loc.tip);
      REQUIRE(result.status == TipContactStatus::found);
      // The given contact is one of the tangencies found...
      bool has_p = false;
      for (const TipContact& c : result.contacts) has_p |= (c.point - g.point).norm() < 1e-6;
      CHECK(has_p);
      // ...and the highest tangency is where a dropped cutter rests.
      const double drop = drop_cutter(mould, cutter, loc.tip.x(), loc.tip.y());
      CHECK(result.contacts[0].tip_z == doctest::Approx(drop).epsilon(1e-8).scale(1));
      if (std::abs(drop - loc.tip.z()) < 1e-8) {
        ++resting;
        CHECK((result.contacts[0].point - g.point).norm() < 1e-6);
        CHECK(std::abs(result.gap) < 1e-8);
        CHECK(std::abs(result.contacts[0].uv.x() - uv.x()) < 1e-8);
        // Raised by 0.25 mm: the same contact, 0.25 mm of air.
        const TipContactResult up = finder.find(loc.tip + Eigen::Vector3d(0, 0, 0.25));
        CHECK(up.gap == doctest::Approx(0.25).epsilon(1e-9));
      } else {
        CHECK(result.gap < 0);  // this tip cuts in somewhere else
      }
    }
  }
  CHECK(resting > 20);
}

TEST_CASE("contact from tip: a ball too big for the dimple rests on its rim, the given contact lies below") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const Face& mould = part.faces[0];
  const Cutter ball("ball", 15, 15);
  const TipContactFinder finder(part, ball);
  // The dimple's bottom, about (72, 30): concave with radius ~9 mm < 15.
  const DifferentialGeometry g = mould.geometry(0.72, 0.375);
  REQUIRE(g.k2 > 1 / 15.0);
  const CutterLocation loc = cutter_location(ball, g.point, g.normal);
  const TipContactResult r = finder.find(loc.tip);
  REQUIRE(r.status == TipContactStatus::found);
  const double drop = drop_cutter(mould, ball, loc.tip.x(), loc.tip.y());
  CHECK(drop > loc.tip.z() + 0.1);  // the ball cannot get down there
  CHECK(r.contacts[0].tip_z == doctest::Approx(drop).epsilon(1e-8).scale(1));
  CHECK(r.gap == doctest::Approx(loc.tip.z() - drop).epsilon(1e-8).scale(1));
  CHECK((r.contacts[0].point - g.point).norm() > 1);
  bool has_p = false;
  for (const TipContact& c : r.contacts) has_p |= (c.point - g.point).norm() < 1e-6;
  CHECK(has_p);  // the fold of the offset surface is listed too
}

TEST_CASE("contact from tip: a cutter hanging over the mould's edge rests on the edge") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const Face& mould = part.faces[0];
  for (const Cutter& cutter : {Cutter("ball", 4, 4), Cutter("bull", 5, 1), Cutter("flat", 3, 0)}) {
    const TipContactFinder finder(part, cutter);
    const double off = 0.8 * cutter.radius();  // mostly off the part: it sits on the edge
    for (const Eigen::Vector2d& xy : {Eigen::Vector2d(100 + off, 40), Eigen::Vector2d(-off, 17),
                                      Eigen::Vector2d(50, 80 + off), Eigen::Vector2d(-1, 30),
                                      Eigen::Vector2d(99, 79)}) {
      CAPTURE(cutter.name());
      CAPTURE(xy.x());
      CAPTURE(xy.y());
      const TipContactResult r = finder.find(Eigen::Vector3d(xy.x(), xy.y(), 60));
      REQUIRE(r.status == TipContactStatus::found);
      // Beyond x = 100 the part rises toward its edge: the cutter sits on it.
      if (xy.x() > 100) CHECK(r.contacts[0].kind == ContactKind::edge);
      CHECK(r.contacts[0].tip_z == doctest::Approx(drop_cutter(mould, cutter, xy.x(), xy.y())).epsilon(1e-9).scale(1));
    }
  }
}

TEST_CASE("contact from tip: a flat bottom rests on the dome's top") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const Face& mould = part.faces[0];
  const Cutter flat("flat", 3, 0);
  const TipContactFinder finder(part, flat);
  // Near the dome's summit (about (30.6, 45)), a tip 50 mm up.
  const TipContactResult r = finder.find(Eigen::Vector3d(31, 45.5, 50));
  REQUIRE(r.status == TipContactStatus::found);
  const TipContact& top = r.contacts[0];
  CHECK(top.kind == ContactKind::flat_bottom);
  CHECK(std::hypot(top.normal.x(), top.normal.y()) < 1e-9);
  CHECK(top.tip_z == doctest::Approx(drop_cutter(mould, flat, 31, 45.5)).epsilon(1e-9));
  CHECK(r.gap == doctest::Approx(50 - top.tip_z));
  // Far off the part: nothing under the cutter.
  const TipContactResult off = finder.find(Eigen::Vector3d(400, 400, 50));
  CHECK(off.status == TipContactStatus::no_contact);
  CHECK(off.contacts.empty());
}

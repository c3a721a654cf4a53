#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <vector>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "machining/brute_force_envelope.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/prediction/furrow_step.hpp"

using namespace furrow;

namespace {

std::string example(const std::string& name) { return std::string(FURROW_SOURCE_DIR) + "/examples/parts/" + name; }

struct BruteStep {
  double max_error = -1e300, min_error = 1e300;
  double max_at = 0, min_at = 0;  // curve parameter
};

// The curve sampled at `coarse` + 1 points, then at `fine` points between
// the neighbours of the best coarse sample (for each extreme); each error
// from the brute-force envelope (dense cutter positions) and a
// scanned-then-bisected root along the normal.
BruteStep brute_force_step(const Cutter& cutter, const Eigen::Vector3d& t0, const Eigen::Vector3d& t1,
                           const std::function<void(double, Eigen::Vector3d&, Eigen::Vector3d&)>& point_at,
                           int move_samples, int coarse = 60, int fine = 60) {
  BruteStep r;
  auto height = [&](double x, double y) { return test::brute_force_height(cutter, t0, t1, x, y, move_samples); };
  auto consider = [&](double lambda) {
    Eigen::Vector3d q, n;
    point_at(lambda, q, n);
    const double e = test::brute_force_normal_error(height, q, n, 5e-3, 3.0);
    if (!std::isfinite(e)) return;
    if (e > r.max_error) r.max_error = e, r.max_at = lambda;
    if (e < r.min_error) r.min_error = e, r.min_at = lambda;
  };
  for (int i = 0; i <= coarse; ++i) consider(double(i) / coarse);
  const double h = 1.0 / coarse;
  for (const double centre : {r.max_at, r.min_at})
    for (int i = 0; i <= fine; ++i) consider(std::clamp(centre - h + 2 * h * i / fine, 0.0, 1.0));
  return r;
}

// A circular section of radius rho in the plane y = y0, angle psi from +x
// toward +z: convex (normal away from the centre) or concave (toward it).
struct Section {
  double rho, y0, psi0, psi1;
  bool convex;
  void at(double lambda, Eigen::Vector3d& q, Eigen::Vector3d& n) const {
    const double psi = psi0 + lambda * (psi1 - psi0);
    const Eigen::Vector3d radial(std::cos(psi), 0, std::sin(psi));
    q = Eigen::Vector3d(0, y0, 0) + rho * radial;
    n = convex ? radial : -radial;
  }
};

SurfacePoint on_part(const VerticalProjector& projector, const Eigen::Vector3d& p) {
  const SurfacePoint s = projector.project(p.x(), p.y());
  REQUIRE(s.valid);
  REQUIRE((s.point - p).norm() < 1e-9);
  return s;
}

}  // namespace

TEST_CASE("reference figure: ball R 12.7, convex cylinder 25.4, 3.68 mm step overcuts 0.100 mm at mid-step") {
  const Part part = read_part(example("semi_cylinder.json"));
  const VerticalProjector projector(part);
  const Cutter ball("ball", 12.7, 12.7);
  const double rho = 25.4, r = 12.7, step = 3.68, half = 0.5 * step / rho;
  const Section section{rho, 25.4, M_PI / 2 + half, M_PI / 2 - half, true};
  Eigen::Vector3d q0, q1, n0, n1;
  section.at(0, q0, n0);
  section.at(1, q1, n1);
  const SurfacePoint a = on_part(projector, q0), b = on_part(projector, q1);
  CHECK((a.normal - n0).norm() < 1e-9);

  const double analytic_overcut = -(rho + r) * (1 - std::cos(half));
  const double analytic_chord = rho * (1 - std::cos(half));
  for (int kind = 0; kind < 2; ++kind) {
    CAPTURE(kind);
    const SurfaceCurve curve = kind == 0 ? vertical_section_curve(projector, a, b)
                                         : iso_parametric_curve(part, 0, a.uv, b.uv);
    const FurrowStepResult s = furrow_step_error(ball, curve);
    REQUIRE(s.valid);
    CHECK(s.converged);
    CHECK(s.unreached == 0);
    // docs/architecture.md's figure, and the closed form behind it.
    CHECK(std::fabs(s.overcut.error - (-0.100)) <= 0.001);
    CHECK(std::fabs(s.overcut.error - analytic_overcut) < 1e-7);
    CHECK(s.overcut.at.point.x() == doctest::Approx(0).scale(1).epsilon(1e-4));  // mid-step: the top
    CHECK(s.undercut.error < 1e-9);  // nothing left on a convex step
    const ChordDeviation c = chord_deviation(curve);
    REQUIRE(c.valid);
    CHECK(std::fabs(c.deviation - 0.0667) <= 0.0005);
    CHECK(std::fabs(c.deviation - analytic_chord) < 1e-7);
    // The chord estimate is a third short of the real error.
    CHECK(c.deviation / -s.overcut.error == doctest::Approx(rho / (rho + r)).epsilon(1e-5));
  }
  // Brute force on the exact circle (independent of the NURBS).
  const CutterLocation la = cutter_location(ball, q0, n0), lb = cutter_location(ball, q1, n1);
  const BruteStep brute =
      brute_force_step(ball, la.tip, lb.tip, [&](double l, Eigen::Vector3d& q, Eigen::Vector3d& n) { section.at(l, q, n); }, 300);
  const FurrowStepResult s = furrow_step_error(ball, vertical_section_curve(projector, a, b));
  CHECK(std::fabs(s.overcut.error - brute.min_error) < 1e-6);
  CHECK(brute.min_at == doctest::Approx(0.5).epsilon(0.01).scale(0));
}

TEST_CASE("the same step on a concave cylinder leaves material: brute force and closed form agree") {
  Part part;
  part.faces.emplace_back("tube", make_cylinder(25.4, 50.8, -M_PI, 0.0));
  const VerticalProjector projector(part);
  const Cutter ball("ball", 12.7, 12.7);
  const double rho = 25.4, r = 12.7, half = 0.5 * 3.68 / rho;
  const Section section{rho, 25.4, -M_PI / 2 - half, -M_PI / 2 + half, false};
  Eigen::Vector3d q0, q1, n0, n1;
  section.at(0, q0, n0);
  section.at(1, q1, n1);
  const SurfacePoint a = on_part(projector, q0), b = on_part(projector, q1);
  CHECK((a.normal - n0).norm() < 1e-9);
  const FurrowStepResult s = furrow_step_error(ball, vertical_section_curve(projector, a, b));
  REQUIRE(s.valid);
  CHECK(s.converged);
  CHECK(s.overcut.error > -1e-9);
  CHECK(s.undercut.error > 0.03);
  // The ball centres run on a circle of radius rho - r: its chord sags
  // (rho - r)(1 - cos(half)) toward the axis, the ball's far side stays that
  // much short of the tube.
  CHECK(std::fabs(s.undercut.error - (rho - r) * (1 - std::cos(half))) < 1e-7);
  const CutterLocation la = cutter_location(ball, q0, n0), lb = cutter_location(ball, q1, n1);
  const BruteStep brute =
      brute_force_step(ball, la.tip, lb.tip, [&](double l, Eigen::Vector3d& q, Eigen::Vector3d& n) { section.at(l, q, n); }, 300);
  CHECK(std::fabs(s.undercut.error - brute.max_error) < 1e-6);
}

TEST_CASE("bull-nose and flat end mills on convex and concave sections agree with brute force to 1 um") {
  Part convex_part = read_part(example("semi_cylinder.json"));
  Part concave_part;
  concave_part.faces.emplace_back("tube", make_cylinder(25.4, 50.8, -M_PI, 0.0));
  const Cutter cutters[] = {Cutter("bull", 5, 1.5), Cutter("flat", 4, 0), Cutter("ball", 3, 3)};
  for (int convex = 0; convex < 2; ++convex) {
    const Part& part = convex ? convex_part : concave_part;
    const VerticalProjector projector(part);
    const double rho = 25.4;
    // Off the top, so that the contact normals are tilted (the bull-nose
    // touches on its corner, the flat end mill on its rim).
    for (double centre : {0.35, 0.9}) {
      const double mid = convex ? M_PI / 2 + centre : -M_PI / 2 + centre;
      const Section section{rho, 20.0, mid - 0.06, mid + 0.06, convex == 1};
      Eigen::Vector3d q0, q1, n0, n1;
      section.at(0, q0, n0);
      section.at(1, q1, n1);
      const SurfacePoint a = on_part(projector, q0), b = on_part(projector, q1);
      for (const Cutter& cutter : cutters) {
        CAPTURE(cutter.name());
        CAPTURE(convex);
        CAPTURE(centre);
        const FurrowStepResult s = furrow_step_error(cutter, vertical_section_curve(projector, a, b));
        REQUIRE(s.valid);
        CHECK(s.converged);
        const CutterLocation la = cutter_location(cutter, q0, n0), lb = cutter_location(cutter, q1, n1);
        const BruteStep brute = brute_force_step(
            cutter, la.tip, lb.tip, [&](double l, Eigen::Vector3d& q, Eigen::Vector3d& n) { section.at(l, q, n); }, 300);
        CHECK(std::fabs(s.undercut.error - std::max(0.0, brute.max_error)) < 1e-6);
        CHECK(std::fabs(s.overcut.error - std::min(0.0, brute.min_error)) < 1e-6);
        CHECK(s.magnitude() > 1e-4);  // a real error, not a trivial zero
      }
    }
  }
}

TEST_CASE("an inflecting step on the mould has both an undercut and an overcut, each as brute force finds") {
  const Part part = read_part(example("mould.json"));
  // Along y = 30 across the dimple's flank (x 57..69): the section bends
  // from convex (saddle ring) to concave (dimple).
  const VerticalProjector projector(part);
  const Cutter cutters[] = {Cutter("ball", 3, 3), Cutter("bull", 4, 1)};
  for (const Cutter& cutter : cutters) {
    const SurfacePoint a = projector.project(57.0, 30.0), b = projector.project(69.0, 30.0);
    REQUIRE(a.valid);
    REQUIRE(b.valid);
    const SurfaceCurve curve = vertical_section_curve(projector, a, b);
    const FurrowStepResult s = furrow_step_error(cutter, curve);
    REQUIRE(s.valid);
    CHECK(s.converged);
    CHECK(s.undercut.error > 1e-3);
    CHECK(s.overcut.error < -1e-3);
    CHECK(s.undercut.lambda > s.overcut.lambda);  // convex first, then concave
    const CutterLocation la = cutter_location(cutter, a.point, a.normal), lb = cutter_location(cutter, b.point, b.normal);
    const BruteStep brute = brute_force_step(
        cutter, la.tip, lb.tip,
        [&](double l, Eigen::Vector3d& q, Eigen::Vector3d& n) {
          const SurfacePoint p = curve(l);
          q = p.point;
          n = p.normal;
        },
        300);
    CAPTURE(cutter.name());
    CHECK(std::fabs(s.undercut.error - brute.max_error) < 1e-6);
    CHECK(std::fabs(s.overcut.error - brute.min_error) < 1e-6);
  }
}

TEST_CASE("a remembering curve evaluates each point once and changes no bit of the error or the chord deviation") {
  const Part part = read_part(example("mould.json"));
  const VerticalProjector projector(part);
  const Cutter ball("ball", 3, 3);
  const SurfacePoint a = projector.project(57.0, 30.0), b = projector.project(69.0, 30.0);
  REQUIRE(a.valid);
  REQUIRE(b.valid);
  const SurfaceCurve plain = vertical_section_curve(projector, a, b);
  // Counts the projections a curve makes, by lambda.
  std::map<double, int> calls;
  const SurfaceCurve counted = [&](double lambda) {
    ++calls[lambda];
    return plain(lambda);
  };
  const SurfaceCurve remembering = remembering_curve(counted);
  const FurrowStepResult r = furrow_step_error(ball, remembering), p = furrow_step_error(ball, plain);
  const ChordDeviation rc = chord_deviation(remembering), pc = chord_deviation(plain);
  REQUIRE(r.valid);
  CHECK(r.undercut.error == p.undercut.error);
  CHECK(r.undercut.lambda == p.undercut.lambda);
  CHECK(r.overcut.error == p.overcut.error);
  CHECK(r.overcut.lambda == p.overcut.lambda);
  CHECK(r.undercut.at.point == p.undercut.at.point);
  CHECK(r.overcut.at.normal == p.overcut.at.normal);
  CHECK(r.samples == p.samples);
  CHECK(rc.deviation == pc.deviation);
  CHECK(rc.lambda == pc.lambda);
  // The grid (shared by both predictors) and every refinement point are
  // projected once; the error samples at least 17 points.
  int repeated = 0;
  for (const auto& [lambda, n] : calls) repeated += n > 1;
  CHECK(repeated == 0);
  CHECK(calls.size() >= 17);
  CHECK(calls.count(0.5) == 1);
}

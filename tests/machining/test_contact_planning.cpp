#include <doctest/doctest.h>

#include <cmath>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "machining/gouge/local_gouge.hpp"
#include "machining/toolpath/contact_planning.hpp"
#include "machining/prediction/pass_scallops.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;

namespace {

std::string example(const std::string& name) { return std::string(FURROW_SOURCE_DIR) + "/examples/parts/" + name; }

// Passes of the mould to plan on: iso-u at a few v, and two iso-planar ones.
std::vector<PassCurve> mould_passes(const Part& part, const VerticalProjector& projector) {
  std::vector<PassCurve> passes;
  for (double v : {0.2, 0.375, 0.55, 0.8}) passes.push_back(iso_parametric_pass(part, 0, true, v, 0.0, 1.0));
  passes.push_back(iso_parametric_pass(part, 0, false, 0.3, 0.0, 1.0));
  const double a = 30 * M_PI / 180;
  const Eigen::Vector2d d(std::cos(a), std::sin(a)), m(-std::sin(a), std::cos(a));
  // The plane through (60, 30) at 30 degrees, inside the part for t in
  // [12, 108] (t measured along d from the plane's point nearest the origin).
  const Eigen::Vector2d origin = (Eigen::Vector2d(60, 30).dot(m)) * m;
  passes.push_back(iso_planar_pass(projector, origin, d, 12, 108));
  return passes;
}

// The exact rule's error of the step a -> b as the planner takes it: beside
// the curve too where the cutter fits the part at the step's start
// (forward_step.hpp).
double planned_error(const Part& part, const Cutter& cutter, const PassCurve& pass, double a, double b) {
  const SurfacePoint p = pass.at(a);
  const DifferentialGeometry g = part.faces[p.face].geometry(p.uv.x(), p.uv.y());
  const bool fits = !g.degenerate && check_local_gouge(cutter, g).status == GougeStatus::clear;
  return step_error(part, cutter, pass.between(a, b), StepRule::exact, {}, fits);
}

// Largest real (exact) error over the steps of a placement.
double worst_real_error(const Part& part, const Cutter& cutter, const PassCurve& pass, const ForwardSteps& steps) {
  double worst = 0;
  for (std::size_t k = 1; k < steps.params.size(); ++k)
    worst = std::max(worst, step_error(part, cutter, pass.between(steps.params[k - 1], steps.params[k]), StepRule::exact));
  return worst;
}

}  // namespace

TEST_CASE("exact forward steps: no step over the tolerance, none shorter than necessary") {
  const Part part = read_part(example("mould.json"));
  const VerticalProjector projector(part);
  const Cutter cutters[] = {Cutter("ball6", 3, 3), Cutter("bull10r2", 5, 2)};
  for (const Cutter& cutter : cutters) {
    ForwardStepOptions options;
    options.tolerance = 0.01;
    const std::vector<PassCurve> passes = mould_passes(part, projector);
    for (std::size_t p = 0; p < passes.size(); ++p) {
      const PassCurve& pass = passes[p];
      const ForwardSteps steps = place_contact_points(part, pass, cutter, options);
      CAPTURE(cutter.name());
      CAPTURE(p);
      REQUIRE(steps.params.size() >= 3);
      CHECK(steps.capped == 0);
      CHECK(steps.params.front() == pass.t0);
      CHECK(steps.params.back() == pass.t1);
      for (std::size_t k = 1; k < steps.params.size(); ++k) {
        const double a = steps.params[k - 1], b = steps.params[k];
        REQUIRE(b > a);
        const double e = planned_error(part, cutter, pass, a, b);
        CHECK(e <= options.tolerance);
        if (k + 1 == steps.params.size()) continue;  // the last step may be shorter
        // As long as the tolerance allows: its error within 1e-4 relative
        // below the tolerance, unless the error jumps there.
        if (steps.jumps == 0)
          CHECK(options.tolerance - e <= 1e-4 * options.tolerance);
        // 1 % longer would exceed the tolerance: the step is as long as it can be.
        const double longer = planned_error(part, cutter, pass, a, a + 1.01 * (b - a));
        CHECK(longer > options.tolerance);
      }
    }
  }
}

TEST_CASE("exact steps around a circular arc: the analytic step of a ball on a convex circle, to 1e-4 of the tolerance") {
  // A ball of radius r around a convex circle of radius R: the centres lie on
  // the circle R + r and the deepest point between two contacts an angle a
  // apart is under the chord of the centres, (R + r)(1 - cos(a / 2)) deep.
  const double R = 25.4, r = 6.35;
  const Part part = read_part(example("semi_cylinder.json"));
  const Cutter ball("ball", r, r);
  for (double tolerance : {0.01, 0.001, 0.05}) {
    CAPTURE(tolerance);
    ForwardStepOptions options;
    options.tolerance = tolerance;
    const PassCurve pass = iso_parametric_pass(part, 0, true, 0.5, 0.3, 0.7);  // around the section
    const ForwardSteps steps = place_contact_points(part, pass, ball, options);
    REQUIRE(steps.params.size() >= 3);
    CHECK(steps.capped == 0);
    CHECK(steps.jumps == 0);
    const double analytic_angle = 2 * std::acos(1 - tolerance / (R + r));
    for (std::size_t k = 1; k + 1 < steps.params.size(); ++k) {
      const Eigen::Vector3d a = pass.at(steps.params[k - 1]).point, b = pass.at(steps.params[k]).point;
      // The contact points' angle about the cylinder axis (y).
      const double angle = std::abs(std::atan2(a.z(), a.x()) - std::atan2(b.z(), b.x()));
      const double true_error = (R + r) * (1 - std::cos(angle / 2));
      CHECK(true_error <= tolerance * (1 + 1e-9));
      CHECK(true_error >= tolerance * (1 - 1e-4));
      CHECK(angle == doctest::Approx(analytic_angle).epsilon(1e-4).scale(0));
    }
  }
}

TEST_CASE("the exact rule needs fewer contact points than chord deviation at equal real tolerance on the mould") {
  const Part part = read_part(example("mould.json"));
  const VerticalProjector projector(part);
  const Cutter ball("ball6", 3, 3);
  const double e = 0.01;
  const std::vector<PassCurve> passes = mould_passes(part, projector);
  ForwardStepOptions exact;
  exact.tolerance = e;
  std::size_t exact_points = 0;
  for (const PassCurve& pass : passes) exact_points += place_contact_points(part, pass, ball, exact).params.size();

  // Chord deviation set to e leaves real errors above e (convex stretches:
  // (rho + r) / rho times the chord): shrink its tolerance until the real
  // error of every step is within e.
  ForwardStepOptions chord;
  chord.rule = StepRule::chord;
  chord.tolerance = e;
  double real = 0;
  std::size_t chord_points = 0;
  for (int round = 0; round < 30; ++round) {
    real = 0;
    chord_points = 0;
    for (const PassCurve& pass : passes) {
      const ForwardSteps s = place_contact_points(part, pass, ball, chord);
      chord_points += s.params.size();
      real = std::max(real, worst_real_error(part, ball, pass, s));
    }
    if (real <= e) break;
    chord.tolerance *= std::min(0.98, e / real);
  }
  REQUIRE(real <= e);
  MESSAGE("contact points at real tolerance ", e, " mm: exact rule ", exact_points, ", chord rule ", chord_points,
          " (chord tolerance ", chord.tolerance, " mm)");
  CHECK(exact_points < chord_points);
  // At its nominal tolerance the chord rule is out of tolerance in reality.
  ForwardStepOptions nominal = chord;
  nominal.tolerance = e;
  double nominal_real = 0;
  for (const PassCurve& pass : passes)
    nominal_real = std::max(nominal_real, worst_real_error(part, ball, pass, place_contact_points(part, pass, ball, nominal)));
  CHECK(nominal_real > 1.2 * e);
}

TEST_CASE("iso-scallop side steps on convex and concave cylinders: the z-map ridge is the target") {
  const Part convex = read_part(example("semi_cylinder.json"));
  Part concave;
  concave.faces.emplace_back("tube", make_cylinder(25.4, 50.8, -M_PI, 0.0));
  const Cutter ball("ball8", 4, 4);
  const double h = 0.005;
  for (int is_convex = 0; is_convex < 2; ++is_convex) {
    const Part& part = is_convex ? convex : concave;
    ContactPlanOptions options;
    options.scallop = h;
    options.forward.tolerance = 0.01;
    options.min_normal_z = 0.5;  // the middle of the section only, to keep the test quick
    // Passes along the axis (v, i.e. y), side steps around the section.
    const ContactPlan plan = plan_contact_points(part, ball, {PassDirection::along_v, 0}, options);
    REQUIRE(plan.passes.size() >= 10);
    const double w = ball_side_step_for_scallop(4, is_convex ? -1 / 25.4 : 1 / 25.4, h).side_step;
    std::vector<ZMapMove> moves;
    std::vector<std::vector<PathContact>> contacts;
    for (std::size_t p = 0; p < plan.passes.size(); ++p) {
      const PlannedPass& pass = plan.passes[p];
      REQUIRE(pass.points.size() == 2);  // straight along the axis: one step
      contacts.push_back({{true, pass.points[0].at, pass.points[0].tip}, {true, pass.points[1].at, pass.points[1].tip}});
      moves.push_back({pass.points[0].tip, pass.points[1].tip, static_cast<int>(p), 0});
      if (p == 0) continue;
      // Arc between neighbouring passes = the exact side step.
      const Eigen::Vector3d a = plan.passes[p - 1].points[0].at.point, b = pass.points[0].at.point;
      const double angle = std::acos(std::clamp(Eigen::Vector2d(a.x(), a.z()).normalized().dot(Eigen::Vector2d(b.x(), b.z()).normalized()), -1.0, 1.0));
      CAPTURE(is_convex);
      CAPTURE(p);
      // Up to the side-step tolerance (1e-6 mm) and the midpoint arc length.
      if (p + 1 < plan.passes.size()) CHECK(std::fabs(25.4 * angle - w) < 1e-5);
      else CHECK(25.4 * angle <= w + 1e-5);  // the last pass sits on the boundary
    }
    ZMap zmap(part_xy_extent(part), 0.05);
    zmap.cut(ball, moves);
    const VerticalProjector projector(part);
    const auto scallops = pass_pair_scallops(projector, zmap, ball, contacts);
    for (std::size_t k = 0; k + 1 < scallops.size(); ++k) {
      for (const ScallopPeak& peak : {scallops[k].ridge, scallops[k].cusp}) {
        REQUIRE(peak.found);
        CHECK(peak.height == doctest::Approx(h).epsilon(1e-4).scale(0));
      }
    }
  }
}

TEST_CASE("iso-planar passes on a tilted plane: offsets from the flat side step, tips on the cutter-location surface") {
  const double slope = 0.2;  // z = 0.2 x
  Part part;
  part.faces.emplace_back("ramp", make_plane({0, 0, 0}, {30, 0, 30 * slope}, {0, 20, 0}));
  const Cutter ball("ball6", 3, 3);
  ContactPlanOptions options;
  options.scallop = 0.004;
  const ContactPlan plan = plan_contact_points(part, ball, parse_pass_direction("plane:90", "test"), options);
  // Planes x = const (direction +y); passes step along x by w cos(atan(slope)).
  const double w = ball_side_step_for_scallop(3, 0.0, 0.004).side_step;
  REQUIRE(plan.passes.size() >= 3);
  for (std::size_t p = 1; p + 1 < plan.passes.size(); ++p) {
    const double dx = std::fabs(plan.passes[p].points[0].at.point.x() - plan.passes[p - 1].points[0].at.point.x());
    CHECK(dx == doctest::Approx(w / std::sqrt(1 + slope * slope)).epsilon(1e-6));
  }
  for (const PlannedPass& pass : plan.passes) {
    CHECK(pass.points.size() == 2);  // a plane needs one step per pass
    for (const PlannedContact& q : pass.points) CHECK((q.tip - (q.at.point + 3 * q.at.normal - Eigen::Vector3d(0, 0, 3))).norm() < 1e-12);
  }
}

TEST_CASE("planning refuses bad settings and unmachinable parts") {
  Part part;
  part.faces.emplace_back("plane", make_plane({0, 0, 0}, {10, 0, 0}, {0, 10, 0}));
  const Cutter ball("ball", 1, 1);
  ContactPlanOptions bad;
  bad.scallop = 0;
  CHECK_THROWS_AS(plan_contact_points(part, ball, {}, bad), InputError);
  CHECK_THROWS_AS(parse_pass_direction("diagonal", "--direction"), InputError);
  CHECK_THROWS_AS(parse_pass_direction("plane:abc", "--direction"), InputError);
  CHECK(parse_pass_direction("plane:-30.5", "--direction").angle_deg == -30.5);
  // A downward-facing plane cannot be machined from above.
  Part down;
  down.faces.emplace_back("ceiling", make_plane({0, 0, 0}, {0, 10, 0}, {10, 0, 0}));
  CHECK_THROWS_WITH_AS(plan_contact_points(down, ball, {}, {}),
                       doctest::Contains("no part of the surface can be machined from above"), InputError);
}

TEST_CASE("oblique plane passes across a corner of the part: no level loses its pass at the face edge") {
  // Short pieces across the mould's corner end on the face's edge, found
  // by bisection; an end that projected just outside used to drop the
  // piece, leaving twice the side step (and four times the scallop).
  const Part part = read_part(example("mould.json"));
  const Cutter ball("ball6", 3, 3);
  ContactPlanOptions options;
  options.scallop = 0.01;
  options.forward.tolerance = 0.01;
  options.min_normal_z = 0.3;
  const ContactPlan plan = plan_contact_points(part, ball, parse_pass_direction("plane:30", "test"), options);
  const double flat_w = ball_side_step_for_scallop(3, 0.0, 0.01).side_step;
  REQUIRE(plan.passes.size() > 100);
  int checked = 0;
  for (std::size_t p = 1; p < plan.passes.size(); ++p) {
    const double gap = plan.passes[p].level - plan.passes[p - 1].level;
    if (gap == 0) continue;  // two pieces of one level
    CAPTURE(p);
    CHECK(gap <= 1.05 * flat_w);
    ++checked;
  }
  CHECK(checked > 100);
}

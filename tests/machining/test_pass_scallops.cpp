// The scallop between passes measured two ways (pass_scallops.hpp): the cusp
// of the two passes' cutters and the ridge the z-map keeps, apart from the
// furrow each pass leaves along itself.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "base/numbers.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "machining/prediction/path_prediction.hpp"
#include "machining/toolpath/contact_planning.hpp"
#include "machining/toolpath/toolpath_generation.hpp"

using namespace furrow;

namespace {

std::string example(const std::string& name) { return std::string(FURROW_SOURCE_DIR) + "/examples/parts/" + name; }

struct Planned {
  ContactPlan plan;
  Prediction prediction;
};

// Plans a finishing path (scallop target `scallop`, forward tolerance
// `tolerance`) and predicts it.
Planned plan_and_predict(const Part& part, const Cutter& cutter, const PassDirectionSpec& direction, double scallop,
                         double tolerance, double min_normal_z, double resolution) {
  ContactPlanOptions plan_options;
  plan_options.scallop = scallop;
  plan_options.forward.tolerance = tolerance;
  plan_options.min_normal_z = min_normal_z;
  Planned r;
  r.plan = plan_contact_points(part, cutter, direction, plan_options);
  Toolpath path = plan_tips(r.plan);
  path.source = "planned";
  PathPredictionOptions options;
  options.tolerance = tolerance;
  options.resolution = resolution;
  const PathPrediction p = predict_path(part, cutter, path, options);
  r.prediction = make_prediction(part, p, options, "part", "planned");
  return r;
}

}  // namespace

TEST_CASE("a concave tube cut around: the cusp is the flat ball formula, the furrows along the passes add to the ridge") {
  // Passes around the inside of a tube (concave along the feed, straight
  // across): each straight move leaves a furrow of up to the 10 um
  // tolerance, the side step along the axis a 5 um cusp. The ridge between
  // passes carries both, the cusp only the side step.
  Part part;
  part.faces.emplace_back("tube", make_cylinder(25.4, 30, -kPi, 0.0));
  const double r = 3;
  const Cutter ball("ball6", r, r);
  const double target = 0.005, tolerance = 0.01;
  const Planned p = plan_and_predict(part, ball, {PassDirection::along_u, 0}, target, tolerance, 0.6, 0.02);
  const Prediction& pr = p.prediction;
  REQUIRE(pr.scallops.size() >= 8);
  CHECK(pr.summary.max_step_error == doctest::Approx(tolerance).epsilon(0.01).scale(0));
  for (const ScallopRecord& s : pr.scallops) {
    CAPTURE(s.pass_a);
    REQUIRE(s.has_cusp);
    // The oracle: two balls an axial distance w apart over a straight line.
    const Eigen::Vector3d a = p.plan.passes[static_cast<std::size_t>(s.pass_a)].points[0].at.point;
    const Eigen::Vector3d b = p.plan.passes[static_cast<std::size_t>(s.pass_b)].points[0].at.point;
    const double w = std::fabs(b.y() - a.y());
    const double flat = r - std::sqrt(r * r - 0.25 * w * w);
    CHECK(s.cusp == doctest::Approx(flat).epsilon(1e-4).scale(0));
    CHECK(s.cusp <= target * 1.0001);
    // The ridge keeps the furrows of both passes on top of the cusp.
    CHECK(s.height > s.cusp + 0.8 * tolerance);
    CHECK(s.height < s.cusp + 1.05 * tolerance);
  }
  CHECK(pr.summary.max_cusp == doctest::Approx(target).epsilon(0.02).scale(0));
  CHECK(pr.summary.max_scallop > pr.summary.max_cusp + 0.8 * tolerance);
}

TEST_CASE("iso-scallop passes meet their target within 2 percent measured as the cusp, on curved parts and oblique passes") {
  // The planner's side step comes from the osculating circle across the
  // pass at sample points; the cusp is measured on the true surface between
  // the real passes, so this holds the planner to its promise where the
  // curvature varies along and across the passes. No bull-nose or flat
  // cutter tilted along the pass: standing cutters do not measure it exactly
  // (pass_scallops.hpp).
  struct Case {
    std::string name;
    Part part;
    Cutter cutter;
    PassDirectionSpec direction;
    double min_normal_z;
  };
  std::vector<Case> cases;
  {
    Part sphere;  // convex both ways; passes along latitude circles
    sphere.faces.emplace_back("sphere", make_sphere(30, 0.2, 1.2, 0.3, 1.2));
    cases.push_back({"sphere ball", sphere, Cutter("ball6", 3, 3), {PassDirection::along_u, 0}, 0.3});
    Part torus;  // the inside of a ring: a saddle
    torus.faces.emplace_back("ring", make_torus(40, 15, 0.0, 0.6, 1.8, 2.6));
    cases.push_back({"torus saddle ball", torus, Cutter("ball8", 4, 4), {PassDirection::along_u, 0}, 0.3});
  }
  // A bull-nose across the crest of a convex part: between two passes
  // either side of it the cutter touches on opposite sides of its flat
  // bottom. Tilted across the passes only, so standing cutters are exact.
  cases.push_back({"cylinder bull", read_part(example("semi_cylinder.json")), Cutter("bull10r2", 5, 2),
                   {PassDirection::along_v, 0}, 0.3});
  cases.push_back({"mould oblique", read_part(example("mould.json")), Cutter("ball6", 3, 3), {PassDirection::plane, 30}, 0.3});
  const double target = 0.01;
  for (const Case& c : cases) {
    CAPTURE(c.name);
    const Planned p = plan_and_predict(c.part, c.cutter, c.direction, target, 0.01, c.min_normal_z, 0.05);
    const Prediction& pr = p.prediction;
    REQUIRE(pr.scallops.size() >= 5);
    double largest = 0;
    for (const ScallopRecord& s : pr.scallops) {
      CAPTURE(s.pass_a);
      REQUIRE(s.has_cusp);
      CHECK(s.cusp <= 1.02 * target);
      largest = std::max(largest, s.cusp);
    }
    CHECK(largest >= 0.98 * target);
    CHECK(pr.summary.max_cusp == largest);
  }
}

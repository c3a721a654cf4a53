// The prediction seen as a risk map: cell values as written, zero where
// nothing was predicted, gouge sites carried over, and a prediction of
// another part refused.
#include <doctest/doctest.h>

#include "base/error.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "planning/prediction_risk.hpp"
#include "plan_fixtures.hpp"
#include "prediction_fixture.hpp"

using namespace furrow;
using namespace furrow::test;

TEST_CASE("the risk map gives the worst predicted error of the cell, either sign") {
  const Part part = mould();
  const Eigen::Vector2d peak(0.4, 0.5);
  // Through the file: what the planner reads is what the writer wrote.
  const Prediction p = parse_prediction_json(prediction_to_json_text(synthetic_prediction(part, peak, {{0.3, 0.3}})), "p.json");
  const PredictionRiskMap risk(p, part, "p.json", "mould.json");
  for (int ci : {3, 20, 37}) {
    for (int cj : {5, 19}) {
      const Eigen::Vector2d uv((ci + 0.5) / 50, (cj + 0.5) / 40);
      // Worst of |mean|, |mean + 0.003|, |mean - 0.002| (the file keeps 1e-7 mm).
      CHECK(std::abs(risk.error_magnitude(0, uv) - (synthetic_mean(uv, peak) + 0.003)) <= 1e-7);
    }
  }
  CHECK(risk.error_magnitude(0, {0.5 / 50, 0.5}) == 0);  // column 0: not reached
  CHECK(risk.error_magnitude(3, {0.5, 0.5}) == 0);       // no such face
  REQUIRE(risk.gouge_sites().size() == 1);
  const RiskSite& s = risk.gouge_sites()[0];
  CHECK(s.id == "G1");
  CHECK(s.face == 0);
  CHECK(s.uv_centre.isApprox(Eigen::Vector2d(0.3, 0.3)));
  CHECK(s.uv_box.contains(s.uv_centre));
  CHECK(s.depth == doctest::Approx(0.05));
}

TEST_CASE("a prediction of another part is refused") {
  const Part part = mould();
  Prediction p = synthetic_prediction(part, {0.5, 0.5}, {});
  p.faces[0].name = "crown";
  CHECK_THROWS_AS(PredictionRiskMap(p, part, "p.json", "mould.json"), InputError);
  p = synthetic_prediction(part, {0.5, 0.5}, {});
  p.faces[0].domain.u1 = 2;
  CHECK_THROWS_AS(PredictionRiskMap(p, part, "p.json", "mould.json"), InputError);
}

#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/primitives.hpp"
#include "inspection/comparison_error_field.hpp"

using namespace furrow;

namespace {

// The machine error: two wide bumps, +80 um of material left and
// -60 um overcut, on a 100 x 60 mm plate [mm of the plate].
double planted(double x, double y) {
  auto bump = [](double dx, double dy, double r) { return std::exp(-(dx * dx + dy * dy) / (2 * r * r)); };
  return 0.08 * bump(x - 30, y - 30, 12) - 0.06 * bump(x - 70, y - 25, 10);
}

// The path's own scallops: 10 um cusps every 1.5 mm across x, geometry the
// prediction knows.
double scallop(double x) { return 0.005 * (1 - std::cos(2 * kPi * x / 1.5)); }

Part two_plates() {
  Part part;
  part.faces.emplace_back("top", make_plane({0, 0, 0}, {100, 0, 0}, {0, 60, 0}));
  part.faces.emplace_back("side", make_plane({0, 0, -20}, {100, 0, 0}, {0, 0, 20}));
  return part;
}

// 300 points on the top plate measured as planted + scallop + 1 um noise,
// with the prediction's residual as comparison.json holds it; every 10th
// point is a blunder (not evaluated, deviation +1 mm) and every 15th lies
// where the prediction did not reach (residual +1 mm, where the file has
// none): either would wreck the field if it were used.
ComparisonDocument planted_comparison(bool with_prediction) {
  ComparisonDocument doc;
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(0, 1), v(0, 1);
  std::normal_distribution<double> noise(0, 0.001);
  for (int i = 0; i < 300; ++i) {
    ComparisonDocument::Point p;
    p.id = "P" + std::to_string(i);
    p.face = "top";
    p.face_index = 0;
    p.uv = {u(rng), v(rng)};
    const double x = 100 * p.uv.x(), y = 60 * p.uv.y();
    p.evaluated = i % 10 != 0;
    const bool reached = i % 15 != 0;
    p.deviation = p.evaluated ? planted(x, y) + scallop(x) + noise(rng) : 1.0;
    if (with_prediction) {
      PointPrediction q;
      q.face_predicted = true;
      q.status = reached ? ErrorCellStatus::reached : ErrorCellStatus::not_reached;
      q.compared = p.evaluated && reached;
      q.predicted = scallop(x);
      q.measured = p.deviation;
      q.residual = reached ? q.measured - q.predicted : 1.0;
      p.prediction = q;
    }
    doc.points.push_back(p);
  }
  if (with_prediction) doc.prediction = PredictionComparison{};
  return doc;
}

// The prediction of the path as `furrow predict` writes it, given apart: the
// scallops as cell means on cells 0.05 mm wide across x (two along y), every
// cell reached except those below x = 10 mm, which the path did not cut.
Prediction scallop_prediction() {
  FaceGridRecord f;
  f.name = "top";
  f.cells_u = 2000;
  f.cells_v = 2;
  const std::size_t n = 4000;
  f.status.resize(n);
  f.mean.resize(n);
  f.max_undercut.resize(n);
  f.max_overcut.resize(n);
  for (int cj = 0; cj < f.cells_v; ++cj)
    for (int ci = 0; ci < f.cells_u; ++ci) {
      const std::size_t k = std::size_t(cj) * f.cells_u + ci;
      const double x = 100 * (ci + 0.5) / f.cells_u;
      const bool reached = ci >= 200;
      f.status[k] = reached ? ErrorCellStatus::reached : ErrorCellStatus::not_reached;
      if (!reached) continue;
      f.mean[k] = f.max_undercut[k] = f.max_overcut[k] = scallop(x);
    }
  Prediction prediction;
  prediction.faces.push_back(f);
  return prediction;
}

}  // namespace

TEST_CASE("comparison error field: a prediction given apart is taken off the deviations before the fit") {
  const Part part = two_plates();
  const ComparisonDocument doc = planted_comparison(false);
  const Prediction prediction = scallop_prediction();
  const ComparisonErrorField fit = fit_error_field(doc, part, {}, "comparison.json", &prediction);
  CHECK(fit.prediction_removed);
  CHECK(fit.prediction_given);
  // Points below x = 10 mm lie on cells the prediction did not reach.
  std::size_t uncut = 0;
  for (const auto& p : doc.points) uncut += p.evaluated && p.uv.x() < 0.1;
  CHECK(uncut > 10);
  CHECK(fit.not_predicted == uncut);
  CHECK(fit.samples == 270 - uncut);
  // Oracle: the planted field, as in the test above (where the comparison
  // held the residuals), over the plate from 15 mm (5 mm beyond the samples'
  // edge at 10 mm) to its rim; the 5 um scallop mean is gone.
  double sum = 0, sum2 = 0, worst = 0;
  int count = 0;
  for (double x = 15; x <= 95; x += 2.5)
    for (double y = 5; y <= 55; y += 2.5) {
      const double e = fit.field.value(0, x / 100, y / 60) - planted(x, y);
      sum += e, sum2 += e * e, worst = std::max(worst, std::abs(e)), ++count;
    }
  MESSAGE("mean " << 1000 * sum / count << " um, RMS " << 1000 * std::sqrt(sum2 / count) << " um, worst "
                  << 1000 * worst << " um");
  CHECK(std::abs(sum / count) < 0.0005);
  CHECK(std::sqrt(sum2 / count) < 0.002);
  CHECK(worst < 0.006);
}

TEST_CASE("comparison error field: the planted machine error is recovered once the prediction is removed") {
  const Part part = two_plates();
  const ComparisonErrorField fit = fit_error_field(planted_comparison(true), part, {}, "comparison.json");
  CHECK(fit.prediction_removed);
  // 30 blunders (i % 10 == 0); of the rest, those with i % 15 == 0 and not
  // i % 10 == 0: multiples of 15 that are odd multiples of 15 -> 10.
  CHECK(fit.not_evaluated == 30);
  CHECK(fit.not_predicted == 10);
  CHECK(fit.samples == 260);
  REQUIRE(fit.field.faces.size() == 2);
  CHECK(fit.field.faces[0]->fitted());
  CHECK(fit.field.faces[1]->status() == "no samples");
  CHECK(fit.field.value(1, 0.5, 0.5) == 0);
  // Inside the plate, away from its rim: the planted field, within a few
  // noise sigmas (1 um) plus what smoothing takes off the bumps' peaks.
  double sum2 = 0, worst = 0;
  int count = 0;
  for (double x = 5; x <= 95; x += 2.5)
    for (double y = 5; y <= 55; y += 2.5) {
      const double e = fit.field.value(0, x / 100, y / 60) - planted(x, y);
      sum2 += e * e, worst = std::max(worst, std::abs(e)), ++count;
    }
  CHECK(std::sqrt(sum2 / count) < 0.002);
  CHECK(worst < 0.006);
  // Peaks: +80 um and -60 um within 10 %.
  CHECK(std::abs(fit.field.value(0, 0.30, 0.50) - planted(30, 30)) < 0.008);
  CHECK(std::abs(fit.field.value(0, 0.70, 25.0 / 60) - planted(70, 25)) < 0.006);
}

TEST_CASE("comparison error field: without a prediction the deviations themselves are fitted") {
  const Part part = two_plates();
  const ComparisonErrorField fit = fit_error_field(planted_comparison(false), part, {}, "comparison.json");
  CHECK_FALSE(fit.prediction_removed);
  CHECK(fit.not_evaluated == 30);
  CHECK(fit.not_predicted == 0);
  CHECK(fit.samples == 270);
  // The field then holds the scallops' mean, 5 um (their cusps are too fine
  // for the samples and smoothed as noise): the fitted field is the planted
  // one raised by it, within what the samples can tell (the scallop's
  // spread, 3.5 um, plus 1 um noise, over 270 points: 0.2 um 1-sigma on the
  // mean, 1.5 um allowed with the rim).
  double sum = 0;
  int count = 0;
  for (double x = 5; x <= 95; x += 2.5)
    for (double y = 5; y <= 55; y += 2.5) sum += fit.field.value(0, x / 100, y / 60) - planted(x, y), ++count;
  CHECK(std::abs(sum / count - 0.005) < 0.0015);
}

TEST_CASE("comparison error field: a point on a face the part does not have is refused") {
  const Part part = two_plates();
  ComparisonDocument doc = planted_comparison(true);
  doc.points[3].face = "bottom";
  try {
    fit_error_field(doc, part, {}, "comparison.json");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) ==
          "comparison.json: points[3] (P3): face 'bottom' (index 0) is not a face of the part: the comparison is of "
          "another part");
  }
  doc.points[3].face = "top";
  doc.points[3].face_index = 2;
  CHECK_THROWS_AS(fit_error_field(doc, part, {}, "comparison.json"), InputError);
}

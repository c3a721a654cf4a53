#include <doctest/doctest.h>

#include <Eigen/QR>
#include <cmath>
#include <random>

#include "machining/compensation/thin_plate_spline.hpp"

using namespace furrow;

namespace {

// A smooth error field of a 100 x 60 mm face, amplitude 50 um [mm].
double smooth_field(const Eigen::Vector2d& x) {
  return 0.05 * std::sin(x.x() / 15.0) * std::cos(x.y() / 20.0) + 0.01;
}

std::vector<Eigen::Vector2d> scattered(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 100), v(0, 60);
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < n; ++i) out.emplace_back(u(rng), v(rng));
  return out;
}

// `field` (or nothing, when null) at the points plus seeded Gaussian noise.
std::vector<double> noisy(const std::vector<Eigen::Vector2d>& points, double (*field)(const Eigen::Vector2d&),
                          double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0, noise);
  std::vector<double> values;
  for (const auto& p : points) values.push_back((field ? field(p) : 0.0) + gauss(rng));
  return values;
}

}  // namespace

TEST_CASE("thin-plate spline: a smooth field under noise is recovered to a fraction of the noise") {
  const double noise = 0.002;  // 2 um, 1 sigma
  for (unsigned seed : {1u, 2u, 3u}) {
    CAPTURE(seed);
    const auto points = scattered(300, seed);
    const std::vector<double> values = noisy(points, smooth_field, noise, 100 + seed);
    const ThinPlateSpline tps(points, values);
    REQUIRE(tps.fitted());
    CHECK(tps.gcv().converged);
    CHECK_FALSE(tps.gcv().at_bound);
    // Over the interior (the spline is not held at the corners), the error
    // against the function: a smoother averaging k samples leaves about
    // noise / sqrt(k) of noise; with k >= 4 that is at most noise / 2 RMS,
    // and no point off by 3 such sigmas (1.5 noise).
    double sum2 = 0, worst = 0;
    int count = 0;
    for (double x = 10; x <= 90; x += 2)
      for (double y = 10; y <= 50; y += 2) {
        const double e = tps.value({x, y}) - smooth_field({x, y});
        sum2 += e * e, worst = std::max(worst, std::abs(e)), ++count;
      }
    CHECK(std::sqrt(sum2 / count) < 0.5 * noise);
    CHECK(worst < 1.5 * noise);
    // The residual sigma estimate finds the noise it was given (300 samples:
    // its own sampling spread is ~4 %, allow 20 %).
    CHECK(std::abs(tps.gcv().sigma - noise) < 0.2 * noise);
  }
}

TEST_CASE("thin-plate spline: GCV on pure noise chooses a nearly flat field") {
  const double noise = 0.002;
  for (unsigned seed : {4u, 5u, 6u}) {
    CAPTURE(seed);
    const auto points = scattered(200, seed);
    const std::vector<double> values = noisy(points, nullptr, noise, 200 + seed);
    const ThinPlateSpline tps(points, values);
    REQUIRE(tps.fitted());
    double amplitude = 0, sum2 = 0;
    int count = 0;
    for (double x = 0; x <= 100; x += 2)
      for (double y = 0; y <= 60; y += 2) {
        const double f = tps.value({x, y});
        amplitude = std::max(amplitude, std::abs(f)), sum2 += f * f, ++count;
      }
    CAPTURE(tps.gcv().lambda);
    CAPTURE(tps.gcv().at_bound);
    // Nothing to find: the field stays far below the noise. A least-squares
    // plane through 200 samples of uniform scatter has a 1-sigma spread of
    // noise * sqrt((1 + 12 (x/a)^2 + 12 (y/b)^2) / 200) at offset (x, y) from
    // the centre of an a x b face: 0.07 noise at the centre, 0.19 at the
    // corners; so an RMS below 0.25 noise and nowhere 4 corner sigmas.
    CHECK(std::sqrt(sum2 / count) < 0.25 * noise);
    CHECK(amplitude < 0.75 * noise);
    CHECK(tps.gcv().trace > 0.9 * double(points.size()));  // almost every degree of freedom left to noise
  }
}

TEST_CASE("thin-plate spline: the chosen lambda is the minimum of the GCV score on a dense grid") {
  const auto points = scattered(120, 7);
  const std::vector<double> values = noisy(points, smooth_field, 0.003, 77);
  const ThinPlateSpline tps(points, values);
  REQUIRE(tps.fitted());
  const double chosen = tps.gcv_score(tps.gcv().lambda);
  CHECK(chosen == doctest::Approx(tps.gcv().gcv).epsilon(1e-9).scale(0));  // relative: GCV ~1e-5 mm^2
  // Brute force over 1/50 decade across the whole search range.
  const double l0 = std::log10(tps.gcv().lambda);
  for (double d = -12; d <= 12; d += 0.02) CHECK(chosen <= tps.gcv_score(std::pow(10.0, l0 + d)) * (1 + 1e-9));
}

TEST_CASE("thin-plate spline: a tiny lambda interpolates and a huge one is the least-squares plane") {
  const auto points = scattered(40, 8);
  std::vector<double> values;
  for (const auto& p : points) values.push_back(smooth_field(p));
  GcvSearchOptions fixed;
  fixed.lambda = 1e-12;
  const ThinPlateSpline interp(points, values, fixed);
  REQUIRE(interp.fitted());
  for (std::size_t i = 0; i < points.size(); ++i) CHECK(std::abs(interp.value(points[i]) - values[i]) < 1e-7);

  fixed.lambda = 1e12;
  const ThinPlateSpline flat(points, values, fixed);
  // The plane by normal equations, solved independently.
  Eigen::MatrixXd P(points.size(), 3);
  Eigen::VectorXd z(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    P.row(Eigen::Index(i)) << 1, points[i].x(), points[i].y();
    z(Eigen::Index(i)) = values[i];
  }
  const Eigen::Vector3d plane = (P.transpose() * P).ldlt().solve(P.transpose() * z);
  for (double x : {0.0, 50.0, 100.0})
    for (double y : {0.0, 30.0, 60.0})
      CHECK(std::abs(flat.value({x, y}) - (plane(0) + plane(1) * x + plane(2) * y)) < 1e-7);
}

TEST_CASE("thin-plate spline: influence diagonal and standard errors agree with fits of unit vectors") {
  // The spline is linear in the values at fixed lambda: f(x) = l(x)^T z, and
  // column j of the influence matrix is the fit of the j-th unit vector.
  const auto points = scattered(30, 9);
  const std::vector<double> values = noisy(points, smooth_field, 0.002, 99);
  const ThinPlateSpline tps(points, values);
  REQUIRE(tps.fitted());
  GcvSearchOptions fixed;
  fixed.lambda = tps.gcv().lambda;
  const Eigen::Vector2d probe(37, 21);
  Eigen::VectorXd l(points.size());
  double trace = 0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    std::vector<double> unit(points.size(), 0.0);
    unit[j] = 1;
    const ThinPlateSpline column(points, unit, fixed);
    CHECK(std::abs(column.value(points[j]) - tps.leverage()(Eigen::Index(j))) < 1e-8);
    trace += 1 - column.value(points[j]);
    l(Eigen::Index(j)) = column.value(probe);
  }
  // Relative tolerances (scale 0): the standard error is ~1e-4 mm.
  CHECK(trace == doctest::Approx(tps.gcv().trace).epsilon(1e-8).scale(0));
  CHECK(tps.standard_error(probe) == doctest::Approx(tps.gcv().sigma * l.norm()).epsilon(1e-8).scale(0));
}

TEST_CASE("thin-plate spline: too few or collinear samples are reported, not fitted") {
  const ThinPlateSpline three({{0, 0}, {1, 0}, {0, 1}}, {1, 2, 3});
  CHECK_FALSE(three.fitted());
  CHECK(three.status() == "fewer than 4 samples");
  CHECK(three.value({0.3, 0.3}) == 0);
  const ThinPlateSpline line({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}}, {1, 2, 3, 4, 5});
  CHECK_FALSE(line.fitted());
  CHECK(line.status() == "samples on one line");
}

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/primitives.hpp"
#include "machining/compensation/error_field.hpp"

using namespace furrow;

namespace {

// A 200 x 20 mm plane: u spans 200 mm, v 20 mm, so (u, v) are far from
// isotropic and only the scaling to millimetres makes the spline round.
Face long_plate() { return Face("plate", make_plane({0, 0, 0}, {200, 0, 0}, {0, 20, 0})); }

// Planted field in millimetres of the plate: one wide bump [mm].
double bump(double x, double y) {
  return 0.06 * std::exp(-((x - 80) * (x - 80) + (y - 10) * (y - 10)) / (2 * 25.0 * 25.0));
}

std::vector<FieldSample> plate_samples(std::size_t n, double u_max, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, u_max), v(0, 1);
  std::normal_distribution<double> gauss(0, noise);
  std::vector<FieldSample> out;
  for (std::size_t i = 0; i < n; ++i) {
    const double su = u(rng), sv = v(rng);
    out.push_back({su, sv, bump(200 * su, 20 * sv) + gauss(rng)});
  }
  return out;
}

}  // namespace

TEST_CASE("error field: parameters are scaled to the face's millimetres") {
  const Face face = long_plate();
  const FaceErrorField field(face, plate_samples(50, 1, 0.001, 1), {}, "test");
  // A plane patch origin + s e_u + t e_v has |S_u| = |e_u|, |S_v| = |e_v|.
  CHECK(std::abs(field.scale_u() - 200) < 1e-9);
  CHECK(std::abs(field.scale_v() - 20) < 1e-9);
  CHECK((field.scaled(0.5, 0.25) - Eigen::Vector2d(100, 5)).norm() < 1e-9);
}

TEST_CASE("error field: a planted bump on a long plate is recovered within the noise") {
  const double noise = 0.001;
  const Face face = long_plate();
  const FaceErrorField field(face, plate_samples(250, 1, noise, 2), {}, "test");
  REQUIRE(field.fitted());
  REQUIRE(field.gcv() != nullptr);
  CHECK(field.gcv()->converged);
  double sum2 = 0;
  int count = 0;
  for (double x = 10; x <= 190; x += 5)
    for (double y = 2; y <= 18; y += 2) {
      const FieldValue at = field.at(x / 200, y / 20);
      CHECK(at.weight == 1);  // 250 samples cover the plate: no fade inside it
      const double e = at.value - bump(x, y);
      sum2 += e * e, ++count;
    }
  // The smoother averages several samples: the error is a fraction of the noise.
  CHECK(std::sqrt(sum2 / count) < 0.5 * noise);
  // Its standard error is of that order too, and positive.
  const double se = field.standard_error(0.4, 0.5);
  CHECK(se > 0);
  CHECK(se < 0.5 * noise);
}

TEST_CASE("error field: the default fade distance is the factor times the median sample spacing") {
  const Face face = long_plate();
  const auto samples = plate_samples(80, 1, 0.001, 3);
  ErrorFieldOptions options;
  options.fade_factor = 3;
  const FaceErrorField field(face, samples, options, "test");
  // Brute-force nearest neighbours in millimetres.
  std::vector<double> spacing;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    double best = 1e300;
    for (std::size_t j = 0; j < samples.size(); ++j)
      if (i != j)
        best = std::min(best, std::hypot(200 * (samples[i].u - samples[j].u), 20 * (samples[i].v - samples[j].v)));
    spacing.push_back(best);
  }
  std::sort(spacing.begin(), spacing.end());
  CHECK(std::abs(field.median_spacing() - spacing[spacing.size() / 2]) < 1e-9);
  CHECK(std::abs(field.fade_distance() - 3 * spacing[spacing.size() / 2]) < 1e-9);
}

TEST_CASE("error field: the fade is the fit near the samples, zero beyond D and C1 between") {
  const Face face = long_plate();
  // Samples over the left half only (x < 100 mm).
  const auto samples = plate_samples(150, 0.5, 0.001, 4);
  ErrorFieldOptions options;
  options.fade_distance = 12;  // [mm]
  const FaceErrorField field(face, samples, options, "test");
  REQUIRE(field.fitted());
  // At every sample: full weight, the value is the spline's.
  for (const FieldSample& s : samples) {
    const FieldValue at = field.at(s.u, s.v);
    CHECK(at.distance < 1e-9);
    CHECK(at.weight == 1);
    CHECK(at.value == at.fitted);
  }
  // Along the plate's middle line to the right: zero from 12 mm past the
  // last sample on, where the unfaded spline is not zero.
  const double last = std::max_element(samples.begin(), samples.end(), [](auto& a, auto& b) {
                        return a.u < b.u;
                      })->u * 200;
  bool saw_nonzero_fit = false;
  for (double x = last + 12.5; x <= 200; x += 1) {
    const FieldValue at = field.at(x / 200, 0.5);
    CHECK(at.distance >= 12);
    CHECK(at.value == 0);
    saw_nonzero_fit |= std::abs(at.fitted) > 1e-6;
  }
  CHECK(saw_nonzero_fit);
  // The weight: 1 up to D/2, 0 from D, continuous with zero slope at both
  // joins (central differences), decreasing between.
  const double D = 12, h = 1e-6;
  CHECK(field.fade_weight(D / 2) == 1);
  CHECK(field.fade_weight(D) == 0);
  for (double d : {D / 2, D})
    CHECK(std::abs((field.fade_weight(d + h) - field.fade_weight(d - h)) / (2 * h)) < 1e-4);
  for (double d = D / 2; d < D; d += 0.1) CHECK(field.fade_weight(d + 0.1) <= field.fade_weight(d));
  // Slope in the middle: derivative of 1 - 3q^2 + 2q^3, q = (2d - D) / D, at q = 1/2.
  CHECK(std::abs((field.fade_weight(0.75 * D + h) - field.fade_weight(0.75 * D - h)) / (2 * h) -
                 (-1.5 * 2 / D)) < 1e-6);
}

TEST_CASE("error field: faces with too few samples have no field and too many are refused") {
  const Face face = long_plate();
  const FaceErrorField few(face, plate_samples(5, 1, 0.001, 5), {}, "test");
  CHECK_FALSE(few.fitted());
  CHECK(few.status() == "5 samples, fewer than 6");
  CHECK(few.value(0.5, 0.5) == 0);
  const FaceErrorField none(face, {}, {}, "test");
  CHECK(none.status() == "no samples");
  ErrorFieldOptions capped;
  capped.max_samples = 10;
  CHECK_THROWS_AS(FaceErrorField(face, plate_samples(11, 1, 0.001, 6), capped, "comparison.json"), InputError);
}

TEST_CASE("error field: the gradient agrees with central differences, inside and in the fade") {
  const Face face = long_plate();
  const auto samples = plate_samples(150, 0.5, 0.001, 7);
  ErrorFieldOptions options;
  options.fade_distance = 12;
  const FaceErrorField field(face, samples, options, "test");
  REQUIRE(field.fitted());
  const double h = 1e-7;  // in u and v: 20 nm and 2 nm on the plate
  int in_taper = 0;
  for (double u = 0.05; u < 0.6; u += 0.013)
    for (double v = 0.1; v < 1; v += 0.17) {
      const FieldValue at = field.at(u, v);
      const Eigen::Vector2d fd((field.value(u + h, v) - field.value(u - h, v)) / (2 * h),
                               (field.value(u, v + h) - field.value(u, v - h)) / (2 * h));
      CAPTURE(u);
      CAPTURE(v);
      // Differences of values ~0.06 mm at 1e-7 steps: rounding ~1e-9 relative.
      CHECK((at.gradient - fd).norm() < 1e-5 * (1 + fd.norm()));
      in_taper += at.weight > 0 && at.weight < 1;
    }
  CHECK(in_taper > 3);  // the fade's own slope was checked too
}

TEST_CASE("error field: a fixed smoothing length sets lambda from the samples' area and damps a wave of wavelength 2 pi times it") {
  // Oracle: lambda by its definition (error_field.hpp), and the smoothing
  // spline's equivalent filter 1 / (1 + lambda_J A w^4), which the
  // definition makes 1/2 at w = 1/h for continuous data on an unbounded
  // face. Measured on this plate it keeps 0.34 of the wave (the filter
  // overstates what is kept; docs/compensation.md says so): the check is
  // that the wave is damped by about that, well below GCV's choice (which
  // keeps a noise-free wave) and well above flattening it. Noise-free
  // samples of a wave along the long side of the plate, over 20 per
  // wavelength.
  const Face face = long_plate();
  const double h = 8;  // [mm]
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0, 1), v(0, 1);
  std::vector<FieldSample> samples;
  for (int i = 0; i < 900; ++i) {
    const double su = u(rng), sv = v(rng);
    samples.push_back({su, sv, 0.01 * std::sin(200 * su / h)});
  }
  ErrorFieldOptions options;
  options.smoothing_length = h;
  const FaceErrorField field(face, samples, options, "test");
  REQUIRE(field.fitted());
  // lambda as defined: 8 pi h^4 over the samples' box in millimetres (the
  // kernel's 8 pi, error_field.hpp).
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const FieldSample& s : samples) {
    x0 = std::min(x0, 200 * s.u), x1 = std::max(x1, 200 * s.u);
    y0 = std::min(y0, 20 * s.v), y1 = std::max(y1, 20 * s.v);
  }
  CHECK(std::abs(field.gcv()->lambda / (8 * kPi * std::pow(h, 4) / ((x1 - x0) * (y1 - y0))) - 1) < 1e-12);
  // The amplitude over the middle of the plate (away from the ends, where a
  // spline is not a filter): least squares of the fit against the wave.
  double num = 0, den = 0;
  for (double x = 50; x <= 150; x += 0.5) {
    const double w = std::sin(x / h);
    num += field.at(x / 200, 0.5).fitted * w;
    den += 0.01 * w * w;
  }
  const double gain = num / den;
  MESSAGE("amplitude kept: " << gain);
  CHECK(gain > 0.25);
  CHECK(gain < 0.5);
  // And a bad length is refused naming where.
  options.smoothing_length = -1;
  CHECK_THROWS_AS(FaceErrorField(face, samples, options, "test"), InputError);
}

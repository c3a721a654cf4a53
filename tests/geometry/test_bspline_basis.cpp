#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "geometry/bspline_basis.hpp"
#include "base/error.hpp"
#include "support/random_surface.hpp"

using namespace furrow;

TEST_CASE("basis functions form a partition of unity and derivatives sum to zero") {
  std::mt19937 rng(7);
  for (int degree = 1; degree <= 6; ++degree) {
    for (bool clamped : {true, false}) {
      const int n = degree + 4;
      const auto knots = test::random_knots(rng, degree, n, clamped);
      const double lo = knots[degree], hi = knots[n];
      for (int k = 0; k <= 20; ++k) {
        const double u = lo + (hi - lo) * k / 20.0;
        const int span = find_span(knots, degree, n, u);
        REQUIRE(span >= degree);
        REQUIRE(span <= n - 1);
        CHECK(knots[span] <= u);
        double ders[3][kMaxDegree + 1];
        basis_functions_with_derivatives(knots, degree, span, u, 2, ders);
        double sum0 = 0, sum1 = 0, sum2 = 0;
        for (int j = 0; j <= degree; ++j) {
          CHECK(ders[0][j] >= -1e-15);
          sum0 += ders[0][j];
          sum1 += ders[1][j];
          sum2 += ders[2][j];
        }
        CHECK(sum0 == doctest::Approx(1.0).epsilon(1e-13));
        CHECK(std::abs(sum1) < 1e-9);
        CHECK(std::abs(sum2) < 1e-7);
      }
    }
  }
}

TEST_CASE("basis derivatives agree with central differences of the basis values") {
  std::mt19937 rng(11);
  for (int degree = 1; degree <= 5; ++degree) {
    const int n = degree + 5;
    const auto knots = test::random_knots(rng, degree, n, false);
    const double lo = knots[degree], hi = knots[n];
    for (int trial = 0; trial < 10; ++trial) {
      const double u = test::parameter_away_from_knots(rng, knots, lo, hi, 1e-3);
      const double h = 1e-6 * (hi - lo);
      const int span = find_span(knots, degree, n, u);
      REQUIRE(find_span(knots, degree, n, u - h) == span);
      REQUIRE(find_span(knots, degree, n, u + h) == span);
      double d[3][kMaxDegree + 1], dm[3][kMaxDegree + 1], dp[3][kMaxDegree + 1];
      basis_functions_with_derivatives(knots, degree, span, u, 2, d);
      basis_functions_with_derivatives(knots, degree, span, u - h, 2, dm);
      basis_functions_with_derivatives(knots, degree, span, u + h, 2, dp);
      for (int j = 0; j <= degree; ++j) {
        const double fd1 = (dp[0][j] - dm[0][j]) / (2 * h);
        const double fd2 = (dp[1][j] - dm[1][j]) / (2 * h);
        CHECK(d[1][j] == doctest::Approx(fd1).epsilon(1e-6).scale(1.0));
        CHECK(d[2][j] == doctest::Approx(fd2).epsilon(1e-6).scale(1.0));
      }
    }
  }
}

TEST_CASE("find_span handles the domain ends, repeated knots and clamps outside values") {
  const std::vector<double> knots = {0, 0, 0, 0.5, 0.5, 1, 1, 1};  // degree 2, 5 points
  CHECK(find_span(knots, 2, 5, 0.0) == 2);
  CHECK(find_span(knots, 2, 5, 0.25) == 2);
  CHECK(find_span(knots, 2, 5, 0.5) == 4);
  CHECK(find_span(knots, 2, 5, 1.0) == 4);   // last non-empty span, not off the end
  CHECK(find_span(knots, 2, 5, 7.0) == 4);   // clamped
  CHECK(find_span(knots, 2, 5, -3.0) == 2);  // clamped
  CHECK(find_span(knots, 2, 5, std::nan("")) == 2);
}

TEST_CASE("knot vector validation names the field and the problem") {
  auto message = [](const std::vector<double>& knots, int degree, int n) {
    try {
      validate_knot_vector(knots, degree, n, "faces[0].knots_u");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message({0, 0, 1, 1}, 1, 2).empty());
  CHECK(message({0, 0, 1}, 1, 2).find("expected 4 knots") != std::string::npos);
  CHECK(message({0, 0, 1}, 1, 2).find("faces[0].knots_u") == 0);
  CHECK(message({0, 1, 0.5, 1}, 1, 2).find("decrease") != std::string::npos);
  CHECK(message({0, 0, std::nan(""), 1}, 1, 2).find("finite") != std::string::npos);
  CHECK(message({0, 0, 1, 1}, 0, 3).find("degree 0") != std::string::npos);
  CHECK(message({0, 0, 0, 0}, 1, 2).find("empty") != std::string::npos);
  CHECK(message({0, 0, 0.5, 0.5, 0.5, 1, 1}, 1, 5).find("repeats") != std::string::npos);
  CHECK(message({0, 0, 1, 1}, 3, 2).find("too few") != std::string::npos);
}

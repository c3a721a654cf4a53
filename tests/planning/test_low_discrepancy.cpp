// Point sets in the unit square: radical inverse digits, the sets' shape,
// and their discrepancy against independent random points (Warnock's closed
// form of the L2-star discrepancy as the oracle).
#include <doctest/doctest.h>

#include <cmath>

#include "planning/low_discrepancy.hpp"
#include "plan_fixtures.hpp"

using namespace furrow;

namespace {

// L2-star discrepancy (Warnock 1972), exact for any point set in [0,1]^2.
double l2_star(const std::vector<Eigen::Vector2d>& p) {
  const double n = static_cast<double>(p.size());
  double a = 0, b = 0;
  for (const auto& x : p) a += (1 - x.x() * x.x()) * (1 - x.y() * x.y());
  for (const auto& x : p)
    for (const auto& y : p) b += (1 - std::max(x.x(), y.x())) * (1 - std::max(x.y(), y.y()));
  return std::sqrt(1.0 / 9 - a / (2 * n) + b / (n * n));
}

}  // namespace

TEST_CASE("radical inverse mirrors the digits about the radix point") {
  CHECK(radical_inverse(0, 2) == 0.0);
  CHECK(radical_inverse(1, 2) == 0.5);
  CHECK(radical_inverse(2, 2) == 0.25);
  CHECK(radical_inverse(3, 2) == 0.75);
  CHECK(radical_inverse(6, 2) == 0.375);  // 110 -> 0.011
  CHECK(radical_inverse(1, 3) == doctest::Approx(1.0 / 3).epsilon(1e-15));
  CHECK(radical_inverse(5, 3) == doctest::Approx(2.0 / 3 + 1.0 / 9).epsilon(1e-15));  // 12 -> 0.21
}

TEST_CASE("sets have the requested shape and stay in the unit square") {
  const auto h = hammersley_set(8);
  REQUIRE(h.size() == 8);
  CHECK(h[0].x() == 1.0 / 16);
  CHECK(h[3].y() == 0.75);
  const Eigen::Vector2i s = strata_for(100, 4.0);  // a patch 4x as wide as high
  CHECK(s.x() == 20);
  CHECK(s.y() == 5);
  CHECK(strata_for(7, 1.0).prod() >= 7);
  std::mt19937_64 rng(3);
  const auto st = stratified_set({5, 4}, rng);
  REQUIRE(st.size() == 20);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i) {
      const Eigen::Vector2d& p = st[static_cast<std::size_t>(j * 5 + i)];
      CHECK(p.x() >= i / 5.0);
      CHECK(p.x() < (i + 1) / 5.0);
      CHECK(p.y() >= j / 4.0);
      CHECK(p.y() < (j + 1) / 4.0);
    }
  const Eigen::Vector2d shift = rotation_from_seed(11);
  for (const auto& p : h) {
    const Eigen::Vector2d q = rotate(p, shift);
    CHECK(q.x() >= 0);
    CHECK(q.x() < 1);
    CHECK(q.y() >= 0);
    CHECK(q.y() < 1);
  }
  CHECK(rotation_from_seed(11) == rotation_from_seed(11));
  CHECK(rotation_from_seed(11) != rotation_from_seed(12));
}

TEST_CASE("low-discrepancy and stratified sets are more even than random points") {
  constexpr std::size_t n = 128;
  std::vector<Eigen::Vector2d> halton;
  for (std::size_t i = 0; i < n; ++i) halton.push_back(halton_point(i));
  std::mt19937_64 rng(5);
  const double d_hammersley = l2_star(hammersley_set(n));
  const double d_halton = l2_star(halton);
  const double d_stratified = l2_star(stratified_set(strata_for(n, 1.0), rng));
  std::vector<double> random;
  for (int s = 0; s < 20; ++s) {
    std::vector<Eigen::Vector2d> r;
    for (std::size_t i = 0; i < n; ++i) r.push_back(random_point(rng));
    random.push_back(l2_star(r));
  }
  const double d_random = test::mean(random);
  MESSAGE("L2-star discrepancy, 128 points: hammersley " << d_hammersley << ", halton " << d_halton
                                                         << ", stratified " << d_stratified << ", random (mean of 20) "
                                                         << d_random);
  // Random points: E[D^2] = (1/4 - 1/9) / n, so D ~ 0.033 at n = 128.
  CHECK(d_random == doctest::Approx(std::sqrt((0.25 - 1.0 / 9) / n)).epsilon(0.25).scale(0));
  CHECK(d_hammersley < d_random / 2);
  CHECK(d_halton < d_random / 2);
  CHECK(d_stratified < d_random / 2);
}

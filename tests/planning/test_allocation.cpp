// The allocation rule (allocation.hpp): hand-computed cases and the rule's
// defining properties on random demands.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "planning/allocation.hpp"

using namespace furrow;

namespace {

RegionDemand flat(double area) { return RegionDemand{area, 0, 0, 0, true}; }

}  // namespace

TEST_CASE("proportional to area for flat regions, floors respected") {
  // Areas 600, 300, 100 and 100 points: shares 60, 30, 10.
  Allocation a = allocate_points({flat(600), flat(300), flat(100)}, 100, 5);
  CHECK(a.counts == std::vector<int>{60, 30, 10});
  CHECK(a.total == 100);
  // With a floor of 15 the small region is pinned; 85 are shared 2:1.
  a = allocate_points({flat(600), flat(300), flat(100)}, 100, 15);
  CHECK(a.counts[2] == 15);
  CHECK(a.at_floor[2]);
  CHECK(a.counts[0] + a.counts[1] == 85);
  CHECK(a.counts[0] == 57);  // 56.67 -> largest remainder
  CHECK(a.counts[1] == 28);
}

TEST_CASE("curvature spread and risk raise a region's weight as documented") {
  RegionDemand bent = flat(100);
  bent.curvature_spread = 0.1;  // s sqrt(A) = 1 -> weight doubles
  CHECK(allocation_weight(bent, 0, {}) == doctest::Approx(200));
  RegionDemand risky = flat(100);
  risky.mean_risk = 0.02;
  CHECK(allocation_weight(risky, 0.01, {}) == doctest::Approx(300));  // 1 + 0.02 / 0.01
  CHECK(allocation_weight(risky, 0.0, {}) == doctest::Approx(100));   // no prediction: ignored
  // Two equal areas, one at twice the part's mean risk, one without: 3 : 1.
  RegionDemand calm = flat(100);
  risky.mean_risk = 0.02;  // part mean = 0.01
  const Allocation a = allocate_points({risky, calm}, 40, 0);
  CHECK(a.counts == std::vector<int>{30, 10});
}

TEST_CASE("floors above the budget, gouge points and unsamplable regions") {
  RegionDemand g = flat(10);
  g.gouge_points = 3;
  RegionDemand none = flat(50);
  none.samplable = false;
  Allocation a = allocate_points({flat(1000), g, none}, 4, 5);
  CHECK(a.floors_exceed_budget);
  CHECK(a.counts == std::vector<int>{5, 8, 0});
  CHECK(a.total == 13);
  a = allocate_points({flat(1000), g, none}, 100, 5);
  CHECK(a.counts[1] == 8);  // share 0.99 < floor 5 + 3
  CHECK(a.counts[0] == 92);
  CHECK(a.counts[2] == 0);
  CHECK_THROWS_AS(allocate_points({flat(1)}, -1, 5), std::invalid_argument);
}

TEST_CASE("random demands: exact total, floors, and one common proportionality factor") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> area(1, 2000), spread(0, 0.05), risk(0, 0.03);
  std::uniform_int_distribution<int> count(1, 12), gouge(0, 2), budget(0, 3000);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<RegionDemand> d(static_cast<std::size_t>(count(rng)));
    for (RegionDemand& r : d) r = {area(rng), spread(rng), trial % 2 ? risk(rng) : 0.0, gouge(rng) * 3, true};
    const long T = budget(rng);
    const int floor = 5;
    const Allocation a = allocate_points(d, T, floor);
    long floors = 0, sum = 0;
    for (std::size_t r = 0; r < d.size(); ++r) {
      floors += floor + d[r].gouge_points;
      sum += a.counts[r];
      CHECK(a.counts[r] >= floor + d[r].gouge_points);
    }
    CHECK(sum == a.total);
    CHECK(a.total == std::max(T, floors));
    if (T <= floors) continue;
    // Free regions: count = round(lambda w) for one lambda, so every free
    // count lies within 1 of lambda w: the intervals [(c-1)/w, (c+1)/w] meet.
    double lo = 0, hi = 1e300;
    for (std::size_t r = 0; r < d.size(); ++r) {
      if (a.at_floor[r]) {
        continue;
      }
      lo = std::max(lo, (a.counts[r] - 1) / a.weights[r]);
      hi = std::min(hi, (a.counts[r] + 1) / a.weights[r]);
    }
    CHECK(lo <= hi * (1 + 1e-12));
    // A pinned region would not have reached its floor at that lambda.
    for (std::size_t r = 0; r < d.size(); ++r)
      if (a.at_floor[r]) CHECK(lo * a.weights[r] <= floor + d[r].gouge_points + 1);
  }
}

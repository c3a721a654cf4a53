// The probe tour on the plan it is made for: 5,000 points on the mould with
// the planner's defaults. The near-linear search must give a tour no longer
// than the earlier implementation (kept as a second implementation in
// reference_tour.hpp), and a local optimum of every candidate move by brute
// force. The speed at 100,000 points is a figure of bench/bench_planning,
// not a test.
#include <doctest/doctest.h>

#include "partition/partition.hpp"
#include "plan_fixtures.hpp"
#include "planning/accessibility.hpp"
#include "planning/probe_planner.hpp"
#include "reference_tour.hpp"
#include "tour_oracles.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// The probe centres the planner passed to plan_tour, in its input order
// (the plan lists them in tour order; tour.order maps back).
std::vector<Eigen::Vector3d> mould_centres(long points) {
  const Part part = mould();
  const RegionMap map = partition_part(part, {}).map;
  PlannerOptions options;
  options.points = points;
  const PlanResult r = plan_probe_points(part, map, options);
  std::vector<Eigen::Vector3d> centres(r.plan.points.size());
  for (std::size_t k = 0; k < r.plan.points.size(); ++k) {
    const PlannedPoint& p = r.plan.points[k];
    centres[static_cast<std::size_t>(r.tour.order[k])] = probe_centre(p.xyz, p.ijk, r.probe);
  }
  // The reconstruction is the planner's input: its tour through it has the
  // length the planner reported.
  REQUIRE(path_length(centres, r.tour.order) == doctest::Approx(r.tour.length).epsilon(1e-12));
  return centres;
}

}  // namespace

TEST_CASE("mould, 5,000 points: no longer than the reference tour, a local optimum of every candidate move") {
  const std::vector<Eigen::Vector3d> p = mould_centres(5000);
  REQUIRE(p.size() == 5000);
  const TourOptions options;
  const TourResult t = plan_tour(p, options);
  const TourResult reference = reference_tour(p, options);
  MESSAGE("mould 5,000 points: nearest neighbour " << t.nearest_neighbour_length << " mm, this search " << t.length
                                                   << " mm, reference " << reference.length << " mm");
  REQUIRE(is_permutation_of_n(t.order, p.size()));
  CHECK(t.converged);
  CHECK(reference.converged);
  // The same construction, so the same starting length.
  CHECK(t.nearest_neighbour_length == doctest::Approx(reference.nearest_neighbour_length).epsilon(1e-12));
  CHECK(t.length <= reference.length);
  CHECK(t.length == doctest::Approx(path_length(p, t.order)));
  const auto nb = sure_neighbours(p, options.neighbours);
  CHECK(best_candidate_two_opt_gain(p, t.order, nb) <= options.min_gain);
  CHECK(best_candidate_or_opt_gain(p, t.order, nb) <= options.min_gain);
  CHECK(plan_tour(p, options).order == t.order);
}

// Distance to region edges: the kd-tree answer equals brute force over all
// segments.
#include <doctest/doctest.h>

#include <random>

#include "planning/edge_distance.hpp"

using namespace furrow;

TEST_CASE("edge distance equals the brute-force minimum over all segments") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> coord(-20, 20), step(-3, 3);
  EdgeDistance edges;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  for (int l = 0; l < 5; ++l) {
    std::vector<Eigen::Vector3d> line{{coord(rng), coord(rng), coord(rng)}};
    for (int k = 0; k < 30; ++k) line.push_back(line.back() + Eigen::Vector3d(step(rng), step(rng), step(rng)));
    const bool closed = l % 2 == 0;
    edges.add_polyline(line, closed);
    for (std::size_t k = 0; k + 1 < line.size(); ++k) segments.emplace_back(line[k], line[k + 1]);
    if (closed) segments.emplace_back(line.back(), line.front());
  }
  edges.build(0.7);
  int checked = 0;
  for (int q = 0; q < 400; ++q) {
    const Eigen::Vector3d p(coord(rng), coord(rng), coord(rng));
    double brute = 1e300;
    for (const auto& s : segments) brute = std::min(brute, point_segment_distance(p, s.first, s.second));
    const double reach = 4;
    const double d = edges.distance(p, reach);
    if (brute <= reach) {
      ++checked;
      CHECK(d == doctest::Approx(brute).epsilon(1e-12));
    } else {
      CHECK(std::isinf(d));
    }
  }
  CHECK(checked > 50);
}

TEST_CASE("point-segment distance: interior, ends, degenerate segment") {
  const Eigen::Vector3d a(0, 0, 0), b(10, 0, 0);
  CHECK(point_segment_distance({5, 3, 4}, a, b) == doctest::Approx(5));
  CHECK(point_segment_distance({-3, 4, 0}, a, b) == doctest::Approx(5));
  CHECK(point_segment_distance({13, 0, 4}, a, b) == doctest::Approx(5));
  CHECK(point_segment_distance({3, 4, 0}, a, a) == doctest::Approx(5));
}

TEST_CASE("edge distance at the centre of a dense circle, where every piece is about as near, equals brute force") {
  // A trim circle of radius 3 polygonised finely, as CAD import writes one:
  // from its centre every piece is a candidate.
  EdgeDistance edges;
  std::vector<Eigen::Vector3d> circle;
  for (int k = 0; k < 2000; ++k) {
    const double t = 2 * 3.14159265358979323846 * k / 2000;
    circle.emplace_back(10 + 3 * std::cos(t), -4 + 3 * std::sin(t), 1);
  }
  edges.add_polyline(circle, true);
  edges.build(0.25);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> off(-0.4, 0.4);
  for (int q = 0; q < 50; ++q) {
    const Eigen::Vector3d p = Eigen::Vector3d(10, -4, 1) + (q == 0 ? Eigen::Vector3d::Zero()
                                                                    : Eigen::Vector3d(off(rng), off(rng), off(rng)));
    double brute = 1e300;
    for (std::size_t k = 0; k < circle.size(); ++k)
      brute = std::min(brute, point_segment_distance(p, circle[k], circle[(k + 1) % circle.size()]));
    CAPTURE(q);
    CHECK(edges.distance(p, 5) == doctest::Approx(brute).epsilon(1e-12));
    CHECK(std::isinf(edges.distance(p, brute - 1e-6)));
  }
}

#pragma once
// Brute-force oracles for the probe tour (planning/tour.hpp): they enumerate
// every 2-opt and Or-opt move of an open path (closed through a dummy point
// at distance 0 from all, as the contract describes), keep those the
// candidate rule allows, and return the best gain. They share no code with
// the search: neighbour sets come from sorting all distances, positions from
// the path itself, gains from plain edge sums.
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace furrow::test {

inline bool is_permutation_of_n(std::vector<int> order, std::size_t n) {
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i)
    if (order[i] != static_cast<int>(i)) return false;
  return order.size() == n;
}

// For each point, the points surely among its k nearest whatever the
// rounding and the tie-break: all others when k >= n - 1, otherwise those
// closer than the k-th nearest distance by a relative 1e-9.
inline std::vector<std::vector<bool>> sure_neighbours(const std::vector<Eigen::Vector3d>& p, int k) {
  const std::size_t n = p.size();
  std::vector<std::vector<bool>> out(n, std::vector<bool>(n, false));
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> d;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) d.push_back((p[i] - p[j]).norm());
    if (d.empty()) continue;
    double limit = INFINITY;
    if (static_cast<std::size_t>(k) < d.size()) {
      std::nth_element(d.begin(), d.begin() + (k - 1), d.end());
      limit = d[static_cast<std::size_t>(k - 1)] * (1 - 1e-9);
    }
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) out[i][j] = static_cast<std::size_t>(k) >= n - 1 || (p[i] - p[j]).norm() < limit;
  }
  return out;
}

// The open path as a cycle through the dummy (index n) and distances on it.
struct DummyCycle {
  const std::vector<Eigen::Vector3d>& p;
  std::vector<int> c;  // c[0] = dummy, then the path
  DummyCycle(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& order) : p(points) {
    c.push_back(static_cast<int>(points.size()));
    c.insert(c.end(), order.begin(), order.end());
  }
  int m() const { return static_cast<int>(c.size()); }
  int at(int i) const { return c[static_cast<std::size_t>(((i % m()) + m()) % m())]; }
  bool dummy(int a) const { return a == static_cast<int>(p.size()); }
  double d(int a, int b) const {
    if (dummy(a) || dummy(b)) return 0;
    return (p[static_cast<std::size_t>(a)] - p[static_cast<std::size_t>(b)]).norm();
  }
};

// Is b a candidate of a (a real point; the dummy is everybody's candidate)?
inline bool candidate(const std::vector<std::vector<bool>>& nb, const DummyCycle& cy, int a, int b) {
  if (cy.dummy(a)) return false;
  return cy.dummy(b) || nb[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
}

// Best gain over every 2-opt move (edges (a, b), (c, d) -> (a, c), (b, d))
// that the candidate rule lets the search see from at least one of its four
// ends: the new edge at that end joins a candidate and is shorter than the
// edge it replaces there.
inline double best_candidate_two_opt_gain(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& order,
                                          const std::vector<std::vector<bool>>& nb) {
  const DummyCycle cy(p, order);
  const int m = cy.m();
  double best = 0;
  for (int i = 0; i < m; ++i)
    for (int j = i + 2; j < m; ++j) {
      const int a = cy.at(i), b = cy.at(i + 1), c = cy.at(j), d = cy.at(j + 1);
      if (d == a) continue;  // adjacent edges
      const double dab = cy.d(a, b), dcd = cy.d(c, d), dac = cy.d(a, c), dbd = cy.d(b, d);
      const bool seen = (candidate(nb, cy, a, c) && dac < dab) || (candidate(nb, cy, c, a) && dac < dcd) ||
                        (candidate(nb, cy, b, d) && dbd < dab) || (candidate(nb, cy, d, b) && dbd < dcd);
      if (seen) best = std::max(best, dab + dcd - dac - dbd);
    }
  return best;
}

// Best gain over every Or-opt move: a run of 1..3 consecutive real points
// moved, in either orientation, between two consecutive points x, y of which
// one is a candidate c of an end of the run (or the dummy) nearer to that
// end than the run's removal gains.
inline double best_candidate_or_opt_gain(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& order,
                                         const std::vector<std::vector<bool>>& nb) {
  const DummyCycle cy(p, order);
  const int m = cy.m();
  double best = 0;
  for (int k = 1; k <= 3; ++k) {
    if (m < k + 3) break;
    for (int i = 1; i + k - 1 < m; ++i) {  // runs of real points: positions i..i+k-1, none is 0 (the dummy)
      const int a = cy.at(i), e = cy.at(i + k - 1), pr = cy.at(i - 1), nx = cy.at(i + k);
      const double removed = cy.d(pr, a) + cy.d(e, nx) - cy.d(pr, nx);
      for (int j = i + k; j < i - 1 + m; ++j) {  // insertion edges (x, y) outside the run and not (pr, a)
        const int x = cy.at(j), y = cy.at(j + 1);
        bool seen = false;
        for (const int end : {a, e})
          for (const int c : {x, y}) seen = seen || (candidate(nb, cy, end, c) && cy.d(end, c) < removed);
        if (!seen) continue;
        const double added = std::min(cy.d(x, a) + cy.d(e, y), cy.d(x, e) + cy.d(a, y)) - cy.d(x, y);
        best = std::max(best, removed - added);
      }
    }
  }
  return best;
}

inline double brute_force_optimum(const std::vector<Eigen::Vector3d>& p) {
  std::vector<int> o(p.size());
  std::iota(o.begin(), o.end(), 0);
  double best = INFINITY;
  do {
    double length = 0;
    for (std::size_t k = 1; k < o.size(); ++k)
      length += (p[static_cast<std::size_t>(o[k])] - p[static_cast<std::size_t>(o[k - 1])]).norm();
    best = std::min(best, length);
  } while (std::next_permutation(o.begin(), o.end()));
  return best;
}

}  // namespace furrow::test

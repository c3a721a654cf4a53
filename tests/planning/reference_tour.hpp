#pragma once
// A second implementation of the probe tour for the tests: the planner's
// earlier one, kept as it was, slow but simple. Nearest neighbour by the
// O(n^2) scan, then sweeps over all points with 2-opt (array reversal) and
// Or-opt that rebuilds the whole tour for each accepted move, same candidate
// lists and options. The tests hold the near-linear search to tours no
// longer than this one's (see test_tour_mould.cpp).
#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <vector>

#include "geometry/point_search.hpp"
#include "planning/tour.hpp"

namespace furrow::test {

// Closed tour over n real points plus a dummy (index n) at distance 0 from all.
class ReferenceSearch {
 public:
  ReferenceSearch(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& open_path,
              std::vector<std::vector<int>> neighbours, const TourOptions& options)
      : p_(p), n_(static_cast<int>(p.size())), m_(n_ + 1), neighbours_(std::move(neighbours)), options_(options) {
    tour_ = open_path;
    tour_.push_back(n_);
    pos_.assign(static_cast<std::size_t>(m_), 0);
    for (int k = 0; k < m_; ++k) pos_[static_cast<std::size_t>(tour_[k])] = k;
  }

  // Returns the number of passes; `converged` false when capped.
  int run(bool& converged) {
    converged = false;
    int pass = 0;
    while (pass < options_.max_passes) {
      ++pass;
      bool improved = false;
      for (int a = 0; a < m_; ++a) {
        while ((options_.two_opt && two_opt(a)) || (options_.or_opt && or_opt(a))) improved = true;
      }
      if (!improved) {
        converged = true;
        break;
      }
    }
    return pass;
  }

  std::vector<int> open_path() const {
    std::vector<int> out;
    out.reserve(static_cast<std::size_t>(n_));
    const int start = pos_[static_cast<std::size_t>(n_)];
    for (int k = 1; k < m_; ++k) out.push_back(tour_[static_cast<std::size_t>((start + k) % m_)]);
    return out;
  }

 private:
  double d(int a, int b) const {
    if (a == n_ || b == n_) return 0;
    return (p_[static_cast<std::size_t>(a)] - p_[static_cast<std::size_t>(b)]).norm();
  }
  int next(int a) const { return tour_[static_cast<std::size_t>((pos_[static_cast<std::size_t>(a)] + 1) % m_)]; }
  int prev(int a) const { return tour_[static_cast<std::size_t>((pos_[static_cast<std::size_t>(a)] + m_ - 1) % m_)]; }
  // Candidates: the point's nearest neighbours, then the dummy.
  template <class F>
  bool for_candidates(int a, F&& f) const {
    if (a == n_) return false;
    for (int c : neighbours_[static_cast<std::size_t>(a)])
      if (f(c)) return true;
    return f(n_);
  }

  // Reverses the tour between positions i and j (inclusive, forward from i).
  void reverse(int i, int j) {
    int len = (j - i + m_) % m_ + 1;
    if (2 * len > m_) {  // reverse the complement instead: the same cycle
      const int ni = (j + 1) % m_, nj = (i + m_ - 1) % m_;
      i = ni;
      j = nj;
      len = m_ - len;
    }
    for (int k = 0; k < len / 2; ++k) {
      const int a = (i + k) % m_, b = (j - k + m_) % m_;
      std::swap(tour_[static_cast<std::size_t>(a)], tour_[static_cast<std::size_t>(b)]);
      pos_[static_cast<std::size_t>(tour_[static_cast<std::size_t>(a)])] = a;
      pos_[static_cast<std::size_t>(tour_[static_cast<std::size_t>(b)])] = b;
    }
  }

  bool two_opt(int a) {
    // Successor direction: a b ... c d -> a c ... b d.
    {
      const int b = next(a);
      const double dab = d(a, b);
      if (for_candidates(a, [&](int c) {
            if (c == b || c == a) return false;
            const double dac = d(a, c);
            if (dac >= dab) return false;
            const int dd = next(c);
            if (dd == a) return false;
            const double gain = dab + d(c, dd) - dac - d(b, dd);
            if (gain <= options_.min_gain) return false;
            reverse(pos_[static_cast<std::size_t>(b)], pos_[static_cast<std::size_t>(c)]);
            return true;
          }))
        return true;
    }
    // Predecessor direction: b a ... d c -> b d ... a c.
    const int b = prev(a);
    const double dab = d(a, b);
    return for_candidates(a, [&](int c) {
      if (c == b || c == a) return false;
      const double dac = d(a, c);
      if (dac >= dab) return false;
      const int dd = prev(c);
      if (dd == a) return false;
      const double gain = dab + d(c, dd) - dac - d(b, dd);
      if (gain <= options_.min_gain) return false;
      reverse(pos_[static_cast<std::size_t>(a)], pos_[static_cast<std::size_t>(dd)]);
      return true;
    });
  }

  // Moves the run of k points starting at a (forward) between c and next(c).
  void move_segment(int a, int k, int c, bool reversed) {
    std::vector<int> segment;
    int x = a;
    for (int s = 0; s < k; ++s, x = next(x)) segment.push_back(x);
    if (reversed) std::reverse(segment.begin(), segment.end());
    std::vector<int> rest;
    rest.reserve(static_cast<std::size_t>(m_));
    for (int y = x; static_cast<int>(rest.size()) < m_ - k; y = next(y)) rest.push_back(y);
    std::vector<int> out;
    out.reserve(static_cast<std::size_t>(m_));
    for (int y : rest) {
      out.push_back(y);
      if (y == c) out.insert(out.end(), segment.begin(), segment.end());
    }
    tour_ = std::move(out);
    for (int q = 0; q < m_; ++q) pos_[static_cast<std::size_t>(tour_[static_cast<std::size_t>(q)])] = q;
  }

  bool or_opt(int a) {
    for (int k = 1; k <= 3; ++k) {
      if (m_ < k + 3) return false;
      int e = a;
      bool has_dummy = a == n_;
      for (int s = 1; s < k; ++s) {
        e = next(e);
        has_dummy = has_dummy || e == n_;
      }
      if (has_dummy) continue;  // the dummy stays put; moves around it come from 2-opt
      const int p = prev(a), nx = next(e);
      const double remove_gain = d(p, a) + d(e, nx) - d(p, nx);
      if (remove_gain <= options_.min_gain) continue;
      auto in_segment = [&](int y) {
        const int off = (pos_[static_cast<std::size_t>(y)] - pos_[static_cast<std::size_t>(a)] + m_) % m_;
        return off < k;
      };
      auto try_insert = [&](int c) {
        if (in_segment(c)) return false;
        const int c2 = next(c);
        if (in_segment(c2) || c == p) return false;
        const double dcc = d(c, c2);
        const double forward = d(c, a) + d(e, c2) - dcc;
        const double backward = d(c, e) + d(a, c2) - dcc;
        const bool rev = backward < forward;
        if (remove_gain - std::min(forward, backward) <= options_.min_gain) return false;
        move_segment(a, k, c, rev);
        return true;
      };
      // Insert next to a neighbour of either end: after it, or before it.
      for (int end : {a, e}) {
        if (for_candidates(end, [&](int c) { return try_insert(c) || (!in_segment(c) && try_insert(prev(c))); }))
          return true;
      }
    }
    return false;
  }

  const std::vector<Eigen::Vector3d>& p_;
  int n_, m_;
  std::vector<std::vector<int>> neighbours_;
  TourOptions options_;
  std::vector<int> tour_, pos_;
};

inline std::vector<std::vector<int>> reference_neighbour_lists(const std::vector<Eigen::Vector3d>& p, int k) {
  const int n = static_cast<int>(p.size());
  std::vector<std::vector<int>> out(static_cast<std::size_t>(n));
  if (n < 2 || k < 1) return out;
  const PointSearch search(p);
  for (int i = 0; i < n; ++i) {
    // k + 1: the point itself comes back among its own nearest.
    for (const PointNeighbour& m : search.nearest(p[static_cast<std::size_t>(i)], static_cast<std::size_t>(k) + 1)) {
      if (static_cast<int>(m.index) == i || static_cast<int>(out[static_cast<std::size_t>(i)].size()) == k) continue;
      out[static_cast<std::size_t>(i)].push_back(static_cast<int>(m.index));
    }
  }
  return out;
}

inline std::vector<int> reference_nearest_neighbour_path(const std::vector<Eigen::Vector3d>& p) {
  const std::size_t n = p.size();
  std::vector<int> order;
  std::vector<bool> used(n, false);
  std::size_t current = 0;
  for (std::size_t step = 0; step < n; ++step) {
    order.push_back(static_cast<int>(current));
    used[current] = true;
    double best = std::numeric_limits<double>::infinity();
    std::size_t next = n;
    for (std::size_t j = 0; j < n; ++j) {
      if (used[j]) continue;
      const double dj = (p[j] - p[current]).squaredNorm();
      if (dj < best) {
        best = dj;
        next = j;
      }
    }
    current = next;
  }
  return order;
}


// The reference tour: order and length, same options as plan_tour.
inline TourResult reference_tour(const std::vector<Eigen::Vector3d>& positions, const TourOptions& options = {}) {
  TourResult result;
  if (positions.empty()) return result;
  result.order = reference_nearest_neighbour_path(positions);
  result.nearest_neighbour_length = path_length(positions, result.order);
  if (positions.size() >= 4 && (options.two_opt || options.or_opt)) {
    ReferenceSearch search(positions, result.order, reference_neighbour_lists(positions, options.neighbours), options);
    result.passes = search.run(result.converged);
    result.order = search.open_path();
  }
  result.length = path_length(positions, result.order);
  return result;
}

}  // namespace furrow::test

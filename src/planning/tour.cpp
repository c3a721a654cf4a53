#include "planning/tour.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

#include "geometry/point_search.hpp"
#include "planning/greedy_path.hpp"
#include "planning/nearest_neighbour_path.hpp"

namespace furrow {

double path_length(const std::vector<Eigen::Vector3d>& positions, const std::vector<int>& order) {
  double length = 0;
  for (std::size_t k = 1; k < order.size(); ++k)
    length += (positions[static_cast<std::size_t>(order[k])] - positions[static_cast<std::size_t>(order[k - 1])]).norm();
  return length;
}

namespace {

std::vector<std::vector<int>> neighbour_lists(const std::vector<Eigen::Vector3d>& positions, int k) {
  const int n = static_cast<int>(positions.size());
  std::vector<std::vector<int>> out(static_cast<std::size_t>(n));
  if (n < 2 || k < 1) return out;
  const PointSearch search(positions);
  // Queries are independent and const: one per point, in parallel; each
  // writes only its own list, so the result does not depend on threads.
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    std::vector<int>& list = out[static_cast<std::size_t>(i)];
    // k + 1: the point itself comes back among its own nearest (or a
    // duplicate of it in its place; then the point is skipped below).
    for (const PointNeighbour& m :
         search.nearest(positions[static_cast<std::size_t>(i)], static_cast<std::size_t>(k) + 1)) {
      if (static_cast<int>(m.index) == i || static_cast<int>(list.size()) == k) continue;
      list.push_back(static_cast<int>(m.index));
    }
  }
  return out;
}


// Closed tour over n real points plus a dummy (index n) at distance 0 from
// all, stored as an array with each point's position in it. A 2-opt move is
// one reversal of the shorter side; an Or-opt move is two or three 2-opt
// moves in a row, so no move ever rebuilds the tour.
class LocalSearch {
 public:
  LocalSearch(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& open_path,
              std::vector<std::vector<int>> neighbours, const TourOptions& options)
      : p_(p), n_(static_cast<int>(p.size())), m_(n_ + 1), neighbours_(std::move(neighbours)), options_(options) {
    tour_ = open_path;
    tour_.push_back(n_);
    pos_.assign(static_cast<std::size_t>(m_), 0);
    for (int k = 0; k < m_; ++k) pos_[static_cast<std::size_t>(tour_[static_cast<std::size_t>(k)])] = k;
    queued_.assign(static_cast<std::size_t>(m_), false);
  }

  // Returns the work done in sweeps (examinations / (n + 1), rounded up);
  // `converged` is false when the cap stopped the search.
  int run(bool& converged) {
    converged = false;
    const long long cap = static_cast<long long>(options_.max_passes) * m_;
    long long examinations = 0;
    bool capped = false;
    while (!capped) {
      // A sweep queues every point; a point whose edges change is queued
      // again (its don't-look bit is cleared), the rest are not looked at
      // until the next sweep. That is not enough on its own: a move can
      // appear at a point whose own edges did not change (a candidate's
      // did). So the search ends only with a sweep in which no point finds
      // an improving move, and the tour is then a local optimum of every
      // move the candidate lists allow.
      for (int a = 0; a < m_; ++a) push(a);
      bool improved = false;
      while (!queue_.empty()) {
        if (examinations == cap) {
          capped = true;
          break;
        }
        const int a = queue_.front();
        queue_.pop_front();
        queued_[static_cast<std::size_t>(a)] = false;
        ++examinations;
        if ((options_.two_opt && two_opt(a)) || (options_.or_opt && or_opt(a))) {
          improved = true;
          push(a);  // other moves may remain at a
        }
      }
      if (!capped && !improved) {
        converged = true;
        break;
      }
    }
    return static_cast<int>((examinations + m_ - 1) / m_);
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
  // Neighbour along the tour in a direction: forward = next.
  int step(int a, bool forward) const { return forward ? next(a) : prev(a); }
  const std::vector<int>& candidates(int a) const { return neighbours_[static_cast<std::size_t>(a)]; }

  void push(int a) {
    if (queued_[static_cast<std::size_t>(a)]) return;
    queued_[static_cast<std::size_t>(a)] = true;
    queue_.push_back(a);
  }

  // Reverses the tour between positions i and j (inclusive, forward from i),
  // or the complement when that is shorter: the same cycle either way.
  void reverse(int i, int j) {
    int len = (j - i + m_) % m_ + 1;
    if (2 * len > m_) {
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

  // The 2-opt move on the cycle a-b ... c-d (b follows a and d follows c in
  // one direction of travel, whichever the array stores): edges (a, b),
  // (c, d) become (a, c), (b, d). Named by points, not positions, because a
  // reversal of the complement flips the array's direction.
  void flip(int a, int b, int c, int d) {
    (void)d;
    if (next(a) == b)
      reverse(pos_[static_cast<std::size_t>(b)], pos_[static_cast<std::size_t>(c)]);
    else
      reverse(pos_[static_cast<std::size_t>(c)], pos_[static_cast<std::size_t>(b)]);
  }

  // 2-opt around a, in both directions of travel: a-b ... c-dd becomes
  // a-c ... b-dd with c among a's candidates (then the dummy). A move with
  // d(a, c) >= d(a, b) is left to the other end (the neighbour-list rule
  // of Johnson & McGeoch).
  bool two_opt(int a) {
    if (a == n_) return false;
    for (const bool forward : {true, false}) {
      const int b = step(a, forward);
      const double dab = d(a, b);
      auto attempt = [&](int c, double dac) {
        const int dd = step(c, forward);
        if (c == b || dd == a) return false;
        const double gain = dab + d(c, dd) - dac - d(b, dd);
        if (gain <= options_.min_gain) return false;
        flip(a, b, c, dd);
        push(a), push(b), push(c), push(dd);
        return true;
      };
      for (const int c : candidates(a)) {
        const double dac = d(a, c);
        if (dac < dab && attempt(c, dac)) return true;
      }
      if (dab > 0 && attempt(n_, 0)) return true;
    }
    return false;
  }

  // Or-opt around a: the run of k = 1..3 points that starts at a in either
  // direction of travel, p-[a..e]-nx, moves between two consecutive points
  // x-y next to a candidate c of either end (x-y is c-next or prev-c), in
  // the better of its two orientations. Only candidates nearer to the end
  // than the run's removal gains are tried (the same neighbour-list rule as
  // for 2-opt: a move whose new edge at the run is longer than that rarely
  // pays, and skipping them halves the time at 100,000 points).
  bool or_opt(int a) {
    if (a == n_) return false;
    for (int k = 1; k <= 3; ++k) {
      if (m_ < k + 3) return false;
      for (const bool forward : {true, false}) {
        if (k == 1 && !forward) continue;  // a single point: the same move both ways
        int e = a;
        bool has_dummy = false;
        for (int s = 1; s < k; ++s) {
          e = step(e, forward);
          has_dummy = has_dummy || e == n_;
        }
        if (has_dummy) continue;  // the dummy stays put; moves around it come from 2-opt
        const int p = step(a, !forward), nx = step(e, forward);
        const double remove_gain = d(p, a) + d(e, nx) - d(p, nx);
        if (remove_gain <= 0) continue;  // no candidate is nearer than that
        const int pa = pos_[static_cast<std::size_t>(a)];
        auto in_segment = [&](int y) {
          const int py = pos_[static_cast<std::size_t>(y)];
          return (forward ? (py - pa + m_) % m_ : (pa - py + m_) % m_) < k;
        };
        // Insert between x and y = step(x, forward).
        auto attempt = [&](int x) {
          const int y = step(x, forward);
          if (in_segment(x) || in_segment(y)) return false;
          const double dxy = d(x, y);
          const double same = d(x, a) + d(e, y) - dxy;      // x-a..e-y
          const double reversed = d(x, e) + d(a, y) - dxy;  // x-e..a-y
          if (remove_gain - std::min(same, reversed) <= options_.min_gain) return false;
          // p-[a..e]-nx ... x-y  ->  p-x ... nx-[e..a]-y  ->  p-nx ... x-[e..a]-y
          flip(p, a, x, y);
          if (x != nx) flip(p, x, nx, e);
          if (same < reversed && k > 1) flip(x, e, a, y);  // -> x-[a..e]-y
          push(p), push(a), push(e), push(nx), push(x), push(y);
          return true;
        };
        for (const int end : {a, e})
          for (const int c : candidates(end))
            if (d(end, c) < remove_gain && (attempt(c) || attempt(step(c, !forward)))) return true;
        if (attempt(n_) || attempt(step(n_, !forward))) return true;
      }
    }
    return false;
  }

  const std::vector<Eigen::Vector3d>& p_;
  int n_, m_;
  std::vector<std::vector<int>> neighbours_;
  TourOptions options_;
  std::vector<int> tour_, pos_;
  std::deque<int> queue_;
  std::vector<bool> queued_;
};

}  // namespace

TourResult plan_tour(const std::vector<Eigen::Vector3d>& positions, const TourOptions& options) {
  if (options.neighbours < 1 || options.max_passes < 0 || !(options.min_gain >= 0))
    throw std::invalid_argument("plan_tour: invalid options");
  TourResult result;
  if (positions.empty()) return result;
  const std::vector<int> nearest = nearest_neighbour_path(positions);  // refuses non-finite positions
  result.nearest_neighbour_length = path_length(positions, nearest);
  result.order = nearest;
  result.start_length = result.nearest_neighbour_length;
  if (positions.size() >= 3) {
    std::vector<std::vector<int>> lists = neighbour_lists(positions, options.neighbours);
    result.order = greedy_path(positions, lists);
    result.start_length = path_length(positions, result.order);
    if (options.two_opt || options.or_opt) {
      LocalSearch search(positions, result.order, lists, options);
      result.passes = search.run(result.converged);
      result.order = search.open_path();
    }
    // Never longer than the yardstick: should the greedy start lead to a
    // worse local optimum (not seen on the planner's point sets), search
    // from nearest neighbour too and keep the shorter.
    if (path_length(positions, result.order) > result.nearest_neighbour_length) {
      TourResult again;
      again.order = nearest;
      if (options.two_opt || options.or_opt) {
        LocalSearch search(positions, nearest, std::move(lists), options);
        again.passes = search.run(again.converged);
        again.order = search.open_path();
      }
      result.passes += again.passes;
      result.converged = again.converged;
      result.order = std::move(again.order);
    }
  }
  result.length = path_length(positions, result.order);
  return result;
}

}  // namespace furrow

#include "partition/region_boundary.hpp"

#include <algorithm>
#include <stdexcept>

namespace furrow {

namespace {

// Directions counter-clockwise, so turning left is (d + 1) % 4.
constexpr int kStep[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};  // +u, +v, -u, -v

struct Edge {
  long long start;  // node key a * (nv + 1) + b
  int a, b, dir;
};

}  // namespace

std::vector<std::vector<NodeLoop>> trace_region_boundaries(const RegionLabels& labels) {
  const int nu = labels.nu, nv = labels.nv;
  const long long row = nv + 1;
  std::vector<std::vector<Edge>> edges(static_cast<std::size_t>(labels.count()));
  auto add = [&](int r, int a, int b, int dir) {
    edges[static_cast<std::size_t>(r)].push_back({a * row + b, a, b, dir});
  };
  // Each cell side facing another label (or nothing) is a border edge,
  // directed so that the cell lies on its left.
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const int r = labels.at(i, j);
      if (r < 0) continue;
      if (j == 0 || labels.at(i, j - 1) != r) add(r, i, j, 0);
      if (i + 1 == nu || labels.at(i + 1, j) != r) add(r, i + 1, j, 1);
      if (j + 1 == nv || labels.at(i, j + 1) != r) add(r, i + 1, j + 1, 2);
      if (i == 0 || labels.at(i - 1, j) != r) add(r, i, j + 1, 3);
    }
  }

  std::vector<std::vector<NodeLoop>> loops(edges.size());
  for (std::size_t r = 0; r < edges.size(); ++r) {
    std::vector<Edge>& e = edges[r];
    std::sort(e.begin(), e.end(), [](const Edge& x, const Edge& y) {
      return x.start != y.start ? x.start < y.start : x.dir < y.dir;
    });
    std::vector<char> used(e.size(), 0);
    // The (at most two) edges leaving a node, found by binary search.
    auto leaving = [&](long long key, std::size_t& first, std::size_t& count) {
      const auto lo = std::lower_bound(e.begin(), e.end(), key,
                                       [](const Edge& x, long long k) { return x.start < k; });
      first = static_cast<std::size_t>(lo - e.begin());
      count = 0;
      while (first + count < e.size() && e[first + count].start == key) ++count;
    };
    std::vector<NodeLoop> outer, holes;
    for (std::size_t s = 0; s < e.size(); ++s) {
      if (used[s]) continue;
      NodeLoop loop;
      std::size_t cur = s;
      while (true) {
        used[cur] = 1;
        const Edge& c = e[cur];
        loop.nodes.emplace_back(c.a, c.b);
        const int na = c.a + kStep[c.dir][0], nb = c.b + kStep[c.dir][1];
        loop.twice_area += static_cast<long long>(c.a) * nb - static_cast<long long>(na) * c.b;
        std::size_t first = 0, count = 0;
        leaving(na * row + nb, first, count);
        std::size_t next = first;
        if (count == 2) {
          // Pinch node: prefer the left turn, which hugs the current cell.
          const int left = (c.dir + 1) % 4;
          next = (e[first].dir == left) ? first : first + 1;
        } else if (count != 1) {
          throw std::logic_error("region border tracing: a node with " + std::to_string(count) +
                                 " leaving edges");
        }
        if (next == s) break;
        if (used[next]) throw std::logic_error("region border tracing: an edge visited twice");
        cur = next;
      }
      loop.hole = loop.twice_area < 0;
      (loop.hole ? holes : outer).push_back(std::move(loop));
    }
    loops[r] = std::move(outer);
    for (NodeLoop& h : holes) loops[r].push_back(std::move(h));
  }
  return loops;
}

}  // namespace furrow

#pragma once
// Independent oracles for the SPC tests: the Nelson rules written from their
// definitions (docs/spc.md "Nelson rules") as maximal runs and brute-force
// windows, and a seeded normal sample that does not depend on the standard
// library's distributions (std::normal_distribution differs between
// implementations; std::mt19937's output does not).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <tuple>
#include <vector>

#include "base/numbers.hpp"

namespace spc_oracle {

struct Found {
  int rule;
  std::size_t first;
  std::size_t last;
  bool operator==(const Found& o) const { return rule == o.rule && first == o.first && last == o.last; }
};

inline int sgn(double v) { return (v > 0) - (v < 0); }

// Box-Muller on 32-bit words of mt19937: uniform in (0, 1] from the word.
inline std::vector<double> normal_sample(std::uint32_t seed, std::size_t n, double mean, double sd) {
  std::mt19937 rng(seed);
  auto uniform = [&] { return (static_cast<double>(rng()) + 1.0) / 4294967296.0; };
  std::vector<double> out;
  while (out.size() < n) {
    const double r = std::sqrt(-2 * std::log(uniform()));
    const double a = 2 * furrow::kPi * uniform();
    out.push_back(mean + sd * r * std::cos(a));
    if (out.size() < n) out.push_back(mean + sd * r * std::sin(a));
  }
  return out;
}

// Mean and mean-moving-range sigma (d2 = 1.128), computed here on their own.
inline std::pair<double, double> centre_and_sigma(const std::vector<double>& x) {
  double mean = 0, mr = 0;
  for (double v : x) mean += v;
  mean /= x.size();
  for (std::size_t i = 1; i < x.size(); ++i) mr += std::abs(x[i] - x[i - 1]);
  return {mean, mr / (x.size() - 1) / 1.128};
}

// All violations by the definitions, sorted by (first, rule).
inline std::vector<Found> nelson(const std::vector<double>& x, double centre, double sigma) {
  const std::size_t n = x.size();
  std::vector<double> z;
  for (double v : x) z.push_back((v - centre) / sigma);
  std::vector<int> step;  // step[k]: direction from x[k] to x[k+1]
  for (std::size_t k = 0; k + 1 < n; ++k) step.push_back(sgn(x[k + 1] - x[k]));
  std::vector<Found> out;
  // 1: each value beyond 3 sigma.
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(z[i]) > 3) out.push_back({1, i, i});
  // 2: maximal runs of one side, 9 values or more.
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && sgn(z[i]) != 0 && sgn(z[j + 1]) == sgn(z[i])) ++j;
    if (sgn(z[i]) != 0 && j - i + 1 >= 9) out.push_back({2, i, j});
    i = j + 1;
  }
  // 3: maximal runs of steps in one direction, 5 steps (6 values) or more.
  for (std::size_t k = 0; k < step.size();) {
    std::size_t m = k;
    while (step[k] != 0 && m + 1 < step.size() && step[m + 1] == step[k]) ++m;
    if (step[k] != 0 && m - k + 1 >= 5) out.push_back({3, k, m + 1});
    k = m + 1;
  }
  // 4: maximal runs of alternating steps, 13 steps (14 values) or more.
  for (std::size_t k = 0; k < step.size();) {
    if (step[k] == 0) {
      ++k;
      continue;
    }
    std::size_t m = k;
    while (m + 1 < step.size() && step[m + 1] == -step[m]) ++m;
    if (m - k + 1 >= 13) out.push_back({4, k, m + 1});
    k = m + 1;
  }
  // 5, 6: every window of 3 (5) with 2 (4) values beyond 2 (1) sigma on one
  // side, from its first to its last such value; overlapping ones of a side merge.
  for (auto [rule, length, k, limit] : {std::tuple<int, std::size_t, int, double>{5, 3, 2, 2.0}, {6, 5, 4, 1.0}}) {
    for (int side : {1, -1}) {
      bool open = false;
      Found cur{rule, 0, 0};
      for (std::size_t i = 0; i + length <= n; ++i) {
        std::vector<std::size_t> beyond;
        for (std::size_t j = i; j < i + length; ++j)
          if (side * z[j] > limit) beyond.push_back(j);
        if (static_cast<int>(beyond.size()) < k) continue;
        if (open && beyond.front() <= cur.last) {
          cur.last = std::max(cur.last, beyond.back());
        } else {
          if (open) out.push_back(cur);
          cur = {rule, beyond.front(), beyond.back()};
          open = true;
        }
      }
      if (open) out.push_back(cur);
    }
  }
  // 7: maximal runs within 1 sigma, 15 values or more.
  for (std::size_t i = 0; i < n;) {
    if (std::abs(z[i]) > 1) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < n && std::abs(z[j + 1]) <= 1) ++j;
    if (j - i + 1 >= 15) out.push_back({7, i, j});
    i = j + 1;
  }
  // 8: windows of 8 all beyond 1 sigma with both sides present; overlapping ones merge.
  {
    bool open = false;
    Found cur{8, 0, 0};
    for (std::size_t i = 0; i + 8 <= n; ++i) {
      bool all = true, above = false, below = false;
      for (std::size_t j = i; j < i + 8; ++j) {
        all = all && std::abs(z[j]) > 1;
        above = above || z[j] > 1;
        below = below || z[j] < -1;
      }
      if (!(all && above && below)) continue;
      if (open && i <= cur.last) {
        cur.last = i + 7;
      } else {
        if (open) out.push_back(cur);
        cur = {8, i, i + 7};
        open = true;
      }
    }
    if (open) out.push_back(cur);
  }
  std::stable_sort(out.begin(), out.end(), [](const Found& a, const Found& b) {
    return a.first != b.first ? a.first < b.first : a.rule < b.rule;
  });
  return out;
}

}  // namespace spc_oracle

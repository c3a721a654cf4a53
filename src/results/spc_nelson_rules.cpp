#include "results/spc_nelson_rules.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace furrow {
namespace {

constexpr std::array<std::size_t, 8> kWindow = {1, 9, 6, 14, 3, 5, 15, 8};

int sign(double v) { return (v > 0) - (v < 0); }

// A window showing a rule's pattern: the values it covers and the tag that
// decides which findings merge (side, direction, phase; 0 when none).
struct Finding {
  bool found = false;
  std::size_t first = 0;
  std::size_t last = 0;
  int tag = 0;
};

// k of the window's values beyond `limit` sigma on one side (rules 5, 6):
// the window counts from the first to the last such value.
Finding k_beyond(const std::vector<double>& z, std::size_t i, std::size_t length, int k, double limit) {
  for (int side : {1, -1}) {
    int count = 0;
    std::size_t first = 0, last = 0;
    for (std::size_t j = i; j < i + length; ++j) {
      if (side * z[j] > limit) {
        if (count++ == 0) first = j;
        last = j;
      }
    }
    if (count >= k) return {true, first, last, side};
  }
  return {};
}

Finding window_finding(int rule, const std::vector<double>& x, const std::vector<double>& z, std::size_t i) {
  const std::size_t length = kWindow[rule - 1];
  const std::size_t end = i + length;  // one past the window
  switch (rule) {
    case 1:
      return {std::abs(z[i]) > 3, i, i, 0};
    case 2: {  // all on one side of the centre
      const int side = sign(z[i]);
      for (std::size_t j = i; j < end; ++j)
        if (side == 0 || sign(z[j]) != side) return {};
      return {true, i, end - 1, side};
    }
    case 3: {  // every step in one direction
      const int direction = sign(x[i + 1] - x[i]);
      for (std::size_t j = i; j + 1 < end; ++j)
        if (direction == 0 || sign(x[j + 1] - x[j]) != direction) return {};
      return {true, i, end - 1, direction};
    }
    case 4: {  // steps alternate; the phase is the sign of the steps at even positions
      for (std::size_t j = i; j + 1 < end; ++j) {
        const int step = sign(x[j + 1] - x[j]);
        if (step == 0) return {};
        if (j + 2 < end && sign(x[j + 2] - x[j + 1]) != -step) return {};
      }
      const int phase = sign(x[i + 1] - x[i]) * (i % 2 == 0 ? 1 : -1);
      return {true, i, end - 1, phase};
    }
    case 5:
      return k_beyond(z, i, length, 2, 2.0);
    case 6:
      return k_beyond(z, i, length, 4, 1.0);
    case 7:
      for (std::size_t j = i; j < end; ++j)
        if (std::abs(z[j]) > 1) return {};
      return {true, i, end - 1, 0};
    case 8: {  // none within 1 sigma, and values on both sides
      bool above = false, below = false;
      for (std::size_t j = i; j < end; ++j) {
        if (!(std::abs(z[j]) > 1)) return {};
        (z[j] > 0 ? above : below) = true;
      }
      return {above && below, i, end - 1, 0};
    }
  }
  return {};
}

}  // namespace

std::size_t nelson_window(int rule) {
  if (rule < 1 || rule > 8) throw std::logic_error("nelson_window: rule outside 1 .. 8");
  return kWindow[rule - 1];
}

std::vector<NelsonViolation> nelson_violations(const std::vector<double>& values, double centre, double sigma) {
  if (!(sigma > 0) || !std::isfinite(sigma) || !std::isfinite(centre))
    throw std::logic_error("nelson_violations: needs a finite centre and a finite sigma > 0");
  std::vector<double> z(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) throw std::logic_error("nelson_violations: a value is not finite");
    z[i] = (values[i] - centre) / sigma;
  }
  std::vector<NelsonViolation> out;
  for (int rule = 1; rule <= 8; ++rule) {
    const std::size_t length = kWindow[rule - 1];
    std::map<int, std::size_t> open;  // tag -> the violation findings of that tag extend
    for (std::size_t i = 0; i + length <= values.size(); ++i) {
      const Finding f = window_finding(rule, values, z, i);
      if (!f.found) continue;
      // A window's first counted value never moves back as i grows, so a
      // finding overlaps the open violation of its tag or none before it.
      const auto it = open.find(f.tag);
      if (it != open.end() && f.first <= out[it->second].last) {
        out[it->second].last = std::max(out[it->second].last, f.last);
      } else {
        open[f.tag] = out.size();
        out.push_back({rule, f.first, f.last});
      }
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const NelsonViolation& a, const NelsonViolation& b) {
    return a.index != b.index ? a.index < b.index : a.rule < b.rule;
  });
  return out;
}

}  // namespace furrow

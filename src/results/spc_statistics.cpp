#include "results/spc_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"
#include "results/spc_nelson_rules.hpp"
#include "results/spc_student_t.hpp"

namespace furrow {
namespace {

void check_series(const CharacteristicSeries& c, std::size_t part_count) {
  const std::string where = "SPC input: characteristic " + quote_field(c.id) + ": ";
  if (c.kind != "point" && c.kind != "region")
    throw InputError(where + "kind " + quote_field(c.kind) + " is neither \"point\" nor \"region\"");
  if (c.part_index.size() != c.values.size())
    throw InputError(where + std::to_string(c.values.size()) + " values for " + std::to_string(c.part_index.size()) +
                     " part indices");
  // Deviations and limits within the coordinate range (docs/formats.md
  // "Limits"), so no sum of squares can overflow.
  auto in_range = [](double v) { return std::isfinite(v) && std::abs(v) <= limits::kMaxCoordinateMm; };
  if (!in_range(c.lower) || !in_range(c.upper) || !(c.lower < c.upper))
    throw InputError(where + "the zone's lower limit must be below its upper limit, both finite within 1e6 mm");
  for (std::size_t i = 0; i < c.values.size(); ++i) {
    if (!in_range(c.values[i]))
      throw InputError(where + "value " + std::to_string(i) + " is not a finite deviation within 1e6 mm");
    if (c.part_index[i] >= part_count)
      throw InputError(where + "part index " + std::to_string(c.part_index[i]) + " beyond the " +
                       std::to_string(part_count) + " parts");
    if (i > 0 && c.part_index[i] <= c.part_index[i - 1])
      throw InputError(where + "part indices must increase (storing order)");
  }
}

// Capability of the zone [lower, upper] for a process centred at `mean`
// with `sigma`: the potential index and the one that sees the centring.
// False when a sigma too small for a double (a spread of a few 1e-310 mm)
// makes an index infinite: then neither is given.
bool capability(double lower, double upper, double mean, double sigma, std::optional<double>& potential,
                std::optional<double>& actual) {
  const double p = (upper - lower) / (6 * sigma);
  const double a = std::min(upper - mean, mean - lower) / (3 * sigma);
  if (!std::isfinite(p) || !std::isfinite(a)) return false;
  potential = p;
  actual = a;
  return true;
}

// Least squares of value on part index, and its interval from the residual
// scatter with n - 2 degrees of freedom (docs/spc.md "Trend").
void trend(CharacteristicSpc& c) {
  const std::size_t n = c.values.size();
  if (n < 2) {
    c.notes.push_back("no slope: fewer than 2 values");
    return;
  }
  double xbar = 0, ybar = 0;
  for (std::size_t i = 0; i < n; ++i) {
    xbar += static_cast<double>(c.part_index[i]);
    ybar += c.values[i];
  }
  xbar /= n;
  ybar /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = static_cast<double>(c.part_index[i]) - xbar;
    sxx += dx * dx;
    sxy += dx * (c.values[i] - ybar);
  }
  SpcSlope slope;
  slope.value = sxy / sxx;  // part indices increase, so sxx > 0
  if (n < 3) {
    c.notes.push_back("no slope interval: fewer than 3 values");
  } else {
    double sse = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = c.values[i] - (ybar + slope.value * (static_cast<double>(c.part_index[i]) - xbar));
      sse += r * r;
    }
    const double dof = static_cast<double>(n - 2);
    const double standard_error = std::sqrt(sse / dof / sxx);
    const StudentQuantileResult t = student_t_quantile(0.5 + kSpcSlopeConfidence / 2, dof);
    if (t.converged) {
      slope.low = slope.value - t.value * standard_error;
      slope.high = slope.value + t.value * standard_error;
    } else {
      c.notes.push_back("no slope interval: the Student t quantile did not converge");
    }
  }
  c.slope = slope;
}

CharacteristicSpc characteristic_spc(const CharacteristicSeries& s, const std::vector<PartRecord>& parts) {
  CharacteristicSpc c;
  c.id = s.id;
  c.kind = s.kind;
  c.lower = s.lower;
  c.upper = s.upper;
  c.part_index = s.part_index;
  c.values = s.values;
  c.n = s.values.size();
  const std::size_t n = c.n;
  if (n == 0) {
    c.notes.push_back("no values: the characteristic was measured in none of the parts");
    return c;
  }
  double sum = 0;
  for (double v : s.values) sum += v;
  const double mean = sum / n;
  c.mean = mean;
  if (n < 2) {
    c.notes.push_back("no sigma, limits, capability or rules: fewer than 2 values");
    trend(c);
    return c;
  }
  double mr = 0, ss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) mr += std::abs(s.values[i] - s.values[i - 1]);
    ss += (s.values[i] - mean) * (s.values[i] - mean);
  }
  mr /= (n - 1);
  c.mr_mean = mr;
  c.mr_ucl = kSpcD4 * mr;
  const double within = mr / kSpcD2;
  const double overall = std::sqrt(ss / (n - 1));
  c.sigma_within = within;
  c.sigma_overall = overall;
  c.lcl = mean - 3 * within;
  c.ucl = mean + 3 * within;
  // Every moving range zero means every value equal: no spread to compare
  // the zone or the rules with.
  if (within > 0) {
    const bool short_term = capability(s.lower, s.upper, mean, within, c.cp, c.cpk);
    const bool long_term = capability(s.lower, s.upper, mean, overall, c.pp, c.ppk);
    if (!short_term || !long_term)
      c.notes.push_back("no capability for a spread this small: an index would be infinite");
    for (const NelsonViolation& v : nelson_violations(s.values, mean, within))
      c.violations.push_back({v.rule, v.index, v.last, parts[s.part_index[v.index]].serial});
  } else {
    c.notes.push_back("no capability or rules: every value is the same (zero sigma)");
  }
  trend(c);
  return c;
}

}  // namespace

SpcResult compute_spc(const SpcInput& input) {
  SpcResult result;
  result.parts = input.parts;
  std::set<std::string> ids;
  for (const CharacteristicSeries& s : input.characteristics) {
    if (!ids.insert(s.id).second) throw InputError("SPC input: characteristic " + quote_field(s.id) + " appears twice");
    check_series(s, input.parts.size());
  }
  for (const CharacteristicSeries& s : input.characteristics)
    result.characteristics.push_back(characteristic_spc(s, input.parts));
  std::sort(result.characteristics.begin(), result.characteristics.end(),
            [](const CharacteristicSpc& a, const CharacteristicSpc& b) { return a.id < b.id; });
  return result;
}

std::vector<std::pair<std::size_t, std::size_t>> latest_part_violations(const SpcResult& result) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  if (result.parts.empty()) return out;
  const std::size_t latest = result.parts.size() - 1;
  for (std::size_t k = 0; k < result.characteristics.size(); ++k) {
    const CharacteristicSpc& c = result.characteristics[k];
    if (c.part_index.empty() || c.part_index.back() != latest) continue;
    for (std::size_t v = 0; v < c.violations.size(); ++v)
      if (c.violations[v].last == c.values.size() - 1) out.emplace_back(k, v);
  }
  return out;
}

bool violation_in_latest_part(const SpcResult& result) { return !latest_part_violations(result).empty(); }

std::vector<std::size_t> worst_first(const SpcResult& result) {
  std::vector<std::size_t> order(result.characteristics.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto& cs = result.characteristics;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const CharacteristicSpc& x = cs[a];
    const CharacteristicSpc& y = cs[b];
    if (x.cpk.has_value() != y.cpk.has_value()) return x.cpk.has_value();
    if (x.cpk && *x.cpk != *y.cpk) return *x.cpk < *y.cpk;
    if (x.violations.size() != y.violations.size()) return x.violations.size() > y.violations.size();
    return x.id < y.id;
  });
  return order;
}

}  // namespace furrow

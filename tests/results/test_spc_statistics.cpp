#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "results/spc_nelson_rules.hpp"
#include "results/spc_statistics.hpp"
#include "results/spc_student_t.hpp"
#include "spc_oracle.hpp"

using namespace furrow;

namespace {

std::vector<spc_oracle::Found> as_found(const std::vector<NelsonViolation>& v) {
  std::vector<spc_oracle::Found> out;
  for (const NelsonViolation& f : v) out.push_back({f.rule, f.index, f.last});
  return out;
}

// One characteristic over parts 0 .. n-1 (serials S0, S1, ...).
SpcInput one_series(const std::vector<double>& values, double lower = -0.1, double upper = 0.1) {
  SpcInput in;
  CharacteristicSeries c;
  c.id = "P1";
  c.kind = "point";
  c.lower = lower;
  c.upper = upper;
  for (std::size_t i = 0; i < values.size(); ++i) {
    in.parts.push_back({"S" + std::to_string(i), "2026-01-01T00:00:00Z", "PASS"});
    c.part_index.push_back(i);
  }
  c.values = values;
  in.characteristics.push_back(c);
  return in;
}

}  // namespace

TEST_CASE("the regularized incomplete beta matches its closed forms") {
  for (double x : {0.0, 0.1, 0.37, 0.5, 0.8, 0.99, 1.0}) {
    CHECK(std::abs(regularized_incomplete_beta(1, 1, x).value - x) < 1e-14);
    CHECK(std::abs(regularized_incomplete_beta(3, 1, x).value - x * x * x) < 1e-14);
    CHECK(std::abs(regularized_incomplete_beta(1, 4, x).value - (1 - std::pow(1 - x, 4))) < 1e-14);
    // I_x(1/2, 1/2) = (2 / pi) asin(sqrt x), the arcsine distribution.
    CHECK(std::abs(regularized_incomplete_beta(0.5, 0.5, x).value - 2 / kPi * std::asin(std::sqrt(x))) < 1e-13);
  }
  CHECK(regularized_incomplete_beta(30, 0.5, 0.9).converged);
}

TEST_CASE("Student t quantiles match the exact forms and the printed table") {
  // One degree of freedom is the Cauchy distribution: tan(pi (p - 1/2)).
  for (double p : {0.6, 0.9, 0.975, 0.995, 0.1}) {
    const StudentQuantileResult q = student_t_quantile(p, 1);
    REQUIRE(q.converged);
    CHECK(std::abs(q.value - std::tan(kPi * (p - 0.5))) < 1e-9 * (1 + std::abs(q.value)));
  }
  // Two degrees of freedom: (2p - 1) / sqrt(2 p (1 - p)).
  for (double p : {0.55, 0.9, 0.975, 0.025}) {
    const StudentQuantileResult q = student_t_quantile(p, 2);
    REQUIRE(q.converged);
    CHECK(std::abs(q.value - (2 * p - 1) / std::sqrt(2 * p * (1 - p))) < 1e-10);
  }
  // Two-sided 95 % values of the usual table, printed to 3 decimals.
  const double table[][2] = {{3, 3.182},  {5, 2.571},   {10, 2.228},  {20, 2.086},
                             {30, 2.042}, {120, 1.980}, {1000, 1.962}, {1e6, 1.960}};
  for (const auto& row : table) {
    const StudentQuantileResult q = student_t_quantile(0.975, row[0]);
    REQUIRE(q.converged);
    CHECK(std::abs(q.value - row[1]) <= 0.0005);
    CHECK(std::abs(student_t_cdf(q.value, row[0]) - 0.975) < 1e-12);
  }
  CHECK(student_t_quantile(0.5, 7).value == 0.0);
}

TEST_CASE("the t quantile and the incomplete beta report a cap reached instead of a guess") {
  const IncompleteBetaResult beta = regularized_incomplete_beta(30, 0.5, 0.9, {1e-15, 2});
  CHECK_FALSE(beta.converged);
  CHECK(beta.iterations == 2);
  const StudentQuantileResult t = student_t_quantile(0.975, 3, {1e-12, 3});
  CHECK_FALSE(t.converged);
  CHECK(t.iterations == 3);
}

TEST_CASE("capability and chart limits match a hand computation") {
  // mean 0.02; moving ranges 0.02 0.01 0.02 0.04 -> mean 0.0225;
  // squares about the mean 1e-4 1e-4 0 4e-4 4e-4 -> s^2 = 1e-3 / 4.
  const SpcResult r = compute_spc(one_series({0.01, 0.03, 0.02, 0.04, 0.00}, -0.1, 0.1));
  REQUIRE(r.characteristics.size() == 1);
  const CharacteristicSpc& c = r.characteristics[0];
  const double sw = 0.0225 / 1.128, so = std::sqrt(0.00025);
  CHECK(c.n == 5);
  CHECK(std::abs(*c.mean - 0.02) < 1e-15);
  CHECK(std::abs(*c.mr_mean - 0.0225) < 1e-15);
  CHECK(std::abs(*c.mr_ucl - 3.267 * 0.0225) < 1e-15);
  CHECK(std::abs(*c.sigma_within - sw) < 1e-15);
  CHECK(std::abs(*c.sigma_overall - so) < 1e-15);
  CHECK(std::abs(*c.lcl - (0.02 - 3 * sw)) < 1e-15);
  CHECK(std::abs(*c.ucl - (0.02 + 3 * sw)) < 1e-15);
  CHECK(std::abs(*c.cp - 0.2 / (6 * sw)) < 1e-12);
  CHECK(std::abs(*c.cpk - 0.08 / (3 * sw)) < 1e-12);  // nearer the upper limit: 0.1 - 0.02
  CHECK(std::abs(*c.pp - 0.2 / (6 * so)) < 1e-12);
  CHECK(std::abs(*c.ppk - 0.08 / (3 * so)) < 1e-12);
  CHECK(std::abs(*c.cp - 1.6711111) < 1e-6);  // the same by calculator
  CHECK(c.notes.empty());
}

TEST_CASE("a series too short or without variation has no capability and says why") {
  const SpcResult none = compute_spc(one_series({}));
  CHECK_FALSE(none.characteristics[0].mean.has_value());
  CHECK_FALSE(none.characteristics[0].slope.has_value());
  CHECK(none.characteristics[0].notes.size() == 1);

  const SpcResult one = compute_spc(one_series({0.01}));
  const CharacteristicSpc& c1 = one.characteristics[0];
  CHECK(*c1.mean == 0.01);
  CHECK_FALSE(c1.sigma_within.has_value());
  CHECK_FALSE(c1.cpk.has_value());
  CHECK_FALSE(c1.slope.has_value());
  CHECK(c1.notes.size() == 2);

  const SpcResult flat = compute_spc(one_series({0.02, 0.02, 0.02, 0.02}));
  const CharacteristicSpc& cf = flat.characteristics[0];
  CHECK(*cf.sigma_within == 0.0);
  CHECK(*cf.sigma_overall == 0.0);
  CHECK_FALSE(cf.cp.has_value());
  CHECK_FALSE(cf.cpk.has_value());
  CHECK_FALSE(cf.pp.has_value());
  CHECK_FALSE(cf.ppk.has_value());
  CHECK(cf.violations.empty());
  REQUIRE(cf.slope.has_value());
  CHECK(cf.slope->value == 0.0);
  CHECK(*cf.slope->low == 0.0);  // no scatter about the line: an interval of width 0
  CHECK(cf.notes.size() == 1);
  CHECK(cf.notes[0].find("zero sigma") != std::string::npos);

  // A spread of one subnormal step: the sigmas exist, an index would be infinite.
  const SpcResult tiny = compute_spc(one_series({0.0, 5e-324, 0.0}));
  CHECK(*tiny.characteristics[0].sigma_within > 0);
  CHECK_FALSE(tiny.characteristics[0].cpk.has_value());
  CHECK_FALSE(tiny.characteristics[0].ppk.has_value());
  REQUIRE(tiny.characteristics[0].notes.size() == 1);
  CHECK(tiny.characteristics[0].notes[0].find("infinite") != std::string::npos);

  const SpcResult two = compute_spc(one_series({0.01, 0.03}));
  REQUIRE(two.characteristics[0].slope.has_value());
  CHECK(std::abs(two.characteristics[0].slope->value - 0.02) < 1e-15);
  CHECK_FALSE(two.characteristics[0].slope->low.has_value());
}

TEST_CASE("the slope and its interval match the closed form") {
  // y = 1 + 0.5 i + e with e = (1, -1, -1, 1), orthogonal to 1 and to i:
  // slope 0.5 exactly, SSE 4, Sxx 5, 2 dof, t = 0.95 / sqrt(2 0.975 0.025).
  SpcInput in = one_series({2.0, 0.5, 1.0, 3.5}, -10, 10);
  const CharacteristicSpc c = compute_spc(in).characteristics[0];
  REQUIRE(c.slope.has_value());
  const double half = 0.95 / std::sqrt(2 * 0.975 * 0.025) * std::sqrt(4.0 / 2 / 5);
  CHECK(std::abs(c.slope->value - 0.5) < 1e-14);
  CHECK(std::abs(*c.slope->low - (0.5 - half)) < 1e-9);
  CHECK(std::abs(*c.slope->high - (0.5 + half)) < 1e-9);
  // The slope is per part of the whole selection: a part in between without
  // this characteristic counts (indices 0 2 4 6 halve the slope).
  for (std::size_t i = 0; i < 4; ++i) in.characteristics[0].part_index[i] = 2 * i;
  in.parts.resize(7, {"X", "2026-01-01T00:00:00Z", "PASS"});
  CHECK(std::abs(compute_spc(in).characteristics[0].slope->value - 0.25) < 1e-14);
}

TEST_CASE("each Nelson rule is triggered once where a designed pattern starts") {
  // A background that breaks every rule (runs of at most 4 within 1 sigma,
  // 2 on a side, 3 alternating steps), centre 0 and sigma 1; each pattern
  // overwrites it at a known position.
  const std::vector<double> cycle = {0.5, 0.5, -0.5, -0.5, 1.5, -1.5};
  std::vector<double> background;
  for (int k = 0; k < 8; ++k) background.insert(background.end(), cycle.begin(), cycle.end());
  CHECK(nelson_violations(background, 0, 1).empty());
  CHECK(spc_oracle::nelson(background, 0, 1).empty());
  struct Design {
    int rule;
    std::size_t at;
    std::vector<double> pattern;
  };
  std::vector<double> within15;
  for (int k = 0; k < 15; ++k) within15.push_back(k % 4 < 2 ? 0.5 : -0.5);
  const std::vector<Design> designs = {
      {1, 9, {3.5}},
      {2, 9, {0.5, 1.5, 0.5, 0.5, 1.5, 0.5, 0.5, 1.5, 0.5}},
      {3, 9, {-1.2, -0.6, -0.1, 0.4, 0.9, 1.4}},
      {4, 8, {0.5, -0.5, 1.5, -0.5, 0.5, -1.5, 0.5, -0.5, 1.5, -0.5, 0.5, -1.5, 0.5, -0.5}},
      {5, 9, {2.5, 0.5, 2.2}},
      {6, 9, {1.5, 1.5, 0.5, 1.5, 1.5}},
      {7, 12, within15},
      {8, 9, {1.5, 1.5, -1.5, -1.5, 1.5, 1.5, -1.5, -1.5}},
  };
  for (const Design& d : designs) {
    CAPTURE(d.rule);
    std::vector<double> x = background;
    std::copy(d.pattern.begin(), d.pattern.end(), x.begin() + d.at);
    const std::vector<NelsonViolation> found = nelson_violations(x, 0, 1);
    REQUIRE(found.size() == 1);
    CHECK(found[0].rule == d.rule);
    CHECK(found[0].index == d.at);
    CHECK(as_found(found) == spc_oracle::nelson(x, 0, 1));
  }
}

TEST_CASE("a continuing run is one violation at its first value") {
  // Twelve values above the centre, then the background: one rule-2
  // violation from 0 to 11, not four overlapping ones.
  std::vector<double> x(12, 0.5);
  for (int k = 0; k < 4; ++k) x.insert(x.end(), {-0.5, -0.5, 1.5, -1.5, 0.5, 0.5});
  x[3] = 0.6;  // breaks rule 7's run of 15 within 1 sigma
  x[6] = 1.4;
  const std::vector<NelsonViolation> found = nelson_violations(x, 0, 1);
  CHECK(as_found(found) == spc_oracle::nelson(x, 0, 1));
  REQUIRE(found.size() == 1);
  CHECK(found[0].rule == 2);
  CHECK(found[0].index == 0);
  CHECK(found[0].last == 11);
  // Nine above then nine below: two violations, one per side.
  std::vector<double> y;
  for (int k = 0; k < 18; ++k) y.push_back((k < 9 ? 1 : -1) * (k % 3 == 0 ? 1.5 : 0.5));
  const std::vector<NelsonViolation> two = nelson_violations(y, 0, 1);
  CHECK(as_found(two) == spc_oracle::nelson(y, 0, 1));
  std::size_t rule2 = 0;
  for (const NelsonViolation& v : two) rule2 += v.rule == 2;
  CHECK(rule2 == 2);
}

TEST_CASE("the Nelson rules agree with the brute-force oracle on random series") {
  // Noise, shifts, drifts and rounded values (ties break runs): every
  // violation, its start and its end, as the definitions give them.
  for (std::uint32_t seed = 1; seed <= 300; ++seed) {
    CAPTURE(seed);
    std::vector<double> x = spc_oracle::normal_sample(seed, 80, 0, 1);
    std::mt19937 rng(seed * 7919u);
    const int kind = seed % 4;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (kind == 1 && i >= 40) x[i] += 1.5;                        // a shift
      if (kind == 2) x[i] += 0.04 * static_cast<double>(i);         // a drift
      if (kind == 3) x[i] = std::round(x[i] * 2) / 2;               // coarse values, many ties
    }
    if (rng() % 2) x[rng() % x.size()] += 5;  // an outlier somewhere
    const auto [centre, sigma] = spc_oracle::centre_and_sigma(x);
    CHECK(as_found(nelson_violations(x, centre, sigma)) == spc_oracle::nelson(x, centre, sigma));
  }
}

TEST_CASE("an in-control seeded sample raises no violation") {
  const std::vector<double> x = spc_oracle::normal_sample(2029, 60, 0.01, 0.003);
  const auto [centre, sigma] = spc_oracle::centre_and_sigma(x);
  REQUIRE(spc_oracle::nelson(x, centre, sigma).empty());  // the sample is in control by the definitions
  const SpcResult r = compute_spc(one_series(x));
  CHECK(r.characteristics[0].violations.empty());
  CHECK(std::abs(*r.characteristics[0].mean - centre) < 1e-15);
  CHECK(std::abs(*r.characteristics[0].sigma_within - sigma) < 1e-15);
  CHECK_FALSE(violation_in_latest_part(r));
}

TEST_CASE("a drifting series is flagged where the oracle finds the drift") {
  // 25 parts, +2.5 um per part at one spot, 2 um noise.
  std::vector<double> x = spc_oracle::normal_sample(42, 25, 0, 0.002);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.0025 * static_cast<double>(i);
  const auto [centre, sigma] = spc_oracle::centre_and_sigma(x);
  const std::vector<spc_oracle::Found> expected = spc_oracle::nelson(x, centre, sigma);
  std::size_t first = x.size();
  for (const auto& f : expected)
    if ((f.rule == 1 || f.rule == 3) && first == x.size()) first = f.first;
  REQUIRE(first < x.size());  // the definitions see the drift
  const SpcResult r = compute_spc(one_series(x));
  const CharacteristicSpc& c = r.characteristics[0];
  std::size_t got = x.size();
  for (const SpcViolation& v : c.violations)
    if ((v.rule == 1 || v.rule == 3) && got == x.size()) got = v.index;
  CHECK(got == first);
  CHECK(c.violations.size() == expected.size());
  CHECK(c.violations[0].serial == "S" + std::to_string(c.violations[0].index));
  // The trend: the interval holds the true slope and not zero.
  REQUIRE(c.slope.has_value());
  CHECK(*c.slope->low < 0.0025);
  CHECK(*c.slope->high > 0.0025);
  CHECK(*c.slope->low > 0);
}

TEST_CASE("a violation counts for the latest part only when it reaches it") {
  std::vector<double> x = spc_oracle::normal_sample(2029, 60, 0.01, 0.003);
  x.push_back(0.05);  // far beyond 3 sigma, in the latest part
  const auto [centre, sigma] = spc_oracle::centre_and_sigma(x);
  REQUIRE(spc_oracle::nelson(x, centre, sigma) == std::vector<spc_oracle::Found>{{1, 60, 60}});
  SpcInput in = one_series(x);
  CHECK(violation_in_latest_part(compute_spc(in)));
  // The same outlier, then one more part that this characteristic did not
  // measure: the latest part has no value of it.
  in.parts.push_back({"S61", "2026-01-02T00:00:00Z", "PASS"});
  CHECK_FALSE(violation_in_latest_part(compute_spc(in)));
  // The outlier earlier, the latest value ordinary.
  std::vector<double> y = spc_oracle::normal_sample(2029, 60, 0.01, 0.003);
  y.insert(y.begin() + 30, 0.05);
  const auto [cy, sy] = spc_oracle::centre_and_sigma(y);
  REQUIRE(spc_oracle::nelson(y, cy, sy) == std::vector<spc_oracle::Found>{{1, 30, 30}});
  CHECK_FALSE(violation_in_latest_part(compute_spc(one_series(y))));
}

TEST_CASE("a series that breaks the contract is refused naming the characteristic") {
  SpcInput in = one_series({0.01, 0.02, 0.03});
  in.characteristics[0].part_index = {0, 2, 1};
  CHECK_THROWS_WITH_AS(compute_spc(in), doctest::Contains("characteristic \"P1\""), InputError);
  in = one_series({0.01, 0.02, 0.03}, 0.1, -0.1);
  CHECK_THROWS_AS(compute_spc(in), InputError);
  in = one_series({0.01, NAN, 0.03});
  CHECK_THROWS_AS(compute_spc(in), InputError);
  in = one_series({0.01, 2e6});
  CHECK_THROWS_WITH_AS(compute_spc(in), doctest::Contains("1e6 mm"), InputError);
  in = one_series({0.01, 0.02});
  in.characteristics[0].part_index[1] = 5;
  CHECK_THROWS_AS(compute_spc(in), InputError);
  in = one_series({0.01, 0.02});
  in.characteristics.push_back(in.characteristics[0]);
  CHECK_THROWS_WITH_AS(compute_spc(in), doctest::Contains("twice"), InputError);
  in = one_series({0.01, 0.02});
  in.characteristics[0].kind = "surface";
  CHECK_THROWS_WITH_AS(compute_spc(in), doctest::Contains("\"surface\""), InputError);
}

TEST_CASE("characteristics are sorted by id and ranked worst first by cpk then violations") {
  SpcInput in = one_series({0.01, 0.03, 0.02, 0.04, 0.00});
  CharacteristicSeries wide = in.characteristics[0];
  wide.id = "A";
  wide.lower = -1;
  wide.upper = 1;
  CharacteristicSeries flat = in.characteristics[0];
  flat.id = "B";
  flat.values = {0, 0, 0, 0, 0};
  in.characteristics.push_back(wide);
  in.characteristics.push_back(flat);
  const SpcResult r = compute_spc(in);
  REQUIRE(r.characteristics.size() == 3);
  CHECK(r.characteristics[0].id == "A");
  CHECK(r.characteristics[1].id == "B");
  CHECK(r.characteristics[2].id == "P1");
  // P1 (zone 0.2 wide) before A (zone 2 wide); B has no cpk: last.
  CHECK(worst_first(r) == std::vector<std::size_t>{2, 0, 1});
}

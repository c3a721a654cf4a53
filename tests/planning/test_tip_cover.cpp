// The tip cover (planning/tip_cover.hpp) against oracles written here:
// exhaustive search over every subset of the sets on small random
// instances (the cheapest cover in the documented order: fewest fresh
// sets, then fewest sets); on a larger instance with a planted optimum
// (k disjoint sets, each with an element no other set holds, so no cover
// has fewer than k sets and those k are one), the greedy result within
// H(n) times it; and the textbook instance where greedy is not optimal,
// which the exact search must fix.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "planning/tip_cover.hpp"

using namespace furrow;

namespace {

// An instance given by its true cover relation `covers[s]` and the
// `maybe` lists (a superset: the extra pairs test false); counts the tests
// of every pair.
struct Instance {
  int elements = 0;
  std::vector<TipKind> kinds;
  std::vector<std::set<int>> covers;
  std::vector<std::vector<int>> maybe;
  std::map<std::pair<int, int>, int> tested;

  TipCoverProblem problem() {
    TipCoverProblem p;
    p.elements = elements;
    p.kinds = kinds;
    p.maybe = maybe;
    p.test = [this](int s, const std::vector<int>& list) {
      std::vector<char> out;
      for (int e : list) {
        ++tested[{s, e}];
        out.push_back(covers[static_cast<std::size_t>(s)].count(e) ? 1 : 0);
      }
      return out;
    };
    return p;
  }
};

Instance random_instance(std::mt19937& rng, int sets, int elements) {
  Instance in;
  in.elements = elements;
  std::uniform_int_distribution<int> kind(0, 2), coin(0, 99);
  for (int s = 0; s < sets; ++s) {
    in.kinds.push_back(s == 0 ? TipKind::forced : kind(rng) == 0 ? TipKind::qualified : TipKind::fresh);
    std::set<int> c;
    std::vector<int> m;
    for (int e = 0; e < elements; ++e) {
      const int r = coin(rng);
      if (r < (s == 0 ? 15 : 25)) c.insert(e);
      if (r < 40) m.push_back(e);  // within "tilt": covered, or blocked
    }
    in.covers.push_back(c);
    in.maybe.push_back(m);
  }
  return in;
}

struct Cost {
  int fresh = 0, total = 0;
  bool operator<(const Cost& o) const { return fresh != o.fresh ? fresh < o.fresh : total < o.total; }
  bool operator==(const Cost& o) const { return fresh == o.fresh && total == o.total; }
};

// Exhaustive oracle: the cheapest subset (forced sets always in) covering
// every element some set covers.
Cost exhaustive(const Instance& in) {
  const int sets = static_cast<int>(in.kinds.size());
  std::set<int> coverable, forced_cover;
  for (int s = 0; s < sets; ++s)
    for (int e : in.covers[static_cast<std::size_t>(s)]) coverable.insert(e);
  Cost best{1 << 20, 1 << 20};
  for (std::uint32_t mask = 0; mask < (1u << sets); ++mask) {
    bool ok = true;
    std::set<int> got;
    Cost c;
    for (int s = 0; s < sets; ++s) {
      const bool in_mask = (mask >> s) & 1u;
      if (in.kinds[static_cast<std::size_t>(s)] == TipKind::forced && !in_mask) ok = false;
      if (!in_mask) continue;
      got.insert(in.covers[static_cast<std::size_t>(s)].begin(), in.covers[static_cast<std::size_t>(s)].end());
      c.total += 1;
      c.fresh += in.kinds[static_cast<std::size_t>(s)] == TipKind::fresh;
    }
    if (ok && got == coverable && c < best) best = c;
  }
  return best;
}

Cost cost_of(const Instance& in, const TipCover& cover) {
  Cost c;
  for (int s : cover.chosen) {
    c.total += 1;
    c.fresh += in.kinds[static_cast<std::size_t>(s)] == TipKind::fresh;
  }
  return c;
}

// Every coverable element covered by a chosen set, the rest reported.
void check_is_cover(const Instance& in, const TipCover& cover) {
  std::set<int> coverable, got;
  for (const std::set<int>& c : in.covers) coverable.insert(c.begin(), c.end());
  for (int s : cover.chosen) got.insert(in.covers[static_cast<std::size_t>(s)].begin(), in.covers[static_cast<std::size_t>(s)].end());
  CHECK(got == coverable);
  std::vector<int> missing;
  for (int e = 0; e < in.elements; ++e)
    if (!coverable.count(e)) missing.push_back(e);
  CHECK(cover.uncoverable == missing);
  for (std::size_t s = 0; s < in.kinds.size(); ++s)
    if (in.kinds[s] == TipKind::forced)
      CHECK(std::find(cover.chosen.begin(), cover.chosen.end(), static_cast<int>(s)) != cover.chosen.end());
}

}  // namespace

TEST_CASE("tip cover: the exact search finds the exhaustive optimum on small random instances") {
  std::mt19937 rng(20261129);
  int greedy_worse = 0;
  for (int round = 0; round < 60; ++round) {
    const int sets = 4 + round % 9;        // up to 12 sets: 4096 subsets for the oracle
    const int elements = 6 + round % 11;
    Instance in = random_instance(rng, sets, elements);
    // The covered pairs must be among the maybe pairs: keep only those.
    for (std::size_t s = 0; s < in.covers.size(); ++s) {
      std::set<int> kept;
      for (int e : in.covers[s])
        if (std::binary_search(in.maybe[s].begin(), in.maybe[s].end(), e)) kept.insert(e);
      in.covers[s] = kept;
    }
    const Cost oracle = exhaustive(in);
    TipCoverProblem p = in.problem();
    const TipCover exact = solve_tip_cover(p);
    CAPTURE(round);
    CHECK(exact.exact);
    CHECK(exact.optimal);
    check_is_cover(in, exact);
    CHECK(cost_of(in, exact) == oracle);
    for (const auto& [pair, count] : in.tested) CHECK(count == 1);  // each pair tested once

    // The greedy alone: a cover, never better than the optimum, and its
    // fresh count within its reported bound of it.
    Instance again = in;
    again.tested.clear();
    TipCoverOptions greedy_only;
    greedy_only.exact_max_pairs = -1;
    TipCoverProblem q = again.problem();
    const TipCover greedy = solve_tip_cover(q, greedy_only);
    CHECK(!greedy.exact);
    CHECK(!greedy.optimal);
    check_is_cover(again, greedy);
    const Cost g = cost_of(again, greedy);
    CHECK(!(g < oracle));
    CHECK(g.fresh <= greedy.bound * oracle.fresh + 1e-9);
    greedy_worse += oracle < g;
    for (const auto& [pair, count] : again.tested) CHECK(count == 1);
  }
  MESSAGE("greedy was worse than the optimum on " << greedy_worse << " of 60 instances");
}

TEST_CASE("tip cover: greedy on a larger instance stays within H(n) of a planted optimum") {
  // 400 elements in k = 7 disjoint fresh sets of a partition, each holding
  // one element no other set has (so every cover takes all k: the optimum
  // is k), plus 80 random fresh sets over the rest and a forced set
  // covering nothing.
  std::mt19937 rng(7);
  const int k = 7, elements = 400;
  Instance in;
  in.elements = elements;
  in.kinds.push_back(TipKind::forced);
  in.covers.push_back({});
  in.maybe.push_back({});
  std::vector<int> order(elements);
  for (int e = 0; e < elements; ++e) order[static_cast<std::size_t>(e)] = e;
  std::shuffle(order.begin(), order.end(), rng);
  std::set<int> privates;
  for (int j = 0; j < k; ++j) {
    std::set<int> part;
    for (int e = j; e < elements; e += k) part.insert(order[static_cast<std::size_t>(e)]);
    privates.insert(order[static_cast<std::size_t>(j)]);
    in.kinds.push_back(TipKind::fresh);
    in.covers.push_back(part);
  }
  std::uniform_int_distribution<int> coin(0, 99);
  for (int s = 0; s < 80; ++s) {
    std::set<int> c;
    const int density = 5 + (s % 6) * 6;  // 5 to 35 % of the elements
    for (int e = 0; e < elements; ++e)
      if (!privates.count(e) && coin(rng) < density) c.insert(e);
    in.kinds.push_back(TipKind::fresh);
    in.covers.push_back(c);
  }
  for (std::size_t s = 1; s < in.covers.size(); ++s) in.maybe.push_back(std::vector<int>(in.covers[s].begin(), in.covers[s].end()));
  TipCoverProblem p = in.problem();
  TipCoverOptions o;
  o.exact_max_pairs = 1000;  // beyond the exact search's size limit: greedy
  const TipCover greedy = solve_tip_cover(p, o);
  long pairs = 0;
  for (const auto& m : in.maybe) pairs += static_cast<long>(m.size());
  REQUIRE(pairs > o.exact_max_pairs);
  CHECK(!greedy.exact);
  check_is_cover(in, greedy);
  CHECK(greedy.fresh >= k);
  double h = 0;
  for (int j = 1; j <= greedy.bound_n; ++j) h += 1.0 / j;
  CHECK(std::abs(greedy.bound - h) < 1e-12);
  CHECK(greedy.bound_n <= elements);
  CHECK(greedy.fresh <= greedy.bound * k + 1e-9);
  MESSAGE("planted optimum " << k << ", greedy " << greedy.fresh << " (bound H(" << greedy.bound_n
                             << ") = " << greedy.bound << "), " << greedy.tests << " of " << pairs << " pairs tested");
}

TEST_CASE("tip cover: the textbook instance where greedy takes 3 sets and the exact search 2") {
  // 14 elements in two rows of 7 (fresh sets); fresh columns of 2, 4 and 8
  // elements, half in each row. Greedy takes the columns (8 >
  // 7, then 4 > 3, then 2 > 1), the optimum is the two rows.
  Instance in;
  in.elements = 14;
  in.kinds = {TipKind::forced, TipKind::fresh, TipKind::fresh, TipKind::fresh, TipKind::fresh, TipKind::fresh};
  std::set<int> top, bottom, c1, c2, c3;
  for (int e = 0; e < 7; ++e) top.insert(e), bottom.insert(7 + e);
  c1 = {0, 7};
  c2 = {1, 2, 8, 9};
  c3 = {3, 4, 5, 6, 10, 11, 12, 13};
  in.covers = {{}, top, bottom, c1, c2, c3};
  for (const std::set<int>& c : in.covers) in.maybe.emplace_back(c.begin(), c.end());
  TipCoverOptions greedy_only;
  greedy_only.exact_max_pairs = -1;
  TipCoverProblem p = in.problem();
  const TipCover greedy = solve_tip_cover(p, greedy_only);
  CHECK(greedy.fresh == 3);
  CHECK(greedy.bound_n == 8);
  CHECK(greedy.fresh <= greedy.bound * 2);
  Instance again = in;
  TipCoverProblem q = again.problem();
  const TipCover exact = solve_tip_cover(q);
  CHECK(exact.optimal);
  CHECK(exact.fresh == 2);
  CHECK(exact.chosen == std::vector<int>{0, 1, 2});
}

TEST_CASE("tip cover: a qualified set is taken first and dropped when a fresh one that is needed anyway covers it") {
  // Set 1 (qualified) covers {0,1}, set 2 (fresh) {0,1,2,3}, set 3 (fresh)
  // {2,3}, set 4 (qualified) {0}. Elements 2 and 3 need one fresh set;
  // set 2 alone then covers everything: the optimum is {0, 2} (one fresh,
  // two in all), {0, 1, 3} being as fresh but one set more.
  Instance in;
  in.elements = 4;
  in.kinds = {TipKind::forced, TipKind::qualified, TipKind::fresh, TipKind::fresh, TipKind::qualified};
  in.covers = {{}, {0, 1}, {0, 1, 2, 3}, {2, 3}, {0}};
  for (const std::set<int>& c : in.covers) in.maybe.emplace_back(c.begin(), c.end());
  for (long pairs_limit : {20000L, -1L}) {
    Instance again = in;
    TipCoverOptions o;
    o.exact_max_pairs = pairs_limit;
    TipCoverProblem p = again.problem();
    const TipCover c = solve_tip_cover(p, o);
    CAPTURE(pairs_limit);
    CHECK(c.fresh == 1);
    CHECK(c.chosen == std::vector<int>{0, 2});
  }
}

namespace {

// The plain greedy of tip_cover.hpp written out with every pair known:
// forced sets; qualified sets by most newly covered elements while one adds
// any; fresh sets likewise (ties to the lower index); then every chosen
// non-forced set whose elements the others cover removed, last chosen first.
std::vector<int> plain_greedy(const Instance& in) {
  const int sets = static_cast<int>(in.kinds.size());
  std::vector<char> covered(static_cast<std::size_t>(in.elements), 0);
  std::vector<int> chosen;
  auto gain = [&](int s) {
    int g = 0;
    for (int e : in.covers[static_cast<std::size_t>(s)]) g += !covered[static_cast<std::size_t>(e)];
    return g;
  };
  auto take = [&](int s) {
    for (int e : in.covers[static_cast<std::size_t>(s)]) covered[static_cast<std::size_t>(e)] = 1;
    chosen.push_back(s);
  };
  for (int s = 0; s < sets; ++s)
    if (in.kinds[static_cast<std::size_t>(s)] == TipKind::forced) take(s);
  for (TipKind kind : {TipKind::qualified, TipKind::fresh})
    for (;;) {
      int best = -1, best_gain = 0;
      for (int s = 0; s < sets; ++s) {
        if (in.kinds[static_cast<std::size_t>(s)] != kind) continue;
        if (std::find(chosen.begin(), chosen.end(), s) != chosen.end()) continue;
        if (gain(s) > best_gain) best = s, best_gain = gain(s);
      }
      if (best < 0) break;
      take(best);
    }
  for (std::size_t k = chosen.size(); k-- > 0;) {
    if (in.kinds[static_cast<std::size_t>(chosen[k])] == TipKind::forced) continue;
    std::set<int> others;
    for (std::size_t j = 0; j < chosen.size(); ++j)
      if (j != k) others.insert(in.covers[static_cast<std::size_t>(chosen[j])].begin(), in.covers[static_cast<std::size_t>(chosen[j])].end());
    bool needed = false;
    for (int e : in.covers[static_cast<std::size_t>(chosen[k])]) needed = needed || !others.count(e);
    if (!needed) chosen.erase(chosen.begin() + static_cast<long>(k));
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

}  // namespace

TEST_CASE("tip cover: the greedy with early stops and a test order chooses what the plain greedy chooses") {
  // The greedy tests a candidate set a batch at a time and stops once its
  // bound falls below the next candidate's; neither the batch size nor the
  // order the pairs are tested in may change the cover. Oracle: the plain
  // greedy above, over the full relation. Also: every pair the solver
  // tested holds the true answer.
  std::mt19937 rng(11);
  long fewer = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Instance in = random_instance(rng, 30 + trial % 7, 60 + 5 * (trial % 5));
    const std::vector<int> oracle = plain_greedy(in);
    for (long batch : {1L, 4L, 32L, 1000L}) {
      for (int ordered = 0; ordered < 2; ++ordered) {
        Instance again = in;
        TipCoverProblem p = again.problem();
        if (ordered) {
          for (const std::vector<int>& m : p.maybe) {
            std::vector<int> order(m.size());
            for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
            std::shuffle(order.begin(), order.end(), rng);
            p.test_order.push_back(order);
          }
        }
        TipCoverOptions o;
        o.exact_max_pairs = -1;
        o.test_batch = batch;
        const TipCover c = solve_tip_cover(p, o);
        CAPTURE(trial);
        CAPTURE(batch);
        CAPTURE(ordered);
        CHECK(c.chosen == oracle);
        check_is_cover(in, c);
        for (std::size_t s = 0; s < p.maybe.size(); ++s)
          for (std::size_t i = 0; i < p.maybe[s].size(); ++i)
            if (c.known[s][i] >= 0) CHECK((c.known[s][i] == 1) == (in.covers[s].count(p.maybe[s][i]) == 1));
        long pairs = 0;
        for (const auto& m : p.maybe) pairs += static_cast<long>(m.size());
        CHECK(c.tests <= pairs);
        fewer += c.tests < pairs;
      }
    }
  }
  CHECK(fewer > 0);  // the early stop does skip pairs
}

TEST_CASE("tip cover: a test order that is not a permutation is refused") {
  Instance in;
  in.elements = 2;
  in.kinds = {TipKind::forced, TipKind::fresh};
  in.covers = {{0}, {1}};
  in.maybe = {{0}, {0, 1}};
  TipCoverProblem p = in.problem();
  p.test_order = {{0}, {1, 1}};
  CHECK_THROWS_AS(solve_tip_cover(p), std::invalid_argument);
}

#include "planning/tip_cover.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <queue>
#include <stdexcept>

namespace furrow {

double harmonic(int n) {
  double h = 0;
  for (int k = n; k >= 1; --k) h += 1.0 / k;  // smallest terms first
  return h;
}

namespace {

// What is known of the pairs, and the elements covered so far.
class CoverState {
 public:
  explicit CoverState(const TipCoverProblem& p) : p_(p), covered_(static_cast<std::size_t>(p.elements), 0) {
    known_.resize(p.maybe.size());
    for (std::size_t s = 0; s < p.maybe.size(); ++s) known_[s].assign(p.maybe[s].size(), -1);
  }

  // Tests the untested pairs of set s (only among uncovered elements when
  // `uncovered_only`).
  void test(int s, bool uncovered_only) {
    const std::vector<int>& list = p_.maybe[static_cast<std::size_t>(s)];
    std::vector<signed char>& k = known_[static_cast<std::size_t>(s)];
    std::vector<int> batch, at;
    for (std::size_t i = 0; i < list.size(); ++i)
      if (k[i] < 0 && !(uncovered_only && covered_[static_cast<std::size_t>(list[i])])) {
        batch.push_back(list[i]);
        at.push_back(static_cast<int>(i));
      }
    if (batch.empty()) return;
    const std::vector<char> got = p_.test(s, batch);
    if (got.size() != batch.size()) throw std::logic_error("tip cover: test gave the wrong number of answers");
    for (std::size_t i = 0; i < batch.size(); ++i) k[static_cast<std::size_t>(at[i])] = got[i] ? 1 : 0;
    tests_ += static_cast<long>(batch.size());
  }

  // Tests the untested pairs of s among uncovered elements a batch at a
  // time, in problem.test_order's order, while `go_on(bound)` holds for the
  // gain bound (gain(s) below) after each batch. True when none is left
  // untested. The bound only shrinks, so stopping early never hides a set
  // that would have ranked first.
  template <class GoOn>
  bool test_while(int s, long batch_size, GoOn go_on) {
    const std::vector<int>& list = p_.maybe[static_cast<std::size_t>(s)];
    const std::vector<int>* order =
        p_.test_order.empty() ? nullptr : &p_.test_order[static_cast<std::size_t>(s)];
    std::vector<signed char>& k = known_[static_cast<std::size_t>(s)];
    std::vector<int> at;
    for (std::size_t j = 0; j < list.size(); ++j) {
      const std::size_t i = order ? static_cast<std::size_t>((*order)[j]) : j;
      if (k[i] < 0 && !covered_[static_cast<std::size_t>(list[i])]) at.push_back(static_cast<int>(i));
    }
    int bound = gain(s);
    for (std::size_t from = 0; from < at.size();) {
      if (!go_on(bound)) return false;
      const std::size_t to = std::min(at.size(), from + static_cast<std::size_t>(std::max(1L, batch_size)));
      std::vector<int> batch;
      for (std::size_t j = from; j < to; ++j) batch.push_back(list[static_cast<std::size_t>(at[j])]);
      const std::vector<char> got = p_.test(s, batch);
      if (got.size() != batch.size()) throw std::logic_error("tip cover: test gave the wrong number of answers");
      for (std::size_t j = 0; j < batch.size(); ++j) {
        k[static_cast<std::size_t>(at[from + j])] = got[j] ? 1 : 0;
        bound -= got[j] ? 0 : 1;
      }
      tests_ += static_cast<long>(batch.size());
      from = to;
    }
    return true;
  }

  // Uncovered elements s covers, counting untested pairs as covered (an
  // upper bound; exact once test(s, true) ran since the last cover).
  int gain(int s) const {
    const std::vector<int>& list = p_.maybe[static_cast<std::size_t>(s)];
    const std::vector<signed char>& k = known_[static_cast<std::size_t>(s)];
    int g = 0;
    for (std::size_t i = 0; i < list.size(); ++i) g += k[i] != 0 && !covered_[static_cast<std::size_t>(list[i])];
    return g;
  }

  // Marks what s covers (tested pairs only).
  void take(int s) {
    const std::vector<int>& list = p_.maybe[static_cast<std::size_t>(s)];
    const std::vector<signed char>& k = known_[static_cast<std::size_t>(s)];
    for (std::size_t i = 0; i < list.size(); ++i)
      if (k[i] == 1) covered_[static_cast<std::size_t>(list[i])] = 1;
  }

  bool covered(int e) const { return covered_[static_cast<std::size_t>(e)] != 0; }
  const std::vector<std::vector<signed char>>& known() const { return known_; }
  std::vector<std::vector<signed char>>& known() { return known_; }
  long tests() const { return tests_; }

 private:
  const TipCoverProblem& p_;
  std::vector<char> covered_;
  std::vector<std::vector<signed char>> known_;
  long tests_ = 0;
};

// Removes chosen non-forced sets whose covered elements the others cover,
// the last chosen first. Every chosen set is tested in full first.
void remove_redundant(const TipCoverProblem& p, CoverState& state, std::vector<int>& chosen) {
  std::vector<int> count(static_cast<std::size_t>(p.elements), 0);
  for (int s : chosen) {
    state.test(s, false);
    const std::vector<int>& list = p.maybe[static_cast<std::size_t>(s)];
    for (std::size_t i = 0; i < list.size(); ++i)
      count[static_cast<std::size_t>(list[i])] += state.known()[static_cast<std::size_t>(s)][i] == 1;
  }
  for (std::size_t k = chosen.size(); k-- > 0;) {
    const int s = chosen[k];
    if (p.kinds[static_cast<std::size_t>(s)] == TipKind::forced) continue;
    const std::vector<int>& list = p.maybe[static_cast<std::size_t>(s)];
    const std::vector<signed char>& known = state.known()[static_cast<std::size_t>(s)];
    bool needed = false;
    for (std::size_t i = 0; i < list.size() && !needed; ++i)
      needed = known[i] == 1 && count[static_cast<std::size_t>(list[i])] == 1;
    if (needed) continue;
    for (std::size_t i = 0; i < list.size(); ++i) count[static_cast<std::size_t>(list[i])] -= known[i] == 1;
    chosen.erase(chosen.begin() + static_cast<long>(k));
  }
}

// The greedy cover (header), chosen sets in the order chosen.
std::vector<int> greedy(const TipCoverProblem& p, const TipCoverOptions& options, CoverState& state, TipCover& out) {
  const int sets = static_cast<int>(p.kinds.size());
  std::vector<int> chosen;
  for (int s = 0; s < sets; ++s)
    if (p.kinds[static_cast<std::size_t>(s)] == TipKind::forced) {
      state.test(s, true);
      state.take(s);
      chosen.push_back(s);
    }
  // Qualified sets: tested in full (as with a fixed tip list), best first.
  for (;;) {
    int best = -1, best_gain = 0;
    for (int s = 0; s < sets; ++s) {
      if (p.kinds[static_cast<std::size_t>(s)] != TipKind::qualified) continue;
      if (std::find(chosen.begin(), chosen.end(), s) != chosen.end()) continue;
      state.test(s, true);
      const int g = state.gain(s);
      if (g > best_gain) best = s, best_gain = g;
    }
    if (best < 0) break;
    state.take(best);
    chosen.push_back(best);
  }
  // Fresh sets, lazily: the queue holds upper bounds; the best is tested,
  // and taken when its true gain still ranks first (ties: lower index).
  using Entry = std::pair<int, int>;  // gain, -set
  std::priority_queue<Entry> queue;
  for (int s = 0; s < sets; ++s)
    if (p.kinds[static_cast<std::size_t>(s)] == TipKind::fresh) {
      const int g = state.gain(s);
      if (g > 0) queue.push({g, -s});
    }
  while (!queue.empty()) {
    const int s = -queue.top().second;
    queue.pop();
    // Tested only while it may still rank first: once its bound drops
    // below the next entry's it goes back with that bound.
    state.test_while(s, options.test_batch,
                     [&](int bound) { return queue.empty() || !(Entry{bound, -s} < queue.top()); });
    const int g = state.gain(s);
    if (g == 0) continue;
    if (!queue.empty() && Entry{g, -s} < queue.top()) {
      queue.push({g, -s});
      continue;
    }
    if (out.bound_n == 0) out.bound_n = g;  // the first pick has the largest gain there is
    state.take(s);
    chosen.push_back(s);
  }
  remove_redundant(p, state, chosen);
  return chosen;
}

using Bits = std::vector<std::uint64_t>;

bool test_bit(const Bits& b, int i) { return (b[static_cast<std::size_t>(i) / 64] >> (i % 64)) & 1u; }
void set_bit(Bits& b, int i) { b[static_cast<std::size_t>(i) / 64] |= std::uint64_t{1} << (i % 64); }

// Branch and bound over a reduced instance: `cover[s]` the element bits of
// set s, `weight[s]` its cost, `sets_of[e]` the sets holding element e.
class Search {
 public:
  Search(std::vector<Bits> cover, std::vector<long> weight, int elements, long max_nodes)
      : cover_(std::move(cover)), weight_(std::move(weight)), elements_(elements), max_nodes_(max_nodes) {
    sets_of_.resize(static_cast<std::size_t>(elements));
    for (std::size_t s = 0; s < cover_.size(); ++s)
      for (int e = 0; e < elements; ++e)
        if (test_bit(cover_[s], e)) sets_of_[static_cast<std::size_t>(e)].push_back(static_cast<int>(s));
  }

  // Improves on `best` (cost `best_cost`); false when the node cap stopped it.
  bool run(std::vector<int>& best, long& best_cost) {
    best_ = best;
    best_cost_ = best_cost;
    Bits uncovered((static_cast<std::size_t>(elements_) + 63) / 64, 0);
    for (int e = 0; e < elements_; ++e) set_bit(uncovered, e);
    std::vector<int> chosen;
    const bool finished = descend(uncovered, chosen, 0);
    best = best_;
    best_cost = best_cost_;
    return finished;
  }
  long nodes() const { return nodes_; }

 private:
  // Elements no two of which share a set each need a set of their own.
  long lower_bound(const Bits& uncovered) const {
    std::vector<char> used(cover_.size(), 0);
    long bound = 0;
    for (int e = 0; e < elements_; ++e) {
      if (!test_bit(uncovered, e)) continue;
      const std::vector<int>& s = sets_of_[static_cast<std::size_t>(e)];
      bool free = true;
      for (int k : s) free = free && !used[static_cast<std::size_t>(k)];
      if (!free) continue;
      long cheapest = -1;
      for (int k : s) {
        used[static_cast<std::size_t>(k)] = 1;
        if (cheapest < 0 || weight_[static_cast<std::size_t>(k)] < cheapest) cheapest = weight_[static_cast<std::size_t>(k)];
      }
      bound += cheapest;
    }
    return bound;
  }

  bool descend(const Bits& uncovered, std::vector<int>& chosen, long cost) {
    if (++nodes_ > max_nodes_) return false;
    int pick = -1;
    std::size_t fewest = 0;
    for (int e = 0; e < elements_; ++e)
      if (test_bit(uncovered, e) && (pick < 0 || sets_of_[static_cast<std::size_t>(e)].size() < fewest)) {
        pick = e;
        fewest = sets_of_[static_cast<std::size_t>(e)].size();
      }
    if (pick < 0) {
      if (cost < best_cost_) {
        best_cost_ = cost;
        best_ = chosen;
      }
      return true;
    }
    if (cost + lower_bound(uncovered) >= best_cost_) return true;
    std::vector<int> order = sets_of_[static_cast<std::size_t>(pick)];
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return weight_[static_cast<std::size_t>(a)] < weight_[static_cast<std::size_t>(b)];
    });
    for (int s : order) {
      Bits rest = uncovered;
      for (std::size_t w = 0; w < rest.size(); ++w) rest[w] &= ~cover_[static_cast<std::size_t>(s)][w];
      chosen.push_back(s);
      const bool done = descend(rest, chosen, cost + weight_[static_cast<std::size_t>(s)]);
      chosen.pop_back();
      if (!done) return false;
    }
    return true;
  }

  std::vector<Bits> cover_;
  std::vector<long> weight_;
  int elements_;
  long max_nodes_;
  std::vector<std::vector<int>> sets_of_;
  std::vector<int> best_;
  long best_cost_ = 0;
  long nodes_ = 0;
};

// Exact search over every pair (tested beforehand); `chosen` holds the
// greedy cover on entry and the best cover found on return.
bool exact(const TipCoverProblem& p, const CoverState& state, std::vector<int>& chosen, long max_nodes, long& nodes) {
  const int sets = static_cast<int>(p.kinds.size());
  // Elements the forced sets leave, with the free sets holding each.
  std::vector<char> forced_covers(static_cast<std::size_t>(p.elements), 0);
  std::vector<std::vector<int>> holders(static_cast<std::size_t>(p.elements));
  for (int s = 0; s < sets; ++s) {
    const std::vector<int>& list = p.maybe[static_cast<std::size_t>(s)];
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (state.known()[static_cast<std::size_t>(s)][i] != 1) continue;
      if (p.kinds[static_cast<std::size_t>(s)] == TipKind::forced) forced_covers[static_cast<std::size_t>(list[i])] = 1;
      else holders[static_cast<std::size_t>(list[i])].push_back(s);
    }
  }
  // Elements with the same holders are one element.
  std::map<std::vector<int>, int> classes;
  for (int e = 0; e < p.elements; ++e) {
    const std::vector<int>& h = holders[static_cast<std::size_t>(e)];
    if (forced_covers[static_cast<std::size_t>(e)] || h.empty()) continue;
    classes.emplace(h, static_cast<int>(classes.size()));
  }
  const int n = static_cast<int>(classes.size());
  const std::size_t words = (static_cast<std::size_t>(n) + 63) / 64;
  std::vector<Bits> cover(static_cast<std::size_t>(sets), Bits(words, 0));
  for (const auto& [h, e] : classes)
    for (int s : h) set_bit(cover[static_cast<std::size_t>(s)], e);
  // Costs: a fresh set outweighs all the others together.
  std::vector<long> weight(static_cast<std::size_t>(sets), 0);
  for (int s = 0; s < sets; ++s)
    weight[static_cast<std::size_t>(s)] = p.kinds[static_cast<std::size_t>(s)] == TipKind::fresh ? sets + 1 : 1;
  // Drop empty and dominated sets (contained in a set no dearer; of equal
  // ones the lower index stays).
  std::vector<int> keep;
  for (int s = 0; s < sets; ++s) {
    if (p.kinds[static_cast<std::size_t>(s)] == TipKind::forced) continue;
    const Bits& a = cover[static_cast<std::size_t>(s)];
    bool empty = true;
    for (std::uint64_t w : a) empty = empty && w == 0;
    if (empty) continue;
    bool dominated = false;
    for (int t = 0; t < sets && !dominated; ++t) {
      if (t == s || p.kinds[static_cast<std::size_t>(t)] == TipKind::forced) continue;
      if (weight[static_cast<std::size_t>(t)] > weight[static_cast<std::size_t>(s)]) continue;
      const Bits& b = cover[static_cast<std::size_t>(t)];
      bool subset = true, equal = true;
      for (std::size_t w = 0; w < words; ++w) {
        subset = subset && (a[w] & ~b[w]) == 0;
        equal = equal && a[w] == b[w];
      }
      const bool same_weight = weight[static_cast<std::size_t>(t)] == weight[static_cast<std::size_t>(s)];
      dominated = subset && (!equal || !same_weight || t < s);
    }
    if (!dominated) keep.push_back(s);
  }
  std::vector<Bits> kept_cover;
  std::vector<long> kept_weight;
  for (int s : keep) {
    kept_cover.push_back(cover[static_cast<std::size_t>(s)]);
    kept_weight.push_back(weight[static_cast<std::size_t>(s)]);
  }
  // The greedy cover as the first bound, in the reduced sets' terms: its
  // cost is what it costs; the search only replaces it by a cheaper one.
  long best_cost = 0;
  std::vector<int> forced, best;
  for (int s : chosen) {
    if (p.kinds[static_cast<std::size_t>(s)] == TipKind::forced) forced.push_back(s);
    else best_cost += weight[static_cast<std::size_t>(s)];
  }
  const long greedy_cost = best_cost;
  Search search(std::move(kept_cover), std::move(kept_weight), n, max_nodes);
  const bool finished = search.run(best, best_cost);
  nodes = search.nodes();
  if (best_cost < greedy_cost) {
    chosen = forced;
    for (int k : best) chosen.push_back(keep[static_cast<std::size_t>(k)]);
  }
  return finished;
}

}  // namespace

TipCover solve_tip_cover(const TipCoverProblem& p, const TipCoverOptions& options) {
  if (p.maybe.size() != p.kinds.size()) throw std::invalid_argument("tip cover: one `maybe` list per set is needed");
  if (!p.test_order.empty()) {
    if (p.test_order.size() != p.maybe.size()) throw std::invalid_argument("tip cover: one `test_order` per set is needed");
    for (std::size_t s = 0; s < p.maybe.size(); ++s) {
      std::vector<int> sorted = p.test_order[s];
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t i = 0; i < sorted.size(); ++i)
        if (sorted.size() != p.maybe[s].size() || sorted[i] != static_cast<int>(i))
          throw std::invalid_argument("tip cover: a `test_order` is not a permutation of its `maybe` list's positions");
    }
  }
  TipCover out;
  CoverState state(p);
  long pairs = 0;
  for (const std::vector<int>& list : p.maybe) pairs += static_cast<long>(list.size());
  out.exact = pairs <= options.exact_max_pairs;
  if (out.exact)
    for (int s = 0; s < static_cast<int>(p.maybe.size()); ++s) state.test(s, false);
  std::vector<int> chosen = greedy(p, options, state, out);
  out.bound = harmonic(out.bound_n);
  if (out.exact) out.optimal = exact(p, state, chosen, options.exact_max_nodes, out.nodes);
  std::sort(chosen.begin(), chosen.end());
  out.chosen = chosen;
  // What the cover leaves: elements none of its sets covers. After the
  // greedy they are those no set covers at all (it stops only then).
  std::vector<char> covered(static_cast<std::size_t>(p.elements), 0);
  for (int s : chosen) {
    state.test(s, false);
    const std::vector<int>& list = p.maybe[static_cast<std::size_t>(s)];
    for (std::size_t i = 0; i < list.size(); ++i)
      if (state.known()[static_cast<std::size_t>(s)][i] == 1) covered[static_cast<std::size_t>(list[i])] = 1;
    out.fresh += p.kinds[static_cast<std::size_t>(s)] == TipKind::fresh;
  }
  for (int e = 0; e < p.elements; ++e)
    if (!covered[static_cast<std::size_t>(e)]) out.uncoverable.push_back(e);
  out.tests = state.tests();
  out.known = state.known();
  return out;
}

}  // namespace furrow

#pragma once
// Which tips of an indexable head a plan uses: a weighted set cover
// (docs/cmm.md "Tips chosen by the planner").
//
// Elements are the candidate probe points, sets the head's orientations:
// set s covers element e when that tip reaches the point collision-free.
// Every set has a kind: `forced` is used whatever it covers (the vertical
// tip, which measures the part alignment), `qualified` is already qualified
// on the CMM, `fresh` would have to be qualified by the operator. The cover
// holds every element some set covers; the others are returned as
// `uncoverable` (the planner relocates or drops those points).
//
// Objective, in this order: fewest fresh sets (an already-qualified tip
// costs nothing to use), then fewest sets in all. Fewest tip changes along
// the tour follows from the second: the tour visits each tip's points in
// one run (tip_groups.hpp), so k tips make k - 1 changes, and the vertical
// tip is always among them (the alignment runs first with it).
//
// Which set covers which element is known lazily, because finding out is
// the expensive part (the collision checks): `maybe[s]` lists, ascending,
// the elements s may cover (e.g. those within the tilt limit of its axis;
// anything outside is taken as not covered), and `test(s, elements)` says
// for each listed element whether s covers it. Each pair is tested at most
// once; `test` may run its batch in parallel.
//
// Method:
//   exact, when the instance is small (at most `exact_max_pairs` pairs in
//     all the `maybe` lists: every pair is tested): elements with the same
//     sets are merged, sets contained in a set that is no dearer are
//     dropped, and a branch and bound (branch on the uncovered element with
//     the fewest sets; bound: elements no two of which share a set each need
//     their own set) seeded with the greedy cover searches at most
//     `exact_max_nodes` nodes; `optimal` when it finishes within them.
//   greedy otherwise: the forced sets, then qualified sets by most newly
//     covered elements while one adds any, then fresh sets likewise (a
//     set's untested pairs count as covered until it is the best candidate
//     and gets tested, `test_batch` pairs at a time in `test_order`, and
//     goes back into the queue as soon as its bound falls below the next
//     candidate's: the gain only shrinks, so this picks what the full
//     greedy would), then every set whose elements the others cover is
//     removed, the last chosen first. The fresh count is at most
//     H(n) = 1 + 1/2 + ... + 1/n times the fewest possible, n being the
//     most elements one fresh set adds after the free ones (the classical
//     greedy bound); `bound` reports H(n).
//
// Deterministic: ties go to the lower set index. Failure: none (an empty
// instance gives an empty cover); `test` must return one answer per element.
#include <functional>
#include <vector>

namespace furrow {

enum class TipKind { forced, qualified, fresh };

struct TipCoverOptions {
  long exact_max_pairs = 20000;   // size limit of the exact search (pairs tested)
  long exact_max_nodes = 200000;  // branch-and-bound nodes before it gives up proving
  // Greedy: pairs of a candidate set tested per batch before its gain bound
  // is compared with the next candidate's again. Changes how many pairs are
  // tested (`tests`), never the cover; fixed, not tied to the thread count,
  // so that the report is the same on every machine.
  long test_batch = 32;
};

struct TipCoverProblem {
  int elements = 0;
  std::vector<TipKind> kinds;               // per set
  std::vector<std::vector<int>> maybe;      // per set, ascending element indices
  std::function<std::vector<char>(int set, const std::vector<int>& elements)> test;
  // Optional, per set: the positions in maybe[s] (a permutation of 0 ..
  // size - 1) in the order the greedy tests them, the pairs most likely not
  // covered first. Empty: list order. Changes how many pairs are tested,
  // never the cover.
  std::vector<std::vector<int>> test_order;
};

struct TipCover {
  std::vector<int> chosen;       // set indices, ascending
  std::vector<int> uncoverable;  // elements no set covers, ascending
  int fresh = 0;                 // chosen sets of kind fresh
  bool exact = false;            // the branch and bound ran
  bool optimal = false;          // proven optimal (the search finished)
  long nodes = 0;                // branch-and-bound nodes searched
  int bound_n = 0;               // greedy: the n of H(n) (0: no fresh set was needed)
  double bound = 1;              // greedy: H(bound_n); fresh <= bound * the fewest possible
  long tests = 0;                // pairs tested
  // Per set, aligned with maybe[s]: 1 covers, 0 does not, -1 never tested.
  std::vector<std::vector<signed char>> known;
};

// H(n) = 1 + 1/2 + ... + 1/n (0 for n <= 0).
double harmonic(int n);

TipCover solve_tip_cover(const TipCoverProblem& problem, const TipCoverOptions& options = {});

}  // namespace furrow

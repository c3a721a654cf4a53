#pragma once
// The eight Nelson rules on one characteristic's series of individual
// values, against a centre line and a sigma (docs/spc.md "Nelson rules").
//
// Why a function of its own: the rules depend only on the values, the centre
// and the sigma, so they are tested on designed series with the centre and
// sigma chosen by the test; compute_spc (spc_statistics.hpp) calls it with
// the series' mean and within sigma.
//
// Each rule looks at windows of consecutive values (rule 1 a window of one).
// A window that shows the rule's pattern is a finding; findings of one rule
// with the same side (rules 2, 5, 6), direction (rule 3) or phase (rule 4)
// that share a point are one violation, reported at its first point: a run
// of ten values above the centre is one rule-2 violation at the run's first
// value. For rules 5 and 6 a window counts from its first to its last value
// beyond the limit, so the violation starts at a value that is beyond it.
// Comparisons are strict: a value on the centre line is on neither side,
// "beyond k sigma" is |x - centre| > k sigma, "within 1 sigma" is its
// negation, an equal neighbour is neither an increase nor a decrease.
#include <cstddef>
#include <vector>

namespace furrow {

struct NelsonViolation {
  int rule = 0;           // 1 .. 8
  std::size_t index = 0;  // position in the series of the violation's first value
  std::size_t last = 0;   // position of its last value (index <= last)
};

// Violations of all eight rules, sorted by (index, rule). Precondition
// (logic_error otherwise): sigma > 0 and finite, centre and values finite.
std::vector<NelsonViolation> nelson_violations(const std::vector<double>& values, double centre, double sigma);

// The window length of each rule (1, 9, 6, 14, 3, 5, 15, 8), for documents
// and tests; rule in 1 .. 8.
std::size_t nelson_window(int rule);

}  // namespace furrow

#pragma once
// What every measurement reader shares (measurement_csv, measurement_xyz,
// dmis_results, ippdme_response_log): the "FILE:LINE: what" error, numbers
// parsed in place with std::from_chars (no copy of the field; the readers
// meet a million points in seconds, docs/formats.md "Measurements"), unit
// directions, and the checks every set gets once it is read (coordinate
// range of docs/formats.md "Limits", unique ids, the point cap).
#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/cmm/measurement_file.hpp"

namespace furrow::measurement_fields {

[[noreturn]] void fail(const std::string& name, int line, const std::string& what);

// `field` (blanks around it allowed, a leading '+' too) as one finite number;
// with `decimal_comma` a ',' stands for the decimal point. InputError
// "name:line: what: "field" is not a (finite) number" otherwise.
double number(std::string_view field, const std::string& name, int line, const std::string& what,
              bool decimal_comma = false);
// The same, reporting success instead of throwing.
bool try_number(std::string_view field, double& out, bool decimal_comma = false);

// `v` normalised; InputError when it has (almost) zero length.
Eigen::Vector3d unit_direction(const Eigen::Vector3d& v, const std::string& name, int line,
                               const std::string& what);

// `text` without blanks (space, tab, CR, LF) at either end.
std::string_view trimmed(std::string_view text);

// Calls `each(line_number, line)` for every line of `text` (LF or CR LF ends,
// the CR removed, 1-based numbers); the view points into `text`.
template <class Each>
void for_each_line(std::string_view text, Each&& each) {
  int number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    each(++number, line);
    start = end + 1;
  }
}

// How often `c` occurs in `text`, by memchr: std::count is not vectorised at
// -O2 and took a tenth of a million-point log's read just to reserve.
std::size_t count_char(std::string_view text, char c);
// An upper bound of the number of lines, to reserve the points once.
std::size_t count_lines(std::string_view text);

// The coordinate range of every point (docs/formats.md "Limits") and the
// point cap, checked as each point is added.
void add_point(MeasurementSet& set, MeasuredPoint&& p, const std::string& name);
// Labels by a 64-bit hash (FNV-1a): sorting (hash, index) pairs keeps the
// comparisons in one contiguous array instead of chasing a million strings.
std::uint64_t label_hash(std::string_view label);
using LabelKeys = std::vector<std::pair<std::uint64_t, std::uint32_t>>;
// (hash, index) of labels 0..n-1, sorted.
template <class LabelOf>
LabelKeys sorted_label_keys(std::size_t n, LabelOf&& label_of) {
  LabelKeys keys(n);
  for (std::size_t k = 0; k < n; ++k) keys[k] = {label_hash(label_of(k)), static_cast<std::uint32_t>(k)};
  std::sort(keys.begin(), keys.end());
  return keys;
}
// The earliest index whose label repeats an earlier one, with that earlier
// one (its first use); nullopt when all labels differ.
template <class LabelOf>
std::optional<std::pair<std::size_t, std::size_t>> first_repeat(const LabelKeys& keys, LabelOf&& label_of) {
  std::optional<std::pair<std::size_t, std::size_t>> best;
  for (std::size_t a = 0; a < keys.size();) {
    std::size_t b = a + 1;
    while (b < keys.size() && keys[b].first == keys[a].first) ++b;
    // One hash, indices ascending: a label equal to an earlier one in the run repeats it.
    for (std::size_t j = a + 1; j < b; ++j)
      for (std::size_t i = a; i < j; ++i)
        if (label_of(keys[i].second) == label_of(keys[j].second)) {
          if (!best || keys[j].second < best->first) best = std::make_pair<std::size_t, std::size_t>(keys[j].second, keys[i].second);
          break;
        }
    a = b;
  }
  return best;
}

// Ids unique over the set: InputError at the first repeated id in file
// order, naming the line of its first use. Sorting an index instead of a
// map of strings keeps a million-point file within its time and memory budget.
void check_unique_ids(const MeasurementSet& set, const std::string& name);

// Shortest text that reads back to exactly `v` (std::to_chars); throws
// std::logic_error for a non-finite value (a writer's bug, not input).
std::string shortest(double v);

}  // namespace furrow::measurement_fields

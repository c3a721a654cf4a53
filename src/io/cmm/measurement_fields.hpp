#pragma once
// What every measurement reader shares (measurement_csv, measurement_xyz,
// dmis_results, ippdme_response_log): the "FILE:LINE: what" error, numbers
// parsed in place with std::from_chars (no copy of the field; the readers
// meet a million points in seconds, docs/formats.md "Measurements"), unit
// directions, and the checks every set gets once it is read (coordinate
// range of docs/formats.md "Limits", unique ids, the point cap).
#include <Eigen/Core>
#include <string>
#include <string_view>

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

// An upper bound of the number of lines, to reserve the points once.
std::size_t count_lines(std::string_view text);

// The coordinate range of every point (docs/formats.md "Limits") and the
// point cap, checked as each point is added.
void add_point(MeasurementSet& set, MeasuredPoint&& p, const std::string& name);
// Ids unique over the set: InputError at the first repeated id in file
// order, naming the line of its first use. Sorting an index instead of a
// map of strings keeps a million-point file within its memory budget.
void check_unique_ids(const MeasurementSet& set, const std::string& name);

// Shortest text that reads back to exactly `v` (std::to_chars); throws
// std::logic_error for a non-finite value (a writer's bug, not input).
std::string shortest(double v);

}  // namespace furrow::measurement_fields

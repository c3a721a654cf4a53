#pragma once
// CSV and delimited text exports of measured points (docs/formats.md
// "Measurements", CSV): what CMM software and Excel write, in any of their
// dialects (csv_dialect.hpp).
//
//   - delimiter ',' ';' tab or runs of blanks; unless the dialect names it,
//     the header line decides: tab if it has one, else ';', else ',', else
//     blanks (counted outside quotes);
//   - decimal comma ("1,5") when the dialect says so, or by default whenever
//     the delimiter is not ',';
//   - RFC 4180 quoting: a field in double quotes may hold the delimiter, a
//     doubled quote stands for one; a quote cannot span lines;
//   - a UTF-8 byte-order mark and CR LF line ends (Excel) are accepted; lines
//     starting with '#' and blank lines are skipped;
//   - header names are matched case-insensitively, trimmed: id (also name,
//     label, point, ...), x y z i j k, and the columns of nominal/actual
//     point tables ("Nominal X", "X nom", "Actual X", "X act", "Deviation",
//     ...). The actual columns are the point, the nominal ones its
//     MeasuredPoint::nominal; deviation columns are ignored (compare
//     computes its own). The dialect's column map overrides the names.
//   - an unknown column is an error in a plain x/y/z table (a typo must not
//     drop a column silently); a nominal/actual table or a mapped header may
//     carry other columns (tolerances, status), which are ignored.
//
// Errors: InputError "FILE:LINE: ..." naming the column (1-based position and
// its field) for a bad value; the header's line for header problems.
#include <string>
#include <string_view>

#include "io/cmm/measurement_file.hpp"

namespace furrow {

// Fills set.points (and ids_from_file) from `text` (no byte-order mark),
// coordinates times `scale` (to mm).
void parse_measurements_csv(std::string_view text, const std::string& name, double scale,
                            const CsvDialect& dialect, MeasurementSet& set);

// id,x,y,z[,i,j,k] with ',' and shortest exact numbers, after a comment line
// with the probe kind and diameter; reading it back reproduces every
// coordinate.
std::string measurements_to_csv(const MeasurementSet& set);
void write_measurements_csv(const MeasurementSet& set, const std::string& path);

}  // namespace furrow

#pragma once
// How a CSV or text export of measured points is written (docs/formats.md
// "Measurements", CSV dialects): the field delimiter, the decimal mark, which
// header names the point's columns, and the file's units. Every CMM package
// and every Excel locale writes its own; the dialect is what the user says
// about a file, or saves once as JSON for a machine (--dialect FILE). What
// the user leaves unset is detected from the file (measurement_csv.hpp).
//
// Errors: InputError naming the option or the dialect file's member.
#include <map>
#include <optional>
#include <string>

namespace furrow {

// Fields a column can be mapped to: the point's id, its actual x, y, z and
// direction i, j, k, and the nominal nx, ny, nz.
bool is_csv_point_field(const std::string& field);

struct CsvDialect {
  // ',', ';', '\t', or ' ' for runs of blanks; nullopt: detected from the header.
  std::optional<char> delimiter;
  // true: "1,5" is 1.5; nullopt: allowed when the delimiter is not ','.
  std::optional<bool> decimal_comma;
  // Point field (is_csv_point_field) -> header name (matched case-insensitively, trimmed).
  std::map<std::string, std::string> columns;
  // "mm" or "inch"; nullopt: MeasurementReadOptions::units.
  std::optional<std::string> units;
};

// "," "comma" ";" "semicolon" "tab" "\t" "whitespace" "space": the delimiter;
// InputError naming `where` otherwise.
char parse_csv_delimiter(const std::string& text, const std::string& where);
// "id=Name,x=X act,..." -> columns; InputError naming `where` for an unknown
// field, a field given twice or an empty name.
std::map<std::string, std::string> parse_csv_columns(const std::string& text, const std::string& where);
// A saved dialect: {"delimiter": ";", "decimal_comma": true, "columns":
// {"id": "Name", "x": "X act", ...}, "units": "mm"}, every member optional.
CsvDialect read_csv_dialect(const std::string& path);
// The same from the text of such a file; `name` stands for it in messages.
CsvDialect parse_csv_dialect(const std::string& text, const std::string& name);
// `base` (a saved dialect, or the default) with what is given on top:
// every given member replaces the base's. InputError naming `where` when the
// result asks for a decimal comma with ',' as delimiter, or when `units` is
// given and the base names other units.
CsvDialect merge_csv_dialect(CsvDialect base, const std::optional<char>& delimiter,
                             const std::optional<bool>& decimal_comma,
                             const std::map<std::string, std::string>& columns, const std::string& where);
// The delimiter as parse_csv_delimiter reads it: ",", ";", "tab", "whitespace".
std::string csv_delimiter_name(char delimiter);

}  // namespace furrow

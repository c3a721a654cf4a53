#pragma once
// Small text helpers shared by every reader of plain-text inputs (CSV,
// G-code, command-line values), so that a number or a file extension means
// the same thing everywhere.
#include <string>

namespace furrow {

// True when the whole of `text` is one finite number (strtod syntax, no
// leading or trailing characters, no overflow); the value goes to `out`.
bool parse_finite(const std::string& text, double& out);

// `text` without leading and trailing blanks (space, tab, CR, LF).
std::string trim(const std::string& text);

// Escapes & < > " ' as XML/HTML entities: safe in text and in quoted
// attribute values of SVG, HTML and XML alike.
std::string markup_escape(const std::string& text);

// ASCII lower case.
std::string to_lower(std::string text);

// A path's extension in lower case, with the dot (".json"; "" when none).
std::string lower_extension(const std::string& path);

// `text` in double quotes for an error message, cut to at most 80 characters
// (the first 75 and "...") so a huge field is never echoed whole; control
// characters as \xHH, quotes and backslashes escaped, a UTF-8 character never
// cut in half (docs/formats.md "Limits").
std::string quote_field(const std::string& text);

// `text` without a leading UTF-8 byte-order mark (EF BB BF), as Excel and
// some CAM packages write it; every text reader calls this first.
std::string strip_bom(std::string text);
// True when `text` starts with a UTF-8 byte-order mark.
bool has_bom(const std::string& text);

// The field separator of a CSV file from its first non-comment line: ';'
// when that line has a semicolon and no comma (Excel in locales whose decimal
// mark is a comma), ',' otherwise (docs/formats.md "Limits").
char csv_separator(const std::string& first_line);

}  // namespace furrow

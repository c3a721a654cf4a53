#include "io/cmm/csv_dialect.hpp"

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "base/text_fields.hpp"
#include "io/part_file.hpp"

namespace furrow {

namespace jf = json_fields;
using json = jf::json;

bool is_csv_point_field(const std::string& field) {
  for (const char* f : {"id", "x", "y", "z", "i", "j", "k", "nx", "ny", "nz"})
    if (field == f) return true;
  return false;
}

char parse_csv_delimiter(const std::string& text, const std::string& where) {
  const std::string t = to_lower(text);
  if (t == "," || t == "comma") return ',';
  if (t == ";" || t == "semicolon") return ';';
  if (t == "\t" || t == "tab" || t == "\\t") return '\t';
  if (t == "whitespace" || t == "space" || t == " ") return ' ';
  throw InputError(where + ": " + quote_field(text) +
                   " is not a delimiter (expected \",\", \";\", \"tab\" or \"whitespace\")");
}

std::string csv_delimiter_name(char delimiter) {
  if (delimiter == '\t') return "tab";
  if (delimiter == ' ') return "whitespace";
  return std::string(1, delimiter);
}

std::map<std::string, std::string> parse_csv_columns(const std::string& text, const std::string& where) {
  std::map<std::string, std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(start, end - start);
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw InputError(where + ": " + quote_field(item) + " is not FIELD=HEADER (e.g. x=\"X act\")");
    const std::string field = to_lower(trim(item.substr(0, eq)));
    const std::string header = trim(item.substr(eq + 1));
    if (!is_csv_point_field(field))
      throw InputError(where + ": unknown field " + quote_field(field) +
                       " (id, x, y, z, i, j, k, nx, ny, nz)");
    if (header.empty()) throw InputError(where + ": field " + quote_field(field) + " maps to an empty header name");
    if (!out.emplace(field, header).second)
      throw InputError(where + ": field " + quote_field(field) + " is mapped twice");
    start = end + 1;
  }
  return out;
}

CsvDialect parse_csv_dialect(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const std::string root = name + ":";
  const json& obj = jf::object(doc, root);
  CsvDialect d;
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string where = jf::child(root, it.key());
    if (it.value().is_null()) continue;
    if (it.key() == "delimiter") {
      d.delimiter = parse_csv_delimiter(jf::string(it.value(), where), where);
    } else if (it.key() == "decimal_comma") {
      d.decimal_comma = jf::boolean(it.value(), where);
    } else if (it.key() == "units") {
      const std::string units = jf::string(it.value(), where);
      units_to_mm(units, where);  // refused here, before any file is read
      d.units = units;
    } else if (it.key() == "columns") {
      const json& cols = jf::object(it.value(), where);
      for (auto c = cols.begin(); c != cols.end(); ++c) {
        const std::string cw = jf::child(where, c.key());
        const std::string field = to_lower(c.key());
        if (!is_csv_point_field(field))
          throw InputError(cw + ": unknown field (id, x, y, z, i, j, k, nx, ny, nz)");
        const std::string header = trim(jf::string(c.value(), cw));
        if (header.empty()) throw InputError(cw + ": an empty header name");
        if (!d.columns.emplace(field, header).second) throw InputError(cw + ": the field is mapped twice");
      }
    } else {
      throw InputError(where + ": unknown member (delimiter, decimal_comma, columns, units)");
    }
  }
  if (d.delimiter == ',' && d.decimal_comma.value_or(false))
    throw InputError(root + " a decimal comma needs a delimiter other than ','");
  return d;
}

CsvDialect merge_csv_dialect(CsvDialect base, const std::optional<char>& delimiter,
                             const std::optional<bool>& decimal_comma,
                             const std::map<std::string, std::string>& columns, const std::string& where) {
  if (delimiter) base.delimiter = delimiter;
  if (decimal_comma) base.decimal_comma = decimal_comma;
  if (!columns.empty()) base.columns = columns;
  if (base.delimiter == ',' && base.decimal_comma.value_or(false))
    throw InputError(where + ": a decimal comma needs a delimiter other than ','");
  return base;
}

CsvDialect read_csv_dialect(const std::string& path) { return parse_csv_dialect(jf::read_text(path), path); }

}  // namespace furrow

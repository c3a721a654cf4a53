#include "base/option_table.hpp"

#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "base/number_text.hpp"

namespace furrow {

namespace {

constexpr std::size_t kHelpColumn = 23;
constexpr std::size_t kLineWidth = 80;

std::string help_sentence(const OptionDoc& d) {
  std::string text = d.help;
  if (d.kind != OptionKind::toggle) text += " (default " + d.default_text + ")";
  if (!d.former_flag.empty()) text += "; formerly " + d.former_flag;
  return text;
}

// `left` (the flag and its value) and the help filled into lines of at
// most kLineWidth under kHelpColumn; a flag too long for the column puts the
// help on the next line.
std::string wrapped(const std::string& left, const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (!lines.empty() && kHelpColumn + lines.back().size() + 1 + word.size() <= kLineWidth)
      lines.back() += " " + word;
    else
      lines.push_back(word);
  }
  const std::string indent(kHelpColumn, ' ');
  std::string out = left;
  if (left.size() < kHelpColumn)
    out += std::string(kHelpColumn - left.size(), ' ');
  else
    out += "\n" + indent;
  for (std::size_t k = 0; k < lines.size(); ++k) out += (k ? "\n" + indent : "") + lines[k];
  return out + "\n";
}

}  // namespace

std::string default_value_text(const nlohmann::json& value) {
  if (value.is_number_float()) return shortest(value.get<double>());
  if (value.is_array()) {  // as the command line writes a list: "0.1,1"
    std::string out;
    for (const nlohmann::json& item : value) out += (out.empty() ? "" : ",") + default_value_text(item);
    return out;
  }
  return value.dump();
}

nlohmann::json nullable_schema(const nlohmann::json& schema, const std::string& help) {
  if (schema.is_null()) return nullptr;
  nlohmann::json out = {{"anyOf", nlohmann::json::array({schema, {{"type", "null"}}})}};
  out["description"] = help;
  return out;
}

nlohmann::json number_schema(Bound bound) {
  nlohmann::json s = {{"type", "number"}};
  switch (bound) {
    case Bound::any:
      break;
    case Bound::positive:
      s["exclusiveMinimum"] = 0;
      break;
    case Bound::non_negative:
      s["minimum"] = 0;
      break;
    case Bound::fraction:
      s["minimum"] = 0;
      s["maximum"] = 1;
      break;
  }
  return s;
}

nlohmann::json section_schema(const std::vector<OptionDoc>& docs, const nlohmann::json& extra) {
  nlohmann::json properties = extra;
  for (const OptionDoc& d : docs) properties[d.key] = d.schema;
  return {{"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
}

std::string option_flag(const std::string& key) {
  std::string flag = "--" + key;
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

std::string option_help_lines(const std::vector<OptionDoc>& docs) {
  std::string out;
  for (const OptionDoc& d : docs) {
    std::string left = "  " + d.flag;
    if (!d.value_name.empty()) left += " " + d.value_name;
    out += wrapped(left, help_sentence(d));
  }
  return out;
}

std::string option_markdown_table(const std::vector<OptionDoc>& docs) {
  std::string out = "| job-file member | command line | default | meaning |\n|---|---|---|---|\n";
  for (const OptionDoc& d : docs) {
    std::string cli = "`" + d.flag + (d.value_name.empty() ? "" : " " + d.value_name) + "`";
    std::string help = d.help;
    if (!d.former_flag.empty()) help += " (formerly `" + d.former_flag + "`)";
    for (char& c : help)
      if (c == '|') c = '/';
    const bool on_by_default = d.flag.rfind("--no-", 0) == 0;
    const std::string fallback =
        d.kind == OptionKind::toggle ? (on_by_default ? "true" : "false") : d.default_text;
    out += "| `" + d.key + "` | " + cli + " | " + fallback + " | " + help + " |\n";
  }
  return out;
}

namespace option_detail {

double checked_number(const nlohmann::json& v, const std::string& where, Bound bound) {
  switch (bound) {
    case Bound::any:
      return json_fields::number(v, where);
    case Bound::positive:
      return json_fields::positive_number(v, where);
    case Bound::non_negative:
      return json_fields::non_negative_number(v, where);
    case Bound::fraction: {
      const double x = json_fields::non_negative_number(v, where);
      if (x > 1) throw InputError(where + ": must lie between 0 and 1, got " + v.dump());
      return x;
    }
  }
  return json_fields::number(v, where);
}

long checked_integer(const nlohmann::json& v, const std::string& where, long min_value) {
  const long x = json_fields::integer(v, where);
  if (x < min_value) throw InputError(where + ": must be at least " + std::to_string(min_value) + ", got " + v.dump());
  return x;
}

std::string checked_text(const nlohmann::json& v, const std::string& where) {
  return json_fields::string(v, where);
}

std::vector<double> checked_numbers(const nlohmann::json& v, const std::string& where, std::size_t count) {
  const std::vector<double> values = json_fields::numbers(v, where);
  if (values.size() != count)
    throw InputError(where + ": expected " + std::to_string(count) + " numbers, got " + std::to_string(values.size()));
  return values;
}

}  // namespace option_detail

}  // namespace furrow

#include "report/html.hpp"

#include "base/text_fields.hpp"

namespace furrow::html {

std::string escape(const std::string& text) { return markup_escape(text); }

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = bytes[i] << 16;
    if (i + 1 < bytes.size()) v |= bytes[i + 1] << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += (i + 1 < bytes.size()) ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string embedded_png(const std::vector<unsigned char>& png, const std::string& alt,
                         const std::string& id) {
  std::string tag = "<img";
  if (!id.empty()) tag += " id=\"" + escape(id) + "\"";
  tag += " alt=\"" + escape(alt) + "\" src=\"data:image/png;base64," + base64(png) + "\">";
  return tag;
}

std::string table(const std::vector<std::string>& header, const std::vector<TableRow>& rows,
                  const std::string& css_class) {
  std::string out = css_class.empty() ? "<table>" : "<table class=\"" + escape(css_class) + "\">";
  if (!header.empty()) {
    out += "<thead><tr>";
    for (const std::string& h : header) out += "<th>" + escape(h) + "</th>";
    out += "</tr></thead>";
  }
  out += "<tbody>\n";
  for (const TableRow& row : rows) {
    out += row.css_class.empty() ? "<tr>" : "<tr class=\"" + escape(row.css_class) + "\">";
    for (const std::string& c : row.cells) out += "<td>" + c + "</td>";
    out += "</tr>\n";
  }
  return out + "</tbody></table>\n";
}

std::string key_value_table(const std::vector<std::pair<std::string, std::string>>& rows) {
  std::string out = "<table class=\"kv\"><tbody>\n";
  for (const auto& [key, value] : rows) out += "<tr><th>" + escape(key) + "</th><td>" + value + "</td></tr>\n";
  return out + "</tbody></table>\n";
}

}  // namespace furrow::html

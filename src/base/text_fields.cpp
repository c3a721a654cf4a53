#include "base/text_fields.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

namespace furrow {

bool parse_finite(const std::string& text, double& out) {
  // strtod would skip leading white space; a field is a number or not.
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno == 0 && std::isfinite(out);
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

std::string to_lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string lower_extension(const std::string& path) {
  return to_lower(std::filesystem::path(path).extension().string());
}

std::string quote_field(const std::string& text) {
  // At most 80 characters in all: 78 inside the quotes, or 75 and "...".
  constexpr std::size_t kInside = 78, kCut = 75;
  static const char* kHex = "0123456789abcdef";
  std::string body;
  std::size_t keep = 0;  // body size at the last whole character within kCut
  std::size_t i = 0;
  for (; i < text.size() && body.size() <= kInside; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f)
      body += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
    else if (c == '"' || c == '\\')
      body += std::string("\\") + static_cast<char>(c);
    else
      body += static_cast<char>(c);
    // A UTF-8 continuation byte belongs to the character before it.
    const bool continues =
        i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80;
    if (!continues && body.size() <= kCut) keep = body.size();
  }
  if (i == text.size() && body.size() <= kInside) return "\"" + body + "\"";
  return "\"" + body.substr(0, keep) + "...\"";
}

bool has_bom(const std::string& text) { return text.rfind("\xEF\xBB\xBF", 0) == 0; }

std::string strip_bom(std::string text) {
  if (has_bom(text)) text.erase(0, 3);
  return text;
}

char csv_separator(const std::string& first_line) {
  const bool semicolon = first_line.find(';') != std::string::npos;
  return semicolon && first_line.find(',') == std::string::npos ? ';' : ',';
}

std::string markup_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace furrow

#pragma once
// Small building blocks for the self-contained HTML report: escaping text
// for HTML, and embedding PNG figures as data URIs so the page opens offline
// with no side files.
#include <string>
#include <utility>
#include <vector>

namespace furrow::html {

// Escapes & < > " ' for use in text and attribute values.
std::string escape(const std::string& text);

// RFC 4648 base64 (with padding).
std::string base64(const std::vector<unsigned char>& bytes);

// <img> element with the PNG embedded: src="data:image/png;base64,...".
std::string embedded_png(const std::vector<unsigned char>& png, const std::string& alt,
                         const std::string& id = "");

// A table row: cells are HTML already (escape text first); `css_class`
// optional.
struct TableRow {
  std::vector<std::string> cells;
  std::string css_class;
};
// <table> with a header row (header texts are escaped here; none when empty).
std::string table(const std::vector<std::string>& header, const std::vector<TableRow>& rows,
                  const std::string& css_class = "");
// Two-column table of names (escaped) and values (HTML).
std::string key_value_table(const std::vector<std::pair<std::string, std::string>>& rows);

}  // namespace furrow::html

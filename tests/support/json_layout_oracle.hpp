#pragma once
// A second implementation of json_fields::to_text's layout, written the
// plain way (nlohmann's dump() of every subtree decides whether an array
// fits on one line), as an oracle for the faster writers of base/json_text:
// objects break, arrays of at most 100 compact characters stay inline.
#include <nlohmann/json.hpp>
#include <string>

namespace furrow::test {

inline void oracle_layout(const nlohmann::json& v, int indent, std::string& out) {
  const std::string compact = v.dump();
  const bool container = v.is_array() || v.is_object();
  if (!container || v.empty() || (v.is_array() && compact.size() <= 100)) {
    out += compact;
    return;
  }
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  out += v.is_object() ? "{\n" : "[\n";
  std::size_t k = 0;
  for (auto it = v.begin(); it != v.end(); ++it, ++k) {
    out += pad;
    if (v.is_object()) out += nlohmann::json(it.key()).dump() + ": ";
    oracle_layout(*it, indent + 2, out);
    out += k + 1 < v.size() ? ",\n" : "\n";
  }
  out += std::string(static_cast<std::size_t>(indent), ' ') + (v.is_object() ? "}" : "]");
}

inline std::string oracle_text(const nlohmann::json& v) {
  std::string out;
  oracle_layout(v, 0, out);
  return out + "\n";
}

}  // namespace furrow::test

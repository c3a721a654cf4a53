#include "base/json_text.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace furrow::json_text {

namespace {

constexpr std::size_t kInlineWidth = 100;  // to_text's: longer arrays break

// nlohmann's own double formatting (what dump() calls), so that a streamed
// file and one dumped from a tree agree byte for byte; std::to_chars picks
// other texts for some values ("1" for 1.0, fixed notation up to 1e21).
std::size_t format_double(char (&buf)[64], double v) {
  return static_cast<std::size_t>(nlohmann::detail::to_chars(buf, buf + sizeof buf, v) - buf);
}

template <class Int>
void append_int(std::string& out, Int v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// Printable ASCII other than quote and backslash: written as is.
bool plain(std::string_view s) {
  for (char c : s) {
    const auto b = static_cast<unsigned char>(c);
    if (b < 0x20 || b > 0x7e || c == '"' || c == '\\') return false;
  }
  return true;
}

void append_compact(std::string& out, const json& v) {
  switch (v.type()) {
    case json::value_t::null: out += "null"; return;
    case json::value_t::boolean: out += v.get<bool>() ? "true" : "false"; return;
    case json::value_t::number_integer: append_int(out, v.get<json::number_integer_t>()); return;
    case json::value_t::number_unsigned: append_int(out, v.get<json::number_unsigned_t>()); return;
    case json::value_t::number_float: {
      const double x = v.get<double>();
      if (!std::isfinite(x)) {  // as dump() writes it
        out += "null";
        return;
      }
      char buf[64];
      out.append(buf, format_double(buf, x));
      return;
    }
    case json::value_t::string: append_string(out, v.get_ref<const std::string&>()); return;
    case json::value_t::array: {
      out += '[';
      bool first = true;
      for (const json& e : v) {
        if (!first) out += ',';
        first = false;
        append_compact(out, e);
      }
      out += ']';
      return;
    }
    case json::value_t::object: {
      out += '{';
      bool first = true;
      for (auto it = v.begin(); it != v.end(); ++it) {
        if (!first) out += ',';
        first = false;
        append_string(out, it.key());
        out += ':';
        append_compact(out, *it);
      }
      out += '}';
      return;
    }
    default: out += v.dump(); return;  // binary, discarded: never in Furrow's files
  }
}

// Length of v.dump(), or more than `limit` once it is known to exceed it
// (so a large array is not measured whole just to learn it breaks).
std::size_t compact_size(const json& v, std::size_t limit) {
  switch (v.type()) {
    case json::value_t::array:
    case json::value_t::object: {
      std::size_t n = 2 + (v.size() > 1 ? v.size() - 1 : 0);
      for (auto it = v.begin(); it != v.end() && n <= limit; ++it) {
        if (v.is_object()) {
          const std::string& k = it.key();
          n += 1 + (plain(k) ? k.size() + 2 : json(k).dump().size());
        }
        n += compact_size(*it, limit - std::min(n, limit));
      }
      return n;
    }
    case json::value_t::string: {
      const std::string& s = v.get_ref<const std::string&>();
      return plain(s) ? s.size() + 2 : v.dump().size();
    }
    default: {
      std::string text;
      append_compact(text, v);
      return text.size();
    }
  }
}

}  // namespace

void append_number(std::string& out, double v, const char* what) {
  if (!std::isfinite(v)) throw std::logic_error(std::string("non-finite value for ") + what);
  char buf[64];
  out.append(buf, format_double(buf, v));
}

void append_string(std::string& out, std::string_view s) {
  if (plain(s)) {
    out += '"';
    out.append(s.data(), s.size());
    out += '"';
  } else {
    out += json(std::string(s)).dump();  // escapes, checks UTF-8
  }
}

void append_value(std::string& out, const json& v, int indent) {
  const bool object = v.is_object();
  if ((!object && !v.is_array()) || v.empty() || (!object && compact_size(v, kInlineWidth) <= kInlineWidth)) {
    append_compact(out, v);
    return;
  }
  out += object ? "{\n" : "[\n";
  std::size_t k = 0;
  for (auto it = v.begin(); it != v.end(); ++it, ++k) {
    out.append(static_cast<std::size_t>(indent + 2), ' ');
    if (object) {
      append_string(out, it.key());
      out += ": ";
    }
    append_value(out, *it, indent + 2);
    if (k + 1 < v.size()) out += ',';
    out += '\n';
  }
  out.append(static_cast<std::size_t>(indent), ' ');
  out += object ? '}' : ']';
}

void Writer::open(char bracket) {
  before_value();
  out_ += bracket;
  levels_.push_back({bracket == '{', true});
}

void Writer::close(char bracket) {
  const Level level = levels_.back();
  levels_.pop_back();
  if (!level.empty) {
    out_ += '\n';
    pad(2 * levels_.size());
  }
  out_ += bracket;
}

void Writer::before_value() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (levels_.empty()) return;  // the document itself
  Level& top = levels_.back();
  if (top.object) throw std::logic_error("json_text::Writer: a member without a key");
  out_ += top.empty ? "\n" : ",\n";
  top.empty = false;
  pad(2 * levels_.size());
}

void Writer::key(std::string_view name) {
  if (levels_.empty() || !levels_.back().object || after_key_)
    throw std::logic_error("json_text::Writer: a key outside an object");
  Level& top = levels_.back();
  out_ += top.empty ? "\n" : ",\n";
  top.empty = false;
  pad(2 * levels_.size());
  append_string(out_, name);
  out_ += ": ";
  after_key_ = true;
}

void Writer::number(double v, const char* what) {
  before_value();
  append_number(out_, v, what);
}

void Writer::integer(long long v) {
  before_value();
  append_int(out_, v);
}

void Writer::count(unsigned long long v) {
  before_value();
  append_int(out_, v);
}

void Writer::boolean(bool v) {
  before_value();
  out_ += v ? "true" : "false";
}

void Writer::null() {
  before_value();
  out_ += "null";
}

void Writer::string(std::string_view s) {
  before_value();
  append_string(out_, s);
}

void Writer::vector(const Eigen::Vector2d& v) {
  before_value();
  out_ += '[';
  append_number(out_, v.x(), "u");
  out_ += ',';
  append_number(out_, v.y(), "v");
  out_ += ']';
}

void Writer::vector(const Eigen::Vector3d& v) {
  before_value();
  out_ += '[';
  append_number(out_, v.x(), "x");
  out_ += ',';
  append_number(out_, v.y(), "y");
  out_ += ',';
  append_number(out_, v.z(), "z");
  out_ += ']';
}

void Writer::value(const json& v) {
  before_value();
  append_value(out_, v, static_cast<int>(2 * levels_.size()));
}

void Writer::finish() {
  if (!levels_.empty() || after_key_) throw std::logic_error("json_text::Writer: document not closed");
  out_ += '\n';
}

}  // namespace furrow::json_text

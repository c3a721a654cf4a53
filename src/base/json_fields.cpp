#include "base/json_fields.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unordered_set>
#include <sstream>
#include <vector>

#include "base/error.hpp"
#include "base/json_text.hpp"
#include "base/text_fields.hpp"

namespace furrow::json_fields {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  if (!where.empty() && where.back() == ':') throw InputError(where + " " + what);
  throw InputError(where + ": " + what);
}

const char* type_name(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

// The parser's own words, which quote the offending token: cut like any
// quoted value (docs/formats.md "Limits"), control bytes escaped.
std::string brief(const std::string& detail) {
  const std::string q = quote_field(detail.size() > 200 ? detail.substr(0, 200) : detail);
  return q.substr(1, q.size() - 2);
}

// nlohmann's own document builder, which also notes the first member given
// twice in one object: the parser would keep the last value without a word,
// so a pasted or merged file would lose one silently. (Its callback parser
// could say the same, but re-scans the enclosing array at every object's
// end: quadratic in a plan of 100,000 points.)
class DuplicateCheckingDom : public nlohmann::detail::json_sax_dom_parser<json> {
 public:
  explicit DuplicateCheckingDom(json& root) : json_sax_dom_parser(root, true) {}
  bool start_object(std::size_t elements) {
    if (depth_ == levels_.size()) levels_.emplace_back();
    levels_[depth_++].clear();
    return json_sax_dom_parser::start_object(elements);
  }
  bool key(std::string& name) {
    if (duplicate_.empty() && !levels_[depth_ - 1].insert(name).second) duplicate_ = name;
    return json_sax_dom_parser::key(name);
  }
  bool end_object() {
    --depth_;
    return json_sax_dom_parser::end_object();
  }
  const std::string& duplicate() const { return duplicate_; }

 private:
  std::vector<std::unordered_set<std::string>> levels_;  // member names per open object, reused
  std::size_t depth_ = 0;
  std::string duplicate_;
};

}  // namespace

json parse_text(const std::string& text, const std::string& name) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) fail(name, "the file is empty");
  json doc;
  DuplicateCheckingDom dom(doc);
  try {
    json::sax_parse(text, &dom);
    if (!dom.duplicate().empty())
      fail(name, "member " + quote_field(dom.duplicate()) + " is given twice in one object (only one value can be meant)");
    return doc;
  } catch (const json::parse_error& e) {
    // Turn the byte offset into line and column: what an editor shows.
    const std::size_t byte = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < byte; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::ostringstream s;
    s << "line " << line << ", column " << column << ": not valid JSON";
    std::string detail = e.what();
    const auto pos = detail.find("syntax error");
    if (pos != std::string::npos) s << " (" << brief(detail.substr(pos)) << ")";
    fail(name, s.str());
  } catch (const json::exception& e) {
    // e.g. a number too large for a double: not a line-level syntax error.
    fail(name, std::string("not valid JSON (") + brief(e.what()) + ")");
  }
}

std::string read_text(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file (missing or unreadable)");
  // A regular file is read into one string of its size: a measurement file
  // of a million points must not be held twice (docs/formats.md "Measurements").
  const auto size = std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
  if (!ec && size > 0) {
    std::string text(size, '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size) fail(path, "reading the file failed");
    return text;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) fail(path, "reading the file failed");
  return buffer.str();
}

json load_file(const std::string& path) { return parse_text(read_text(path), path); }

std::string child(const std::string& where, const std::string& key_text) {
  // A member name from the file is shown whole only when short (docs/formats.md "Limits").
  const std::string key = key_text.size() <= 78 ? key_text : quote_field(key_text);
  if (!where.empty() && where.back() == ':') return where + " " + key;  // document root
  return where + "." + key;
}

std::string child(const std::string& where, std::size_t index) {
  return where + "[" + std::to_string(index) + "]";
}

const json& member(const json& obj, const std::string& key, const std::string& where) {
  const json* v = optional_member(obj, key, where);
  if (!v) fail(child(where, key), "missing");
  return *v;
}

const json* optional_member(const json& obj, const std::string& key, const std::string& where) {
  if (!obj.is_object()) fail(where, std::string("expected an object, found ") + type_name(obj));
  auto it = obj.find(key);
  if (it == obj.end()) return nullptr;
  return &*it;
}

double number(const json& v, const std::string& where) {
  if (!v.is_number()) fail(where, std::string("expected a number, found ") + type_name(v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(where, "not a finite number");
  return x;
}

double positive_number(const json& v, const std::string& where) {
  const double x = number(v, where);
  if (!(x > 0)) fail(where, "must be positive, got " + v.dump());
  return x;
}

double non_negative_number(const json& v, const std::string& where) {
  const double x = number(v, where);
  if (x < 0) fail(where, "must not be negative, got " + v.dump());
  return x;
}

int integer(const json& v, const std::string& where) {
  const double x = number(v, where);
  if (x != std::floor(x) || std::fabs(x) > 2e9) fail(where, "expected an integer, got " + v.dump());
  return static_cast<int>(x);
}

bool boolean(const json& v, const std::string& where) {
  if (!v.is_boolean()) fail(where, std::string("expected true or false, found ") + type_name(v));
  return v.get<bool>();
}

std::string string(const json& v, const std::string& where) {
  if (!v.is_string()) fail(where, std::string("expected a string, found ") + type_name(v));
  return v.get<std::string>();
}

const json& array(const json& v, const std::string& where) {
  if (!v.is_array()) fail(where, std::string("expected an array, found ") + type_name(v));
  return v;
}

const json& object(const json& v, const std::string& where) {
  if (!v.is_object()) fail(where, std::string("expected an object, found ") + type_name(v));
  return v;
}

std::vector<double> numbers(const json& v, const std::string& where) {
  array(v, where);
  std::vector<double> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], child(where, i)));
  return out;
}

Eigen::Vector2d vector2(const json& v, const std::string& where) {
  const std::vector<double> x = numbers(v, where);
  if (x.size() != 2) fail(where, "expected 2 numbers, got " + std::to_string(x.size()));
  return {x[0], x[1]};
}

Eigen::Vector3d vector3(const json& v, const std::string& where) {
  const std::vector<double> x = numbers(v, where);
  if (x.size() != 3) fail(where, "expected 3 numbers [x, y, z], got " + std::to_string(x.size()));
  return {x[0], x[1], x[2]};
}

json finite(double value, const char* what) {
  if (!std::isfinite(value))
    throw std::logic_error(std::string("non-finite value for ") + what);
  return value;
}

json vector_json(const Eigen::Vector3d& v) {
  return json::array({finite(v.x(), "x"), finite(v.y(), "y"), finite(v.z(), "z")});
}

json vector_json(const Eigen::Vector2d& v) {
  return json::array({finite(v.x(), "u"), finite(v.y(), "v")});
}

std::string to_text(const json& value) {
  std::string out;
  json_text::append_value(out, value, 0);  // the layout lives there, shared with streamed files
  out += "\n";
  return out;
}

}  // namespace furrow::json_fields

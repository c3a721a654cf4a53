#pragma once
// Writing JSON text in Furrow's layout (json_fields::to_text) without
// building a document first, for files with one entry per measured point
// (report.json of 100 000 points is 86 MB: as a nlohmann::json tree it took
// most of the report's time and several times its size in memory).
//
// The layout is to_text's, byte for byte, so a file written either way is
// the same file:
// - an object (not empty) breaks: one member per line, indented by two
//   spaces per level, members in byte order of their keys (the order of
//   nlohmann::json, whose objects are sorted maps);
// - an array whose compact text is at most 100 characters stays on one line
//   (no spaces: [1.0,2.5]); a longer one puts one element per line;
// - numbers: the shortest text that reads back to the same double, as
//   nlohmann::json prints it (Grisu2: "1.0", "-0.0", "1e-300", "1e+308",
//   "0.0001"; integers without a fraction); strings escaped as nlohmann
//   does (\" \\ \b \f \n \r \t, other control characters \u00xx, UTF-8
//   verbatim; invalid UTF-8 throws nlohmann's type_error, as dump() does).
// Independent of the locale (no printf, no streams).
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <Eigen/Core>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace furrow::json_text {

using nlohmann::json;

// Appends `v` as nlohmann::json dumps a double. Non-finite: logic_error
// naming `what` (Furrow never writes NaN; the caller has a bug).
void append_number(std::string& out, double v, const char* what);
// Appends `s` quoted and escaped as nlohmann::json dumps it.
void append_string(std::string& out, std::string_view s);
// Appends `v` in to_text's layout, `indent` spaces being the indent of the
// line it starts on (its closing bracket goes there). No final newline.
void append_value(std::string& out, const json& v, int indent);

// A document written front to back. Containers open with begin_*, every
// member of an object starts with key(); keys must come in byte order (the
// caller writes them so; the tests compare with the tree's text).
// Streamed arrays always break, so they are only for elements whose compact
// text alone exceeds the inline width (an object with a dozen members) —
// short arrays are written whole with value(json) or vector().
class Writer {
 public:
  explicit Writer(std::string& out) : out_(out) {}

  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  void key(std::string_view name);

  void number(double v, const char* what);
  void integer(long long v);
  void count(unsigned long long v);
  void boolean(bool v);
  void null();
  void string(std::string_view s);
  // A 2- or 3-vector as jf::vector_json would hold it ([x,y,z], inline).
  void vector(const Eigen::Vector2d& v);
  void vector(const Eigen::Vector3d& v);
  // A whole subtree, in to_text's layout at the current depth.
  void value(const json& v);
  // Ends the document (the newline of to_text).
  void finish();

 private:
  struct Level {
    bool object;
    bool empty;
  };
  void open(char bracket);
  void close(char bracket);
  void before_value();  // separator and indent for an array element
  void pad(std::size_t spaces) { out_.append(spaces, ' '); }

  std::string& out_;
  std::vector<Level> levels_;
  bool after_key_ = false;
};

}  // namespace furrow::json_text

#pragma once
// Reading JSON documents with errors a user can act on.
//
// Every accessor takes `where`, the path of the value in its document prefixed
// by the file name ("part.json: faces[2].knots_u"; the document root itself is
// named "part.json:", with the colon), and throws InputError with
// that path and what was wrong: missing, wrong type, not finite, out of range.
// Used by every Furrow reader (parts, tools, plans, predictions, jobs) so all
// files report errors the same way.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace furrow::json_fields {

using nlohmann::json;

// Whole file as text. Errors: missing, a folder, unreadable.
std::string read_text(const std::string& path);
// Parses a file. Errors: cannot open, empty, not JSON (with line and column).
json load_file(const std::string& path);
// Parses text; `name` stands for the source in messages.
json parse_text(const std::string& text, const std::string& name);

std::string child(const std::string& where, const std::string& key);
std::string child(const std::string& where, std::size_t index);

const json& member(const json& object, const std::string& key, const std::string& where);
const json* optional_member(const json& object, const std::string& key, const std::string& where);

double number(const json& value, const std::string& where);
double positive_number(const json& value, const std::string& where);
double non_negative_number(const json& value, const std::string& where);
int integer(const json& value, const std::string& where);
bool boolean(const json& value, const std::string& where);
std::string string(const json& value, const std::string& where);
const json& array(const json& value, const std::string& where);
const json& object(const json& value, const std::string& where);
std::vector<double> numbers(const json& value, const std::string& where);
Eigen::Vector2d vector2(const json& value, const std::string& where);
Eigen::Vector3d vector3(const json& value, const std::string& where);

// Converts doubles for output: JSON has no NaN/Inf, and Furrow never writes
// them (a non-finite value reaching a writer is a bug and throws logic_error).
json finite(double value, const char* what);
json vector_json(const Eigen::Vector3d& v);
json vector_json(const Eigen::Vector2d& v);

// Deterministic, readable serialisation: objects one member per line, arrays
// on one line when short (numbers, small vectors) and one element per line
// otherwise. Numbers use the shortest text that reads back to the same double,
// so write -> read round trips exactly. Ends with a newline.
std::string to_text(const json& value);

}  // namespace furrow::json_fields

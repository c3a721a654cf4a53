#pragma once
// JsonCursor: one JSON object of a document and its path, for readers that
// name every field in their errors and refuse members they do not know.
//
// Every reader of a Furrow file (parts, tools, heads, plans, regions,
// predictions, comparisons, jobs, inspection records) walks its document
// with this one type, so a member is named once per read
// (`c.number("error")`, not the value and its path separately) and every
// error reads the same way: "prediction.json: regions[2].area: expected a
// number, found null" (json_fields.hpp states the message rules; the
// cursor only composes them).
//
// Three kinds of member:
//   required  number(key), string(key), at(key), ...: absent is an error
//             ("where.key: missing");
//   nullable  nullable_number(key), nullable_string(key): must be present,
//             null means "none" (the writers write null for "none");
//   optional  find(key), optional_number(key), optional_at(key) and the
//             setters positive(key, target), ...: absent or null leaves the
//             target alone (hand-written files such as jobs leave members out).
// Every read marks the member as known; finish(see) then refuses the first
// member never read: "job.json: plan.densty: unknown member (see
// docs/formats.md "Job file")". A reader that keeps members for humans or
// other tools without reading them says so with skip(key).
//
// The cursor refers to the parsed document, which must outlive it.
// This header exposes nlohmann::json; include it only from .cpp files.
#include <Eigen/Core>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>

#include "base/json_fields.hpp"

namespace furrow {

class JsonCursor {
 public:
  using json = nlohmann::json;

  // `value` must be an object: InputError naming `where` otherwise.
  JsonCursor(const json& value, std::string where);

  const json& value() const { return *value_; }
  const std::string& where() const { return where_; }
  // The path of member `key` ("part.json: faces[2]" + "knots" ->
  // "part.json: faces[2].knots").
  std::string path(const std::string& key) const;
  bool has(const std::string& key) const { return value_->contains(key); }

  // Required members.
  const json& raw(const std::string& key) const;
  JsonCursor at(const std::string& key) const;  // an object member
  double number(const std::string& key) const;
  double positive(const std::string& key) const;
  double non_negative(const std::string& key) const;
  int integer(const std::string& key) const;
  int integer(const std::string& key, int min_value) const;  // "must be at least min_value"
  std::size_t count(const std::string& key) const;           // a whole number >= 0
  bool boolean(const std::string& key) const;
  std::string string(const std::string& key) const;
  const json& array(const std::string& key) const;
  std::vector<double> numbers(const std::string& key) const;
  Eigen::Vector2d vector2(const std::string& key) const;
  Eigen::Vector3d vector3(const std::string& key) const;

  // Nullable members: present, null for none.
  bool is_null(const std::string& key) const { return raw(key).is_null(); }
  std::optional<double> nullable_number(const std::string& key) const;
  std::string nullable_string(const std::string& key) const;  // null -> ""

  // Optional members: absent or null is none.
  const json* find(const std::string& key) const;
  std::optional<JsonCursor> optional_at(const std::string& key) const;
  std::optional<double> optional_number(const std::string& key) const;
  std::optional<std::string> optional_string(const std::string& key) const;
  // Setters for options with defaults: the target keeps its value when the
  // member is absent or null.
  void positive(const std::string& key, double& target) const;
  void non_negative(const std::string& key, double& target) const;
  void positive(const std::string& key, std::optional<double>& target) const;
  void non_negative(const std::string& key, std::optional<double>& target) const;
  void integer(const std::string& key, int& target, int min_value) const;
  void boolean(const std::string& key, bool& target) const;

  // Refuses, before anything is read, the first member not in `keys`: for
  // hand-written files where a misspelt required member should be named as
  // misspelt rather than reported missing.
  void only(std::initializer_list<const char*> keys, const std::string& see) const;
  // Marks `key` as known without reading it.
  void skip(const std::string& key) const { read_.insert(key); }
  // Throws InputError for the first member (by name) never read or
  // skipped; `see` names where the members are documented.
  void finish(const std::string& see) const;

 private:
  const json* value_;
  std::string where_;
  mutable std::set<std::string> read_;
};

}  // namespace furrow

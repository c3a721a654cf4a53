#include "base/json_cursor.hpp"

#include <utility>

#include "base/error.hpp"

namespace furrow {

namespace jf = json_fields;

JsonCursor::JsonCursor(const json& value, std::string where) : value_(&value), where_(std::move(where)) {
  jf::object(value, where_);
}

std::string JsonCursor::path(const std::string& key) const { return jf::child(where_, key); }

const JsonCursor::json& JsonCursor::raw(const std::string& key) const {
  read_.insert(key);
  return jf::member(*value_, key, where_);
}

JsonCursor JsonCursor::at(const std::string& key) const { return JsonCursor(raw(key), path(key)); }
double JsonCursor::number(const std::string& key) const { return jf::number(raw(key), path(key)); }
double JsonCursor::positive(const std::string& key) const { return jf::positive_number(raw(key), path(key)); }
double JsonCursor::non_negative(const std::string& key) const {
  return jf::non_negative_number(raw(key), path(key));
}
int JsonCursor::integer(const std::string& key) const { return jf::integer(raw(key), path(key)); }

int JsonCursor::integer(const std::string& key, int min_value) const {
  const int n = integer(key);
  if (n < min_value)
    throw InputError(path(key) + ": must be at least " + std::to_string(min_value) + ", got " + std::to_string(n));
  return n;
}

std::size_t JsonCursor::count(const std::string& key) const {
  const int n = integer(key);
  if (n < 0) throw InputError(path(key) + ": must not be negative, got " + std::to_string(n));
  return static_cast<std::size_t>(n);
}

bool JsonCursor::boolean(const std::string& key) const { return jf::boolean(raw(key), path(key)); }
std::string JsonCursor::string(const std::string& key) const { return jf::string(raw(key), path(key)); }
const JsonCursor::json& JsonCursor::array(const std::string& key) const { return jf::array(raw(key), path(key)); }
std::vector<double> JsonCursor::numbers(const std::string& key) const { return jf::numbers(raw(key), path(key)); }
Eigen::Vector2d JsonCursor::vector2(const std::string& key) const { return jf::vector2(raw(key), path(key)); }
Eigen::Vector3d JsonCursor::vector3(const std::string& key) const { return jf::vector3(raw(key), path(key)); }

std::optional<double> JsonCursor::nullable_number(const std::string& key) const {
  if (is_null(key)) return std::nullopt;
  return number(key);
}

std::string JsonCursor::nullable_string(const std::string& key) const { return is_null(key) ? "" : string(key); }

const JsonCursor::json* JsonCursor::find(const std::string& key) const {
  read_.insert(key);
  const json* v = jf::optional_member(*value_, key, where_);
  return v && !v->is_null() ? v : nullptr;
}

std::optional<JsonCursor> JsonCursor::optional_at(const std::string& key) const {
  if (const json* v = find(key)) return JsonCursor(*v, path(key));
  return std::nullopt;
}

std::optional<double> JsonCursor::optional_number(const std::string& key) const {
  if (const json* v = find(key)) return jf::number(*v, path(key));
  return std::nullopt;
}

std::optional<std::string> JsonCursor::optional_string(const std::string& key) const {
  if (const json* v = find(key)) return jf::string(*v, path(key));
  return std::nullopt;
}

void JsonCursor::positive(const std::string& key, double& target) const {
  if (const json* v = find(key)) target = jf::positive_number(*v, path(key));
}
void JsonCursor::non_negative(const std::string& key, double& target) const {
  if (const json* v = find(key)) target = jf::non_negative_number(*v, path(key));
}
void JsonCursor::positive(const std::string& key, std::optional<double>& target) const {
  if (const json* v = find(key)) target = jf::positive_number(*v, path(key));
}
void JsonCursor::non_negative(const std::string& key, std::optional<double>& target) const {
  if (const json* v = find(key)) target = jf::non_negative_number(*v, path(key));
}

void JsonCursor::integer(const std::string& key, int& target, int min_value) const {
  if (!find(key)) return;
  target = integer(key, min_value);
}

void JsonCursor::boolean(const std::string& key, bool& target) const {
  if (const json* v = find(key)) target = jf::boolean(*v, path(key));
}

void JsonCursor::only(std::initializer_list<const char*> keys, const std::string& see) const {
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) throw InputError(path(it.key()) + ": unknown member (see " + see + ")");
  }
}

void JsonCursor::finish(const std::string& see) const {
  for (auto it = value_->begin(); it != value_->end(); ++it)
    if (!read_.count(it.key())) throw InputError(path(it.key()) + ": unknown member (see " + see + ")");
}

}  // namespace furrow

#include "cli/args.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "base/error.hpp"
#include "base/text_fields.hpp"

namespace furrow::cli {

Args::Args(std::string command, std::vector<std::string> words)
    : command_(std::move(command)), words_(std::move(words)), used_(words_.size(), false) {}

void Args::fail(const std::string& what) const {
  throw InputError("furrow " + command_ + ": " + what);
}

bool Args::wants_help() const {
  for (const auto& w : words_)
    if (w == "--help" || w == "-h") return true;
  return false;
}

std::optional<std::string> Args::optional_positional() {
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (used_[i]) continue;
    if (words_[i].rfind("--", 0) == 0) continue;  // an unknown option: finish() reports it
    used_[i] = true;
    return words_[i];
  }
  return std::nullopt;
}

std::string Args::positional(const std::string& what) {
  auto v = optional_positional();
  if (!v) fail("missing " + what);
  return *v;
}

std::optional<std::string> Args::option(const std::string& name) {
  const std::vector<std::string> values = repeated_option(name);
  if (values.size() > 1) fail("--" + name + " is given twice");
  if (values.empty()) return std::nullopt;
  return values.front();
}

std::vector<std::string> Args::repeated_option(const std::string& name) {
  const std::string key = "--" + name;
  std::vector<std::string> values;
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (used_[i]) continue;
    if (words_[i] == key) {
      if (i + 1 >= words_.size()) fail(key + " needs a value");
      used_[i] = used_[i + 1] = true;
      values.push_back(words_[++i]);
    } else if (words_[i].rfind(key + "=", 0) == 0) {
      used_[i] = true;
      values.push_back(words_[i].substr(key.size() + 1));
    }
  }
  return values;
}

std::string Args::option_or(const std::string& name, const std::string& fallback) {
  auto v = option(name);
  return v ? *v : fallback;
}

std::string Args::required_option(const std::string& name) {
  auto v = option(name);
  if (!v) fail("--" + name + " is required");
  return *v;
}

bool Args::flag(const std::string& name) {
  const std::string key = "--" + name;
  bool found = false;
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (!used_[i] && words_[i] == key) {
      used_[i] = true;
      found = true;
    }
  }
  return found;
}

std::optional<double> Args::number(const std::string& name) {
  auto v = option(name);
  if (!v) return std::nullopt;
  double x = 0;
  if (!parse_finite(*v, x)) fail("--" + name + " expects a number, got " + quote_field(*v));
  return x;
}

double Args::number_or(const std::string& name, double fallback) {
  auto v = number(name);
  return v ? *v : fallback;
}

double Args::positive_or(const std::string& name, double fallback) {
  auto v = number(name);
  if (v && !(*v > 0)) fail("--" + name + " must be positive, got " + option_or(name, ""));
  return v ? *v : fallback;
}

double Args::non_negative_or(const std::string& name, double fallback) {
  auto v = number(name);
  if (v && *v < 0) {
    std::ostringstream s;
    s << "--" << name << " must not be negative, got " << *v;
    fail(s.str());
  }
  return v ? *v : fallback;
}

std::optional<long> Args::integer(const std::string& name) {
  auto v = option(name);
  if (!v) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const long x = std::strtol(v->c_str(), &end, 10);
  if (v->empty() || end != v->c_str() + v->size() || errno != 0)
    fail("--" + name + " expects a whole number, got " + quote_field(*v));
  return x;
}

long Args::integer_or(const std::string& name, long fallback, long min_value) {
  auto v = integer(name);
  if (v && *v < min_value)
    fail("--" + name + " must be at least " + std::to_string(min_value) + ", got " +
         std::to_string(*v));
  return v ? *v : fallback;
}

void Args::finish() const {
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (used_[i]) continue;
    if (words_[i].rfind("--", 0) == 0) fail("unknown option " + words_[i]);
    fail("unexpected argument " + quote_field(words_[i]));
  }
}

std::vector<double> parse_number_list(const std::string& text, std::size_t count,
                                      const std::string& option) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    double x = 0;
    if (!parse_finite(item, x))
      throw InputError("--" + option + ": " + quote_field(item) + " is not a finite number");
    out.push_back(x);
  }
  if (out.size() != count)
    throw InputError("--" + option + " expects " + std::to_string(count) +
                     " comma-separated numbers, got " + quote_field(text));
  return out;
}

}  // namespace furrow::cli

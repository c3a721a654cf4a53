#include "io/machining/apt_statements.hpp"

#include <cctype>

#include "base/error.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace {

[[noreturn]] void fail_line(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Blanks inside the major word collapse to one space ("TOOL  PATH" is
// "TOOL PATH"); blanks next to a comma go ("TLON, GOFWD" is "TLON,GOFWD").
std::string normalise_major(const std::string& raw) {
  std::string out;
  bool blank = false;
  for (char c : trim(raw)) {
    if (c == ' ' || c == '\t') {
      blank = true;
      continue;
    }
    if (blank && !out.empty() && out.back() != ',' && c != ',') out += ' ';
    blank = false;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

// PPRINT, PARTNO and INSERT carry free text up to the end of their line.
bool is_text_statement(const std::string& line, std::string& major, std::string& rest) {
  const std::string t = trim(line);
  std::size_t n = 0;
  while (n < t.size() && std::isalpha(static_cast<unsigned char>(t[n]))) ++n;
  const std::string word = upper(t.substr(0, n));
  if (word != "PPRINT" && word != "PARTNO" && word != "INSERT") return false;
  if (n < t.size() && t[n] != ' ' && t[n] != '\t' && t[n] != '/') return false;
  major = word;
  rest = trim(n < t.size() && t[n] == '/' ? t.substr(n + 1) : t.substr(n));
  return true;
}

}  // namespace

std::vector<std::string> split_apt_params(const std::string& list, const std::string& name, int line) {
  std::vector<std::string> out;
  std::string current;
  int depth = 0;
  for (char c : list) {
    if (c == '(') ++depth;
    if (c == ')' && --depth < 0) fail_line(name, line, "')' without a matching '('");
    if (c == ',' && depth == 0) {
      out.push_back(trim(current));
      current.clear();
      continue;
    }
    current += c;
  }
  if (depth != 0) fail_line(name, line, "'(' is not closed");
  out.push_back(trim(current));
  return out;
}

std::vector<AptStatement> split_apt_statements(const std::string& text, const std::string& name) {
  std::vector<AptStatement> statements;
  const std::string body = strip_bom(text);
  std::string pending;  // the statement so far, over continuation lines
  int pending_line = 0;
  int number = 0;
  std::size_t begin = 0;
  auto finish = [&](const std::string& statement, int line) {
    AptStatement s;
    s.line = line;
    const auto slash = statement.find('/');
    s.has_slash = slash != std::string::npos;
    s.major = normalise_major(statement.substr(0, slash));
    if (s.has_slash) s.params = split_apt_params(upper(statement.substr(slash + 1)), name, line);
    statements.push_back(std::move(s));
  };
  while (begin < body.size()) {
    std::size_t end = body.find('\n', begin);
    if (end == std::string::npos) end = body.size();
    std::string line = body.substr(begin, end - begin);
    begin = end + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string major, rest;
    if (pending.empty() && is_text_statement(line, major, rest)) {
      AptStatement s;
      s.line = number;
      s.major = major;
      s.text = rest;
      statements.push_back(std::move(s));
      continue;
    }
    const auto comment = line.find("$$");
    if (comment != std::string::npos) line.erase(comment);
    std::string code = trim(line);
    const bool continues = !code.empty() && code.back() == '$';
    if (continues) code.pop_back();
    if (pending.empty() && code.empty() && !continues) continue;
    if (pending.empty() && pending_line == 0) pending_line = number;
    pending += code;
    if (continues) continue;
    finish(pending, pending_line);
    pending.clear();
    pending_line = 0;
  }
  if (pending_line != 0)
    fail_line(name, pending_line, "the statement ends in '$' (continued) but the file ends");
  return statements;
}

}  // namespace furrow

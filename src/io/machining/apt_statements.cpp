#include "io/machining/apt_statements.hpp"

#include <cctype>
#include <vector>

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
  struct Place {
    int line;
    std::size_t column;
  };
  std::vector<Place> places;  // where each byte of `pending` is in the file
  int pending_line = 0;
  int number = 0;
  std::size_t begin = 0;
  auto finish = [&](const std::string& statement, int line) {
    AptStatement s;
    s.line = line;
    s.last_line = number;
    const auto slash = statement.find('/');
    s.has_slash = slash != std::string::npos;
    s.major = normalise_major(statement.substr(0, slash));
    if (s.has_slash) {
      s.params = split_apt_params(upper(statement.substr(slash + 1)), name, line);
      // The same cut as split_apt_params, on positions (it has checked the
      // parentheses): each parameter's trimmed bytes.
      std::size_t from = slash + 1;
      int depth = 0;
      auto span = [&](std::size_t a, std::size_t b) {
        while (a < b && std::isspace(static_cast<unsigned char>(statement[a]))) ++a;
        while (b > a && std::isspace(static_cast<unsigned char>(statement[b - 1]))) --b;
        AptSpan out;
        if (a < b && places[a].line == places[b - 1].line &&
            places[b - 1].column - places[a].column == b - 1 - a)
          out = {places[a].line, places[a].column, places[b - 1].column + 1};
        s.spans.push_back(out);
      };
      for (std::size_t k = from; k < statement.size(); ++k) {
        if (statement[k] == '(') ++depth;
        if (statement[k] == ')') --depth;
        if (statement[k] == ',' && depth == 0) {
          span(from, k);
          from = k + 1;
        }
      }
      span(from, statement.size());
    }
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
      s.line = s.last_line = number;
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
    const std::size_t lead = code.empty() ? 0 : line.find_first_not_of(" \t\r\n");
    for (std::size_t k = 0; k < code.size(); ++k) places.push_back({number, lead + k});
    pending += code;
    if (continues) continue;
    finish(pending, pending_line);
    pending.clear();
    places.clear();
    pending_line = 0;
  }
  if (pending_line != 0)
    fail_line(name, pending_line, "the statement ends in '$' (continued) but the file ends");
  return statements;
}

}  // namespace furrow

#include "io/cmm/ippdme_command.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "base/text_fields.hpp"
#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// The spec's number grammar, without building a message (the fast path
// meets millions of numbers).
enum class NumberProblem { none, two_dots, no_digits, too_many_digits, exponent, other };
NumberProblem number_problem(std::string_view t, int max_digits) {
  std::size_t k = 0;
  if (k < t.size() && (t[k] == '+' || t[k] == '-')) ++k;
  // Answers (max_digits kIppdmeAnswerDigits) count significant digits: a
  // double's shortest exact text may be 0.000 and then 17 more.
  const bool significant = max_digits == kIppdmeAnswerDigits;
  int digits = 0, counted = 0, dots = 0;
  for (; k < t.size() && (is_digit(t[k]) || t[k] == '.'); ++k) {
    if (t[k] == '.') {
      ++dots;
      continue;
    }
    ++digits;
    if (!significant || counted > 0 || t[k] != '0') ++counted;
  }
  if (dots > 1) return NumberProblem::two_dots;
  if (digits < 1) return NumberProblem::no_digits;
  if (counted > max_digits) return NumberProblem::too_many_digits;
  if (k < t.size() && (t[k] == 'e' || t[k] == 'E')) {
    ++k;
    if (k < t.size() && (t[k] == '+' || t[k] == '-')) ++k;
    int exponent = 0;
    for (; k < t.size() && is_digit(t[k]); ++k) ++exponent;
    if (exponent < 1 || exponent > 3) return NumberProblem::exponent;
  }
  return k == t.size() ? NumberProblem::none : NumberProblem::other;
}

bool is_number_char(char c) { return is_digit(c) || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'; }

// The fast path's number at s[k]: the same grammar as number_problem() on
// the longest run of number characters, checked and converted in one pass
// (a million-point session log holds over ten million numbers). False, with
// nothing consumed, where number_problem() would find one.
bool scan_number(std::string_view s, std::size_t& k, int max_digits, double& value) {
  const std::size_t n = s.size(), start = k;
  std::size_t j = k;
  if (j < n && (s[j] == '+' || s[j] == '-')) ++j;
  const bool significant = max_digits == kIppdmeAnswerDigits;
  int digits = 0, counted = 0, dots = 0;
  for (; j < n; ++j) {
    const char c = s[j];
    if (c == '.') {
      ++dots;
      continue;
    }
    if (!is_digit(c)) break;
    ++digits;
    if (!significant || counted > 0 || c != '0') ++counted;
  }
  if (dots > 1 || digits < 1 || counted > max_digits) return false;
  if (j < n && (s[j] == 'e' || s[j] == 'E')) {
    ++j;
    if (j < n && (s[j] == '+' || s[j] == '-')) ++j;
    int exponent = 0;
    for (; j < n && is_digit(s[j]); ++j) ++exponent;
    if (exponent < 1 || exponent > 3) return false;
  }
  if (j < n && is_number_char(s[j])) return false;  // the run goes on: not one number
  // from_chars takes no '+'.
  const char* first = s.data() + start + (s[start] == '+' ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(first, s.data() + j, value);
  if (ec != std::errc() || ptr != s.data() + j || !std::isfinite(value)) return false;
  k = j;
  return true;
}

// The commands of I++ DME 1.4 and the shape of their arguments where it is
// fixed (NIST's parserCmd checks the same counts; docs/formats.md).
enum class Arity { any, none, one_string, one_integer, one_event_tag, one_positive, one, four, seven, four_or_eight,
                   seven_or_fourteen };
struct CommandShape {
  const char* name;
  Arity arity;
  bool event;
};
constexpr CommandShape kCommands[] = {
    {"AbortE", Arity::none, true},
    {"AlignPart", Arity::seven_or_fourteen, false},
    {"AlignTool", Arity::four_or_eight, false},
    {"CenterPart", Arity::four, false},
    {"ChangeTool", Arity::one_string, false},
    {"ClearAllErrors", Arity::none, false},
    {"DisableUser", Arity::none, false},
    {"EnableUser", Arity::none, false},
    {"EndSession", Arity::none, false},
    {"EnumAllProp", Arity::one, false},
    {"EnumProp", Arity::one, false},
    {"EnumTools", Arity::none, false},
    {"FindTool", Arity::one_string, false},
    {"Get", Arity::any, false},
    {"GetChangeToolAction", Arity::one_string, false},
    {"GetCoordSystem", Arity::none, false},
    {"GetCsyTransformation", Arity::one, false},
    {"GetDMEVersion", Arity::none, false},
    {"GetErrStatusE", Arity::none, true},
    {"GetErrorInfo", Arity::one_integer, false},
    {"GetMachineClass", Arity::none, false},
    {"GetProp", Arity::any, false},
    {"GetPropE", Arity::any, true},
    {"GetXtdErrStatus", Arity::none, false},
    {"GoTo", Arity::any, false},
    {"Home", Arity::none, false},
    {"IsHomed", Arity::none, false},
    {"IsUserEnabled", Arity::none, false},
    {"LockAxis", Arity::any, false},
    {"OnMoveReportE", Arity::any, true},
    {"OnPtMeasReport", Arity::any, false},
    {"OnScanReport", Arity::any, false},
    {"PtMeas", Arity::any, false},
    {"ReQualify", Arity::none, false},
    {"ScanInCylEndIsPlane", Arity::any, false},
    {"ScanInCylEndIsSphere", Arity::any, false},
    {"ScanInPlaneEndIsCyl", Arity::any, false},
    {"ScanInPlaneEndIsPlane", Arity::any, false},
    {"ScanInPlaneEndIsSphere", Arity::any, false},
    {"ScanOnCircle", Arity::any, false},
    {"ScanOnCircleHint", Arity::any, false},
    {"ScanOnLine", Arity::any, false},
    {"ScanOnLineHint", Arity::any, false},
    {"ScanUnknownHint", Arity::one_positive, false},
    {"SetCoordSystem", Arity::one, false},
    {"SetCsyTransformation", Arity::seven, false},
    {"SetProp", Arity::any, false},
    {"SetTool", Arity::one_string, false},
    {"StartSession", Arity::none, false},
    {"StopAllDaemons", Arity::none, false},
    {"StopDaemon", Arity::one_event_tag, false},
    {"TiltCenterPart", Arity::seven, false},
    {"TiltPart", Arity::four, false},
};

const CommandShape* find_command(std::string_view name) {
  for (const CommandShape& c : kCommands)
    if (name == c.name) return &c;
  return nullptr;
}

// A recursive-descent scanner over one argument list; depth is bounded
// (kMaxDepth) so that a line of nested parentheses cannot exhaust the stack.
class Scanner {
 public:
  Scanner(std::string_view s, int max_digits) : s_(s), max_digits_(max_digits) {}

  // Spaces are allowed only next to '(', ')' and ','.
  void skip_spaces() {
    if (pos_ >= s_.size() || s_[pos_] != ' ') return;
    const char before = pos_ == 0 ? '(' : s_[pos_ - 1];
    while (pos_ < s_.size() && s_[pos_] == ' ') ++pos_;
    const char after = pos_ < s_.size() ? s_[pos_] : ')';
    auto punct = [](char x) { return x == '(' || x == ')' || x == ','; };
    if (!punct(before) && !punct(after) && error_.empty()) error_ = "ILLEGAL SPACE";
  }

  // Items up to the closing ')' (consumed) or, at depth 0 with
  // `to_end`, up to the end of the text.
  bool list(std::vector<IppdmeItem>& out, int depth, bool to_end) {
    if (depth > kMaxDepth) return fail("ARGUMENTS NESTED TOO DEEPLY");
    skip_spaces();
    if (!to_end && peek() == ')') {
      ++pos_;
      return error_.empty();
    }
    if (to_end && pos_ >= s_.size()) return error_.empty();
    while (true) {
      out.emplace_back();
      if (!item(out.back(), depth)) return false;
      skip_spaces();
      if (!error_.empty()) return false;
      if (peek() == ',') {
        ++pos_;
        skip_spaces();
        continue;
      }
      if (to_end) return pos_ >= s_.size() || fail("BAD CHARACTER AFTER ARGUMENT");
      if (peek() == ')') {
        ++pos_;
        return error_.empty();
      }
      return fail(pos_ >= s_.size() ? "MISSING CLOSING PARENTHESIS" : "BAD ARGUMENTS");
    }
  }

  const std::string& error() const { return error_; }
  std::size_t pos() const { return pos_; }

 private:
  static constexpr int kMaxDepth = 8;

  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
  bool fail(const std::string& what) {
    if (error_.empty()) error_ = what;
    return false;
  }

  bool item(IppdmeItem& it, int depth) {
    const char c = peek();
    if (c == '"') {
      it.kind = IppdmeItem::Kind::string;
      const std::size_t close = s_.find('"', pos_ + 1);
      if (close == std::string_view::npos) return fail("BAD STRING");
      for (std::size_t k = pos_ + 1; k < close; ++k)
        if (s_[k] < 32 || s_[k] > 126) return fail("BAD STRING");
      it.text.assign(s_.substr(pos_ + 1, close - pos_ - 1));
      pos_ = close + 1;
      return true;
    }
    if (is_digit(c) || c == '+' || c == '-' || c == '.') {
      it.kind = IppdmeItem::Kind::number;
      const std::size_t start = pos_;
      while (pos_ < s_.size() && (is_digit(s_[pos_]) || s_[pos_] == '+' || s_[pos_] == '-' || s_[pos_] == '.' ||
                                  s_[pos_] == 'e' || s_[pos_] == 'E'))
        ++pos_;
      it.text.assign(s_.substr(start, pos_ - start));
      const std::string why = ippdme_number_error(it.text, max_digits_);
      return why.empty() || fail(why);
    }
    if (c == '(') {  // a bare list, as AlignPart's answer "(i, j, k)"
      it.kind = IppdmeItem::Kind::keyword;
      it.has_arguments = true;
      ++pos_;
      return list(it.arguments, depth + 1, false);
    }
    if (!is_letter(c)) return fail("BAD ARGUMENTS");
    it.kind = IppdmeItem::Kind::keyword;
    const std::size_t start = pos_;
    while (pos_ < s_.size() && (is_letter(s_[pos_]) || is_digit(s_[pos_]) || s_[pos_] == '_' ||
                                (s_[pos_] == '.' && pos_ + 1 < s_.size() && is_letter(s_[pos_ + 1]))))
      ++pos_;
    it.text.assign(s_.substr(start, pos_ - start));
    skip_spaces();
    if (peek() == '(') {
      ++pos_;
      it.has_arguments = true;
      return list(it.arguments, depth + 1, false);
    }
    return error_.empty();
  }

  std::string_view s_;
  int max_digits_;
  std::size_t pos_ = 0;
  std::string error_;
};

bool is_integer(const IppdmeItem& it) {
  return it.kind == IppdmeItem::Kind::number &&
         it.text.find_first_of(".eE") == std::string::npos;
}

std::string check_arity(const CommandShape& c, const std::vector<IppdmeItem>& args) {
  const std::string name = c.name;
  const std::size_t n = args.size();
  auto numbers = [&] {
    return std::all_of(args.begin(), args.end(), [](const IppdmeItem& a) { return a.kind == IppdmeItem::Kind::number; });
  };
  switch (c.arity) {
    case Arity::any: return "";
    case Arity::none: return n == 0 ? "" : name + ": MUST HAVE NO ARGUMENTS";
    case Arity::one: return n == 1 ? "" : name + ": MUST HAVE ONE ARGUMENT";
    case Arity::one_string:
      if (n != 1) return name + ": MUST HAVE ONE ARGUMENT";
      return args[0].kind == IppdmeItem::Kind::string ? "" : name + ": ARGUMENT MUST BE STRING";
    case Arity::one_integer:
      if (n != 1) return name + ": MUST HAVE ONE ARGUMENT";
      return is_integer(args[0]) ? "" : name + ": ARGUMENT MUST BE INTEGER";
    case Arity::one_positive:
      if (n != 1) return name + ": MUST HAVE ONE ARGUMENT";
      if (args[0].kind != IppdmeItem::Kind::number) return name + ": ARGUMENT MUST BE A NUMBER";
      return std::strtod(args[0].text.c_str(), nullptr) > 0 ? "" : name + ": ARGUMENT MUST BE POSITIVE";
    case Arity::one_event_tag:
      if (n != 1) return name + ": MUST HAVE ONE ARGUMENT";
      return args[0].kind == IppdmeItem::Kind::keyword && args[0].text.size() == 5 && args[0].text[0] == 'E' &&
                     std::all_of(args[0].text.begin() + 1, args[0].text.end(), is_digit)
                 ? ""
                 : name + ": ARGUMENT MUST BE EVENT TAG";
    case Arity::four: return n == 4 && numbers() ? "" : name + (n == 4 ? ": BAD ARGUMENTS" : ": MUST HAVE 4 ARGUMENTS");
    case Arity::seven:
      // SetCsyTransformation names its system first, then six numbers.
      if (n != 7) return name + ": MUST HAVE 7 ARGUMENTS";
      return std::all_of(args.begin() + (name == "SetCsyTransformation" ? 1 : 0), args.end(),
                         [](const IppdmeItem& a) { return a.kind == IppdmeItem::Kind::number; })
                 ? ""
                 : name + ": BAD ARGUMENTS";
    case Arity::four_or_eight:
      return (n == 4 || n == 8) && numbers() ? "" : name + (n == 4 || n == 8 ? ": BAD ARGUMENTS" : ": MUST HAVE 4 OR 8 ARGUMENTS");
    case Arity::seven_or_fourteen:
      return (n == 7 || n == 14) && numbers() ? ""
                                              : name + (n == 7 || n == 14 ? ": BAD ARGUMENTS" : ": MUST HAVE 7 OR 14 ARGUMENTS");
  }
  return "";
}

}  // namespace

std::string ippdme_number_error(std::string_view t, int max_digits) {
  switch (number_problem(t, max_digits)) {
    case NumberProblem::none: return "";
    case NumberProblem::two_dots: return "BAD NUMBER TWO DECIMAL POINTS";
    case NumberProblem::no_digits: return "BAD NUMBER NO DIGITS";
    case NumberProblem::too_many_digits: return "BAD NUMBER MORE THAN " + std::to_string(max_digits) + " DIGITS";
    case NumberProblem::exponent: return "BAD E NUMBER EXPONENT MUST HAVE ONE TWO OR THREE DIGITS";
    case NumberProblem::other: break;
  }
  return "BAD NUMBER";
}

std::string parse_ippdme_command(std::string_view line, IppdmeCommand& out) {
  if (line.size() < 6) return "NOT A COMMAND (TAG, SPACE, COMMAND)";
  const bool event = line[0] == 'E';
  int number = 0;
  for (std::size_t k = event ? 1 : 0; k < 5; ++k) {
    if (!is_digit(line[k])) return "BAD TAG CHARACTER";
    number = 10 * number + (line[k] - '0');
  }
  if (line[5] != ' ') return "NO SPACE AT POS 6";
  // Tag 0 is not a command's (a server's event answers use E0000).
  if (number == 0) return event ? "TAG NUMBER OUT OF RANGE FOR EVENT TAG" : "TAG NUMBER OUT OF RANGE FOR COMMAND TAG";
  out.tag.assign(line.substr(0, 5));
  out.event = event;
  out.number = number;
  std::size_t k = 6;
  while (k < line.size() && is_letter(line[k])) ++k;
  out.name.assign(line.substr(6, k - 6));
  const CommandShape* shape = find_command(out.name);
  if (!shape) return "BAD COMMAND NAME " + quote_field(std::string(line.substr(6, std::min<std::size_t>(k - 6, 40))));
  while (k < line.size() && line[k] == ' ') ++k;  // a space next to a parenthesis is allowed
  if (k >= line.size() || line[k] != '(') return out.name + ": BAD CHARACTER AFTER KEYWORD";
  if (shape->event && !event) return out.name + ": EVENT COMMAND MUST HAVE EVENT TAG";
  if (!shape->event && event) return out.name + ": NON EVENT COMMAND MUST NOT HAVE EVENT TAG";
  Scanner scan(line.substr(k + 1), kIppdmeDigits);
  out.arguments.clear();
  if (!scan.list(out.arguments, 0, false)) return out.name + ": " + scan.error();
  if (k + 1 + scan.pos() != line.size()) return out.name + ": BAD CHARACTER AFTER COMMAND END";
  return check_arity(*shape, out.arguments);
}

std::string parse_ippdme_items(std::string_view text, std::vector<IppdmeItem>& out) {
  out.clear();
  Scanner scan(measurement_fields::trimmed(text), kIppdmeAnswerDigits);
  return scan.list(out, 0, true) ? "" : scan.error();
}

std::string ippdme_point_items(const std::vector<IppdmeItem>& items, IppdmePointItems& out) {
  out = IppdmePointItems{};
  for (const IppdmeItem& it : items) {
    if (it.kind != IppdmeItem::Kind::keyword || !it.has_arguments) {
      out.only_point_items = false;
      continue;
    }
    const std::string& key = it.text;
    const bool ijk = key == "IJK";
    std::optional<double>* one = key == "X" ? &out.x : key == "Y" ? &out.y : key == "Z" ? &out.z
                                 : key == "ER" ? &out.er : key == "Tool.A" ? &out.tool_a
                                 : key == "Tool.B" ? &out.tool_b : key == "Tool.C" ? &out.tool_c : nullptr;
    if (!one && !ijk) {
      out.only_point_items = false;
      continue;
    }
    const std::size_t want = ijk ? 3 : 1;
    if (it.arguments.size() != want ||
        !std::all_of(it.arguments.begin(), it.arguments.end(),
                     [](const IppdmeItem& a) { return a.kind == IppdmeItem::Kind::number; }))
      return key + "() needs " + (ijk ? "three numbers" : "one number");
    double v[3];
    for (std::size_t a = 0; a < want; ++a)
      if (!measurement_fields::try_number(it.arguments[a].text, v[a]) || !std::isfinite(v[a]))
        return key + "(): " + it.arguments[a].text + " is not a finite number";
    if (ijk) {
      if (out.ijk) return "IJK() appears twice";
      out.ijk = Eigen::Vector3d(v[0], v[1], v[2]);
    } else {
      if (*one) return key + "() appears twice";
      *one = v[0];
    }
  }
  return "";
}

bool ippdme_point_items_fast(std::string_view s, int max_digits, IppdmePointItems& out) {
  out = IppdmePointItems{};
  std::size_t k = 0;
  auto skip = [&] {
    while (k < s.size() && s[k] == ' ') ++k;
  };
  skip();  // next to the command's '(' or at the data's start (trimmed)
  if (k == s.size()) return true;
  while (true) {
    const std::size_t key_start = k;
    while (k < s.size() && (is_letter(s[k]) || s[k] == '.')) ++k;
    const std::string_view key = s.substr(key_start, k - key_start);
    if (k >= s.size() || s[k] != '(') return false;
    ++k;
    const bool ijk = key == "IJK";
    std::optional<double>* one = key == "X" ? &out.x : key == "Y" ? &out.y : key == "Z" ? &out.z
                                 : key == "ER" ? &out.er : key == "Tool.A" ? &out.tool_a
                                 : key == "Tool.B" ? &out.tool_b : key == "Tool.C" ? &out.tool_c : nullptr;
    if (!one && !ijk) return false;
    if (ijk ? out.ijk.has_value() : one->has_value()) return false;
    double v[3];
    const int want = ijk ? 3 : 1;
    for (int a = 0; a < want; ++a) {
      skip();
      if (!scan_number(s, k, max_digits, v[a])) return false;
      skip();
      if (k >= s.size() || s[k] != (a + 1 < want ? ',' : ')')) return false;
      ++k;
    }
    if (ijk) out.ijk = Eigen::Vector3d(v[0], v[1], v[2]);
    else *one = v[0];
    skip();
    if (k == s.size()) return true;
    if (s[k] != ',') return false;
    ++k;
    skip();
    if (k == s.size()) return false;
  }
}

}  // namespace furrow

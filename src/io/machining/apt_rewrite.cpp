#include "io/machining/apt_rewrite.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <unordered_map>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/machining/apt_reader.hpp"
#include "io/machining/apt_statements.hpp"
#include "io/part_file.hpp"

namespace furrow {

namespace {

double number_of(const std::string& text) {
  double v = 0;
  parse_finite(text, v);  // the reader accepted every value already
  return v;
}

int decimals_of(const std::string& number) {
  const auto dot = number.find('.');
  if (dot == std::string::npos) return 0;
  std::size_t end = dot + 1;
  while (end < number.size() && number[end] >= '0' && number[end] <= '9') ++end;
  return static_cast<int>(end - dot - 1);
}

std::string format_value(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string s = buffer;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // no "-0.0000"
  return s;
}

bool is_motion(const std::string& major) {
  return major == "GOTO" || major == "FROM" || major == "GODLTA" || major == "TLON,GOFWD";
}

// The reader's points of a statement and where they are to go.
struct Target {
  std::vector<Eigen::Vector3d> from, to;
};

struct Edit {
  std::size_t begin, end;
  std::string text;
};

class AptWriter {
 public:
  AptWriter(const std::string& name, const std::vector<std::string>& lines, int decimals, double scale,
            ProgramRewrite& out)
      : name_(name), lines_(lines), edits_(lines.size() + 1), replaced_(lines.size() + 1),
        removed_(lines.size() + 1, false), extra_(lines.size() + 1), decimals_(decimals), scale_(scale), out_(out) {
    out_.unit_mm = scale;
  }

  void statement(const AptStatement& s, const Target& t);

  // The file written again; `endings[k]` is line k + 1's ending.
  std::string text(const std::vector<std::string>& endings) const {
    std::string text;
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      const int number = static_cast<int>(k + 1);
      if (removed_[number]) continue;
      text += replaced_[number] ? *replaced_[number] : apply(lines_[k], edits_[number]);
      for (const std::string& extra : extra_[number]) text += (endings[k].empty() ? "\n" : endings[k]) + extra;
      text += endings[k];
    }
    return text;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + what);
  }

  static std::string apply(const std::string& line, std::vector<Edit> edits) {
    if (edits.empty()) return line;
    std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin < b.begin; });
    std::string out;
    std::size_t at = 0;
    for (const Edit& e : edits) {
      out.append(line, at, e.begin - at);
      out += e.text;
      at = e.end;
    }
    out.append(line, at, std::string::npos);
    return out;
  }

  // Value `k` of `s` replaced by `text` (it must have one place).
  void replace(const AptStatement& s, std::size_t k, const std::string& text) {
    const AptSpan& span = s.spans.at(k);
    if (span.line == 0)
      fail(s.line, s.major + "/: value " + std::to_string(k + 1) +
                       " must be rewritten but is split over a continuation line");
    edits_[span.line].push_back({span.begin, span.end, text});
  }

  // The separator written between values 1 and 2 ("," or ", "), and the
  // text of values 4-6 (a tool axis) with the separators before them.
  std::string separator(const AptStatement& s) const {
    if (s.spans.size() >= 2 && s.spans[0].line != 0 && s.spans[0].line == s.spans[1].line)
      return lines_[s.spans[0].line - 1].substr(s.spans[0].end, s.spans[1].begin - s.spans[0].end);
    return ",";
  }
  std::string axis_tail(const AptStatement& s) const {
    if (s.spans.size() == 6 && s.spans[2].line != 0 && s.spans[2].line == s.spans[5].line)
      return lines_[s.spans[2].line - 1].substr(s.spans[2].end, s.spans[5].end - s.spans[2].end);
    return {};
  }

  // "x<sep>y<sep>z" of a tip [mm]; `reached` where the program then is.
  std::string coordinates(const Eigen::Vector3d& p, const std::string& sep, Eigen::Vector3d& reached) const {
    std::string text;
    for (int a = 0; a < 3; ++a) {
      const std::string w = format_value(p[a] / scale_, decimals_);
      reached[a] = number_of(w) * scale_;
      text += (a ? sep : std::string()) + w;
    }
    return text;
  }

  // An arc written as GOTO/ statements through `points`: the first replaces
  // the statement's first three values (GOTO/ on one line) or the whole
  // statement, the others follow it.
  void split(const AptStatement& s, const std::vector<Eigen::Vector3d>& points, bool keep_values) {
    const std::string sep = separator(s);
    const std::string tail = keep_values ? axis_tail(s) : std::string();
    Eigen::Vector3d reached = now_;
    const std::string first = coordinates(points.front(), sep, reached);
    const bool in_place = keep_values && s.line == s.last_line && s.spans.size() >= 3 && s.spans[0].line == s.line &&
                          s.spans[2].line == s.line;
    if (in_place) {
      edits_[s.line].push_back({s.spans[0].begin, s.spans[2].end, first});
    } else {
      const std::string& line = lines_[s.line - 1];
      const std::string indent = line.substr(0, line.find_first_not_of(" \t") == std::string::npos
                                                    ? 0
                                                    : line.find_first_not_of(" \t"));
      replaced_[s.line] = indent + "GOTO/" + first + tail;
      for (int k = s.line + 1; k <= s.last_line; ++k) removed_[k] = true;
      out_.lines_removed += static_cast<std::size_t>(s.last_line - s.line);
    }
    for (std::size_t i = 1; i < points.size(); ++i)
      extra_[s.line].push_back("GOTO/" + coordinates(points[i], sep, reached) + tail);
    now_ = reached;
    out_.words_rewritten += 3;
    ++out_.lines_moved;
    ++out_.arcs_split;
    out_.lines_inserted += points.size() - 1;
  }

  // Whether an arc with these points must be written again.
  bool arc_moved(const Target& t) const {
    if (known_ && now_ != orig_) return true;
    const double half_unit = 0.5 * std::pow(10.0, -decimals_) * scale_;
    for (std::size_t i = 0; i < t.to.size(); ++i)
      if ((t.to[i] - t.from[i]).cwiseAbs().maxCoeff() > half_unit) return true;
    return false;
  }

  void straight(const AptStatement& s, const Target& t);

  std::string name_;
  const std::vector<std::string>& lines_;
  std::vector<std::vector<Edit>> edits_;                // per line (1-based)
  std::vector<std::optional<std::string>> replaced_;  // a line written anew
  std::vector<bool> removed_;
  std::vector<std::vector<std::string>> extra_;  // lines inserted after a line
  int decimals_;
  double scale_;  // mm per unit of the statements read so far (UNITS/)
  ProgramRewrite& out_;
  bool known_ = false;  // a position has been set
  bool rapid_ = false;  // RAPID applies to the next motion
  Eigen::Vector3d orig_ = Eigen::Vector3d::Zero();  // the original program's position [mm]
  Eigen::Vector3d now_ = Eigen::Vector3d::Zero();   // the rewritten program's
  const AptStatement* circle_ = nullptr;             // a CIRCLE/ waiting for its GOTO/
};

void AptWriter::statement(const AptStatement& s, const Target& t) {
  const std::string& m = s.major;
  if (m == "UNITS") {
    scale_ = s.params.at(0) == "MM" ? 1.0 : 25.4;
    out_.unit_mm = std::max(out_.unit_mm, scale_);
    return;
  }
  if (m == "RAPID") {
    rapid_ = true;
    return;
  }
  if (m == "CIRCLE") {
    circle_ = &s;
    return;
  }
  if (m == "TLON,GOFWD") {
    const Eigen::Vector3d end = t.from.empty() ? orig_ : t.from.back();
    if (!t.to.empty() && arc_moved(t)) {
      split(s, t.to, false);
    } else {
      now_ = end;
    }
    orig_ = end;
    return;
  }
  if (m == "GOTO" || m == "FROM" || m == "GODLTA") return straight(s, t);
}

void AptWriter::straight(const AptStatement& s, const Target& t) {
  const std::string& m = s.major;
  std::vector<double> v;
  for (const std::string& p : s.params) v.push_back(number_of(p));
  // As the reader computes it, so that the points compare exactly.
  Eigen::Vector3d end;
  if (m == "GODLTA")
    end = orig_ + (v.size() == 1 ? Eigen::Vector3d(0, 0, v[0]) : Eigen::Vector3d(v[0], v[1], v[2])) * scale_;
  else
    end = Eigen::Vector3d(v[0], v[1], v[2]) * scale_;
  const bool cut = m != "FROM" && !rapid_;
  rapid_ = false;
  if (m == "GOTO" && circle_) {
    const AptStatement& circle = *circle_;
    circle_ = nullptr;
    if (arc_moved(t)) {
      for (int k = circle.line; k <= circle.last_line; ++k) removed_[k] = true;
      out_.lines_removed += static_cast<std::size_t>(circle.last_line - circle.line + 1);
      split(s, t.to.empty() ? std::vector<Eigen::Vector3d>{now_} : t.to, true);
    } else {
      now_ = end;
    }
    orig_ = end;
    known_ = true;
    return;
  }
  if (!cut && !t.from.empty() && t.from.back() != end)
    fail(s.line, "the start of the pass moved, but the statement before its first cut does not end there");
  Eigen::Vector3d e = end;  // where the statement must now end
  if (!t.to.empty())
    e = t.to.back();
  else if (cut && known_ && end == orig_)
    e = now_;  // a zero-length cut stays with the tool
  Eigen::Vector3d reached = end;
  bool changed = false;
  if (m == "GODLTA" && v.size() == 1) {
    std::string w[3];
    for (int a = 0; a < 3; ++a) w[a] = format_value((e[a] - now_[a]) / scale_, decimals_);
    if (number_of(w[0]) == 0 && number_of(w[1]) == 0) {
      if (number_of(w[2]) != v[0]) {
        replace(s, 0, w[2]);
        ++out_.words_rewritten;
        changed = true;
      }
      reached = now_ + Eigen::Vector3d(0, 0, number_of(w[2]) * scale_);
    } else {
      const std::string sep = ",";
      replace(s, 0, w[0] + sep + w[1] + sep + w[2]);
      ++out_.words_rewritten;
      out_.words_added += 2;
      changed = true;
      for (int a = 0; a < 3; ++a) reached[a] = now_[a] + number_of(w[a]) * scale_;
    }
  } else {
    for (int a = 0; a < 3; ++a) {
      const double wanted = m == "GODLTA" ? (e[a] - now_[a]) / scale_ : e[a] / scale_;
      const std::string w = format_value(wanted, decimals_);
      double written = v[static_cast<std::size_t>(a)];
      if (number_of(w) != written) {
        replace(s, static_cast<std::size_t>(a), w);
        written = number_of(w);
        ++out_.words_rewritten;
        changed = true;
      }
      reached[a] = m == "GODLTA" ? now_[a] + written * scale_ : written * scale_;
    }
  }
  if (changed) ++out_.lines_moved;
  orig_ = end;
  now_ = reached;
  known_ = true;
}

}  // namespace

ProgramRewrite rewrite_apt(const std::string& text, const std::string& name, const ToolpathReadOptions& options,
                           const std::vector<std::vector<Eigen::Vector3d>>& tips) {
  const Toolpath path = parse_apt(text, name, options);
  if (tips.size() != path.passes.size())
    throw InputError(name + ": " + std::to_string(tips.size()) + " passes of moved tips for a file of " +
                     std::to_string(path.passes.size()));
  std::string body = text;
  ProgramRewrite result;
  std::string out_text;
  const std::string bom = "\xEF\xBB\xBF";
  if (body.compare(0, bom.size(), bom) == 0) {
    out_text = bom;
    body.erase(0, bom.size());
  }
  const std::vector<AptStatement> statements = split_apt_statements(body, name);
  std::unordered_map<int, std::size_t> of_line;
  for (std::size_t k = 0; k < statements.size(); ++k) of_line[statements[k].line] = k;
  std::vector<Target> targets(statements.size());
  for (std::size_t p = 0; p < tips.size(); ++p) {
    const auto& points = path.passes[p].points;
    if (tips[p].size() != points.size())
      throw InputError(name + ": pass " + std::to_string(p + 1) + " has " + std::to_string(tips[p].size()) +
                       " moved tips for " + std::to_string(points.size()) + " points");
    for (std::size_t i = 1; i < points.size(); ++i) {
      Target& t = targets[of_line.at(points[i].line)];
      t.from.push_back(points[i].position);
      t.to.push_back(tips[p][i]);
    }
    if (tips[p][0] == points[0].position) continue;
    // The pass starts where the motion statement before its first cut left
    // the tool (FROM/, a RAPID GOTO/ or GODLTA/).
    std::size_t k = of_line.at(points[1].line);
    bool found = false;
    while (k > 0 && !found) found = is_motion(statements[--k].major);
    if (!found || statements[k].major == "TLON,GOFWD" || !targets[k].to.empty())
      throw InputError(name + ":" + std::to_string(points[1].line) +
                       ": the start of the pass moved, but no straight move before it ends there");
    targets[k].from.push_back(points[0].position);
    targets[k].to.push_back(tips[p][0]);
  }

  // The decimals of the file's coordinates.
  int decimals = 0;
  for (const AptStatement& s : statements) {
    if (s.major != "GOTO" && s.major != "FROM" && s.major != "GODLTA") continue;
    const std::size_t n = s.major == "GODLTA" ? s.params.size() : std::min<std::size_t>(3, s.params.size());
    for (std::size_t k = 0; k < n; ++k) decimals = std::max(decimals, decimals_of(s.params[k]));
  }
  result.decimals = decimals < 3 ? 4 : decimals;

  std::vector<std::string> lines, endings;
  for (std::size_t begin = 0; begin < body.size();) {
    std::size_t end = body.find('\n', begin);
    const bool has_newline = end != std::string::npos;
    if (!has_newline) end = body.size();
    std::string line = body.substr(begin, end - begin);
    std::string ending = has_newline ? "\n" : "";
    if (!line.empty() && line.back() == '\r') {
      line.pop_back();
      ending = "\r" + ending;
    }
    lines.push_back(std::move(line));
    endings.push_back(std::move(ending));
    begin = end + 1;
  }
  AptWriter writer(name, lines, result.decimals, units_to_mm(options.units, name + ": units"), result);
  for (std::size_t k = 0; k < statements.size(); ++k) writer.statement(statements[k], targets[k]);
  result.text = out_text + writer.text(endings);
  return result;
}

}  // namespace furrow

#include "io/machining/gcode_rewrite.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/machining/gcode_reader.hpp"

namespace furrow {

namespace {

// A word of a line outside comments, split as the reader splits it.
struct Token {
  char letter = 0;
  std::size_t begin = 0, end = 0;  // bytes of the letter through the number
  std::string number;              // as written
};

std::vector<Token> tokens_of(const std::string& line) {
  std::vector<Token> out;
  const auto first = line.find_first_not_of(" \t");
  if (first == std::string::npos || line[first] == '%') return out;
  int depth = 0;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == '(' || c == ')' || depth > 0) {
      ++i;
      continue;
    }
    if (c == ';') break;
    if (!std::isalpha(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    Token t;
    t.letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    t.begin = i++;
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    while (i < line.size() && (std::isdigit(static_cast<unsigned char>(line[i])) || line[i] == '.' ||
                               line[i] == '-' || line[i] == '+'))
      t.number += line[i++];
    t.end = i;
    out.push_back(std::move(t));
  }
  return out;
}

double value_of(const std::string& number) {
  double v = 0;
  parse_finite(number, v);  // the reader accepted every word already
  return v;
}

int decimals_of(const std::string& number) {
  const auto dot = number.find('.');
  return dot == std::string::npos ? 0 : static_cast<int>(number.size() - dot - 1);
}

std::string format_value(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string s = buffer;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // no "-0.0000"
  return s;
}

int motion_of(const Token& t) {
  if (t.letter != 'G') return -1;
  const double g = value_of(t.number);
  return g == 0 || g == 1 || g == 2 || g == 3 ? static_cast<int>(g) : -1;
}

bool is_axis(char letter) { return letter == 'X' || letter == 'Y' || letter == 'Z'; }
bool is_arc_word(char letter) { return letter == 'I' || letter == 'J' || letter == 'K' || letter == 'R'; }

struct Edit {
  std::size_t begin, end;
  std::string text;
};

// Edits sorted by position, none overlapping; an insertion has begin == end
// and goes before a word replaced at the same position (a Y added in front
// of a rewritten Z: "G1 Z0." becoming "G1 Y10.09 Z-0.05").
std::string apply_edits(const std::string& line, std::vector<Edit> edits) {
  std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
    return a.begin < b.begin || (a.begin == b.begin && a.end == a.begin && b.end != b.begin);
  });
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

// Where each line's block and each moved point are.
struct LineTarget {
  std::vector<Eigen::Vector3d> from, to;  // the reader's points of the line and their new positions
};

class Rewriter {
 public:
  Rewriter(const std::string& name, int decimals) : name_(name), decimals_(decimals) {}

  // The line `line` (without its ending) of block `b`, written again.
  std::string block(const std::string& line, const GcodeMotionBlock& b, const LineTarget& target, GcodeRewrite& out);
  // A line without a block: only its modal G0-G3 is followed.
  void other(const std::string& line) {
    for (const Token& t : tokens_of(line))
      if (motion_of(t) >= 0) modal_ = motion_of(t);
  }
  std::vector<std::string> extra_lines;  // segment lines after the current one

 private:
  struct Written {
    std::string text;  // the number
    double reached;    // where the rewritten program is after it [mm]
  };
  // The word for `axis` that ends at `e` [mm] from `start` (the rewritten
  // program's position before the line).
  Written word(const GcodeMotionBlock& b, int axis, double e, const double* start) const {
    double w;
    if (b.absolute) {
      if (!b.shift_known[axis])
        throw InputError(name_ + ":" + std::to_string(b.line) + ": " + char('X' + axis) +
                         " must be written to move the line, but its work offset is not in the file");
      w = (e - b.shift[axis]) / b.scale;
    } else {
      w = (e - start[axis]) / b.scale;
    }
    Written out{format_value(w, decimals_), 0};
    const double value = value_of(out.text) * b.scale;  // as the reader converts it
    out.reached = b.absolute ? (b.shift[axis] != 0 ? value + b.shift[axis] : value) : start[axis] + value;
    return out;
  }
  std::string split_arc(const std::string& line, const std::vector<Token>& tokens, const GcodeMotionBlock& b,
                        const LineTarget& target, const std::string& sep, double* start, GcodeRewrite& out);

  std::string name_;
  int decimals_;
  double delta_[3] = {0, 0, 0};  // rewritten minus original position after the last block [mm]
  int modal_ = -1;               // the rewritten program's motion mode
};

std::string Rewriter::split_arc(const std::string& line, const std::vector<Token>& tokens, const GcodeMotionBlock& b,
                                const LineTarget& target, const std::string& sep, double* start,
                                GcodeRewrite& out) {
  const std::vector<Eigen::Vector3d> points =
      target.to.empty() ? std::vector<Eigen::Vector3d>{b.end} : target.to;
  auto words_to = [&](const Eigen::Vector3d& p) {
    std::string text;
    for (int a = 0; a < 3; ++a) {
      const Written w = word(b, a, p[a], start);
      text += (a ? sep : std::string()) + char('X' + a) + w.text;
      start[a] = w.reached;
    }
    return text;
  };
  std::vector<Edit> edits;
  const Token* anchor = nullptr;
  for (const Token& t : tokens) {
    if (motion_of(t) >= 2) edits.push_back({t.begin, t.end, "G1"});
    if (!is_axis(t.letter) && !is_arc_word(t.letter)) continue;
    if (!anchor) {
      anchor = &t;
      continue;
    }
    std::size_t from = t.begin;  // drop the word and the blanks before it
    while (from > 0 && (line[from - 1] == ' ' || line[from - 1] == '\t')) --from;
    edits.push_back({from, t.end, ""});
  }
  edits.push_back({anchor->begin, anchor->end, (b.motion_word ? std::string() : "G1" + sep) + words_to(points[0])});
  for (std::size_t i = 1; i < points.size(); ++i) extra_lines.push_back("G1" + sep + words_to(points[i]));
  ++out.arcs_split;
  ++out.lines_moved;
  out.lines_inserted += points.size() - 1;
  modal_ = 1;
  return apply_edits(line, std::move(edits));
}

std::string Rewriter::block(const std::string& line, const GcodeMotionBlock& b, const LineTarget& target,
                            GcodeRewrite& out) {
  extra_lines.clear();
  const std::vector<Token> tokens = tokens_of(line);
  // Words written together ("G1X1.Y2.") get added words the same way.
  bool compact = false;
  for (std::size_t k = 1; k < tokens.size(); ++k) compact = compact || tokens[k].begin == tokens[k - 1].end;
  const std::string sep = compact ? "" : " ";
  double start[3];  // the rewritten program's position before the line
  bool start_moved = false;
  for (int a = 0; a < 3; ++a) {
    start[a] = b.start_known[a] ? b.start[a] + delta_[a] : 0.0;
    start_moved = start_moved || (b.start_known[a] && delta_[a] != 0);
  }
  const bool all_known = b.start_known[0] && b.start_known[1] && b.start_known[2];
  // Where the line must end: its last moved point; a zero-length cut stays
  // with the tool; anything else where it was.
  Eigen::Vector3d e = b.end;
  if (!target.to.empty())
    e = target.to.back();
  else if (b.motion >= 1 && all_known && b.end == b.start)
    e = Eigen::Vector3d(start[0], start[1], start[2]);

  if (b.motion >= 2) {
    const double half_unit = 0.5 * std::pow(10.0, -decimals_) * b.scale;
    bool moved = start_moved;
    for (std::size_t i = 0; i < target.to.size(); ++i)
      moved = moved || (target.to[i] - target.from[i]).cwiseAbs().maxCoeff() > half_unit;
    if (moved) {
      const std::string written = split_arc(line, tokens, b, target, sep, start, out);
      for (int a = 0; a < 3; ++a) delta_[a] = start[a] - b.end[a];
      return written;
    }
  }

  std::vector<Edit> edits;
  std::map<std::size_t, std::string> inserts;  // position -> words, in axis order
  // A line that relied on a modal G2/G3 the rewritten program no longer has.
  if (!b.motion_word && modal_ != b.motion) {
    for (const Token& t : tokens)
      if (t.letter != 'N' && t.letter != 'O') {
        inserts[t.begin] += "G" + std::to_string(b.motion) + sep;
        break;
      }
  }
  modal_ = b.motion;
  bool changed = false;
  for (int a = 0; a < 3; ++a) {
    const char letter = static_cast<char>('X' + a);
    const Token* given = nullptr;
    for (const Token& t : tokens)
      if (t.letter == letter) given = &t;
    double reached = b.end[a];
    if (given) {
      const Written w = word(b, a, e[a], start);
      const double v0 = value_of(given->number);
      if (value_of(w.text) == v0) {
        reached = b.absolute ? b.end[a] : start[a] + v0 * b.scale;
      } else {
        edits.push_back({given->begin, given->end, std::string(1, letter) + w.text});
        reached = w.reached;
        ++out.words_rewritten;
        changed = true;
      }
    } else if (b.start_known[a]) {
      // The program stays at start[a] unless the line must end elsewhere.
      const Written w = word(b, a, e[a], start);
      const Written stay = word(b, a, start[a], start);
      reached = start[a];
      if (w.text != stay.text) {
        const std::string text = std::string(1, letter) + w.text;
        const Token* after = nullptr;   // first axis word after this axis
        const Token* before = nullptr;  // last axis word before it
        const Token* g = nullptr;       // last G or N word
        for (const Token& t : tokens) {
          if (is_axis(t.letter) && t.letter > letter && !after) after = &t;
          if (is_axis(t.letter) && t.letter < letter) before = &t;
          if (t.letter == 'G' || t.letter == 'N') g = &t;
        }
        if (after)
          inserts[after->begin] += text + sep;
        else if (before)
          inserts[before->end] += sep + text;
        else if (g)
          inserts[g->end] += sep + text;
        else
          inserts[tokens.front().begin] += text + sep;
        reached = w.reached;
        ++out.words_added;
        changed = true;
      }
    }
    delta_[a] = b.start_known[a] || given ? reached - b.end[a] : 0.0;
  }
  if (changed) ++out.lines_moved;
  for (auto& [at, text] : inserts) edits.push_back({at, at, text});
  return edits.empty() ? line : apply_edits(line, std::move(edits));
}

}  // namespace

GcodeRewrite rewrite_gcode(const std::string& text, const std::string& name, const ToolpathReadOptions& options,
                           const std::vector<std::vector<Eigen::Vector3d>>& tips) {
  std::vector<GcodeMotionBlock> blocks;
  const Toolpath path = parse_gcode(text, name, options, &blocks);
  if (tips.size() != path.passes.size())
    throw InputError(name + ": " + std::to_string(tips.size()) + " passes of moved tips for a program of " +
                     std::to_string(path.passes.size()));
  std::unordered_map<int, std::size_t> block_of;
  for (std::size_t i = 0; i < blocks.size(); ++i) block_of[blocks[i].line] = i;
  std::vector<LineTarget> targets(blocks.size());
  for (std::size_t p = 0; p < tips.size(); ++p) {
    const auto& points = path.passes[p].points;
    if (tips[p].size() != points.size())
      throw InputError(name + ": pass " + std::to_string(p + 1) + " has " + std::to_string(tips[p].size()) +
                       " moved tips for " + std::to_string(points.size()) + " points");
    for (std::size_t i = 1; i < points.size(); ++i) {
      LineTarget& t = targets[block_of.at(points[i].line)];
      t.from.push_back(points[i].position);
      t.to.push_back(tips[p][i]);
    }
    if (tips[p][0] == points[0].position) continue;
    // The pass starts where the line before its first cut left the tool.
    const std::size_t first = block_of.at(points[1].line);
    if (first == 0 || !targets[first - 1].to.empty() || blocks[first - 1].motion >= 2 ||
        blocks[first - 1].end != points[0].position)
      throw InputError(name + ":" + std::to_string(points[1].line) +
                       ": the start of the pass moved, but no straight line before it ends there");
    targets[first - 1].from.push_back(points[0].position);
    targets[first - 1].to.push_back(tips[p][0]);
  }

  // The decimals of the program's coordinates.
  std::string body = text;
  std::string out_text;
  const std::string bom = "\xEF\xBB\xBF";
  if (body.compare(0, bom.size(), bom) == 0) {
    out_text = bom;
    body.erase(0, bom.size());
  }
  int decimals = 0;
  for (std::size_t begin = 0; begin < body.size();) {
    std::size_t end = body.find('\n', begin);
    if (end == std::string::npos) end = body.size();
    for (const Token& t : tokens_of(body.substr(begin, end - begin)))
      if (is_axis(t.letter)) decimals = std::max(decimals, decimals_of(t.number));
    begin = end + 1;
  }
  GcodeRewrite result;
  result.decimals = decimals < 3 ? 4 : decimals;
  for (const GcodeMotionBlock& b : blocks) result.unit_mm = std::max(result.unit_mm, b.scale);

  Rewriter rewriter(name, result.decimals);
  std::size_t next_block = 0;
  int number = 0;
  out_text.reserve(body.size() + body.size() / 8);
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
    begin = end + 1;
    ++number;
    if (next_block < blocks.size() && blocks[next_block].line == number) {
      out_text += rewriter.block(line, blocks[next_block], targets[next_block], result);
      ++next_block;
      const std::string segment_ending = ending.empty() ? "\n" : ending;
      for (const std::string& extra : rewriter.extra_lines) out_text += segment_ending + extra;
    } else {
      rewriter.other(line);
      out_text += line;
    }
    out_text += ending;
  }
  result.text = std::move(out_text);
  return result;
}

}  // namespace furrow

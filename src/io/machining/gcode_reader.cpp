#include "io/machining/gcode_reader.hpp"

#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"
#include "io/machining/gcode_arc.hpp"
#include "io/machining/gcode_work_offsets.hpp"
#include "io/part_file.hpp"

namespace furrow {

namespace {

[[noreturn]] void fail_line(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

// A value cut and escaped by quote_field, for G-code's 'word' style.
std::string unquoted(const std::string& quoted_text) { return quoted_text.substr(1, quoted_text.size() - 2); }

// Removes comments: "( ... )" anywhere and everything after ';'.
std::string strip_comments(const std::string& line, const std::string& name, int number) {
  // Most lines have no comment: nothing to copy character by character.
  if (line.find_first_of("();") == std::string::npos) return line;
  std::string out;
  int depth = 0;
  for (char c : line) {
    if (c == ';' && depth == 0) break;
    if (c == '(') {
      ++depth;
      continue;
    }
    if (c == ')') {
      if (depth == 0) fail_line(name, number, "')' without a matching '('");
      --depth;
      continue;
    }
    if (depth == 0) out += c;
  }
  if (depth != 0) fail_line(name, number, "comment '(' is not closed on this line");
  return out;
}

struct Word {
  char letter;
  std::string text;  // number as written
  double value;
};

// Letters and their numbers, with or without spaces between words
// ("G90G20M03S2000", "G1X1.Y2.").
void split_words(const std::string& code, const std::string& name, int number, std::vector<Word>& words) {
  words.clear();
  std::size_t i = 0;
  while (i < code.size()) {
    const char c = code[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(c)))
      fail_line(name, number, "unexpected character '" + unquoted(quote_field(std::string(1, c))) + "'");
    Word w{static_cast<char>(std::toupper(static_cast<unsigned char>(c))), "", 0.0};
    ++i;
    while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
    while (i < code.size() && (std::isdigit(static_cast<unsigned char>(code[i])) || code[i] == '.' ||
                               code[i] == '-' || code[i] == '+'))
      w.text += code[i++];
    if (!parse_finite(w.text, w.value))
      fail_line(name, number, "word '" + unquoted(quote_field(std::string(1, w.letter) + w.text)) + "' has no valid number");
    words.push_back(std::move(w));
  }
}

bool is_ignored_g(double g) {
  static const double kIgnored[] = {40, 43, 49, 61, 64, 80, 94};
  for (double x : kIgnored)
    if (g == x) return true;
  return false;
}

bool is_canned_cycle(double g) {
  return g == 73 || g == 74 || g == 76 || (g >= 81 && g <= 89 && g == std::floor(g));
}

const char* plane_name(ArcPlane plane) {
  switch (plane) {
    case ArcPlane::xy: return "G17 (XY, centre words I J)";
    case ArcPlane::zx: return "G18 (ZX, centre words I K)";
    case ArcPlane::yz: return "G19 (YZ, centre words J K)";
  }
  return "";
}

// Whether centre word I, J or K (axis 0, 1, 2) belongs to the plane.
bool in_plane(ArcPlane plane, int axis) {
  switch (plane) {
    case ArcPlane::xy: return axis != 2;
    case ArcPlane::zx: return axis != 1;
    case ArcPlane::yz: return axis != 0;
  }
  return false;
}

}  // namespace

Toolpath parse_gcode(const std::string& text, const std::string& name, const ToolpathReadOptions& options,
                     std::vector<GcodeMotionBlock>* blocks) {
  Toolpath path;
  path.kind = ToolpathKind::tool_tips;
  path.source = name;
  double scale = units_to_mm(options.units, name + ": units");
  if (!(options.arc_tolerance > 0) || !std::isfinite(options.arc_tolerance))
    throw InputError(name + ": the arc chord tolerance must be a positive number of mm");
  ArcTolerances arc_tolerances;
  arc_tolerances.sag = options.arc_tolerance;
  bool absolute = true;
  int motion = -1;  // 0 rapid, 1 linear, 2 clockwise arc, 3 counter-clockwise arc, -1 none yet
  ArcPlane plane = ArcPlane::xy;
  GcodeWorkOffsets offsets;
  double feed = 0;
  double position[3] = {0, 0, 0};
  bool known[3] = {false, false, false};
  int selected_tool = -1;  // last T word; -1 none yet
  int loaded_tool = 0;     // in the spindle (ToolpathPass::tool)
  int unloaded_at = 0;     // line of a T0 M6 while the spindle is empty
  ToolpathPass current;
  auto close_pass = [&]() {
    if (current.points.size() >= 2) path.passes.push_back(std::move(current));
    current = ToolpathPass{};
  };

  const std::string body = strip_bom(text);
  std::vector<Word> words;
  long points = 0;
  int number = 0;
  std::size_t begin = 0;
  while (begin < body.size()) {
    std::size_t end = body.find('\n', begin);
    if (end == std::string::npos) end = body.size();
    std::string line = body.substr(begin, end - begin);
    begin = end + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string code = strip_comments(line, name, number);
    const auto first = code.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    if (code[first] == '%') continue;  // program delimiters
    split_words(code, name, number, words);

    double target[3] = {0, 0, 0};
    bool axis_given[3] = {false, false, false};
    double centre[3] = {0, 0, 0};
    bool centre_given[3] = {false, false, false};
    double radius = 0;
    bool radius_given = false;
    bool home = false;     // G28
    bool machine = false;  // G53
    bool change = false;   // M6
    bool g10 = false;      // G10: sets a work offset, moves nothing
    double l_word = 0, p_word = 0;
    std::string l_text;  // as written, for messages
    bool l_given = false, p_given = false;
    int motion_here = -1;  // motion word on this line
    for (const Word& w : words) {
      // Only errors and ignored words need the word as written.
      auto written = [&w]() { return std::string(1, w.letter) + w.text; };
      switch (w.letter) {
        case 'N':
        case 'O': break;  // line and program numbers
        case 'G': {
          const double g = w.value;
          if (g == 0 || g == 1 || g == 2 || g == 3) {
            motion = static_cast<int>(g);
            motion_here = motion;
          } else if (g == 17 || g == 18 || g == 19) {
            plane = static_cast<ArcPlane>(static_cast<int>(g));
          } else if (g == 20) {
            scale = 25.4;
          } else if (g == 21) {
            scale = 1.0;
          } else if (g == 90) {
            absolute = true;
          } else if (g == 91) {
            absolute = false;
          } else if (g == 91.1) {
            // Incremental arc centres: what this reader does anyway.
          } else if (g == 90.1) {
            fail_line(name, number, written() + " (absolute arc centres) is not supported; I J K are read as "
                                    "offsets from the arc's start (G91.1)");
          } else if (g == 28) {
            home = true;
          } else if (g == 53) {
            machine = true;
          } else if (const int system = GcodeWorkOffsets::system_of(g)) {
            offsets.select(system);
          } else if (g == 10) {
            g10 = true;
          } else if (g == 92 || g == 92.1 || g == 92.2 || g == 92.3 || g == 52) {
            fail_line(name, number, written() + " (coordinate system offset) is not supported: set work offsets "
                                    "with G10 L2 or G10 L20 and select them with G54-G59.3");
          } else if (g == 41 || g == 42) {
            fail_line(name, number, written() + " (cutter compensation) is not supported: the control would "
                                    "offset the path by a radius that is not in the file");
          } else if (is_canned_cycle(g)) {
            fail_line(name, number, written() + " (canned cycle) is not supported: the control would expand it "
                                    "into moves that are not in the file");
          } else if (is_ignored_g(g)) {
            path.ignored.push_back({number, written()});
          } else {
            fail_line(name, number, written() + " is not supported (G0 G1 G2 G3, G17-G21, G90 G91, G28, G53, "
                                    "G10 L2/L20 and G54-G59.3 move or place the tool here)");
          }
          break;
        }
        case 'X':
        case 'Y':
        case 'Z': {
          const int a = w.letter - 'X';
          if (axis_given[a]) fail_line(name, number, std::string(1, w.letter) + " is given twice");
          axis_given[a] = true;
          target[a] = w.value;
          break;
        }
        case 'I':
        case 'J':
        case 'K': {
          const int a = w.letter - 'I';
          if (centre_given[a]) fail_line(name, number, std::string(1, w.letter) + " is given twice");
          centre_given[a] = true;
          centre[a] = w.value;
          break;
        }
        case 'L':
        case 'P': {
          bool& given = w.letter == 'L' ? l_given : p_given;
          if (given) fail_line(name, number, std::string(1, w.letter) + " is given twice");
          given = true;
          (w.letter == 'L' ? l_word : p_word) = w.value;
          if (w.letter == 'L') l_text = unquoted(quote_field(w.text));
          break;
        }
        case 'R':
          if (radius_given) fail_line(name, number, "R is given twice");
          radius_given = true;
          radius = w.value;
          break;
        case 'F':
          if (!(w.value > 0)) fail_line(name, number, "feed F" + w.text + " must be positive");
          feed = w.value;
          break;
        case 'T':
          if (!(w.value >= 0 && w.value == std::floor(w.value) && w.value <= 1e6))
            fail_line(name, number, "tool number " + written() + " must be a whole number from 0 to 1000000");
          selected_tool = static_cast<int>(w.value);
          break;
        case 'M':
          if (w.value == 6) {
            change = true;
            break;
          }
          path.ignored.push_back({number, written()});
          break;
        case 'S':
        case 'H':
        case 'D':
          path.ignored.push_back({number, written()});
          break;
        default:
          fail_line(name, number, "word " + written() + " is not supported (no rotary axes in 3-axis paths)");
      }
    }
    if ((l_given || p_given) && !g10)
      fail_line(name, number, std::string("word ") + (l_given ? "L" : "P") + " is not supported outside G10 L2/L20");
    if (g10) {
      if (motion_here >= 0 || home || machine || change)
        fail_line(name, number, "G10 with a move or tool change on its line: give it a line of its own");
      if (!l_given || (l_word != 2 && l_word != 20)) {
        if (!l_given) fail_line(name, number, "G10 without L: only G10 L2 and G10 L20 (work offsets) are read");
        const std::string l = "G10 L" + l_text;
        if (l_word == 1 || l_word == 10 || l_word == 11)
          fail_line(name, number, l + " (tool table) is not supported: give the tools in a tool table (--tools)");
        fail_line(name, number, l + " is not supported: only G10 L2 and G10 L20 (work offsets) are read");
      }
      if (!p_given || !(p_word >= 0 && p_word <= GcodeWorkOffsets::kSystems && p_word == std::floor(p_word)))
        fail_line(name, number, "G10 L" + l_text + " needs P0 (the active system) or P1-P9 (G54-G59.3)");
      if (radius_given)
        fail_line(name, number, "G10 with R (a rotated work system) is not supported: the path would turn about Z");
      if (centre_given[0] || centre_given[1] || centre_given[2]) fail_line(name, number, "I J K belong to an arc (G2 or G3)");
      const int system = p_word == 0 ? offsets.active() : static_cast<int>(p_word);
      // As on LinuxCNC: the values are absolute whatever G90/G91, in the
      // program's units; axes not given keep their offset.
      for (int a = 0; a < 3; ++a) {
        if (!axis_given[a]) continue;
        const double value = target[a] * scale;
        limits::check_coordinate(value, name + ":" + std::to_string(number) + ": G10 " + char('X' + a));
        if (l_word == 2)
          offsets.set_absolute(system, a, value);
        else
          offsets.set_to_read(system, a, value, known[a], position[a]);
      }
      continue;
    }
    if (change) {
      // The spindle goes to the change position (machine coordinates) and
      // comes back with another tool: the pass ends and nothing is known of
      // where the tool is until the program says so.
      if (selected_tool < 0) fail_line(name, number, "M6 (tool change) without a tool number: no T word before it");
      if (home || machine || axis_given[0] || axis_given[1] || axis_given[2])
        fail_line(name, number, "M6 (tool change) with a move on its line: give the move on a line of its own");
      close_pass();
      RapidMove unchecked;
      unchecked.line = number;
      unchecked.tool = loaded_tool;
      path.rapids.push_back(unchecked);
      loaded_tool = selected_tool;
      unloaded_at = loaded_tool == 0 ? number : 0;
      path.tool_changes.push_back({number, loaded_tool});
      for (bool& k : known) k = false;
    }
    const bool arc_words = radius_given || centre_given[0] || centre_given[1] || centre_given[2];
    const bool arc = !home && !machine && (motion == 2 || motion == 3);
    if (arc_words && !arc) fail_line(name, number, "I J K R belong to an arc (G2 or G3)");

    if (home || machine) {
      // The tool goes to (or through) machine coordinates, which this file
      // does not place in the part frame: the pass ends, and the axes moved
      // are unknown until an absolute position names them again.
      // G53 moves at rapid whatever the motion mode (as on Fanuc controls);
      // a cutting word on its own line asks for something it cannot do.
      if (machine && motion_here > 0)
        fail_line(name, number, "G53 with a cutting move: machine coordinates are not in the part frame");
      const bool any = axis_given[0] || axis_given[1] || axis_given[2];
      close_pass();
      RapidMove unchecked;  // ends in machine coordinates: not placed in the part frame
      unchecked.line = number;
      unchecked.tool = loaded_tool;
      path.rapids.push_back(unchecked);
      for (int a = 0; a < 3; ++a)
        if (axis_given[a] || (home && !any)) known[a] = false;
      continue;
    }

    const bool moves = axis_given[0] || axis_given[1] || axis_given[2];
    if (!moves && !arc_words) continue;
    if (motion < 0) fail_line(name, number, "coordinates before any motion mode (G0, G1, G2 or G3)");
    // Unit and mode changes on this line apply to its own coordinates
    // (they were read above, in any word order).
    offsets.fix_frame();
    GcodeMotionBlock block;
    block.line = number;
    block.motion = motion;
    block.motion_word = motion_here >= 0;
    block.absolute = absolute;
    block.scale = scale;
    for (int a = 0; a < 3; ++a) {
      block.start_known[a] = known[a];
      block.start[a] = known[a] ? position[a] : 0.0;
      block.axis_given[a] = axis_given[a];
      block.shift_known[a] = offsets.shift(a, block.shift[a]);
    }
    double next[3];
    for (int a = 0; a < 3; ++a) {
      if (!axis_given[a]) {
        next[a] = position[a];
        continue;
      }
      const double value = target[a] * scale;
      if (absolute) {
        double shift = 0;
        if (!offsets.shift(a, shift))
          fail_line(name, number, std::string(1, char('X' + a)) + " in " + GcodeWorkOffsets::name(offsets.active()) +
                                      ": its offset from the part frame (" +
                                      GcodeWorkOffsets::name(offsets.frame_system()) +
                                      ", in effect at the first move) is not in the file (set both with G10 L2, "
                                      "or this one with G10 L20 where the position is known)");
        // Unshifted coordinates stay bit for bit as written.
        next[a] = shift != 0 ? value + shift : value;
      } else {
        if (!known[a])
          fail_line(name, number, std::string("relative move in ") + char('X' + a) +
                                      " before the position is known (give an absolute position first)");
        next[a] = position[a] + value;
      }
      // After unit conversion and relative moves (docs/formats.md "Limits").
      limits::check_coordinate(next[a], name + ":" + std::to_string(number) + ": " + char('X' + a));
    }
    if (blocks) {
      for (int a = 0; a < 3; ++a) block.end[a] = known[a] || axis_given[a] ? next[a] : 0.0;
      blocks->push_back(block);
    }
    if (motion == 0) {
      RapidMove rapid;
      rapid.line = number;
      rapid.tool = loaded_tool;
      rapid.known = known[0] && known[1] && known[2];  // where it starts
      for (int a = 0; a < 3; ++a) known[a] = known[a] || axis_given[a];
      rapid.known = rapid.known && known[0] && known[1] && known[2];
      if (rapid.known) {
        rapid.from = Eigen::Vector3d(position[0], position[1], position[2]);
        rapid.to = Eigen::Vector3d(next[0], next[1], next[2]);
      }
      // A rapid to where the tool already is moves nothing.
      if (!rapid.known || rapid.from != rapid.to) path.rapids.push_back(rapid);
      close_pass();
      for (int a = 0; a < 3; ++a) position[a] = next[a];
      continue;
    }
    // A cut starts from where the tool is: all three axes must be known
    // before it, or the pass would start at a guessed point.
    if (unloaded_at)
      fail_line(name, number, "cutting move with an empty spindle (T0 M6 at line " + std::to_string(unloaded_at) + ")");
    if (!(known[0] && known[1] && known[2]))
      fail_line(name, number, motion == 1 ? "cutting move before X, Y and Z are all known"
                                          : "arc before X, Y and Z are all known");
    for (int a = 0; a < 3; ++a) known[a] = known[a] || axis_given[a];

    auto tip = [&](const Eigen::Vector3d& p) {
      ToolpathPoint t;
      t.position = p;
      t.feed = feed;
      t.line = number;
      return t;
    };
    const Eigen::Vector3d from(position[0], position[1], position[2]);
    const Eigen::Vector3d to(next[0], next[1], next[2]);
    std::vector<Eigen::Vector3d> reached;
    if (motion == 1) {
      reached.push_back(to);
    } else {
      ArcMove move;
      move.start = from;
      move.end = to;
      move.plane = plane;
      move.clockwise = motion == 2;
      if (radius_given) {
        if (centre_given[0] || centre_given[1] || centre_given[2])
          fail_line(name, number, "an arc takes either R or I J K, not both");
        move.by_radius = true;
        move.radius = radius * scale;
      } else {
        bool any = false;
        for (int a = 0; a < 3; ++a) {
          if (!centre_given[a]) continue;
          if (!in_plane(plane, a))
            fail_line(name, number, std::string(1, char('I' + a)) + " is not a centre word in plane " +
                                        plane_name(plane));
          any = true;
          move.centre_offset[a] = centre[a] * scale;
        }
        if (!any) fail_line(name, number, std::string("arc without a centre (I J K) or radius (R) in plane ") +
                                              plane_name(plane));
      }
      try {
        reached = flatten_arc(move, arc_tolerances);
      } catch (const InputError& e) {
        fail_line(name, number, std::string(motion == 2 ? "G2" : "G3") + ": " + e.what());
      }
    }
    if (points + static_cast<long>(reached.size()) > limits::kMaxFilePoints)
      fail_line(name, number, "more than " + std::to_string(limits::kMaxFilePoints) +
                                  " tool-path points (docs/formats.md \"Limits\")");
    if (current.points.empty()) {
      current.points.push_back(tip(from));
      current.tool = loaded_tool;
    }
    for (const Eigen::Vector3d& p : reached)
      if ((p - current.points.back().position).norm() > 0) {  // zero-length moves add nothing
        current.points.push_back(tip(p));
        ++points;
      }
    for (int a = 0; a < 3; ++a) position[a] = next[a];
  }
  close_pass();
  if (path.passes.empty()) throw InputError(name + ": no cutting moves (G1, G2, G3) in the file");
  return path;
}

}  // namespace furrow

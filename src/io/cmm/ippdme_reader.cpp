#include "io/cmm/ippdme_reader.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <regex>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/ippdme_command.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "base/json_fields.hpp"

namespace furrow {

namespace {

[[noreturn]] void fail(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

struct Line {
  int number;
  std::string text;
};

std::vector<Line> crlf_lines(const std::string& file_text, const std::string& name) {
  const std::string text = strip_bom(file_text);  // a byte-order mark is not content
  std::vector<Line> lines;
  std::size_t start = 0;
  int number = 0;
  while (start < text.size()) {
    ++number;
    const std::size_t lf = text.find('\n', start);
    if (lf == std::string::npos) fail(name, number, "the last line is not ended by CR LF");
    if (lf == start || text[lf - 1] != '\r') fail(name, number, "line not ended by CR LF");
    // The commands are matched with std::regex, whose libstdc++ matcher
    // recurses once per character: a line of some 100 000 characters
    // overflowed the stack under fuzz_ippdme_program (docs/testing.md).
    // No line the writer emits is longer than a few hundred characters.
    if (lf - 1 - start > kMaxIppdmeLine)
      fail(name, number, "line longer than " + std::to_string(kMaxIppdmeLine) + " characters");
    lines.push_back({number, text.substr(start, lf - 1 - start)});
    start = lf + 1;
  }
  return lines;
}

// Removes spaces next to '(', ')' and ','; refuses any other space outside
// strings (NIST parserCmd: ILLEGAL SPACE).
std::string unspace(const std::string& s, const std::string& name, int line) {
  std::string out;
  bool in_string = false;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const char c = s[k];
    if (in_string) {
      if (c == '"') in_string = false;
      else if (c < 32 || c > 126) fail(name, line, "non-printable character in a string");
      out += c;
      continue;
    }
    if (c == ' ') {
      const char before = out.empty() ? '(' : out.back();
      std::size_t j = k;
      while (j < s.size() && s[j] == ' ') ++j;
      const char after = j < s.size() ? s[j] : ')';
      auto punct = [](char x) { return x == '(' || x == ')' || x == ','; };
      if (!punct(before) && !punct(after)) fail(name, line, "illegal space");
      continue;
    }
    if (c == '"') in_string = true;
    out += c;
  }
  if (in_string) fail(name, line, "unterminated string");
  return out;
}

double number(const std::string& text, const std::string& name, int line) {
  if (!is_ippdme_number(text)) fail(name, line, quote_field(text) + " is not an I++ DME number");
  return std::strtod(text.c_str(), nullptr);
}

Eigen::Vector3d xyz(const std::smatch& m, std::size_t first, const std::string& name, int line) {
  return {number(m[first], name, line), number(m[first + 1], name, line), number(m[first + 2], name, line)};
}

const std::string kNum = R"(([-+.0-9][-+.0-9eE]*))";

}  // namespace

bool is_ippdme_number(const std::string& t) { return ippdme_number_error(t).empty(); }

ProbeProgram parse_ippdme_program(const std::string& text, const std::string& name) {
  const std::vector<Line> lines = crlf_lines(text, name);
  const std::regex command_line(R"(([0-9]{5}) (.*))");
  const std::regex go_to("GoTo\\(X\\(" + kNum + "\\),Y\\(" + kNum + "\\),Z\\(" + kNum + "\\)\\)");
  const std::regex pt_meas("PtMeas\\(X\\(" + kNum + "\\),Y\\(" + kNum + "\\),Z\\(" + kNum + "\\),IJK\\(" + kNum +
                           "," + kNum + "," + kNum + "\\)\\)");
  const std::regex change_tool(R"re(ChangeTool\("([A-Za-z0-9_]+)"\))re");
  const std::regex set_prop("SetProp\\(Tool\\.(PtMeasPar\\.Approach|PtMeasPar\\.Retract|PtMeasPar\\.Search|"
                            "GoToPar\\.Speed|PtMeasPar\\.Speed)\\(" + kNum + "\\)\\)");

  ProbeProgram program;
  enum class Stage { start, home, csy, tool, approach, retract, search, move_speed, measure_speed, report, body, ended };
  Stage stage = Stage::start;
  int expected_tag = 1;
  long commands = 0;  // commands read so far, this one included
  bool aligned = false;  // the alignment points are behind us
  TipAngles tip;                              // selected, with an indexable head
  long changed_after = -1;                    // moves read when the tip changed before this point, -1: none
  int change_line = 0;
  std::size_t k = 0;
  std::vector<Eigen::Vector3d> moves;
  for (; k < lines.size() && lines[k].text != ":"; k += 2) {
    const Line& line = lines[k];
    std::smatch m;
    if (!std::regex_match(line.text, m, command_line))
      fail(name, line.number, "expected `TTTTT Command(...)` (five-digit tag, one space), got " + quote_field(line.text));
    const int tag = std::stoi(m[1]);
    if (tag != expected_tag)
      fail(name, line.number, "tag " + m[1].str() + " out of sequence (expected " + std::to_string(expected_tag) + ")");
    expected_tag = expected_tag == kMaxIppTag ? 1 : expected_tag + 1;
    ++commands;
    if (k + 1 >= lines.size() || lines[k + 1].text != "\\\\")
      fail(name, line.number + 1, "a command must be followed by a line holding \\\\");
    const std::string cmd = unspace(m[2], name, line.number);
    const int n = line.number;
    auto require = [&](Stage want, const char* what) {
      if (stage != want) fail(name, n, std::string(what) + " out of order");
    };
    std::smatch a;
    if (cmd == "StartSession()") {
      require(Stage::start, "StartSession");
      stage = Stage::home;
    } else if (cmd == "Home()") {
      require(Stage::home, "Home");
      stage = Stage::csy;
    } else if (cmd == "SetCoordSystem(PartCsy)" && stage == Stage::body) {
      // The end of the alignment: what was measured so far aligns the part.
      if (aligned || program.steps.empty()) fail(name, n, "SetCoordSystem(PartCsy) again without alignment points before it");
      aligned = true;
      if (changed_after >= 0) fail(name, change_line, "ChangeTool with no point after it");
      program.alignment_steps = std::move(program.steps);
      program.steps.clear();
      // The alignment is measured with the start tip, not as a tip's step.
      for (ProgramStep& step : program.alignment_steps) step.point.tip.reset();
      program.alignment_final_moves = std::move(moves);
      moves.clear();
    } else if (cmd == "SetCoordSystem(PartCsy)") {
      require(Stage::csy, "SetCoordSystem");
      stage = Stage::tool;
    } else if (std::regex_match(cmd, a, change_tool) && stage == Stage::body) {
      // A tip change of an indexable head (probe_program.hpp).
      const std::optional<TipSensor> t = split_tip_sensor(a[1]);
      if (!program.start_tip || !t || t->base != program.probe.name)
        fail(name, n, "ChangeTool may only change to another tip of the same probe (" + program.probe.name + "_A..B..)");
      if (changed_after >= 0 || t->tip == tip) fail(name, n, "ChangeTool does not change the tip here");
      changed_after = static_cast<long>(moves.size());
      change_line = n;
      tip = t->tip;
      if (std::find(program.tips.begin(), program.tips.end(), tip) == program.tips.end()) program.tips.push_back(tip);
    } else if (std::regex_match(cmd, a, change_tool)) {
      require(Stage::tool, "ChangeTool");
      program.probe.name = a[1];
      if (const std::optional<TipSensor> t = split_tip_sensor(a[1])) {
        program.probe.name = t->base;
        program.start_tip = tip = t->tip;
        program.tips.push_back(tip);
      }
      stage = Stage::approach;
    } else if (std::regex_match(cmd, a, set_prop)) {
      const std::string key = a[1];
      const double v = number(a[2], name, n);
      if (!(v > 0)) fail(name, n, key + " must be positive");
      if (key == "PtMeasPar.Approach")
        require(Stage::approach, "SetProp(Approach)"), program.approach = v, stage = Stage::retract;
      else if (key == "PtMeasPar.Retract")
        require(Stage::retract, "SetProp(Retract)"), program.retract = v, stage = Stage::search;
      else if (key == "PtMeasPar.Search")
        require(Stage::search, "SetProp(Search)"), program.search = v, stage = Stage::move_speed;
      else if (key == "GoToPar.Speed")
        require(Stage::move_speed, "SetProp(GoToPar.Speed)"), program.move_speed = v, stage = Stage::measure_speed;
      else
        require(Stage::measure_speed, "SetProp(PtMeasPar.Speed)"), program.measure_speed = v, stage = Stage::report;
    } else if (cmd == "OnPtMeasReport(X(),Y(),Z(),IJK())") {
      require(Stage::report, "OnPtMeasReport");
      stage = Stage::body;
    } else if (std::regex_match(cmd, a, go_to)) {
      require(Stage::body, "GoTo");
      moves.push_back(xyz(a, 1, name, n));
    } else if (std::regex_match(cmd, a, pt_meas)) {
      require(Stage::body, "PtMeas");
      const Eigen::Vector3d ijk = xyz(a, 4, name, n);
      if (!(ijk.norm() > 0)) fail(name, n, "PtMeas direction IJK has zero length");
      ProgramStep step;
      step.point.order = static_cast<int>(program.steps.size()) + 1;
      step.command = commands;
      step.point.xyz = xyz(a, 1, name, n);
      step.point.ijk = ijk.normalized();
      if (program.start_tip) step.point.tip = tip;
      if (changed_after >= 0 && changed_after != (moves.size() < 2 ? 0 : 1))
        fail(name, change_line, "a tip change belongs after the first move of a point with two or more moves, else before them");
      changed_after = -1;
      step.moves_before = std::move(moves);
      moves.clear();
      program.steps.push_back(std::move(step));
    } else if (cmd == "EndSession()") {
      require(Stage::body, "EndSession");
      stage = Stage::ended;
    } else {
      fail(name, n, quote_field(cmd) + " is not a command Furrow writes");
    }
  }
  if (stage != Stage::ended) fail(name, k < lines.size() ? lines[k].number : static_cast<int>(lines.size()), "the file does not end with EndSession()");
  if (k >= lines.size()) fail(name, static_cast<int>(lines.size()), "missing the closing `:` line");
  if (k + 2 < lines.size() || (k + 1 < lines.size() && lines[k + 1].text != ":"))
    fail(name, lines[k].number + 1, "text after the closing `:` line");
  if (changed_after >= 0) fail(name, change_line, "ChangeTool with no point after it");
  program.final_moves = std::move(moves);
  if (program.steps.empty()) throw InputError(name + ": the program measures no point");
  return program;
}

ProbeProgram read_ippdme_program(const std::string& path) {
  return parse_ippdme_program(json_fields::read_text(path), path);
}

}  // namespace furrow

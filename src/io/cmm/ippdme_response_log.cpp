#include "io/cmm/ippdme_response_log.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <vector>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace mf = measurement_fields;

namespace {

// "TTTTT X": the tag (1..99999) when `line` starts with five digits and a
// space followed by something; 0 otherwise.
int tag_of(std::string_view line) {
  if (line.size() < 7 || line[5] != ' ') return 0;
  int tag = 0;
  for (int k = 0; k < 5; ++k) {
    if (!std::isdigit(static_cast<unsigned char>(line[k]))) return 0;
    tag = 10 * tag + (line[k] - '0');
  }
  return tag;
}

bool is_response_mark(char c) { return c == '#' || c == '%' || c == '&' || c == '!'; }

std::string tag_text(int tag) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%05d", tag);
  return buf;
}

std::string command_id(int tag, int use) {
  return use == 1 ? tag_text(tag) : tag_text(tag) + "_" + std::to_string(use);
}

// The state of the command that currently holds a tag.
struct OpenCommand {
  bool open = false;
  int use = 0;          // how many commands had this tag so far
  int point = -1;       // index of its point, -1 before its data
  int error_line = 0;   // line of its first error response
  std::string error;    // that response's text
};

// X(..), Y(..), Z(..), IJK(.., .., ..) in any order, other items ignored.
void read_data(std::string_view data, const std::string& name, int line, MeasuredPoint& p) {
  double xyz[3];
  bool seen[3] = {false, false, false};
  std::size_t pos = 0;
  while (pos < data.size()) {
    while (pos < data.size() && (data[pos] == ' ' || data[pos] == ',')) ++pos;
    if (pos >= data.size()) break;
    const std::size_t open = data.find('(', pos);
    const std::size_t close = open == std::string_view::npos ? open : data.find(')', open);
    if (close == std::string_view::npos)
      mf::fail(name, line, "data: expected NAME(values), got " + quote_field(std::string(data.substr(pos))));
    std::string key(mf::trimmed(data.substr(pos, open - pos)));
    for (char& c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const std::string_view args = data.substr(open + 1, close - open - 1);
    if (key == "X" || key == "Y" || key == "Z") {
      const int a = key[0] - 'X';
      if (seen[a]) mf::fail(name, line, "data: " + key + "() appears twice");
      if (!mf::try_number(args, xyz[a]) || !std::isfinite(xyz[a])) xyz[a] = mf::number(args, name, line, key + "()");
      seen[a] = true;
    } else if (key == "IJK") {
      double v[3];
      std::size_t start = 0;
      for (int k = 0; k < 3; ++k) {
        const std::size_t comma = k < 2 ? args.find(',', start) : args.size();
        if (comma == std::string_view::npos || (k == 2 && args.find(',', start) != std::string_view::npos))
          mf::fail(name, line, "data: IJK() needs three numbers");
        v[k] = mf::number(args.substr(start, comma - start), name, line, "IJK()");
        start = comma + 1;
      }
      p.ijk = mf::unit_direction({v[0], v[1], v[2]}, name, line, "IJK()");
    }
    pos = close + 1;
  }
  if (!seen[0] || !seen[1] || !seen[2]) mf::fail(name, line, "data: X(), Y() and Z() are needed");
  p.xyz = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
}

}  // namespace

bool is_ippdme_response_log(std::string_view text) {
  bool answer = false, decided = false;
  mf::for_each_line(text, [&](int, std::string_view line) {
    if (decided || mf::trimmed(line).empty()) return;
    decided = true;
    answer = tag_of(line) > 0 && is_response_mark(line[6]);
  });
  return answer;
}

void parse_ippdme_response_log(std::string_view text, const std::string& name, const ProbeProgram* program,
                               const std::string& program_name, MeasurementSet& set) {
  std::vector<OpenCommand> commands(kMaxIppTag + 1);
  std::vector<int> tag_of_point;  // per point: tag and use, for the program
  set.points.reserve(mf::count_lines(text) / 3 + 1);
  // Closes the command on `tag`: an error response without data fails it.
  auto complete = [&](int tag) {
    OpenCommand& c = commands[tag];
    if (c.error_line && c.point < 0)
      mf::fail(name, c.error_line, "command " + command_id(tag, c.use) + " returned an error and no point: " + c.error);
    c.open = false;
  };
  auto start = [&](int tag, int line) {
    OpenCommand& c = commands[tag];
    if (c.open) mf::fail(name, line, "tag " + tag_text(tag) + " is used again before its command completed");
    c.open = true;
    ++c.use;
    c.point = -1;
    c.error_line = 0;
    c.error.clear();
  };
  mf::for_each_line(text, [&](int number, std::string_view line) {
    if (mf::trimmed(line).empty()) return;
    const int tag = tag_of(line);
    if (tag == 0) mf::fail(name, number, "expected a response \"TTTTT &|#|%|!\", got " + quote_field(std::string(line)));
    const char mark = line[6];
    if (!is_response_mark(mark)) return;  // the client's command, when the log records both sides
    OpenCommand& c = commands[tag];
    switch (mark) {
      case '&':
        start(tag, number);
        break;
      case '#': {
        if (!c.open) start(tag, number);  // a log that does not record acknowledgements
        if (c.point >= 0)
          mf::fail(name, number, "a second data line for command " + command_id(tag, c.use) + " (first on line " +
                                     std::to_string(set.points[c.point].line) + ")");
        MeasuredPoint p;
        p.line = number;
        p.id = command_id(tag, c.use);
        read_data(line.substr(7), name, number, p);
        c.point = static_cast<int>(set.points.size());
        tag_of_point.push_back(c.use * (kMaxIppTag + 1) + tag);
        mf::add_point(set, std::move(p), name);
        break;
      }
      case '!':
        if (!c.open) start(tag, number);
        if (!c.error_line) {
          c.error_line = number;
          c.error = std::string(mf::trimmed(line.substr(7)));
        }
        break;
      case '%':
        if (!c.open) mf::fail(name, number, "tag " + tag_text(tag) + " completes a command that was not started");
        complete(tag);
        break;
    }
  });
  for (int tag = 1; tag <= kMaxIppTag; ++tag)
    if (commands[tag].open) complete(tag);  // a log cut short: data so far counts, errors still fail
  set.ids_from_file = false;  // tags are not plan ids
  if (!program) return;

  // Each step's PtMeas command number, as the program reader counted them
  // (ProgramStep::command); command n has tag (n - 1) % 99999 + 1 and is the
  // (n - 1) / 99999 + 1-th use of that tag.
  // Alignment points (measured first) answer like the others: points on
  // the part with their nominals.
  std::vector<const ProgramStep*> steps;
  for (const ProgramStep& s : program->alignment_steps) steps.push_back(&s);
  for (const ProgramStep& s : program->steps) steps.push_back(&s);
  std::unordered_map<long, std::size_t> ptmeas;  // use * 100000 + tag -> step
  std::vector<long> step_key(steps.size());
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const long n = steps[s]->command - 1;
    if (n < 0) throw InputError(program_name + ": step " + std::to_string(s + 1) + " has no PtMeas command number");
    step_key[s] = (n / kMaxIppTag + 1) * (kMaxIppTag + 1) + n % kMaxIppTag + 1;
    ptmeas.emplace(step_key[s], s);
  }
  std::vector<char> answered(steps.size(), 0);
  for (std::size_t k = 0; k < set.points.size(); ++k) {
    MeasuredPoint& p = set.points[k];
    const auto it = ptmeas.find(tag_of_point[k]);
    if (it == ptmeas.end())
      mf::fail(name, p.line, "command " + p.id + " returned a point but is not a PtMeas of " + program_name);
    const PlannedPoint& planned = steps[it->second]->point;
    p.nominal = planned.xyz;
    p.nominal_ijk = planned.ijk;
    answered[it->second] = 1;
  }
  for (std::size_t s = 0; s < step_key.size(); ++s)
    if (!answered[s]) {
      const long key = step_key[s];
      const int tag = static_cast<int>(key % (kMaxIppTag + 1)), use = static_cast<int>(key / (kMaxIppTag + 1));
      throw InputError(name + ": PtMeas " + command_id(tag, use) + " of " + program_name +
                       " has no point in the log (not measured)");
    }
}

std::string ippdme_response_log_text(const MeasurementSet& set) {
  using mf::shortest;
  std::string out;
  out.reserve(set.points.size() * 160);
  int tag = 1;
  for (const MeasuredPoint& p : set.points) {
    const std::string t = tag_text(tag);
    out += t + " &\r\n" + t + " # X(" + shortest(p.xyz.x()) + "), Y(" + shortest(p.xyz.y()) + "), Z(" +
           shortest(p.xyz.z()) + ")";
    if (p.ijk) out += ", IJK(" + shortest(p.ijk->x()) + ", " + shortest(p.ijk->y()) + ", " + shortest(p.ijk->z()) + ")";
    out += "\r\n" + t + " %\r\n";
    tag = tag == kMaxIppTag ? 1 : tag + 1;
  }
  return out;
}

}  // namespace furrow

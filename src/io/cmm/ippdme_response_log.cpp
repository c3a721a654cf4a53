#include "io/cmm/ippdme_response_log.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <unordered_map>
#include <vector>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/ippdme_line_lexer.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace mf = measurement_fields;

namespace {

// Five digits, as tags are written ("%05d" without printf's cost: one per point).
std::string tag_text(int tag) {
  std::string text(5, '0');
  for (int k = 4; k >= 0 && tag > 0; --k, tag /= 10) text[static_cast<std::size_t>(k)] = static_cast<char>('0' + tag % 10);
  return text;
}

std::string command_id(int tag, int use) {
  return use == 1 ? tag_text(tag) : tag_text(tag) + "_" + std::to_string(use);
}

enum class Known { unknown, other, ptmeas };

// The state of the command that currently holds a tag.
struct OpenCommand {
  bool open = false;
  int use = 0;          // how many commands had this tag so far
  int point = -1;       // index of its point, -1 before its data
  bool reported = false;  // reported as not measured
  int error_line = 0;   // line of its first error response
  std::string error;    // that response's text
  Known known = Known::unknown;
  const IppdmePtMeas* ptmeas = nullptr;  // the program's, or the slot's
  int slot = -1;                         // the logged PtMeas it holds
  int start_line = 0;
};

// A command seen in the log, waiting for its first response. Kept per tag
// only until it is answered, so a log of any length holds at most one per tag.
struct Pending {
  bool set = false;
  Known known = Known::other;
  int slot = -1;  // the logged PtMeas
};

constexpr int kTags = kMaxIppTag + 1;

// Lexed a chunk ahead on a second thread (ippdme_line_lexer.hpp): about
// 40,000 lines of a session log, small enough for two chunks to cost next to
// nothing in memory, large enough for a thread a chunk to cost nothing in time.
constexpr std::size_t kLexChunkBytes = std::size_t{1} << 21;

long occurrence_key(int tag, int use) { return static_cast<long>(use) * kTags + tag; }

bool same_frame(const IppdmeFrame& a, const IppdmeFrame& b) {
  if (a.csy != b.csy || a.part.has_value() != b.part.has_value()) return false;
  return !a.part || a.part->matrix() == b.part->matrix();
}

class SessionReader {
 public:
  SessionReader(const std::string& name, const IppdmeSession* program, const std::string& program_name,
                MeasurementSet& set)
      : name_(name), program_(program), program_name_(program_name), set_(set), commands_(kTags), pending_(kTags) {
    if (program_) {
      for (std::size_t k = 0; k < program_->ptmeas.size(); ++k) {
        const IppdmePtMeas& p = program_->ptmeas[k];
        if (p.tag[0] == 'E') continue;
        program_ptmeas_.emplace(occurrence_key(std::stoi(p.tag), p.use), k);
      }
      answered_.assign(program_->ptmeas.size(), 0);
    }
  }

  void line(const IppdmeLexedLine& l, const IppdmePointItems* fast_items) {
    const int number = l.number, tag = l.tag;
    const std::string_view ipp = l.ipp;
    if (tag == -1) {
      // What a log records as sent or received without a tag of the spec: a
      // malformed command of the client (NIST's parser tests send them), which
      // the server refuses; no answer can belong to it.
      if (l.directed) return;
      mf::fail(name_, number, "not an I++ DME response or command: " + quote_field(std::string(ipp.substr(0, 200))));
    }
    const char mark = l.mark;
    if (!mark) return command(l, fast_items);
    const std::string_view rest = ipp.substr(7);
    if (mark == '#' && fast_items) {
      point_items_ = *fast_items;  // the usual answer of a PtMeas, read in place
      point_items_error_.clear();
    } else if (mark == '#' || mark == '!') {
      const std::string why = parse_ippdme_items(rest, items_);
      if (!why.empty()) mf::fail(name_, number, std::string(mark == '#' ? "data" : "error") + ": " + why);
      if (mark == '!' && (items_.size() != 1 || items_[0].text != "Error" || items_[0].arguments.size() != 4))
        mf::fail(name_, number, "error: expected Error(severity, number, \"command\", \"text\")");
      if (mark == '#') point_items_error_ = ippdme_point_items(items_, point_items_);
    }
    if (tag == -2) return;  // an event's answer: no command of the program
    OpenCommand& c = commands_[tag];
    switch (mark) {
      case '&':
        start(tag, number);
        break;
      case '#':
        if (!c.open) start(tag, number);  // a log that does not record acknowledgements
        data(tag, number);
        break;
      case '!':
        if (!c.open) start(tag, number);
        if (!c.error_line) {
          c.error_line = number;
          c.error = std::string(mf::trimmed(rest));
        }
        break;
      case '%':
        if (!c.open) mf::fail(name_, number, "tag " + tag_text(tag) + " completes a command that was not started");
        complete(tag, number);
        break;
    }
  }

  void finish() {
    for (int tag = 0; tag < kTags; ++tag)
      if (commands_[tag].open) complete(tag, commands_[tag].start_line, "no completion: the log ends before it");
    // Sent and never answered; with the program its list below says so.
    for (int tag = 0; tag < kTags && !program_; ++tag)
      if (pending_[tag].set && pending_[tag].known == Known::ptmeas) {
        const IppdmePtMeas& p = slots_[pending_[tag].slot];
        not_measured(p, command_id(tag, p.use), p.line, "sent, but the log holds no answer");
      }
    if (program_)
      for (std::size_t k = 0; k < answered_.size(); ++k)
        if (!answered_[k]) {
          const IppdmePtMeas& p = program_->ptmeas[k];
          not_measured(p, p.use == 1 ? p.tag : p.tag + "_" + std::to_string(p.use), 0,
                       "PtMeas on line " + std::to_string(p.line) + " of " + program_name_ +
                           " has no answer in the log");
        }
    to_one_frame();
    set_.ids_from_file = false;  // tags are not plan ids
  }

 private:
  void command(const IppdmeLexedLine& l, const IppdmePointItems* fast_items) {
    const int number = l.number, tag = l.tag;
    const std::string_view ipp = l.ipp;
    logged_ = true;
    if (tag == -2) return;  // event commands hold event tags
    Pending& p = pending_[tag];
    if (p.slot >= 0) free_slot(p.slot);  // a command the server never answered
    p = Pending{true, Known::other, -1};
    // A PtMeas of point items only was read in place; anything else is parsed.
    const IppdmePointItems* found = fast_items;
    if (!found) {
      if (!parse_ippdme_command(ipp, cmd_).empty()) return;  // the server answers it with an error
      advance_ippdme_frame(cmd_, frame_);
      if (cmd_.name != "PtMeas") return;
      if (!ippdme_point_items(cmd_.arguments, point_items_).empty()) return;
      found = &point_items_;
    }
    const IppdmePointItems& items = *found;
    p.slot = take_slot();
    IppdmePtMeas& m = slots_[p.slot];
    m.tag.assign(ipp.substr(0, 5));
    m.use = commands_[tag].use + 1;
    m.line = number;
    m.target.reset();
    m.ijk.reset();
    if (items.has_xyz()) m.target = Eigen::Vector3d(*items.x, *items.y, *items.z);
    if (items.ijk && items.ijk->norm() > 0) m.ijk = items.ijk->normalized();
    m.frame = frame_;
    p.known = Known::ptmeas;
  }

  void start(int tag, int line) {
    OpenCommand& c = commands_[tag];
    if (c.open) mf::fail(name_, line, "tag " + tag_text(tag) + " is used again before its command completed");
    c.open = true;
    ++c.use;
    c.point = -1;
    c.reported = false;
    c.error_line = 0;
    c.error.clear();
    c.start_line = line;
    c.known = Known::unknown;
    c.ptmeas = nullptr;
    if (c.slot >= 0) free_slot(c.slot);
    c.slot = -1;
    if (program_) {
      const auto it = program_ptmeas_.find(occurrence_key(tag, c.use));
      c.known = Known::other;
      if (it != program_ptmeas_.end()) {
        answered_[it->second] = 1;
        c.known = Known::ptmeas;
        c.ptmeas = &program_->ptmeas[it->second];
      }
    }
    Pending& p = pending_[tag];
    if (p.set) {  // the command as the log records it
      c.known = p.known;
      c.ptmeas = nullptr;
      if (p.known == Known::ptmeas) {
        c.slot = p.slot;
        c.ptmeas = &slots_[c.slot];
      }
      p = Pending{};
    } else if (logged_ && !program_) {
      c.known = Known::other;  // the log records its commands, and this one is not there
    }
  }

  void data(int tag, int line) {
    OpenCommand& c = commands_[tag];
    if (c.known == Known::other) return;  // GetProp, EnumTools, a scan ...: not a point
    const IppdmePointItems& items = point_items_;
    // A malformed X(), Y(), Z(), IJK() or ER() is an error whatever the command.
    if (!point_items_error_.empty()) mf::fail(name_, line, "data: " + point_items_error_);
    if (c.known == Known::unknown && (!items.only_point_items || !items.has_xyz())) return;
    if (c.point >= 0 || c.reported)
      mf::fail(name_, line, "a second data line for PtMeas " + command_id(tag, c.use) +
                                (c.point >= 0 ? " (first on line " + std::to_string(set_.points[c.point].line) + ")" : ""));
    if (!items.has_xyz()) {
      not_measured(c, tag, line, "the answer has no X(), Y() and Z() (OnPtMeasReport asked for fewer)");
      return;
    }
    MeasuredPoint p;
    p.line = line;
    p.id = command_id(tag, c.use);
    p.xyz = Eigen::Vector3d(*items.x, *items.y, *items.z);
    if (items.ijk) p.ijk = mf::unit_direction(*items.ijk, name_, line, "data: IJK()");
    if (items.er) {
      if (!(*items.er >= 0)) mf::fail(name_, line, "data: ER() must not be negative");
      p.effective_radius = *items.er;
    }
    if (c.ptmeas) {
      p.nominal = c.ptmeas->target;
      p.nominal_ijk = c.ptmeas->ijk;
    }
    c.point = static_cast<int>(set_.points.size());
    note_frame(c.ptmeas);
    mf::add_point(set_, std::move(p), name_);
  }

  void complete(int tag, int line, const std::string& why_open = "") {
    OpenCommand& c = commands_[tag];
    c.open = false;
    if (c.known != Known::ptmeas || c.point >= 0 || c.reported) return;
    const std::string reason = c.error_line ? c.error : why_open.empty() ? "completed without data" : why_open;
    not_measured(c, tag, c.error_line ? c.error_line : line, reason);
  }

  int take_slot() {
    if (free_slots_.empty()) {
      slots_.emplace_back();
      return static_cast<int>(slots_.size() - 1);
    }
    const int k = free_slots_.back();
    free_slots_.pop_back();
    return k;
  }
  void free_slot(int k) { free_slots_.push_back(k); }

  void not_measured(OpenCommand& c, int tag, int line, const std::string& reason) {
    c.reported = true;
    static const IppdmePtMeas none;
    not_measured(c.ptmeas ? *c.ptmeas : none, command_id(tag, c.use), line, reason);
  }
  void not_measured(const IppdmePtMeas& p, const std::string& id, int line, const std::string& reason) {
    set_.not_measured.push_back({id, p.target, reason, line});
    unmeasured_frames_.push_back(p.frame);
  }

  // Frames change rarely: each point refers to a short list of them.
  void note_frame(const IppdmePtMeas* p) {
    const IppdmeFrame f = p ? p->frame : IppdmeFrame{};
    if (frames_.empty() || !same_frame(frames_.back(), f)) frames_.push_back(f);
    frame_of_point_.push_back(frames_.size() - 1);
  }

  // MachineCsy and PartCsy brought into PartCsy when both occur
  // (IppdmeFrame); a point in a system Furrow cannot place is refused.
  void to_one_frame() {
    bool machine = false, part = false;
    auto check = [&](const IppdmeFrame& f, const std::string& id, int line) {
      if (f.csy == IppdmeCsy::moveable_machine || f.csy == IppdmeCsy::multiple_arm)
        mf::fail(name_, line, "PtMeas " + id + " is measured in " + to_string(f.csy) +
                                  ", which a client cannot place from the program (docs/formats.md "
                                  "\"Reading any I++ DME session\")");
      (f.csy == IppdmeCsy::part ? part : machine) = true;
    };
    for (std::size_t k = 0; k < set_.points.size(); ++k)
      check(frames_[frame_of_point_[k]], set_.points[k].id, set_.points[k].line);
    for (std::size_t k = 0; k < set_.not_measured.size(); ++k)
      check(unmeasured_frames_[k], set_.not_measured[k].id, set_.not_measured[k].line);
    if (!machine || !part) return;
    for (const IppdmeFrame& f : frames_)
      if (f.csy == IppdmeCsy::machine && !f.part)
        throw InputError(name_ + ": points are measured in MachineCsy and in PartCsy, and no "
                                 "SetCsyTransformation(PartCsy, ...) before the MachineCsy ones relates the two");
    for (std::size_t k = 0; k < set_.points.size(); ++k) {
      const IppdmeFrame& f = frames_[frame_of_point_[k]];
      if (f.csy != IppdmeCsy::machine) continue;
      MeasuredPoint& p = set_.points[k];
      const Eigen::Isometry3d& t = *f.part;
      p.xyz = t * p.xyz;
      if (p.ijk) p.ijk = t.linear() * *p.ijk;
      if (p.nominal) p.nominal = t * *p.nominal;
      if (p.nominal_ijk) p.nominal_ijk = t.linear() * *p.nominal_ijk;
    }
    for (std::size_t k = 0; k < set_.not_measured.size(); ++k)
      if (unmeasured_frames_[k].csy == IppdmeCsy::machine && set_.not_measured[k].nominal) {
        if (!unmeasured_frames_[k].part)
          throw InputError(name_ + ": PtMeas " + set_.not_measured[k].id + " is in MachineCsy with no PartCsy placement");
        set_.not_measured[k].nominal = *unmeasured_frames_[k].part * *set_.not_measured[k].nominal;
      }
  }

  const std::string& name_;
  const IppdmeSession* program_;
  const std::string& program_name_;
  MeasurementSet& set_;
  std::vector<OpenCommand> commands_;
  std::vector<Pending> pending_;
  // The logged PtMeas in flight; a deque, so that OpenCommand::ptmeas stays valid.
  std::deque<IppdmePtMeas> slots_;
  std::vector<int> free_slots_;
  std::unordered_map<long, std::size_t> program_ptmeas_;  // occurrence -> index
  std::vector<char> answered_;
  bool logged_ = false;  // the log records commands
  IppdmeFrame frame_;    // of the logged commands
  IppdmeCommand cmd_;
  std::vector<IppdmeItem> items_;
  IppdmePointItems point_items_;   // of the line being read
  std::string point_items_error_;  // why its point items are malformed
  std::vector<IppdmeFrame> frames_;
  std::vector<std::size_t> frame_of_point_;
  std::vector<IppdmeFrame> unmeasured_frames_;
};

}  // namespace

bool is_ippdme_response_log(std::string_view text) {
  bool answer = false, decided = false;
  mf::for_each_line(text, [&](int, std::string_view line) {
    if (decided) return;
    bool directed = false;
    const std::string_view ipp = ippdme_line_part(line, directed);
    if (ipp.empty()) return;
    decided = true;
    const int tag = ippdme_tag_of(ipp);
    answer = tag != -1 && (is_ippdme_response_mark(ipp[6]) || looks_like_ippdme_command(ipp));
  });
  return answer;
}

void parse_ippdme_response_log(std::string_view text, const std::string& name, const IppdmeSession* program,
                               const std::string& program_name, MeasurementSet& set) {
  // Every point has its data line, and every data line its '#'.
  set.points.reserve(mf::count_char(text, '#') + 1);
  SessionReader reader(name, program, program_name, set);
  for_each_lexed_ippdme_line(text, kLexChunkBytes, [&](const IppdmeLexedLine& line, const IppdmePointItems* items) { reader.line(line, items); });
  reader.finish();
}

std::string ippdme_response_log_text(const MeasurementSet& set) {
  using mf::shortest;
  std::string out;
  out.reserve(set.points.size() * 170);
  const bool centres = set.kind == ProbePointKind::probe_centre && set.probe_radius > 0;
  int tag = 1;
  for (const MeasuredPoint& p : set.points) {
    const std::string t = tag_text(tag);
    out += t + " &\r\n" + t + " # X(" + shortest(p.xyz.x()) + "), Y(" + shortest(p.xyz.y()) + "), Z(" +
           shortest(p.xyz.z()) + ")";
    if (p.ijk) out += ", IJK(" + shortest(p.ijk->x()) + ", " + shortest(p.ijk->y()) + ", " + shortest(p.ijk->z()) + ")";
    if (centres) out += ", ER(" + shortest(set.probe_radius) + ")";
    out += "\r\n" + t + " %\r\n";
    tag = tag == kMaxIppTag ? 1 : tag + 1;
  }
  return out;
}

}  // namespace furrow

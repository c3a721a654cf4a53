#include "io/cmm/dmis_program_reader.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "base/json_fields.hpp"
#include "io/cmm/dmis_results.hpp"

namespace furrow {

namespace {

[[noreturn]] void fail(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

// A number as the writer prints it: optional '-', digits, optional fraction.
const std::regex kNumber(R"(-?[0-9]+(\.[0-9]+)?)");

double number(const std::string& text, const std::string& name, int line) {
  if (!std::regex_match(text, kNumber)) fail(name, line, quote_field(text) + " is not a number as Furrow writes them");
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  if (!std::isfinite(v)) fail(name, line, quote_field(text) + " is not finite");
  return v;
}

std::vector<std::string> fields(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

Eigen::Vector3d point3(const std::vector<std::string>& f, std::size_t first, const std::string& name, int line) {
  return {number(f[first], name, line), number(f[first + 1], name, line), number(f[first + 2], name, line)};
}

class Cursor {
 public:
  Cursor(std::vector<DmisStatement> statements, std::string name)
      : st_(std::move(statements)), name_(std::move(name)) {
    // Statements are matched with std::regex, whose libstdc++ matcher
    // recurses once per character: a statement of some 100 000 characters
    // overflowed the stack under fuzz_dmis_program (docs/testing.md).
    for (const DmisStatement& s : st_)
      if (s.text.size() > kMaxDmisProgramStatement)
        fail(name_, s.line, "statement longer than " + std::to_string(kMaxDmisProgramStatement) + " characters");
  }
  bool done() const { return k_ >= st_.size(); }
  const DmisStatement& peek() const { return st_[k_]; }
  const DmisStatement& take(const char* what) {
    if (done()) fail(name_, st_.empty() ? 1 : st_.back().line, std::string("the program ends before ") + what);
    return st_[k_++];
  }
  // The next statement, which must match `pattern`; returns the whole
  // match and the captures as strings.
  std::vector<std::string> expect(const std::regex& pattern, const char* what) {
    const DmisStatement& s = take(what);
    line_ = s.line;
    std::smatch m;
    if (!std::regex_match(s.text, m, pattern))
      fail(name_, s.line, std::string("expected ") + what + ", got " + quote_field(s.text));
    return std::vector<std::string>(m.begin(), m.end());
  }
  bool next_is(const std::regex& pattern) const { return !done() && std::regex_match(peek().text, pattern); }
  int line() const { return line_; }
  const std::string& name() const { return name_; }

 private:
  std::vector<DmisStatement> st_;
  std::string name_;
  std::size_t k_ = 0;
  int line_ = 0;
};

const std::string kNum = R"((-?[0-9]+(?:\.[0-9]+)?))";
// Labels as the writer spells them: upper case (dmis_label).
const std::string kLabel = R"(([A-Z0-9_]+))";

const std::regex kGoTo("GOTO/" + kNum + "," + kNum + "," + kNum);
const std::regex kText("TEXT/MAN,'[^']*'");

Eigen::Vector3d vec(const std::vector<std::string>& m, std::size_t first, const std::string& name, int line) {
  return {number(m[first], name, line), number(m[first + 1], name, line), number(m[first + 2], name, line)};
}

std::vector<Eigen::Vector3d> read_moves(Cursor& in) {
  std::vector<Eigen::Vector3d> moves;
  while (in.next_is(kGoTo)) {
    const std::vector<std::string> m = in.expect(kGoTo, "GOTO/x,y,z");
    moves.push_back(vec(m, 1, in.name(), in.line()));
  }
  return moves;
}

// The 3-2-1 alignment or the manual points (dmis_writer.hpp); checks that
// the DCC pass measures what the features and the manual pass name.
void read_alignment(Cursor& in, ProbeProgram& program) {
  const std::string& name = in.name();
  const std::string n6 = "," + kNum + "," + kNum + "," + kNum + "," + kNum + "," + kNum + "," + kNum;
  const std::regex plane("F\\(DATUM_" + kLabel + "\\)=FEAT/PLANE,CART" + n6);
  const std::regex line("F\\(DATUM_" + kLabel + "\\)=FEAT/LINE,BND,CART" + n6 + "," + kNum + "," + kNum + "," + kNum);
  const std::regex point("F\\(DATUM_" + kLabel + "\\)=FEAT/POINT,CART" + n6);
  const std::regex circle("F\\(DATUM_" + kLabel + "\\)=FEAT/CIRCLE,(?:INNER|OUTER),CART" + n6 + "," + kNum);
  const std::regex manual_point("F\\(" + kLabel + "\\)=FEAT/POINT,CART" + n6);
  PartAlignment a;
  if (in.next_is(plane)) {
    a.method = PartAlignment::Method::datums;
    for (int k = 0; k < 3; ++k) {
      DatumFeature d;
      std::vector<std::string> m;
      if (in.next_is(plane)) {
        m = in.expect(plane, "a datum plane");
        d.kind = DatumFeature::Kind::plane;
        d.origin = vec(m, 2, name, in.line());
        d.direction = vec(m, 5, name, in.line());
        d.normal = d.direction;
      } else if (in.next_is(line)) {
        m = in.expect(line, "a datum line");
        d.kind = DatumFeature::Kind::line;
        d.origin = vec(m, 2, name, in.line());
        Eigen::Vector3d t = vec(m, 5, name, in.line()) - d.origin;
        t.z() = 0;
        if (!(t.norm() > 0)) fail(name, in.line(), "a datum line needs two points apart horizontally");
        d.direction = t.normalized();
        d.normal = vec(m, 8, name, in.line());
      } else if (in.next_is(circle)) {
        // A bore or boss at the points' height: its axis (the circle's
        // normal) must be vertical, as the DATSET's XORIG,YORIG assume.
        m = in.expect(circle, "a datum circle");
        d.kind = DatumFeature::Kind::cylinder;
        d.origin = vec(m, 2, name, in.line());
        d.direction = vec(m, 5, name, in.line());
        d.normal = d.direction;
        d.radius = std::stod(m[8]) / 2;
        if (!(d.radius > 0) || !std::isfinite(d.radius)) fail(name, in.line(), "a datum circle needs a positive diameter");
        if (!(std::abs(std::abs(d.direction.normalized().z()) - 1) < 1e-6))
          fail(name, in.line(), "a datum circle's axis must be vertical (i,j,k = 0,0,+-1)");
      } else {
        m = in.expect(point, "F(DATUM_LABEL)=FEAT/PLANE|LINE|CIRCLE|POINT,...");
        d.kind = DatumFeature::Kind::point;
        d.origin = vec(m, 2, name, in.line());
        d.direction = vec(m, 5, name, in.line());
        d.normal = d.direction;
      }
      if (!(d.normal.norm() > 0)) fail(name, in.line(), "a datum direction has zero length");
      d.normal.normalize();
      d.direction.normalize();
      d.label = m[1];
      for (const DatumFeature& e : a.datums)
        if (e.label == d.label) fail(name, in.line(), "datum " + d.label + " is defined twice");
      a.datums.push_back(std::move(d));
    }
    in.expect(std::regex("MODE/MAN"), "MODE/MAN");
    std::vector<int> counts;
    for (const DatumFeature& d : a.datums) {
      in.expect(kText, "TEXT/MAN,'prompt'");
      const std::vector<std::string> m = in.expect(
          std::regex(std::string("MEAS/") + dmis_measure_word(d.kind) + ",F\\(DATUM_" + d.label + "\\),([0-9]+)"),
          "MEAS/kind,F(DATUM_label),n of the datum defined in that place");
      counts.push_back(std::stoi(m[1]));
      const int need = d.kind == DatumFeature::Kind::plane || d.kind == DatumFeature::Kind::cylinder ? 3
                       : d.kind == DatumFeature::Kind::line                                       ? 2
                                                                                                  : 1;
      if (counts.back() < need || counts.back() > 1000) fail(name, in.line(), "too few or too many points for datum " + d.label);
      in.expect(std::regex("ENDMES"), "ENDMES");
    }
    // DATSET: every datum in order, with the axis it directs and the origin
    // it sets (a circle: both in-plane origins).
    std::string ds = "DATSET";
    char sep = '/';
    for (const DatumFeature& d : a.datums) {
      ds += sep + std::string("FA\\(DATUM_") + d.label + "\\)" +
            (d.kind == DatumFeature::Kind::cylinder ? ",XORIG,YORIG" : "(,[XYZ]DIR)?(,[XYZ]ORIG)?");
      sep = ',';
    }
    const std::regex datset_manual("D\\(MANUAL\\)=(" + ds + ")");
    const std::regex trans("D\\((MANUAL_CAD|PART)\\)=TRANS/XORIG," + kNum + ",YORIG," + kNum + ",ZORIG," + kNum);
    const std::string datset_text = in.expect(datset_manual, "D(MANUAL)=DATSET/FA(DATUM_A),...")[1];
    {
      // Axes: from the DATSET text, one datum's words after the other.
      std::size_t at = 0;
      for (DatumFeature& d : a.datums) {
        at = datset_text.find("FA(DATUM_" + d.label + ")", at);
        const std::size_t next = datset_text.find(",FA(", at);
        const std::string words = datset_text.substr(at, next == std::string::npos ? std::string::npos : next - at);
        const std::size_t dir = words.find("DIR"), orig = words.find("ORIG");
        d.axis = dir == std::string::npos ? 0 : words[dir - 1];
        d.origin_axis = orig == std::string::npos || d.kind == DatumFeature::Kind::cylinder ? 0 : words[orig - 1];
        if (!d.axis && !d.origin_axis && d.kind != DatumFeature::Kind::cylinder)
          fail(name, in.line(), "datum " + d.label + " sets neither a direction nor an origin");
        at += words.size();
      }
    }
    const std::vector<std::string> t = in.expect(trans, "D(MANUAL_CAD)=TRANS/XORIG,x,YORIG,y,ZORIG,z");
    if (t[1] != "MANUAL_CAD") fail(name, in.line(), "expected D(MANUAL_CAD)=TRANS/...");
    a.origin = -vec(t, 2, name, in.line());
    in.expect(std::regex("MODE/PROG,MAN"), "MODE/PROG,MAN");
    const std::regex ptmeas("PTMEAS/CART" + n6);
    int order = 0;
    for (std::size_t k = 0; k < a.datums.size(); ++k) {
      DatumFeature& d = a.datums[k];
      const std::vector<std::string> m = in.expect(
          std::regex(std::string("MEAS/") + dmis_measure_word(d.kind) + ",F\\(DATUM_" + d.label + "\\),([0-9]+)"),
          "MEAS/kind,F(DATUM_label),n as in the manual pass");
      if (std::stoi(m[1]) != counts[k]) fail(name, in.line(), "datum " + d.label + " has another point count than in the manual pass");
      for (int n = 1; n <= counts[k]; ++n) {
        ProgramStep step;
        step.moves_before = read_moves(in);
        const std::vector<std::string> p = in.expect(ptmeas, "PTMEAS/CART,x,y,z,i,j,k");
        step.point.id = "D" + d.label + std::to_string(n);
        step.point.order = ++order;
        step.point.xyz = vec(p, 1, name, in.line());
        step.point.ijk = vec(p, 4, name, in.line());
        if (!(step.point.ijk.norm() > 0)) fail(name, in.line(), "PTMEAS direction has zero length");
        step.point.ijk.normalize();
        d.points.push_back(step.point);
        program.alignment_steps.push_back(std::move(step));
      }
      in.expect(std::regex("ENDMES"), "ENDMES");
    }
    program.alignment_final_moves = read_moves(in);
    if (in.expect(std::regex("D\\(DATUMS\\)=(" + ds + ")"), "D(DATUMS)=DATSET/... as D(MANUAL)")[1] != datset_text)
      fail(name, in.line(), "D(DATUMS) differs from D(MANUAL)");
    const std::vector<std::string> t2 = in.expect(trans, "D(PART)=TRANS/XORIG,x,YORIG,y,ZORIG,z");
    if (t2[1] != "PART" || t2[2] != t[2] || t2[3] != t[3] || t2[4] != t[4])
      fail(name, in.line(), "D(PART)=TRANS differs from D(MANUAL_CAD)");
    for (const DatumFeature& d : a.datums)
      in.expect(std::regex("OUTPUT/FA\\(DATUM_" + d.label + "\\)"), "OUTPUT/FA(DATUM_label) of every datum in order");
    in.expect(std::regex("SAVE/DA\\(PART\\)"), "SAVE/DA(PART) after the datums' outputs");
  } else if (in.next_is(std::regex("MODE/MAN"))) {
    a.method = PartAlignment::Method::free_form;
    in.expect(std::regex("MODE/MAN"), "MODE/MAN");
    while (in.next_is(manual_point)) {
      const std::vector<std::string> m = in.expect(manual_point, "F(label)=FEAT/POINT,CART,...");
      ProgramStep step;
      step.point.id = m[1];
      step.point.order = static_cast<int>(a.manual.size()) + 1;
      step.point.xyz = vec(m, 2, name, in.line());
      step.point.ijk = vec(m, 5, name, in.line());
      if (!(step.point.ijk.norm() > 0)) fail(name, in.line(), "a direction has zero length");
      step.point.ijk.normalize();
      in.expect(kText, "TEXT/MAN,'prompt'");
      if (in.expect(std::regex("MEAS/POINT,F\\(" + kLabel + "\\),1"), "MEAS/POINT,F(label),1")[1] != m[1])
        fail(name, in.line(), "MEAS refers to another feature than " + m[1]);
      in.expect(std::regex("ENDMES"), "ENDMES");
      if (in.expect(std::regex("OUTPUT/FA\\(" + kLabel + "\\)"), "OUTPUT/FA(label)")[1] != m[1])
        fail(name, in.line(), "OUTPUT refers to another feature than " + m[1]);
      a.manual.push_back(step.point);
      program.alignment_steps.push_back(std::move(step));
    }
    if (a.manual.size() < 3) fail(name, in.line(), "a manual alignment needs at least 3 points");
    in.expect(std::regex("MODE/PROG,MAN"), "MODE/PROG,MAN");
  } else {
    // No alignment of its own; perhaps one recalled from a first program.
    const std::regex recall("RECALL/DA\\((" + kLabel + ")\\)");
    if (in.next_is(recall)) program.recalled_alignment = in.expect(recall, "RECALL/DA(label)")[1];
    return;
  }
  program.alignment = std::move(a);
}

}  // namespace

ProbeProgram parse_dmis_program(const std::string& text, const std::string& name) {
  Cursor in(dmis_statements(text), name);
  ProbeProgram program;
  const std::regex dmismn(R"(DMISMN/'([A-Za-z0-9_-]+)',05\.2)");
  program.name = in.expect(dmismn, "DMISMN/'name',05.2")[1];
  const std::vector<std::string> filnam = in.expect(std::regex(R"(FILNAM/'([A-Za-z0-9_-]+)',05\.2)"), "FILNAM/'name',05.2");
  if (filnam[1] != program.name) fail(name, in.line(), "FILNAM differs from DMISMN");
  in.expect(std::regex("UNITS/MM,ANGDEC"), "UNITS/MM,ANGDEC");
  const std::regex part_id("PN\\(PART\\)=PARTID/'([ -&(-~]*)'");
  const std::regex part_revision("PR\\(REV\\)=PARTRV/'([ -&(-~]*)'");
  if (in.next_is(part_id)) program.part = in.expect(part_id, "PN(PART)=PARTID/'part'")[1];
  if (in.next_is(part_revision)) program.revision = in.expect(part_revision, "PR(REV)=PARTRV/'revision'")[1];
  if (in.expect(std::regex("PL\\(PROGRAM\\)=PLANID/'([A-Za-z0-9_-]+)'"), "PL(PROGRAM)=PLANID/'name'")[1] !=
      program.name)
    fail(name, in.line(), "PLANID differs from DMISMN");
  in.expect(std::regex("PRCOMP/ON"), "PRCOMP/ON");
  // One sensor for the vertical stylus, or one per tip of an indexable head
  // named PROBE_A..B.. after its angles (probe_program.hpp).
  const std::regex snsdef("S\\(" + kLabel + "\\)=SNSDEF/PROBE,INDEX,POL," + kNum + "," + kNum + ",0,0,-1," + kNum + "," + kNum);
  std::map<std::string, TipAngles> sensors;  // tip sensors by label
  do {
    const std::vector<std::string> sensor = in.expect(snsdef, "S(LABEL)=SNSDEF/PROBE,INDEX,POL,a,b,0,0,-1,head_length,diameter");
    const double head_length = number(sensor[4], name, in.line());
    const double diameter = number(sensor[5], name, in.line());
    if (!(diameter > 0) || !(head_length > 0)) fail(name, in.line(), "head-to-ball length and ball diameter must be positive");
    const TipAngles angles{number(sensor[2], name, in.line()), number(sensor[3], name, in.line())};
    const std::optional<TipSensor> tip = split_tip_sensor(sensor[1]);
    if (tip && tip->tip != angles) fail(name, in.line(), "sensor " + sensor[1] + " is named after other angles than it has");
    const bool first = program.probe.name.empty();
    if (first) {
      program.probe.name = tip ? tip->base : sensor[1];
      program.head_length = head_length;
      program.probe.diameter = diameter;
      if (!tip && (angles.a != 0 || angles.b != 0)) fail(name, in.line(), "the vertical stylus's sensor must have angles 0,0");
    } else if (!tip || sensors.empty() || tip->base != program.probe.name || head_length != program.head_length ||
               diameter != program.probe.diameter) {
      fail(name, in.line(), "a second sensor must be another tip of the same probe (PROBE_A..B.., same length and ball)");
    }
    if (tip) {
      if (!sensors.emplace(sensor[1], angles).second) fail(name, in.line(), "sensor " + sensor[1] + " is defined twice");
      program.tips.push_back(angles);
    }
  } while (in.next_is(snsdef));
  const std::regex snslct("SNSLCT/S\\(" + kLabel + "\\)");
  const std::string selected = in.expect(snslct, "SNSLCT/S(label)")[1];
  if (sensors.empty() ? selected != program.probe.name : !sensors.count(selected))
    fail(name, in.line(), "SNSLCT selects a sensor that was not defined");
  if (!sensors.empty()) program.start_tip = sensors.at(selected);
  auto speed = [&](const char* key) {
    const double v = number(in.expect(std::regex(std::string("FEDRAT/") + key + ",MMPS," + kNum),
                                      (std::string("FEDRAT/") + key + ",MMPS,value").c_str())[1],
                            name, in.line());
    if (!(v > 0)) fail(name, in.line(), std::string(key) + " must be positive");
    return v;
  };
  program.move_speed = speed("POSVEL");
  program.measure_speed = speed("MESVEL");
  auto setting = [&](const char* key) {
    const double v = number(in.expect(std::regex(std::string("SNSET/") + key + "," + kNum),
                                      (std::string("SNSET/") + key + ",value").c_str())[1],
                            name, in.line());
    if (!(v > 0)) fail(name, in.line(), std::string(key) + " must be positive");
    return v;
  };
  program.approach = setting("APPRCH");
  program.retract = setting("RETRCT");
  program.search = setting("SEARCH");
  const std::regex profile("T\\(PROFILE\\)=TOL/PROFP," + kNum + "," + kNum);
  if (in.next_is(profile)) {
    const std::vector<std::string> t = in.expect(profile, "T(PROFILE)=TOL/PROFP,lower,upper");
    PointProfileTolerance zone{number(t[1], name, in.line()), number(t[2], name, in.line())};
    if (zone.lower > 0 || zone.upper < 0 || !(zone.upper - zone.lower > 0))
      fail(name, in.line(), "the profile zone must run from a limit <= 0 to one >= 0");
    program.tolerance = zone;
  }
  if (in.expect(std::regex(R"(DID\(RESULTS\)=DEVICE/STOR,'([A-Za-z0-9_-]+)\.dmo')"),
                "DID(RESULTS)=DEVICE/STOR,'name.dmo'")[1] != program.name)
    fail(name, in.line(), "the results file is not named after the program");
  in.expect(std::regex("OPEN/DID\\(RESULTS\\),FDATA,DMIS,OUTPUT"), "OPEN/DID(RESULTS),FDATA,DMIS,OUTPUT");
  in.expect(std::regex("MODE/PROG,MAN"), "MODE/PROG,MAN");
  read_alignment(in, program);

  const std::regex go_to("GOTO/" + kNum + "," + kNum + "," + kNum);
  const std::regex feature("F\\(" + kLabel + "\\)=FEAT/POINT,CART(,-?[0-9]+(\\.[0-9]+)?){6}");
  const std::regex meas("MEAS/POINT,F\\(" + kLabel + "\\),1");
  const std::regex ptmeas("PTMEAS/CART(,-?[0-9]+(\\.[0-9]+)?){6}");
  const std::regex output("OUTPUT/FA\\(" + kLabel + "\\)" + (program.tolerance ? ",TA\\(PROFILE\\)" : ""));
  std::set<std::string> labels;
  std::vector<Eigen::Vector3d> moves;
  auto read_move = [&] {
    const std::vector<std::string> m = in.expect(go_to, "GOTO/x,y,z");
    moves.emplace_back(number(m[1], name, in.line()), number(m[2], name, in.line()), number(m[3], name, in.line()));
  };
  std::optional<TipAngles> tip = program.start_tip;
  for (;;) {
    // A tip change comes before the step's moves or after its first one
    // (probe_program.hpp); which of the two is checked at the point.
    std::optional<std::size_t> changed_after;
    int change_line = 0;
    while (in.next_is(go_to) || (in.next_is(snslct) && !sensors.empty())) {
      if (in.next_is(go_to)) {
        read_move();
        continue;
      }
      const std::string label = in.expect(snslct, "SNSLCT/S(label)")[1];
      change_line = in.line();
      if (!sensors.count(label)) fail(name, change_line, "SNSLCT selects a sensor that was not defined");
      if (changed_after || sensors.at(label) == *tip) fail(name, change_line, "SNSLCT does not change the tip here");
      changed_after = moves.size();
      tip = sensors.at(label);
    }
    if (!in.next_is(feature)) {
      if (changed_after) fail(name, change_line, "SNSLCT with no point after it");
      break;
    }
    if (changed_after && *changed_after != (moves.size() < 2 ? 0u : 1u))
      fail(name, change_line, "a tip change belongs after the first move of a point with two or more moves, else before them");
    const DmisStatement& fs = in.take("a feature");
    const std::optional<DmisPointFeature> f = parse_dmis_point_feature(fs, name, 1.0);
    if (!f || f->actual) fail(name, fs.line, "expected a nominal point feature F(label)=FEAT/POINT,...");
    if (!labels.insert(f->label).second) fail(name, fs.line, "feature " + f->label + " is defined twice");
    if (in.expect(meas, "MEAS/POINT,F(label),1")[1] != f->label)
      fail(name, in.line(), "MEAS refers to another feature than the one just defined (" + f->label + ")");
    const DmisStatement& ps = in.take("PTMEAS");
    if (!std::regex_match(ps.text, ptmeas)) fail(name, ps.line, "expected PTMEAS/CART,x,y,z,i,j,k, got " + quote_field(ps.text));
    const std::vector<std::string> pf = fields(ps.text.substr(ps.text.find('/') + 1));
    const Eigen::Vector3d touch = point3(pf, 1, name, ps.line);
    const Eigen::Vector3d touch_ijk = point3(pf, 4, name, ps.line);
    // The nominal is as printed (f->xyz); the direction as printed too, before normalising.
    const std::vector<std::string> ff = fields(fs.text.substr(fs.text.find('/') + 1));
    if (touch != point3(ff, 2, name, fs.line) || touch_ijk != point3(ff, 5, name, fs.line))
      fail(name, ps.line, "PTMEAS differs from the nominal of " + f->label);
    in.expect(std::regex("ENDMES"), "ENDMES");
    if (in.expect(output, program.tolerance ? "OUTPUT/FA(LABEL),TA(PROFILE)" : "OUTPUT/FA(LABEL)")[1] != f->label)
      fail(name, in.line(), "OUTPUT refers to another feature than " + f->label);
    ProgramStep step;
    step.point.id = f->label;
    step.point.order = static_cast<int>(program.steps.size()) + 1;
    step.point.xyz = f->xyz;
    step.point.ijk = f->ijk;
    step.point.tip = tip;
    step.moves_before = std::move(moves);
    moves.clear();
    program.steps.push_back(std::move(step));
  }
  program.final_moves = std::move(moves);
  in.expect(std::regex("CLOSE/DID\\(RESULTS\\)"), "CLOSE/DID(RESULTS)");
  in.expect(std::regex("ENDFIL"), "ENDFIL");
  if (!in.done()) fail(name, in.peek().line, "statements after ENDFIL");
  if (program.steps.empty()) throw InputError(name + ": the program measures no point");
  return program;
}

ProbeProgram read_dmis_program(const std::string& path) {
  return parse_dmis_program(json_fields::read_text(path), path);
}

}  // namespace furrow

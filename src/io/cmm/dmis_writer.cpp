#include "io/cmm/dmis_writer.hpp"

#include <algorithm>

#include <functional>
#include <sstream>

namespace furrow {

namespace {

std::string xyz_text(const Eigen::Vector3d& p) {
  return fixed_number(p.x(), kProgramDecimals) + "," + fixed_number(p.y(), kProgramDecimals) + "," +
         fixed_number(p.z(), kProgramDecimals);
}

std::string ijk_text(const Eigen::Vector3d& n) {
  return fixed_number(n.x(), kDirectionDecimals) + "," + fixed_number(n.y(), kDirectionDecimals) + "," +
         fixed_number(n.z(), kDirectionDecimals);
}

// TEXT/MAN prompts are quoted text: no quote may end them early.
std::string prompt_text(std::string s) {
  for (char& c : s)
    if (c == '\'' || c == '$' || c < 0x20 || c > 0x7e) c = '_';
  return s;
}

std::string near_text(const Eigen::Vector3d& p) {
  return "(" + fixed_number(p.x(), 1) + ", " + fixed_number(p.y(), 1) + ", " + fixed_number(p.z(), 1) + ")";
}

// A bore's wall faces its axis, a boss's faces away.
bool is_bore(const DatumFeature& d) {
  double outward = 0;
  for (const PlannedPoint& p : d.points) {
    Eigen::Vector3d radial = p.xyz - d.origin;
    radial -= radial.dot(d.direction) * d.direction;
    outward += p.ijk.dot(radial);
  }
  return outward < 0;
}

// Each datum with the axis it directs and the origins it sets; a circle
// (a bore or boss on the vertical axis) sets both in-plane origins.
std::string datset(const PartAlignment& a) {
  std::string s = "DATSET";
  char sep = '/';
  for (const DatumFeature& d : a.datums) {
    s += sep + std::string("FA(DATUM_") + d.label + ")";
    sep = ',';
    if (d.axis) s += std::string(",") + d.axis + "DIR";
    if (d.kind == DatumFeature::Kind::cylinder) s += ",XORIG,YORIG";
    if (d.origin_axis) s += std::string(",") + d.origin_axis + "ORIG";
  }
  return s;
}

// The datum frame's origin is `origin` in CAD coordinates: moving the
// origin to -origin (in the datum frame) puts it on the CAD origin.
std::string trans(const PartAlignment& a) {
  return "TRANS/XORIG," + fixed_number(-a.origin.x(), kProgramDecimals) + ",YORIG," +
         fixed_number(-a.origin.y(), kProgramDecimals) + ",ZORIG," + fixed_number(-a.origin.z(), kProgramDecimals);
}

void write_alignment(const ProbeProgram& program, const std::function<void(const std::string&)>& line) {
  const PartAlignment& a = *program.alignment;
  line("$$ Part alignment (" + std::string(to_string(a.method)) + "): " + prompt_text(a.reason));
  if (a.method == PartAlignment::Method::free_form) {
    line("$$ Manual alignment: touch each point by joystick when prompted, then set the part frame");
    line("$$ by the CMM's best fit of them to their nominals before continuing.");
    line("MODE/MAN");
    for (const PlannedPoint& p : a.manual) {
      const std::string label = dmis_label(p.id);
      line("F(" + label + ")=FEAT/POINT,CART," + xyz_text(p.xyz) + "," + ijk_text(p.ijk));
      line("TEXT/MAN,'" + prompt_text("Touch " + label + " on face " + p.face + " near " + near_text(p.xyz)) + "'");
      line("MEAS/POINT,F(" + label + "),1");
      line("ENDMES");
      line("OUTPUT/FA(" + label + ")");
    }
    // No moves here: the operator leaves the probe above the clearance
    // plane, and the tour starts from there as without an alignment (a
    // GOTO here could not be told from the first point's moves).
    line("MODE/PROG,MAN");
    return;
  } else {
    line("$$ Manual pre-alignment: touch the datum points by joystick when prompted; the program");
    line("$$ then measures the datums again under program control and sets the part frame.");
    for (const DatumFeature& d : a.datums) {
      std::string f = "F(DATUM_" + d.label + ")=FEAT/";
      if (d.kind == DatumFeature::Kind::plane)
        f += "PLANE,CART," + xyz_text(d.origin) + "," + ijk_text(d.direction);
      else if (d.kind == DatumFeature::Kind::line)
        f += "LINE,BND,CART," + xyz_text(d.points.front().xyz) + "," + xyz_text(d.points.back().xyz) + "," +
             ijk_text(d.normal);
      else if (d.kind == DatumFeature::Kind::cylinder)  // measured as a circle at the points' height
        f += std::string("CIRCLE,") + (is_bore(d) ? "INNER" : "OUTER") + ",CART," + xyz_text(d.origin) + "," +
             ijk_text(d.direction) + "," + fixed_number(2 * d.radius, kProgramDecimals);
      else
        f += "POINT,CART," + xyz_text(d.origin) + "," + ijk_text(d.normal);
      line(f);
    }
    line("MODE/MAN");
    for (const DatumFeature& d : a.datums) {
      std::string near;
      for (const PlannedPoint& p : d.points) near += (near.empty() ? "" : ", ") + near_text(p.xyz);
      line("TEXT/MAN,'" + prompt_text("Datum " + d.label + ": touch " + std::to_string(d.points.size()) +
                                      " point(s) on face " + d.face + " near " + near) + "'");
      line(std::string("MEAS/") + dmis_measure_word(d.kind) + ",F(DATUM_" + d.label + ")," + std::to_string(d.points.size()));
      line("ENDMES");
    }
    line("D(MANUAL)=" + datset(a));
    line("D(MANUAL_CAD)=" + trans(a));
    line("MODE/PROG,MAN");
    std::size_t k = 0;
    for (const DatumFeature& d : a.datums) {
      line(std::string("MEAS/") + dmis_measure_word(d.kind) + ",F(DATUM_" + d.label + ")," + std::to_string(d.points.size()));
      for (std::size_t n = 0; n < d.points.size(); ++n, ++k) {
        const ProgramStep& step = program.alignment_steps[k];
        for (const Eigen::Vector3d& m : step.moves_before) line("GOTO/" + xyz_text(m));
        line("PTMEAS/CART," + xyz_text(step.point.xyz) + "," + ijk_text(step.point.ijk));
      }
      line("ENDMES");
    }
    // Up and over to the tour's start before the frame statements, which
    // end the alignment for a reader.
    for (const Eigen::Vector3d& m : program.alignment_final_moves) line("GOTO/" + xyz_text(m));
    line("D(DATUMS)=" + datset(a));
    line("D(PART)=" + trans(a));
    for (const DatumFeature& d : a.datums) line("OUTPUT/FA(DATUM_" + d.label + ")");
    // Saved for the programs that run on this set-up (furrow remeasure's
    // RECALL/DA(PART)).
    line("SAVE/DA(PART)");
  }
}

}  // namespace

std::string dmis_program_text(const ProbeProgram& program) {
  check_program(program, "DMIS");
  std::ostringstream out;
  const std::function<void(const std::string&)> line = [&](const std::string& s) { out << s << "\r\n"; };
  const std::string probe = dmis_label(program.probe.name);
  line("$$ Furrow probe program " + program.name);
  line("$$ part: " + (program.part.empty() ? std::string("not named") : program.part) +
       "; revision: " + (program.revision.empty() ? std::string("not stated") : program.revision) +
       "; date: " + (program.date.empty() ? std::string("not stated") : program.date));
  line("$$ " + std::to_string(program.steps.size()) + " points; probe " + probe + ", ball diameter " +
       fixed_number(program.probe.diameter, 4) + " mm, stylus length " + fixed_number(program.stylus_length, 3) +
       " mm, head to ball centre " + fixed_number(program.head_length, 3) + " mm");
  line("$$ Coordinates are the part's CAD frame: establish the part coordinate system");
  if (program.alignment)
    line("$$ with the alignment this program begins with; start with the probe qualified and above the clearance plane.");
  else if (!program.recalled_alignment.empty())
    line("$$ recalled from the first program (RECALL/DA), the part not moved since; start with the probe qualified and above the clearance plane.");
  else
    line("$$ (alignment) before running, with the probe qualified and above the clearance plane.");
  line("DMISMN/'" + program.name + "',05.2");
  line("FILNAM/'" + program.name + "',05.2");
  line("UNITS/MM,ANGDEC");
  if (!program.part.empty()) line("PN(PART)=PARTID/'" + program.part + "'");
  if (!program.revision.empty()) line("PR(REV)=PARTRV/'" + program.revision + "'");
  line("PL(PROGRAM)=PLANID/'" + program.name + "'");
  line("PRCOMP/ON");
  if (program.tips.empty()) {
    line("S(" + probe + ")=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1," + fixed_number(program.head_length, kProgramDecimals) +
         "," + fixed_number(program.probe.diameter, kProgramDecimals));
    line("SNSLCT/S(" + probe + ")");
  } else {
    // The tips to qualify, in the order the program uses them.
    std::string list;
    for (const TipAngles& t : program.tips) {
      const bool fresh = std::find(program.unqualified_tips.begin(), program.unqualified_tips.end(), t) !=
                         program.unqualified_tips.end();
      list += (list.empty() ? " " : ", ") + tip_name(t) + (fresh ? " (new: qualify it)" : " (qualified)");
    }
    line("$$ tips in the order used:" + list);
    // One sensor per tip: its A and B, the stylus straight along the probe
    // body (0,0,-1 in the head's frame), the head-to-ball length.
    for (const TipAngles& t : program.tips)
      line("S(" + dmis_label(tip_sensor_name(program, t)) + ")=SNSDEF/PROBE,INDEX,POL," + angle_text(t.a) + "," +
           angle_text(t.b) + ",0,0,-1," + fixed_number(program.head_length, kProgramDecimals) + "," +
           fixed_number(program.probe.diameter, kProgramDecimals));
    line("SNSLCT/S(" + dmis_label(tip_sensor_name(program, *program.start_tip)) + ")");
  }
  line("FEDRAT/POSVEL,MMPS," + fixed_number(program.move_speed, kProgramDecimals));
  line("FEDRAT/MESVEL,MMPS," + fixed_number(program.measure_speed, kProgramDecimals));
  line("SNSET/APPRCH," + fixed_number(program.approach, kProgramDecimals));
  line("SNSET/RETRCT," + fixed_number(program.retract, kProgramDecimals));
  line("SNSET/SEARCH," + fixed_number(program.search, kProgramDecimals));
  if (program.tolerance)
    line("T(PROFILE)=TOL/PROFP," + fixed_number(program.tolerance->lower, kProgramDecimals) + "," +
         fixed_number(program.tolerance->upper, kProgramDecimals));
  line("DID(RESULTS)=DEVICE/STOR,'" + program.name + ".dmo'");
  line("OPEN/DID(RESULTS),FDATA,DMIS,OUTPUT");
  line("MODE/PROG,MAN");
  if (program.alignment) write_alignment(program, line);
  if (!program.recalled_alignment.empty()) line("RECALL/DA(" + dmis_label(program.recalled_alignment) + ")");
  const std::string tolerance_output = program.tolerance ? ",TA(PROFILE)" : "";
  std::optional<TipAngles> tip = program.start_tip;
  for (const ProgramStep& step : program.steps) {
    const PlannedPoint& p = step.point;
    const std::string label = dmis_label(p.id);
    std::string info = "$$ " + label + ": order " + std::to_string(p.order) + ", face " + std::to_string(p.face_index);
    if (p.region) info += ", region " + std::to_string(*p.region);
    if (p.tip) info += ", tip " + tip_name(*p.tip);
    line(info);
    // A tip change: after the rise to the clearance plane (probe_program.hpp).
    const bool change = p.tip && p.tip != tip;
    const std::string select = change ? "SNSLCT/S(" + dmis_label(tip_sensor_name(program, *p.tip)) + ")" : "";
    if (change && step.moves_before.size() < 2) line(select);
    for (std::size_t k = 0; k < step.moves_before.size(); ++k) {
      line("GOTO/" + xyz_text(step.moves_before[k]));
      if (change && k == 0 && step.moves_before.size() >= 2) line(select);
    }
    tip = p.tip;
    line("F(" + label + ")=FEAT/POINT,CART," + xyz_text(p.xyz) + "," + ijk_text(p.ijk));
    line("MEAS/POINT,F(" + label + "),1");
    line("PTMEAS/CART," + xyz_text(p.xyz) + "," + ijk_text(p.ijk));
    line("ENDMES");
    line("OUTPUT/FA(" + label + ")" + tolerance_output);
  }
  for (const Eigen::Vector3d& m : program.final_moves) line("GOTO/" + xyz_text(m));
  line("CLOSE/DID(RESULTS)");
  line("ENDFIL");
  return out.str();
}

}  // namespace furrow

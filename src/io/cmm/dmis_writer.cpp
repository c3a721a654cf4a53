#include "io/cmm/dmis_writer.hpp"

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

}  // namespace

std::string dmis_program_text(const ProbeProgram& program) {
  check_program(program, "DMIS");
  std::ostringstream out;
  auto line = [&](const std::string& s) { out << s << "\r\n"; };
  const std::string probe = dmis_label(program.probe.name);
  line("$$ Furrow probe program " + program.name);
  line("$$ part: " + (program.part.empty() ? std::string("not named") : program.part) +
       "; revision: " + (program.revision.empty() ? std::string("not stated") : program.revision) +
       "; date: " + (program.date.empty() ? std::string("not stated") : program.date));
  line("$$ " + std::to_string(program.steps.size()) + " points; probe " + probe + ", ball diameter " +
       fixed_number(program.probe.diameter, 4) + " mm, stylus length " + fixed_number(program.stylus_length, 3) +
       " mm, head to ball centre " + fixed_number(program.head_length, 3) + " mm");
  line("$$ Coordinates are the part's CAD frame: establish the part coordinate system");
  line("$$ (alignment) before running, with the probe qualified and above the clearance plane.");
  line("DMISMN/'" + program.name + "',05.2");
  line("FILNAM/'" + program.name + "',05.2");
  line("UNITS/MM,ANGDEC");
  if (!program.part.empty()) line("PN(PART)=PARTID/'" + program.part + "'");
  if (!program.revision.empty()) line("PR(REV)=PARTRV/'" + program.revision + "'");
  line("PL(PROGRAM)=PLANID/'" + program.name + "'");
  line("PRCOMP/ON");
  line("S(" + probe + ")=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1," + fixed_number(program.head_length, kProgramDecimals) +
       "," + fixed_number(program.probe.diameter, kProgramDecimals));
  line("SNSLCT/S(" + probe + ")");
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
  const std::string tolerance_output = program.tolerance ? ",TA(PROFILE)" : "";
  for (const ProgramStep& step : program.steps) {
    const PlannedPoint& p = step.point;
    const std::string label = dmis_label(p.id);
    std::string info = "$$ " + label + ": order " + std::to_string(p.order) + ", face " + std::to_string(p.face_index);
    if (p.region) info += ", region " + std::to_string(*p.region);
    line(info);
    for (const Eigen::Vector3d& m : step.moves_before) line("GOTO/" + xyz_text(m));
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

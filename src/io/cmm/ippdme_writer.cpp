#include "io/cmm/ippdme_writer.hpp"

#include <cstdio>
#include <sstream>

namespace furrow {

namespace {

class CommandFile {
 public:
  void command(const std::string& text) {
    char tag[8];
    std::snprintf(tag, sizeof tag, "%05d", tag_);
    out_ << tag << ' ' << text << "\r\n\\\\\r\n";
    tag_ = tag_ == kMaxIppTag ? 1 : tag_ + 1;
  }
  std::string finish() {
    out_ << ":\r\n:\r\n";
    return out_.str();
  }

 private:
  std::ostringstream out_;
  int tag_ = 1;
};

std::string position(const Eigen::Vector3d& p) {
  return "X(" + fixed_number(p.x(), kProgramDecimals) + "), Y(" + fixed_number(p.y(), kProgramDecimals) + "), Z(" +
         fixed_number(p.z(), kProgramDecimals) + ")";
}

}  // namespace

std::string ippdme_program_text(const ProbeProgram& program) {
  check_program(program, "I++ DME");
  CommandFile file;
  file.command("StartSession()");
  file.command("Home()");
  file.command("SetCoordSystem(PartCsy)");
  file.command("ChangeTool(\"" +
               (program.start_tip ? tip_sensor_name(program, *program.start_tip) : program.probe.name) + "\")");
  file.command("SetProp(Tool.PtMeasPar.Approach(" + fixed_number(program.approach, kProgramDecimals) + "))");
  file.command("SetProp(Tool.PtMeasPar.Retract(" + fixed_number(program.retract, kProgramDecimals) + "))");
  file.command("SetProp(Tool.PtMeasPar.Search(" + fixed_number(program.search, kProgramDecimals) + "))");
  file.command("SetProp(Tool.GoToPar.Speed(" + fixed_number(program.move_speed, kProgramDecimals) + "))");
  file.command("SetProp(Tool.PtMeasPar.Speed(" + fixed_number(program.measure_speed, kProgramDecimals) + "))");
  file.command("OnPtMeasReport(X(), Y(), Z(), IJK())");
  std::optional<TipAngles> tip = program.start_tip;
  auto measure = [&](const ProgramStep& step) {
    // A tip change: after the rise to the clearance plane (probe_program.hpp).
    const std::optional<TipAngles>& want = step.point.tip;
    const bool change = want && want != tip;
    const std::string select = change ? "ChangeTool(\"" + tip_sensor_name(program, *want) + "\")" : "";
    if (change && step.moves_before.size() < 2) file.command(select);
    for (std::size_t k = 0; k < step.moves_before.size(); ++k) {
      file.command("GoTo(" + position(step.moves_before[k]) + ")");
      if (change && k == 0 && step.moves_before.size() >= 2) file.command(select);
    }
    if (want) tip = want;
    const Eigen::Vector3d& n = step.point.ijk;
    file.command("PtMeas(" + position(step.point.xyz) + ", IJK(" + fixed_number(n.x(), kDirectionDecimals) + ", " +
                 fixed_number(n.y(), kDirectionDecimals) + ", " + fixed_number(n.z(), kDirectionDecimals) + "))");
  };
  if (program.alignment) {
    // The alignment points, in the pre-aligned PartCsy; the client computes
    // the part frame from their responses and sets it (SetCsyTransformation)
    // before PartCsy is selected again (docs/cmm.md "Part alignment").
    for (const ProgramStep& step : program.alignment_steps) measure(step);
    for (const Eigen::Vector3d& m : program.alignment_final_moves) file.command("GoTo(" + position(m) + ")");
    file.command("SetCoordSystem(PartCsy)");
  }
  for (const ProgramStep& step : program.steps) measure(step);
  for (const Eigen::Vector3d& m : program.final_moves) file.command("GoTo(" + position(m) + ")");
  file.command("EndSession()");
  return file.finish();
}

}  // namespace furrow

#include "stage/compensate_stage.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "io/machining/apt_reader.hpp"
#include "io/machining/apt_rewrite.hpp"
#include "io/machining/gcode_reader.hpp"
#include "io/machining/gcode_rewrite.hpp"
#include "io/machining/rework_program.hpp"
#include "machining/prediction/path_contacts.hpp"

namespace furrow {

namespace {

using nlohmann::json;

json point_list(const std::vector<OffsetPoint>& points) {
  json out = json::array();
  for (const OffsetPoint& p : points)
    out.push_back({{"line", p.line}, {"requested", p.requested}, {"applied", p.applied}});
  return out;
}

json clip_back_list(const std::vector<ClipBackPoint>& points) {
  json out = json::array();
  for (const ClipBackPoint& p : points)
    out.push_back({{"line", p.line}, {"requested", p.requested}, {"applied", p.applied}, {"rounds", p.rounds}});
  return out;
}

json rework_section(const ReworkProgram& r) {
  const ReworkSelection& s = r.selection;
  json stretches = json::array();
  for (const ReworkStretch& st : s.stretches) {
    double length = 0;
    for (std::size_t k = 1; k < st.tips.size(); ++k) length += (st.tips[k] - st.tips[k - 1]).norm();
    stretches.push_back({{"first_line", st.first_line},
                         {"last_line", st.last_line},
                         {"points", st.tips.size()},
                         {"length", length}});
  }
  json regions = json::array();
  for (const ReworkRegion& g : s.regions)
    regions.push_back({{"box", {g.box.min().x(), g.box.min().y(), g.box.max().x(), g.box.max().y()}},
                       {"stretches", g.stretches.size()}});
  json doc = {{"threshold", r.threshold},
              {"threshold_from", r.threshold_given ? "option" : "comparison tolerance"},
              {"largest_field", s.largest_field},
              {"written", !r.text.empty()},
              {"clearance", s.clearance},
              {"step", s.step},
              {"moves", s.moves},
              {"moves_kept", s.moves_kept},
              {"pieces", s.pieces},
              {"pieces_kept", s.pieces_kept},
              {"stretches", stretches},
              {"regions", regions}};
  if (!r.text.empty())
    doc["check"] = {{"resolution", r.check.resolution},
                    {"tolerance", r.check.tolerance},
                    {"nodes", r.check.nodes},
                    {"deeper", r.check.deeper},
                    {"worst_excess", r.check.worst_excess},
                    {"rapids", r.check.rapids},
                    {"rapids_unchecked", r.check.rapids_unchecked},
                    {"rapid_nodes_cut", r.check.rapid_nodes_cut},
                    {"worst_rapid_depth", r.check.worst_rapid_depth},
                    {"safe", r.check.safe()}};
  return doc;
}

json statistics_json(const ExpectedStatistics& s) {
  return {{"points", s.count},
          {"rms_before", s.rms_before},
          {"worst_before", {{"id", s.worst_before_id}, {"value", s.worst_before}}},
          {"rms_field", s.rms_field},
          {"largest_standard_error", s.largest_standard_error},
          {"rms_after", s.rms_after},
          {"worst_after", {{"id", s.worst_after_id}, {"value", s.worst_after}}}};
}

json expected_section(const CompensationExpectation& e) {
  json regions = json::array();
  for (const RegionExpectation& r : e.regions) {
    json one = statistics_json(r.statistics);
    one["region"] = r.region;
    regions.push_back(one);
  }
  json points = json::array();
  for (const ExpectedPoint& p : e.points)
    points.push_back({{"id", p.id},
                      {"region", p.region >= 0 ? json(p.region) : json(nullptr)},
                      {"measured", p.measured},
                      {"field", p.field},
                      {"standard_error", p.standard_error},
                      {"cut", p.cut},
                      {"correction", p.correction},
                      {"residual", p.residual}});
  return {{"reach", e.reach}, {"overall", statistics_json(e.overall)}, {"regions", regions}, {"points", points}};
}

std::string document(const Part& part, const CompensatedProgram& c, const CompensateOptions& options,
                     const CompensationSources& names) {
  json faces = json::array();
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const FaceErrorField* field = c.field.field.faces.size() > f ? c.field.field.faces[f].get() : nullptr;
    json face = {{"face", part.faces[f].name()},
                 {"fitted", field && field->fitted()},
                 {"status", field ? field->status() : std::string("no samples")},
                 {"samples", field ? field->samples() : 0}};
    if (field && field->fitted()) {
      face["sigma"] = field->gcv()->sigma;
      face["lambda"] = field->gcv()->lambda;
      face["fade_distance"] = field->fade_distance();
    }
    faces.push_back(face);
  }
  // Moves moved and their largest offset, per face of their contact.
  json doc = {
      {"part", names.part},
      {"comparison", names.comparison},
      {"toolpath", names.toolpath},
      {"program", names.out},
      {"gain", options.gain},
      {"max_offset", options.max_offset},
      {"smoothing", options.smoothing ? json(*options.smoothing) : json("auto")},
      {"prediction", names.prediction.empty() ? json(nullptr) : json(names.prediction)},
      {"prediction_removed", c.field.prediction_removed},
      {"not_predicted", c.field.not_predicted},
      {"samples", c.field.samples},
      {"faces", faces},
      {"moves_moved", c.offset.moved},
      {"largest_offset", c.offset.largest_offset},
      {"no_contact", c.offset.no_contact},
      {"in_air", c.offset.in_air},
      {"clipped", point_list(c.offset.clipped)},
      {"gouge_clipped", point_list(c.offset.gouge_clipped)},
      {"unreachable", point_list(c.offset.unreachable)},
      {"clip_back",
       {{"rounds", c.clip_back_rounds},
        {"max_rounds", options.clip_back},
        {"points", clip_back_list(c.clip_back)}}},
      {"written",
       {{"decimals", c.program.decimals},
        {"lines_moved", c.program.lines_moved},
        {"words_rewritten", c.program.words_rewritten},
        {"words_added", c.program.words_added},
        {"arcs_split", c.program.arcs_split},
        {"lines_inserted", c.program.lines_inserted},
        {"lines_removed", c.program.lines_removed}}},
      {"zmap_check",
       {{"resolution", c.check.resolution},
        {"tolerance", c.check.tolerance},
        {"nodes", c.check.nodes},
        {"not_judged", c.check.not_judged},
        {"deeper", c.check.deeper},
        {"worst_excess", c.check.worst_excess},
        {"safe", c.check.safe()}}},
  };
  doc["expected"] = expected_section(c.expected);
  if (c.rework) doc["rework"] = rework_section(*c.rework);
  return doc.dump(2) + "\n";
}

}  // namespace

CompensatedProgram compensate_stage(const Part& part, const PathTools& tools, const std::string& program_text,
                                    ProgramFormat format, const ToolpathReadOptions& read,
                                    const ComparisonDocument& comparison, const CompensateOptions& options,
                                    const CompensationSources& names, const Prediction* prediction) {
  if (!(options.gain > 0 && options.gain <= 2))
    throw InputError("compensate: --gain must be in (0, 2]");
  if (!(options.max_offset > 0) || !std::isfinite(options.max_offset))
    throw InputError("compensate: --max-offset must be a positive number of mm");
  if (options.clip_back < 0 || options.clip_back > 30)
    throw InputError("compensate: --clip-back must be in [0, 30]");
  if (options.rework_threshold && !options.rework)
    throw InputError("compensate: --rework-threshold is given without --rework");
  if (options.rework_threshold && (!(*options.rework_threshold >= 0) || !std::isfinite(*options.rework_threshold)))
    throw InputError("compensate: --rework-threshold must be a length >= 0 in mm");
  if (tools.changes_tools() && options.rework)
    throw InputError(names.toolpath + ": the program changes tools; --rework takes a program of one tool "
                     "(compensate it without --rework)");
  const bool apt = format == ProgramFormat::apt;
  auto parse = [&](const std::string& text, const std::string& name) {
    return apt ? parse_apt(text, name, read) : parse_gcode(text, name, read);
  };
  const Toolpath path = parse(program_text, names.toolpath);
  CompensatedProgram out;
  ErrorFieldOptions field_options;
  field_options.smoothing_length = options.smoothing;
  if (prediction) check_prediction_against_part(*prediction, part, names.prediction, names.part);
  out.field = fit_error_field(comparison, part, field_options, names.comparison, prediction);
  // Each pass with the cutter in the spindle when it is cut: its contacts,
  // offsets and z-map check are that cutter's.
  const Cutter& cutter = tools.cutters.front();  // the only one with --rework
  auto cutter_of = [&](std::size_t pass) -> const Cutter& {
    return tools.cutters[static_cast<std::size_t>(tools.of_pass[pass])];
  };
  PathOffsetOptions offset_options;
  offset_options.gain = options.gain;
  offset_options.max_offset = options.max_offset;
  const PathGeometry geometry = locate_path(part, tools, path);
  out.offset = offset_path(part, tools, geometry, out.field.field, offset_options);
  // Write, read back (what is checked is what is written), check; where the
  // check blames moves, halve their ends' offsets and go again.
  std::map<std::pair<std::size_t, std::size_t>, ClipBackPoint> reduced;
  for (;;) {
    out.program = apt ? rewrite_apt(program_text, names.toolpath, read, out.offset.tips)
                      : rewrite_gcode(program_text, names.toolpath, read, out.offset.tips);
    const Toolpath written = parse(out.program.text, names.out);
    const double half_unit = 0.5 * std::pow(10.0, -out.program.decimals) * out.program.unit_mm;
    out.check = check_compensation_zmap(tools, path, written, out.offset, half_unit);
    if (out.check.safe() || out.clip_back_rounds >= options.clip_back) break;
    bool changed = false;
    for (const auto& [pass, step] : out.check.blamed)
      for (std::size_t k : {step, step + 1}) {
        const double d = out.offset.offsets[pass][k];
        if (d == 0) continue;
        auto [at, fresh] = reduced.try_emplace({pass, k});
        if (fresh) at->second = {pass, k, geometry.passes[pass][k].line, d, d, 0};
        // Halved once per round, however many of its moves are blamed.
        if (at->second.rounds > out.clip_back_rounds) continue;
        reduce_offset(out.offset, cutter_of(pass), geometry, pass, k, 0.5, offset_options.location);
        at->second.applied = out.offset.offsets[pass][k];
        at->second.rounds = out.clip_back_rounds + 1;
        changed = true;
      }
    if (!changed) break;  // nothing left to reduce: the check cannot be met this way
    ++out.clip_back_rounds;
  }
  for (const auto& [where, point] : reduced) out.clip_back.push_back(point);
  // After the clip-back: the offsets the program carries.
  // A contact cuts the surface within its cutter's radius; with several
  // cutters the largest stands for all (docs/compensation.md "Programs that
  // change tools").
  double reach = 0;
  for (const Cutter& c : tools.cutters) reach = std::max(reach, c.radius());
  out.expected = expect_compensation(comparison, out.field.field, geometry, out.offset, reach);
  if (options.rework && out.check.safe()) {
    ReworkProgram r;
    r.threshold_given = options.rework_threshold.has_value();
    r.threshold = options.rework_threshold.value_or(comparison.options.tolerance.upper());
    ReworkOptions rework_options;
    rework_options.threshold = r.threshold;
    r.selection = select_rework(part, cutter, path, out.offset, out.field.field, rework_options);
    if (!r.selection.stretches.empty()) {
      const int decimals = out.program.decimals;
      r.text = write_rework_program(program_text, path, r.selection.stretches, r.selection.clearance, decimals,
                                    apt ? ReworkFormat::apt : ReworkFormat::gcode);
      const Toolpath rework = parse(r.text, names.out);
      // Read back to the tips written: the header may set inch units or a
      // work offset that the rework's millimetres in the part frame ignore.
      const double half = 0.5 * std::pow(10.0, -decimals);
      bool same = rework.passes.size() == r.selection.stretches.size();
      for (std::size_t s = 0; same && s < rework.passes.size(); ++s) {
        const auto& tips = r.selection.stretches[s].tips;
        const auto& points = rework.passes[s].points;
        same = points.size() == tips.size() + 1;
        for (std::size_t k = 0; same && k < tips.size(); ++k)
          same = (points[k + 1].position - tips[k]).cwiseAbs().maxCoeff() <= half * (1 + 1e-6) + 1e-9;
      }
      if (!same)
        throw InputError(names.toolpath +
                         ": the rework program, read back, is not where it was written: its header sets units or a "
                         "work offset the rework (written in millimetres in the part frame) cannot carry");
      const Toolpath written = parse(out.program.text, names.out);
      const double full_half = 0.5 * std::pow(10.0, -out.program.decimals) * out.program.unit_mm;
      r.check = check_rework(cutter, path, written, rework, r.selection.clearance,
                             1e-3 + std::sqrt(3.0) * (half + full_half));
    }
    out.rework = std::move(r);
  }
  out.json = document(part, out, options, names);
  return out;
}

PredictedPath predict_compensated(const Part& part, const std::optional<ToolSpec>& tool,
                                  const std::string& tool_source,
                                  const std::optional<std::vector<ToolTableEntry>>& table,
                                  const std::string& table_source, const std::string& program_text,
                                  ProgramFormat format, const ToolpathReadOptions& read,
                                  const PathPredictionOptions& options, const PredictionSources& names,
                                  const StageProgress& progress) {
  // read_toolpath's rules, on the text about to be written.
  if (program_text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(names.toolpath + ": the file is empty");
  const Toolpath path = format == ProgramFormat::apt ? parse_apt(program_text, names.toolpath, read)
                                                     : parse_gcode(program_text, names.toolpath, read);
  const PathTools tools = tools_for_path(path, tool, tool_source, table, table_source);
  return predict_stage(part, tools, path, options, names, nullptr, progress);
}

}  // namespace furrow

#include "stage/compensate_stage.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "io/machining/gcode_reader.hpp"
#include "machining/prediction/path_contacts.hpp"
#include "machining/prediction/zmap.hpp"

namespace furrow {

namespace {

using nlohmann::json;

// The z-map check of docs/compensation.md "Writing the program".
CompensationGougeCheck check_with_zmap(const Cutter& cutter, const Toolpath& original,
                                       const Toolpath& written, const PathOffset& offset, double half_unit) {
  CompensationGougeCheck check;
  // Only where tips moved can the programs differ.
  Eigen::AlignedBox2d box;
  for (std::size_t p = 0; p < original.passes.size(); ++p)
    for (std::size_t k = 0; k < original.passes[p].points.size(); ++k)
      if (offset.tips[p][k] != original.passes[p].points[k].position) {
        box.extend(original.passes[p].points[k].position.head<2>());
        box.extend(offset.tips[p][k].head<2>());
      }
  if (box.isEmpty()) return check;
  // A fifteenth of the shank radius (0.2 mm for a 6 mm ball): a gouge
  // narrower than a cell can fall between nodes (a stated limit).
  check.resolution = cutter.radius() / 15;
  check.tolerance = 1e-3 + std::sqrt(3.0) * half_unit;
  const double margin = cutter.radius() + 2 * check.resolution;
  box.min().array() -= margin;
  box.max().array() += margin;
  ZMap before(box, check.resolution), after(box, check.resolution);
  before.cut(cutter, moves_from_toolpath(original));
  const std::vector<ZMapMove> moves = moves_from_toolpath(written);
  after.cut(cutter, moves);
  // The offset of each written move: per move when the written program has
  // the original's points (arcs are split through the same points), else
  // the largest anywhere.
  bool same_points = written.passes.size() == original.passes.size();
  for (std::size_t p = 0; same_points && p < original.passes.size(); ++p)
    same_points = written.passes[p].points.size() == original.passes[p].points.size();
  const double c = check.resolution;
  for (int j = 0; j < after.ny(); ++j)
    for (int i = 0; i < after.nx(); ++i) {
      const double h = after.node_height(i, j), h0 = before.node_height(i, j);
      if (!std::isfinite(h) || !std::isfinite(h0)) continue;
      ++check.nodes;
      if (h >= h0) continue;
      double d = offset.largest_offset;
      const std::int32_t owner = after.node_owner(i, j);
      const ZMapMove& move = moves[static_cast<std::size_t>(owner)];
      const auto pass = static_cast<std::size_t>(move.pass), step = static_cast<std::size_t>(move.step);
      if (same_points)
        d = std::max(std::abs(offset.offsets[pass][step]), std::abs(offset.offsets[pass][step + 1]));
      // The original machined surface's slope at the node. At the rim of
      // the swept region (a neighbour uncut) and where it is steeper than
      // n_z = 0.2 (a ball's side, where a lateral move of a micrometre
      // changes the height a lot) a z-map cannot tell: not judged.
      if (i == 0 || j == 0 || i + 1 == after.nx() || j + 1 == after.ny()) {
        ++check.not_judged;
        continue;
      }
      const double xm = before.node_height(i - 1, j), xp = before.node_height(i + 1, j);
      const double ym = before.node_height(i, j - 1), yp = before.node_height(i, j + 1);
      if (!std::isfinite(xm) || !std::isfinite(xp) || !std::isfinite(ym) || !std::isfinite(yp)) {
        ++check.not_judged;
        continue;
      }
      const double sx = (xp - xm) / (2 * c), sy = (yp - ym) / (2 * c);
      const double nz = 1 / std::sqrt(1 + sx * sx + sy * sy);
      if (nz < 0.2) {
        ++check.not_judged;
        continue;
      }
      const double excess = (h0 - h) - (d / nz + check.tolerance);
      if (excess <= 0) continue;
      ++check.deeper;
      if (excess > check.worst_excess) {
        check.worst_excess = excess;
        check.worst = Eigen::Vector3d(after.x(i), after.y(j), h);
        check.worst_line = written.passes[pass].points[step + 1].line;
      }
    }
  return check;
}

json point_list(const std::vector<OffsetPoint>& points) {
  json out = json::array();
  for (const OffsetPoint& p : points)
    out.push_back({{"line", p.line}, {"requested", p.requested}, {"applied", p.applied}});
  return out;
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
      {"prediction_removed", c.field.prediction_removed},
      {"samples", c.field.samples},
      {"faces", faces},
      {"moves_moved", c.offset.moved},
      {"largest_offset", c.offset.largest_offset},
      {"no_contact", c.offset.no_contact},
      {"in_air", c.offset.in_air},
      {"clipped", point_list(c.offset.clipped)},
      {"gouge_clipped", point_list(c.offset.gouge_clipped)},
      {"unreachable", point_list(c.offset.unreachable)},
      {"written",
       {{"decimals", c.program.decimals},
        {"lines_moved", c.program.lines_moved},
        {"words_rewritten", c.program.words_rewritten},
        {"words_added", c.program.words_added},
        {"arcs_split", c.program.arcs_split},
        {"lines_inserted", c.program.lines_inserted}}},
      {"zmap_check",
       {{"resolution", c.check.resolution},
        {"tolerance", c.check.tolerance},
        {"nodes", c.check.nodes},
        {"not_judged", c.check.not_judged},
        {"deeper", c.check.deeper},
        {"worst_excess", c.check.worst_excess},
        {"safe", c.check.safe()}}},
  };
  return doc.dump(2) + "\n";
}

}  // namespace

CompensatedProgram compensate_stage(const Part& part, const PathTools& tools, const std::string& program_text,
                                    const ToolpathReadOptions& read, const ComparisonDocument& comparison,
                                    const CompensateOptions& options, const CompensationSources& names) {
  if (!(options.gain > 0 && options.gain <= 2))
    throw InputError("compensate: --gain must be in (0, 2]");
  if (!(options.max_offset > 0) || !std::isfinite(options.max_offset))
    throw InputError("compensate: --max-offset must be a positive number of mm");
  if (tools.changes_tools())
    throw InputError(names.toolpath + ": the program changes tools; compensation takes one tool");
  std::vector<GcodeMotionBlock> blocks;
  const Toolpath path = parse_gcode(program_text, names.toolpath, read, &blocks);
  CompensatedProgram out;
  ErrorFieldOptions field_options;
  field_options.smoothing_length = options.smoothing;
  out.field = fit_error_field(comparison, part, field_options, names.comparison);
  const Cutter& cutter = tools.cutters.front();
  PathOffsetOptions offset_options;
  offset_options.gain = options.gain;
  offset_options.max_offset = options.max_offset;
  const PathGeometry geometry = locate_path(part, cutter, path);
  out.offset = offset_path(part, tools, geometry, out.field.field, offset_options);
  out.program = rewrite_gcode(program_text, names.toolpath, read, out.offset.tips);
  // What is written is what is checked: the program read back.
  const Toolpath written = parse_gcode(out.program.text, names.out, read);
  double scale = 1;  // mm per program unit; the coarser where G20 and G21 mix
  for (const GcodeMotionBlock& b : blocks) scale = std::max(scale, b.scale);
  const double half_unit = 0.5 * std::pow(10.0, -out.program.decimals) * scale;
  out.check = check_with_zmap(cutter, path, written, out.offset, half_unit);
  out.json = document(part, out, options, names);
  return out;
}

}  // namespace furrow

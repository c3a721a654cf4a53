#include "inspection/compensation_record.hpp"

#include <cmath>
#include <map>

#include "base/error.hpp"
#include "base/json_cursor.hpp"

namespace furrow {

namespace {

namespace jf = json_fields;
using json = nlohmann::json;

const char* kSee = "docs/formats.md \"Compensation record\"";

// One of the record's lists of limited points: only its length is shown.
std::size_t listed(const JsonCursor& c, const std::string& key) { return c.array(key).size(); }

// {"id", "value"}: the worst point of a statistic.
void read_worst(const JsonCursor& c, const std::string& key, std::string& id, double& value) {
  const JsonCursor w = c.at(key);
  id = w.string("id");
  value = w.number("value");
  w.finish(kSee);
}

ExpectedStatistics read_statistics(const JsonCursor& c) {
  ExpectedStatistics s;
  s.count = c.count("points");
  s.rms_before = c.non_negative("rms_before");
  s.rms_after = c.non_negative("rms_after");
  s.rms_field = c.non_negative("rms_field");
  s.largest_standard_error = c.non_negative("largest_standard_error");
  read_worst(c, "worst_before", s.worst_before_id, s.worst_before);
  read_worst(c, "worst_after", s.worst_after_id, s.worst_after);
  return s;
}

CompensationExpectation read_expected(const JsonCursor& c) {
  CompensationExpectation e;
  e.reach = c.positive("reach");
  {
    const JsonCursor overall = c.at("overall");
    e.overall = read_statistics(overall);
    overall.finish(kSee);
  }
  const json& regions = c.array("regions");
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const JsonCursor r(regions[k], jf::child(c.path("regions"), k));
    RegionExpectation one;
    one.region = r.integer("region", 0);
    one.statistics = read_statistics(r);
    r.finish(kSee);
    if (!e.regions.empty() && one.region <= e.regions.back().region)
      throw InputError(jf::child(c.path("regions"), k) + ".region: regions must be in increasing order");
    e.regions.push_back(one);
  }
  const json& points = c.array("points");
  for (std::size_t k = 0; k < points.size(); ++k) {
    const JsonCursor p(points[k], jf::child(c.path("points"), k));
    ExpectedPoint q;
    q.id = p.string("id");
    q.region = p.is_null("region") ? -1 : p.integer("region", 0);
    q.measured = p.number("measured");
    q.field = p.number("field");
    q.standard_error = p.non_negative("standard_error");
    q.cut = p.boolean("cut");
    q.correction = p.number("correction");
    q.residual = p.number("residual");
    p.finish(kSee);
    e.points.push_back(q);
  }
  if (e.overall.count != e.points.size())
    throw InputError(c.path("overall") + ".points: " + std::to_string(e.overall.count) + " points, but " +
                     std::to_string(e.points.size()) + " are listed");
  return e;
}

}  // namespace

CompensationRecord parse_compensation_record(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const JsonCursor root(doc, name + ":");
  CompensationRecord r;
  root.skip("part");
  r.comparison = root.string("comparison");
  r.toolpath = root.string("toolpath");
  r.program = root.string("program");
  r.gain = root.positive("gain");
  r.max_offset = root.positive("max_offset");
  if (root.raw("smoothing").is_string()) {
    if (root.string("smoothing") != "auto")
      throw InputError(root.path("smoothing") + ": expected a length in mm or \"auto\"");
  } else {
    r.smoothing = root.positive("smoothing");
  }
  root.nullable_string("prediction");
  r.prediction_removed = root.boolean("prediction_removed");
  root.count("not_predicted");
  r.samples = root.count("samples");
  root.array("faces");  // per-face fit details: in the record, not in the report
  r.moves_moved = root.count("moves_moved");
  r.largest_offset = root.non_negative("largest_offset");
  r.no_contact = root.count("no_contact");
  r.in_air = root.count("in_air");
  r.clipped = listed(root, "clipped");
  r.gouge_clipped = listed(root, "gouge_clipped");
  r.unreachable = listed(root, "unreachable");
  {
    const JsonCursor c = root.at("clip_back");
    r.clip_back_rounds = c.integer("rounds", 0);
    c.integer("max_rounds", 0);
    r.clip_back_points = listed(c, "points");
    c.finish(kSee);
  }
  root.skip("written");     // what the writer changed in the program's text
  root.skip("zmap_check");  // true in every written record
  {
    const JsonCursor e = root.at("expected");
    r.expected = read_expected(e);
    e.finish(kSee);
  }
  if (const std::optional<JsonCursor> w = root.optional_at("rework")) {
    CompensationRecord::Rework rw;
    rw.threshold = w->non_negative("threshold");
    rw.moves = w->count("moves");
    rw.moves_kept = w->count("moves_kept");
    rw.stretches = w->array("stretches").size();
    for (const char* key : {"threshold_from", "largest_field", "written", "clearance", "step", "pieces",
                            "pieces_kept", "regions", "check"})
      w->skip(key);
    w->finish(kSee);
    r.rework = rw;
  }
  root.finish(kSee);
  return r;
}

CompensationRecord read_compensation_record(const std::string& path) {
  return parse_compensation_record(jf::read_text(path), path);
}

void check_record_against(CompensationRecord& record, const ComparisonDocument& comparison, const std::string& name) {
  std::map<std::string, std::size_t> evaluated;
  for (std::size_t i = 0; i < comparison.points.size(); ++i)
    if (comparison.points[i].evaluated) evaluated.emplace(comparison.points[i].id, i);
  const std::string other = name + " is the compensation of another comparison: ";
  for (ExpectedPoint& p : record.expected.points) {
    const auto at = evaluated.find(p.id);
    if (at == evaluated.end()) throw InputError(other + "point " + p.id + " is not an evaluated point of it");
    // The record copies the comparison's deviation as read, so it is the
    // same double; a picometre allows for a comparison written again.
    const ComparisonDocument::Point& c = comparison.points[at->second];
    if (std::abs(c.deviation - p.measured) > 1e-9)
      throw InputError(other + "point " + p.id + " has the deviation " + std::to_string(p.measured) +
                       " mm there and " + std::to_string(c.deviation) + " mm in the comparison");
    p.index = at->second;
  }
  if (record.expected.points.size() != evaluated.size())
    throw InputError(other + "it lists " + std::to_string(record.expected.points.size()) +
                     " measured points, the comparison has " + std::to_string(evaluated.size()) + " evaluated");
}

}  // namespace furrow

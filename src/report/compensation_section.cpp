#include "report/compensation_section.hpp"

#include "base/json_fields.hpp"
#include "base/number_text.hpp"
#include "report/html.hpp"

namespace furrow {

namespace {

using html::escape;
using html::TableRow;
using nlohmann::json;

std::string um(double mm) { return signed_fixed(mm * 1000, 1); }
std::string um_unsigned(double mm) { return fixed(mm * 1000, 1); }
std::string count(std::size_t n) { return std::to_string(n); }

// A worst point as "+61.3 (P0042)"; a dash for a scope without points.
std::string worst(const std::string& id, double mm) {
  return id.empty() ? "&ndash;" : um(mm) + " (" + escape(id) + ")";
}

TableRow statistics_row(const std::string& scope, const ExpectedStatistics& s) {
  TableRow row;
  row.cells = {scope,
               count(s.count),
               um_unsigned(s.rms_before),
               worst(s.worst_before_id, s.worst_before),
               um_unsigned(s.rms_after),
               worst(s.worst_after_id, s.worst_after),
               um_unsigned(s.rms_field),
               um_unsigned(s.largest_standard_error)};
  return row;
}

json number(double v, const char* what) { return json_fields::finite(v, what); }

json statistics_json(const ExpectedStatistics& s) {
  return {{"points", s.count},
          {"rms_before", number(s.rms_before, "rms_before")},
          {"worst_before", s.worst_before_id.empty()
                               ? json(nullptr)
                               : json({{"id", s.worst_before_id}, {"value", number(s.worst_before, "worst")}})},
          {"rms_after", number(s.rms_after, "rms_after")},
          {"worst_after", s.worst_after_id.empty()
                              ? json(nullptr)
                              : json({{"id", s.worst_after_id}, {"value", number(s.worst_after, "worst")}})},
          {"rms_field", number(s.rms_field, "rms_field")},
          {"largest_standard_error", number(s.largest_standard_error, "largest_standard_error")}};
}

}  // namespace

std::string compensation_section_html(const std::optional<CompensationRecord>& record, const std::string& source,
                                      const std::string& figures_html) {
  if (!record) return "";
  const CompensationRecord& r = *record;
  const CompensationExpectation& e = r.expected;
  std::string out = "<section id=\"compensation\"><h2>Compensation</h2>\n";
  out += "<p>What the compensated program <code>" + escape(r.program) +
         "</code> is expected to leave at the measured points once it is cut (from <code>" + escape(source) +
         "</code>): the measured deviation plus the correction the program writes at the path contact nearest to "
         "each point, within " +
         fixed(e.reach, 2) +
         " mm (the cutter's radius; farther, the program does not cut the point). It assumes a repeatable error "
         "and the next part set up where this one was (docs/compensation.md).</p>\n";
  std::string limited = count(r.clipped) + " clipped at the maximum offset, " + count(r.gouge_clipped) +
                        " cut back against a local gouge, " + count(r.unreachable) + " unreachable, " +
                        count(r.clip_back_points) + " reduced by the z-map clip-back in " +
                        std::to_string(r.clip_back_rounds) + " round" + (r.clip_back_rounds == 1 ? "" : "s");
  std::vector<std::pair<std::string, std::string>> kv = {
      {"Gain", fixed(r.gain, 3)},
      {"Maximum offset", um_unsigned(r.max_offset) + " &micro;m"},
      {"Smoothing", r.smoothing ? fixed(*r.smoothing, 3) + " mm" : "automatic (GCV)"},
      {"Field fitted to", std::string(r.prediction_removed ? "residuals against the prediction"
                                                           : "the deviations themselves (no prediction)") +
                              ", " + count(r.samples) + " samples"},
      {"Moves moved", count(r.moves_moved) + ", largest offset " + um_unsigned(r.largest_offset) + " &micro;m"},
      {"Corrections limited", limited},
  };
  if (r.rework)
    kv.push_back({"Rework", "the program re-cuts " + count(r.rework->moves_kept) + " of " + count(r.rework->moves) +
                                " moves in " + count(r.rework->stretches) + " stretches, where more than " +
                                um_unsigned(r.rework->threshold) + " &micro;m of material is left"});
  out += html::key_value_table(kv);
  std::vector<TableRow> rows = {statistics_row("All points", e.overall)};
  for (const RegionExpectation& g : e.regions) rows.push_back(statistics_row("R" + std::to_string(g.region), g.statistics));
  out += html::table({"Points of", "Points", "RMS before [um]", "Worst before [um]", "RMS expected after [um]",
                      "Worst expected after [um]", "Field RMS [um]", "Largest field 1-sigma [um]"},
                     rows, "compensation");
  return out + figures_html + "</section>\n";
}

nlohmann::json compensation_section_json(const std::optional<CompensationRecord>& record, const std::string& source) {
  if (!record) return nullptr;
  const CompensationRecord& r = *record;
  json regions = json::array();
  for (const RegionExpectation& g : r.expected.regions) {
    json one = statistics_json(g.statistics);
    one["region"] = g.region;
    regions.push_back(std::move(one));
  }
  return {{"record", source},
          {"program", r.program},
          {"gain", number(r.gain, "gain")},
          {"max_offset", number(r.max_offset, "max_offset")},
          {"smoothing", r.smoothing ? number(*r.smoothing, "smoothing") : json("auto")},
          {"prediction_removed", r.prediction_removed},
          {"samples", r.samples},
          {"moves_moved", r.moves_moved},
          {"largest_offset", number(r.largest_offset, "largest_offset")},
          {"clipped", r.clipped},
          {"gouge_clipped", r.gouge_clipped},
          {"unreachable", r.unreachable},
          {"clip_back", {{"points", r.clip_back_points}, {"rounds", r.clip_back_rounds}}},
          {"rework", r.rework ? json({{"threshold", number(r.rework->threshold, "threshold")},
                                      {"moves", r.rework->moves},
                                      {"moves_kept", r.rework->moves_kept},
                                      {"stretches", r.rework->stretches}})
                              : json(nullptr)},
          {"reach", number(r.expected.reach, "reach")},
          {"overall", statistics_json(r.expected.overall)},
          {"regions", std::move(regions)}};
}

}  // namespace furrow

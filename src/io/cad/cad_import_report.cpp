#include "io/cad/cad_import_report.hpp"

#include <cstdio>
#include <sstream>

#include "base/json_fields.hpp"

namespace furrow {

namespace {

std::string fmt(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

}  // namespace

std::string cad_import_report_text(const CadImportResult& r, const std::string& source,
                                   const std::string& output) {
  std::ostringstream out;
  out << source << ": " << r.format << ", file units " << r.part.source_units << " (written in mm), "
      << r.solids << (r.solids == 1 ? " solid, " : " solids, ") << r.part.faces.size()
      << (r.part.faces.size() == 1 ? " face" : " faces") << " imported";
  if (!r.skipped.empty()) out << ", " << r.skipped.size() << " left out";
  out << "\n";
  if (r.free_faces > 0) {
    int flipped = 0, undecided = 0;
    for (const CadFaceReport& f : r.faces) {
      flipped += f.flipped;
      undecided += f.orientation == CadFaceOrientation::file;
    }
    out << "  " << r.free_faces << " face(s) bound no solid: sewn into " << r.sewn_shells << " shell(s), "
        << r.closed_shells << " closed; " << flipped << " face(s) turned to point out of the material";
    if (undecided > 0)
      out << "; " << undecided << " face(s) undecided (open shell, no --outward rule): oriented like most of "
          << "their shell in the file";
    out << "\n";
  }
  for (std::size_t i = 0; i < r.faces.size(); ++i) {
    const CadFaceReport& f = r.faces[i];
    out << "face " << i << " \"" << f.name << "\"";
    if (!f.entity.empty()) out << " " << f.entity;
    out << ": " << f.source_type << ", "
        << (f.exact ? "exact" : "approximated") << fmt(" (max deviation %.2g mm)", f.deviation)
        << ", ";
    if (f.loops == 0)
      out << "untrimmed";
    else
      out << f.loops << (f.loops == 1 ? " trim loop, " : " trim loops, ") << f.trim_vertices
          << " vertices" << fmt(" (within %.2g mm)", f.trim_deviation);
    if (!f.trim_tolerance_met) out << " - trim tolerance NOT reached";
    if (f.orientation != CadFaceOrientation::solid)
      out << ", orientation " << to_string(f.orientation) << (f.flipped ? " (turned)" : "");
    out << "\n";
  }
  for (const CadSkippedFace& s : r.skipped)
    out << "left out: face" << (s.name.empty() ? "" : " \"" + s.name + "\"")
        << (s.entity.empty() ? "" : " " + s.entity) << ": " << s.reason << "\n";
  out << "wrote " << output << "\n";
  return out.str();
}

std::string cad_import_report_json(const CadImportResult& r, const std::string& source,
                                   const std::string& output) {
  using json_fields::json;
  json doc;
  doc["source"] = source;
  doc["output"] = output;
  doc["format"] = r.format;
  doc["source_units"] = r.part.source_units;
  doc["products"] = r.products;
  doc["solids"] = r.solids;
  doc["free_faces"] = r.free_faces;
  doc["sewn_shells"] = r.sewn_shells;
  doc["closed_shells"] = r.closed_shells;
  json faces = json::array();
  for (const CadFaceReport& f : r.faces) {
    json j;
    j["name"] = f.name;
    j["entity"] = f.entity;
    j["source_type"] = f.source_type;
    j["exact"] = f.exact;
    j["deviation_mm"] = f.deviation;
    if (!f.exact) j["approximation_bound_mm"] = f.approximation_bound;
    j["trim_loops"] = f.loops;
    j["trim_vertices"] = f.trim_vertices;
    j["trim_deviation_mm"] = f.trim_deviation;
    j["trim_tolerance_met"] = f.trim_tolerance_met;
    j["orientation"] = to_string(f.orientation);
    j["flipped"] = f.flipped;
    faces.push_back(std::move(j));
  }
  doc["faces"] = std::move(faces);
  json skipped = json::array();
  for (const CadSkippedFace& s : r.skipped)
    skipped.push_back({{"name", s.name}, {"entity", s.entity}, {"reason", s.reason}});
  doc["skipped"] = std::move(skipped);
  return json_fields::to_text(doc);
}

}  // namespace furrow

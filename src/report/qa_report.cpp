#include "report/qa_report.hpp"

#include <ctime>
#include <filesystem>
#include <future>

#include "base/error.hpp"
#include "base/atomic_file.hpp"
#include "base/output_set.hpp"
#include "base/json_fields.hpp"
#include "report/file_digest.hpp"
#include "report/points_csv.hpp"
#include "report/report_qif.hpp"
#include "report/report_figures.hpp"
#include "report/report_html.hpp"
#include "report/report_json.hpp"
#include "report/verdict.hpp"

namespace furrow {

void check_comparison_faces(const ComparisonDocument& doc, const Part& part) {
  auto check = [&](int index, const std::string& name, const std::string& what) {
    if (index < 0 || static_cast<std::size_t>(index) >= part.faces.size() ||
        part.faces[static_cast<std::size_t>(index)].name() != name)
      throw InputError("comparison of another part: " + what + " lies on face " + std::to_string(index) + " \"" +
                       name + "\", which part " + doc.sources.part + " does not have");
  };
  for (const auto& p : doc.points) check(p.face_index, p.face, "point " + p.id);
  if (doc.gouges) {
    for (const GougeSiteCheck& s : doc.gouges->sites) check(s.face_index, s.face, "gouge site " + s.id);
    for (const OvercutCluster& c : doc.gouges->unexplained) check(c.face_index, c.face, "overcut " + c.id);
  }
}

InputDigest digest_file(const std::string& role, const std::string& path) {
  InputDigest d;
  d.role = role;
  d.path = path;
  const std::string bytes = json_fields::read_text(path);
  d.sha256 = sha256_hex(bytes);
  d.bytes = bytes.size();
  return d;
}

InputDigest digest_generated(const std::string& role, const std::string& path, const std::string& bytes) {
  InputDigest d;
  d.role = role;
  d.path = path;
  d.sha256 = sha256_hex(bytes);
  d.bytes = bytes.size();
  d.generated = true;
  return d;
}

std::string utc_timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

std::vector<std::optional<AnalyticSurface>> face_surfaces(const Part& part, const ComparisonDocument& doc) {
  std::vector<char> measured(part.faces.size(), 0);
  for (const ComparisonDocument::Point& p : doc.points)
    if (p.face_index >= 0 && static_cast<std::size_t>(p.face_index) < part.faces.size())
      measured[static_cast<std::size_t>(p.face_index)] = 1;
  std::vector<std::optional<AnalyticSurface>> out(part.faces.size());
  for (std::size_t f = 0; f < part.faces.size(); ++f)
    if (measured[f]) out[f] = part.faces[f].analytic() ? part.faces[f].analytic() : recognise_analytic(part.faces[f].surface());
  return out;
}

std::vector<FolderFile> make_report(const ComparisonDocument& doc, const Part& part, const RegionMap* regions,
                                    const ReportContext& context, const Prediction* prediction) {
  check_comparison_faces(doc, part);
  ReportContext with_surfaces = context;
  if (with_surfaces.face_surfaces.empty()) with_surfaces.face_surfaces = face_surfaces(part, doc);
  return render_report(doc, regions,
                       make_report_figures(doc, part, regions, prediction,
                                           context.compensation ? &*context.compensation : nullptr),
                       with_surfaces);
}

std::vector<FolderFile> render_report(const ComparisonDocument& doc, const RegionMap* regions,
                                      const std::vector<ReportFigure>& figures, const ReportContext& context) {
  const ReportVerdict verdict = report_verdict(doc);
  // The four documents only read the comparison, so they are written two at
  // a time, the longest (report.json) beside the other three (docs/report.md,
  // "Speed"). Each is the same text whichever thread writes it.
  std::future<std::string> json = std::async(std::launch::async, [&] {
    return report_json_text(doc, verdict, regions, context, figures);
  });
  std::vector<FolderFile> files;
  files.push_back({"report.html", report_html(doc, verdict, regions, context, figures)});
  std::string csv = points_csv_text(doc);
  files.push_back({"report.json", json.get()});
  files.push_back({"points.csv", std::move(csv)});
  // QIF Results hold measured points; a scan's are in its deviation cloud
  // (docs/report.md "A scan"), so a scan's report has no results.qif.
  if (!context.scan)
    files.push_back({"results.qif", comparison_to_qif(doc, context.inputs, context.generated, context.record)});  // docs/qif.md
  for (const ReportFigure& f : figures) {
    files.push_back({f.file, std::string(f.png.begin(), f.png.end())});
    if (!f.svg.empty()) files.push_back({f.svg_file(), f.svg});  // the same text as inline in the HTML
  }
  return files;
}

void check_inputs_outside(const std::string& folder, const std::vector<InputDigest>& inputs) {
  for (const InputDigest& in : inputs)
    if (!in.generated) check_output_spares_input(folder, in.path, in.role);
}

void write_folder_files(const std::string& folder, const std::vector<FolderFile>& files) {
  for (const FolderFile& f : files)
    write_file_atomically((std::filesystem::path(folder) / f.path).string(), f.bytes);
}

}  // namespace furrow

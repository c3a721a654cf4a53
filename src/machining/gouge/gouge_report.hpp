#pragma once
// What `furrow gouge` writes: the per-point JSON (docs/formats.md "Gouge
// JSON") and a short text summary. Deterministic: same inputs, same bytes.
#include <string>
#include <vector>

#include "machining/gouge/gouge_scan.hpp"

namespace furrow {

struct GougeSummary {
  std::size_t points = 0, clear = 0, gouge = 0, unreachable = 0, degenerate = 0,
              concave_crease = 0, border = 0;
  std::size_t border_unresolved = 0;  // border points whose neighbour search did not converge
  double max_excess = 0;  // largest excess over gouging points [1/mm]
  long worst = -1;        // index of that point, -1 when nothing gouges
  std::vector<std::size_t> face_points, face_gouges;  // per face
};

GougeSummary summarize_gouges(const Part& part, const std::vector<GougePoint>& points);

// Where the sites came from, for the report's "sites" member.
struct SiteSource {
  int grid = 0;             // nodes per direction (grid mode)
  std::string points_file;  // contact-point file (points mode), else empty
};

std::string gouge_report_json(const Part& part, const std::string& part_path,
                              const Cutter& cutter, const std::vector<GougePoint>& points,
                              const SiteSource& source, const GougeScanOptions& options);

// A few lines for a terminal.
std::string gouge_summary_text(const Part& part, const std::string& part_path,
                               const Cutter& cutter, const std::vector<GougePoint>& points);

}  // namespace furrow

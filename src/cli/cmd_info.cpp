// furrow info PART: what a part file contains, at a glance or as JSON.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/commands.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "partition/classification.hpp"
#include "partition/part_summary.hpp"

namespace furrow::cli {

namespace {

std::string fmt(const char* format, double a, double b) {
  char buf[96];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

void print_classes(std::ostream& out, const std::array<double, 4>& area, double total) {
  out << "classes";
  for (int c = 0; c < kCurvatureClassCount; ++c)
    out << "  " << to_string(static_cast<CurvatureClass>(c))
        << fmt(" %.1f%%", total > 0 ? 100.0 * area[c] / total : 0.0, 0);
  out << "\n";
}

void print_text(std::ostream& out, const std::string& path, const PartSummary& s) {
  out << "part " << path << ": " << s.faces.size() << (s.faces.size() == 1 ? " face" : " faces")
      << ", file units " << s.source_units << " (shown in mm)\n";
  for (std::size_t i = 0; i < s.faces.size(); ++i) {
    const FaceSummary& f = s.faces[i];
    out << "\nface " << i << " \"" << f.name << "\"";
    if (!f.source_type.empty()) out << " (" << f.source_type << ")";
    out << ": degree " << f.degree_u << "x" << f.degree_v << ", control net " << f.num_u << "x"
        << f.num_v << (f.rational ? ", rational" : ", polynomial")
        << (f.reversed ? ", reversed" : "") << (f.trimmed ? ", trimmed" : "") << "\n";
    out << "  domain      u " << fmt("[%g, %g]", f.domain.u0, f.domain.u1) << "  v "
        << fmt("[%g, %g]", f.domain.v0, f.domain.v1) << "\n";
    if (!f.box.isEmpty())
      out << "  extent      x " << fmt("[%.4f, %.4f]", f.box.min().x(), f.box.max().x()) << "  y "
          << fmt("[%.4f, %.4f]", f.box.min().y(), f.box.max().y()) << "  z "
          << fmt("[%.4f, %.4f]", f.box.min().z(), f.box.max().z()) << " mm\n";
    out << "  area        " << fmt("%.4f mm^2", f.area, 0) << "\n";
    if (f.valid_samples > 0) {
      out << "  K           " << fmt("[%.6g, %.6g] 1/mm^2", f.K.min, f.K.max) << "\n";
      out << "  H           " << fmt("[%.6g, %.6g] 1/mm", f.H.min, f.H.max) << "\n";
      out << "  k1          " << fmt("[%.6g, %.6g] 1/mm", f.k1.min, f.k1.max) << "\n";
      out << "  k2          " << fmt("[%.6g, %.6g] 1/mm", f.k2.min, f.k2.max) << "\n";
    }
    if (f.degenerate_samples > 0)
      out << "  degenerate  " << f.degenerate_samples << " samples with a vanishing normal\n";
    if (f.analytic) out << "  analytic    " << describe(*f.analytic) << "\n";
    out << "  ";
    print_classes(out, f.class_area, f.area);
    if (!s.eps) out << "  eps         " << fmt("%.3g 1/mm", f.eps, 0) << "\n";
  }
  out << "\nwhole part: " << fmt("area %.4f mm^2", s.area, 0) << ", ";
  print_classes(out, s.class_area, s.area);
  out << "(sampled on " << s.grid << "x" << s.grid << " cells per face, eps ";
  if (s.eps) {
    out << *s.eps << " 1/mm";
  } else {
    out << "per face as in furrow partition";
  }
  out << "; convex means bulging toward the tool)\n";
}

int run_info(Args& args) {
  const bool as_json = args.flag("json");
  const long grid = args.integer_or("grid", 200, 2);
  const std::optional<double> eps = args.number("eps");
  if (eps && *eps < 0) args.fail("--eps must not be negative, got " + std::to_string(*eps));
  const auto out_path = args.option("out");
  const std::string path = args.positional("PART (a part file)");
  args.finish();
  if (grid > 4000) args.fail("--grid " + std::to_string(grid) + " is too fine (at most 4000)");

  const Part part = read_part(path);
  // Work is bounded over all faces too (docs/formats.md "Limits").
  constexpr double kMaxSamples = 64e6;
  const double samples = static_cast<double>(grid) * grid * static_cast<double>(part.faces.size());
  if (samples > kMaxSamples)
    args.fail("--grid " + std::to_string(grid) + " over the " + std::to_string(part.faces.size()) + " faces of " + path +
              " is " + std::to_string(static_cast<long long>(samples)) + " samples, more than the limit of 64000000");
  const PartSummary summary = summarize_part(part, static_cast<int>(grid), eps);
  std::ostringstream text;
  if (as_json) {
    text << part_summary_json(summary);
  } else {
    print_text(text, path, summary);
  }
  if (out_path) {
    OutputSet outputs;
    outputs.add_input(path, "part");
    outputs.file(*out_path, text.str());
    outputs.publish();
  } else {
    std::cout << text.str();
  }
  return kExitOk;
}

}  // namespace

const Command kInfoCommand = {
    "info", "describe a part: faces, extent, curvature ranges, class shares",
    "usage: furrow info PART [--json] [--grid N] [--eps K] [--out FILE]\n"
    "\n"
    "Lists each face of PART (part JSON, STEP or IGES) with its original surface type:\n"
    "degrees, control net, parameter domain, extent, area, the sampled ranges of\n"
    "K, H, k1, k2 and the share of convex/concave/saddle/planar area.\n"
    "\n"
    "  --json      machine-readable output (docs/formats.md)\n"
    "  --grid N    samples per direction per face (default 200)\n"
    "  --eps K     curvature tolerance for the classes in 1/mm (default: each face's\n"
    "              own, the rule furrow partition uses; see docs/partition.md)\n"
    "  --out FILE  write to FILE instead of standard output\n",
    run_info};

}  // namespace furrow::cli

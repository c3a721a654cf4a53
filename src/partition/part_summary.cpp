#include "partition/part_summary.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"
#include "base/numbers.hpp"
#include "partition/curvature_field.hpp"
#include "partition/curvature_tolerance.hpp"

namespace furrow {

namespace {

void extend(Range& r, double x, bool first) {
  if (first) {
    r.min = r.max = x;
  } else {
    r.min = std::min(r.min, x);
    r.max = std::max(r.max, x);
  }
}

FaceSummary summarize_face(const Face& face, int grid, std::optional<double> user_eps) {
  const NurbsSurface& s = face.surface();
  FaceSummary f;
  f.name = face.name();
  f.source_type = face.source_type();
  f.degree_u = s.degree_u();
  f.degree_v = s.degree_v();
  f.num_u = s.num_u();
  f.num_v = s.num_v();
  f.rational = s.is_rational();
  f.reversed = face.reversed();
  f.trimmed = !face.trim().empty();
  f.domain = s.domain();
  f.eps = user_eps ? *user_eps : face_curvature_tolerance(face).eps;
  f.analytic = face.analytic() ? face.analytic() : recognise_analytic(s);

  // Extent from nodes including the domain edges (cell centres miss them).
  for (int i = 0; i <= grid; ++i) {
    for (int j = 0; j <= grid; ++j) {
      const double u = f.domain.u0 + f.domain.width_u() * i / grid;
      const double v = f.domain.v0 + f.domain.width_v() * j / grid;
      if (face.trim().contains({u, v})) f.box.extend(s.point(u, v));
    }
  }
  const CurvatureField field = compute_curvature_field(face, grid, grid);
  bool first = true;
  for (const CurvatureSample& c : field.samples) {
    if (c.status == SampleStatus::degenerate) ++f.degenerate_samples;
    if (!c.valid()) continue;
    if (f.box.isEmpty()) f.box.extend(c.point);  // a trim that misses every node
    ++f.valid_samples;
    extend(f.K, c.K, first);
    extend(f.H, c.H, first);
    extend(f.k1, c.k1, first);
    extend(f.k2, c.k2, first);
    first = false;
    f.area += c.area;
    f.class_area[static_cast<int>(classify_curvature(c.k1, c.k2, f.eps))] += c.area;
  }
  return f;
}

json_fields::json range_json(const Range& r) {
  return {json_fields::finite(r.min, "min"), json_fields::finite(r.max, "max")};
}

json_fields::json class_json(const std::array<double, 4>& area, double total) {
  json_fields::json j = json_fields::json::object();
  for (int c = 0; c < kCurvatureClassCount; ++c) {
    j[to_string(static_cast<CurvatureClass>(c))] = {
        {"area", json_fields::finite(area[c], "class area")},
        {"share", json_fields::finite(total > 0 ? area[c] / total : 0.0, "class share")}};
  }
  return j;
}

}  // namespace

PartSummary summarize_part(const Part& part, int grid, std::optional<double> eps) {
  if (grid < 2) throw InputError("info: the sampling grid must be at least 2, got " + std::to_string(grid));
  if (eps && (!(*eps >= 0) || !std::isfinite(*eps))) throw InputError("info: eps must be a finite number >= 0");
  PartSummary summary;
  summary.source_units = part.source_units;
  summary.grid = grid;
  summary.eps = eps;
  for (const Face& face : part.faces) {
    FaceSummary f = summarize_face(face, grid, eps);
    summary.box.extend(f.box);
    summary.area += f.area;
    for (int c = 0; c < kCurvatureClassCount; ++c) summary.class_area[c] += f.class_area[c];
    summary.faces.push_back(std::move(f));
  }
  return summary;
}

std::string part_summary_json(const PartSummary& s) {
  using json_fields::finite;
  using json_fields::json;
  using json_fields::vector_json;
  json faces = json::array();
  for (const FaceSummary& f : s.faces) {
    json jf;
    jf["name"] = f.name;
    if (!f.source_type.empty()) jf["source_type"] = f.source_type;
    jf["degree"] = {f.degree_u, f.degree_v};
    jf["control_net"] = {f.num_u, f.num_v};
    jf["rational"] = f.rational;
    jf["reversed"] = f.reversed;
    jf["trimmed"] = f.trimmed;
    jf["domain"] = {{"u", {finite(f.domain.u0, "u0"), finite(f.domain.u1, "u1")}},
                    {"v", {finite(f.domain.v0, "v0"), finite(f.domain.v1, "v1")}}};
    if (!f.box.isEmpty())
      jf["bounding_box"] = {{"min", vector_json(f.box.min())}, {"max", vector_json(f.box.max())}};
    jf["area_mm2"] = finite(f.area, "area");
    jf["valid_samples"] = f.valid_samples;
    jf["degenerate_samples"] = f.degenerate_samples;
    if (f.valid_samples > 0) {
      jf["K"] = range_json(f.K);
      jf["H"] = range_json(f.H);
      jf["k1"] = range_json(f.k1);
      jf["k2"] = range_json(f.k2);
    }
    if (f.analytic) jf["analytic"] = analytic_json(*f.analytic);
    jf["eps"] = finite(f.eps, "eps");
    jf["classes"] = class_json(f.class_area, f.area);
    faces.push_back(std::move(jf));
  }
  json doc;
  doc["units"] = "mm";
  doc["source_units"] = s.source_units;
  doc["grid"] = s.grid;
  if (s.eps) {
    doc["eps"] = finite(*s.eps, "eps");
  } else {
    doc["eps"] = "per face";
  }
  doc["face_count"] = s.faces.size();
  if (!s.box.isEmpty())
    doc["bounding_box"] = {{"min", vector_json(s.box.min())}, {"max", vector_json(s.box.max())}};
  doc["area_mm2"] = finite(s.area, "area");
  doc["classes"] = class_json(s.class_area, s.area);
  doc["faces"] = std::move(faces);
  return json_fields::to_text(doc);
}

}  // namespace furrow

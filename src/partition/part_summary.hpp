#pragma once
// What `furrow info` reports about a part: per face its NURBS structure, the
// sampled extent and curvature ranges, and how its area splits into curvature
// classes. Sampling is a cell-centred grid (see curvature_field.hpp), so the
// numbers are estimates whose resolution is stated in the summary.
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

struct Range {
  double min = 0, max = 0;
};

struct FaceSummary {
  std::string name, source_type;
  int degree_u = 0, degree_v = 0, num_u = 0, num_v = 0;
  bool rational = false, reversed = false, trimmed = false;
  ParameterDomain domain;
  Eigen::AlignedBox3d box;  // of sampled surface points (nodes incl. edges)
  double area = 0;          // mm^2, midpoint rule over untrimmed cells
  Range K, H, k1, k2;       // over valid samples
  std::array<double, 4> class_area{};  // indexed by CurvatureClass
  double eps = 0;                      // [1/mm] the classes were taken with
  // The face's elementary surface: the part file's, else recognised here.
  std::optional<AnalyticSurface> analytic;
  int valid_samples = 0, degenerate_samples = 0;
};

struct PartSummary {
  std::string source_units;
  int grid = 0;  // samples per direction per face
  // The user's eps for every face, or unset: each face's own
  // (face_curvature_tolerance(), the same rule as `furrow partition`).
  std::optional<double> eps;
  std::vector<FaceSummary> faces;
  Eigen::AlignedBox3d box;
  double area = 0;
  std::array<double, 4> class_area{};
};

// Preconditions: grid >= 2, eps unset or finite >= 0 (InputError otherwise).
PartSummary summarize_part(const Part& part, int grid, std::optional<double> eps);

// Machine-readable form (documented in docs/formats.md "furrow info --json").
std::string part_summary_json(const PartSummary& summary);

}  // namespace furrow

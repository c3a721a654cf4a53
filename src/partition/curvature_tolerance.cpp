#include "partition/curvature_tolerance.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace furrow {

CurvatureTolerance default_curvature_tolerance(const CurvatureField& field) {
  std::vector<double> magnitude;
  magnitude.reserve(field.samples.size());
  for (const CurvatureSample& s : field.samples)
    if (s.valid()) magnitude.push_back(std::max(std::fabs(s.k1), std::fabs(s.k2)));
  CurvatureTolerance t;
  if (magnitude.empty()) return t;
  const auto rank = static_cast<std::size_t>(
      std::floor(kEpsScalePercentile * static_cast<double>(magnitude.size() - 1)));
  std::nth_element(magnitude.begin(), magnitude.begin() + static_cast<std::ptrdiff_t>(rank),
                   magnitude.end());
  t.curvature_scale = magnitude[rank];
  t.eps = std::max(kEpsFloor, kEpsRelative * t.curvature_scale);
  return t;
}

CurvatureTolerance face_curvature_tolerance(const Face& face) {
  const CurvatureField coarse = compute_curvature_field(face, kEpsScaleGrid, kEpsScaleGrid);
  const auto valid = std::count_if(coarse.samples.begin(), coarse.samples.end(),
                                   [](const CurvatureSample& s) { return s.valid(); });
  if (valid >= kEpsScaleMinSamples) return default_curvature_tolerance(coarse);
  return default_curvature_tolerance(compute_curvature_field(face, kEpsScaleFineGrid, kEpsScaleFineGrid));
}

}  // namespace furrow

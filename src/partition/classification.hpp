#pragma once
// Curvature class of a surface point (docs/architecture.md "Conventions").
//
// With principal curvatures k1 >= k2 (normal out of the material, a dome has
// negative curvatures) and a tolerance eps >= 0 [1/mm]:
//   planar  if |k1| <= eps and |k2| <= eps
//   convex  if k1 <= eps and k2 <= eps and H < 0
//   concave if k1 >= -eps and k2 >= -eps and H > 0
//   saddle  if k1 > eps and k2 < -eps
// This is the K/H rule (K >= 0 & H < 0 convex, K >= 0 & H >= 0 concave,
// K < 0 saddle) made robust near zero: a cylinder is convex or concave, never
// saddle, and ripples below eps do not make speckles.
#include <string>

namespace furrow {

enum class CurvatureClass : unsigned char { planar = 0, convex = 1, concave = 2, saddle = 3 };
constexpr int kCurvatureClassCount = 4;

// Default tolerance when neither the user nor a tool gives one [1/mm].
constexpr double kDefaultCurvatureEps = 1e-4;

CurvatureClass classify_curvature(double k1, double k2, double eps);

const char* to_string(CurvatureClass c);
// Parses "planar", "convex", "concave", "saddle"; false for anything else.
bool parse_curvature_class(const std::string& text, CurvatureClass& out);

}  // namespace furrow

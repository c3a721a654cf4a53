#include "render/colour_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace furrow {

namespace {

// Anchors of the scale (t, r, g, b): a ColorBrewer-like RdBu ramp.
constexpr double kAnchors[][4] = {
    {-1.0, 5, 48, 97},   {-0.6, 33, 102, 172}, {-0.3, 146, 197, 222}, {0.0, 247, 247, 247},
    {0.3, 244, 165, 130}, {0.6, 214, 96, 77},  {1.0, 103, 0, 31},
};

}  // namespace

Rgb diverging_colour(double t) {
  if (!std::isfinite(t)) return {150, 150, 150};
  t = std::clamp(t, -1.0, 1.0);
  constexpr int n = sizeof(kAnchors) / sizeof(kAnchors[0]);
  int k = 0;
  while (k + 2 < n && t > kAnchors[k + 1][0]) ++k;
  const double* a = kAnchors[k];
  const double* b = kAnchors[k + 1];
  const double s = (t - a[0]) / (b[0] - a[0]);
  Rgb c;
  for (int i = 0; i < 3; ++i)
    c[i] = static_cast<unsigned char>(std::lround(a[i + 1] + s * (b[i + 1] - a[i + 1])));
  return c;
}

Rgb status_colour(const char* status) {
  struct Entry {
    const char* name;
    Rgb colour;
  };
  static const Entry kEntries[] = {
      {"CONFIRMED", {200, 30, 30}},    {"NOT CONFIRMED", {40, 150, 60}}, {"NOT MEASURED", {140, 140, 140}},
      {"UNEXPLAINED", {130, 50, 170}}, {"PASS", {40, 150, 60}},          {"FAIL", {200, 30, 30}},
  };
  for (const Entry& e : kEntries)
    if (std::strcmp(e.name, status) == 0) return e.colour;
  return {70, 70, 70};
}

Rgb curvature_class_colour(const char* curvature_class) {
  struct Entry {
    const char* name;
    Rgb colour;
  };
  static const Entry kEntries[] = {
      {"planar", {232, 214, 170}}, {"convex", {238, 130, 72}}, {"concave", {86, 160, 207}}, {"saddle", {112, 186, 110}},
  };
  for (const Entry& e : kEntries)
    if (std::strcmp(e.name, curvature_class) == 0) return e.colour;
  return {215, 215, 215};
}

}  // namespace furrow

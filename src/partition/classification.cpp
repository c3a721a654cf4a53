#include "partition/classification.hpp"

#include <cmath>

namespace furrow {

CurvatureClass classify_curvature(double k1, double k2, double eps) {
  if (std::fabs(k1) <= eps && std::fabs(k2) <= eps) return CurvatureClass::planar;
  if (k1 > eps && k2 < -eps) return CurvatureClass::saddle;
  // Outside the planar box and not a saddle, both curvatures lie on one side
  // of the band [-eps, eps]; the sign of H decides which. H == 0 would need
  // k1 = -k2 with both inside the band, i.e. planar, so it cannot occur here.
  return (k1 + k2 < 0) ? CurvatureClass::convex : CurvatureClass::concave;
}

const char* to_string(CurvatureClass c) {
  switch (c) {
    case CurvatureClass::planar: return "planar";
    case CurvatureClass::convex: return "convex";
    case CurvatureClass::concave: return "concave";
    case CurvatureClass::saddle: return "saddle";
  }
  return "planar";
}

bool parse_curvature_class(const std::string& text, CurvatureClass& out) {
  for (int c = 0; c < kCurvatureClassCount; ++c) {
    if (text == to_string(static_cast<CurvatureClass>(c))) {
      out = static_cast<CurvatureClass>(c);
      return true;
    }
  }
  return false;
}

}  // namespace furrow

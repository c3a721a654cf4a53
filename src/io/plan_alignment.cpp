#include "io/plan_alignment.hpp"

namespace furrow {

const char* to_string(DatumFeature::Kind kind) {
  switch (kind) {
    case DatumFeature::Kind::plane: return "plane";
    case DatumFeature::Kind::line: return "line";
    case DatumFeature::Kind::point: return "point";
    case DatumFeature::Kind::cylinder: return "cylinder";
  }
  return "plane";
}

const char* to_string(PartAlignment::Method method) {
  return method == PartAlignment::Method::datums ? "datums" : "free_form";
}

std::vector<PlannedPoint> PartAlignment::points() const {
  std::vector<PlannedPoint> all;
  for (const DatumFeature& d : datums) all.insert(all.end(), d.points.begin(), d.points.end());
  all.insert(all.end(), manual.begin(), manual.end());
  return all;
}

}  // namespace furrow

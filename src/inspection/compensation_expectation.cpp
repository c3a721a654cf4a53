#include "inspection/compensation_expectation.hpp"

#include <cmath>
#include <map>

#include "geometry/point_search.hpp"

namespace furrow {

namespace {

ExpectedStatistics statistics_of(const std::vector<const ExpectedPoint*>& points) {
  ExpectedStatistics s;
  s.count = points.size();
  if (points.empty()) return s;
  double before = 0, after = 0, field = 0;
  for (const ExpectedPoint* p : points) {
    before += p->measured * p->measured;
    after += p->residual * p->residual;
    field += p->field * p->field;
    if (s.worst_before_id.empty() || std::abs(p->measured) > std::abs(s.worst_before)) {
      s.worst_before = p->measured;
      s.worst_before_id = p->id;
    }
    if (s.worst_after_id.empty() || std::abs(p->residual) > std::abs(s.worst_after)) {
      s.worst_after = p->residual;
      s.worst_after_id = p->id;
    }
    s.largest_standard_error = std::max(s.largest_standard_error, p->standard_error);
  }
  const double n = double(points.size());
  s.rms_before = std::sqrt(before / n);
  s.rms_after = std::sqrt(after / n);
  s.rms_field = std::sqrt(field / n);
  return s;
}

}  // namespace

CompensationExpectation expect_compensation(const ComparisonDocument& comparison, const ErrorField& field,
                                            const PathGeometry& geometry, const PathOffset& offset, double reach) {
  CompensationExpectation out;
  out.reach = reach;
  // Contacts of the path points, with the offset written at each.
  std::vector<Eigen::Vector3d> contacts;
  std::vector<double> applied;
  for (std::size_t pass = 0; pass < geometry.passes.size(); ++pass)
    for (std::size_t k = 0; k < geometry.passes[pass].size(); ++k) {
      const PathPoint& p = geometry.passes[pass][k];
      if (!p.contact.valid || p.in_air) continue;
      contacts.push_back(p.contact.at.point);
      applied.push_back(pass < offset.offsets.size() && k < offset.offsets[pass].size() ? offset.offsets[pass][k]
                                                                                         : 0.0);
    }
  const PointSearch search(contacts);
  for (std::size_t i = 0; i < comparison.points.size(); ++i) {
    const ComparisonDocument::Point& c = comparison.points[i];
    if (!c.evaluated) continue;
    ExpectedPoint e;
    e.index = i;
    e.id = c.id;
    e.region = c.region.value_or(-1);
    e.measured = c.deviation;
    const std::size_t face = c.face_index >= 0 ? std::size_t(c.face_index) : field.faces.size();
    if (face < field.faces.size() && field.faces[face]) {
      const FaceErrorField& f = *field.faces[face];
      e.field = f.value(c.uv.x(), c.uv.y());
      if (f.fitted()) e.standard_error = f.standard_error(c.uv.x(), c.uv.y());
    }
    if (search.size() > 0) {
      const PointNeighbour near = search.nearest(c.foot);
      if (near.distance <= reach) {
        e.cut = true;
        e.correction = applied[near.index];
      }
    }
    e.residual = e.measured + e.correction;
    out.points.push_back(e);
  }
  std::vector<const ExpectedPoint*> all;
  std::map<int, std::vector<const ExpectedPoint*>> by_region;
  for (const ExpectedPoint& p : out.points) {
    all.push_back(&p);
    if (p.region >= 0) by_region[p.region].push_back(&p);
  }
  out.overall = statistics_of(all);
  for (const auto& [region, points] : by_region) out.regions.push_back({region, statistics_of(points)});
  return out;
}

}  // namespace furrow

#include "io/plan_csv.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "base/number_text.hpp"

namespace furrow {

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void vector_fields(std::ostringstream& out, const Eigen::Vector3d& v) {
  out << ',' << shortest(v.x()) << ',' << shortest(v.y()) << ',' << shortest(v.z());
}

}  // namespace

std::string plan_to_csv_text(const InspectionPlan& plan) {
  // Alignment points first, in measuring order (what the programs do), then
  // the free-form points in execution order.
  struct Row {
    const PlannedPoint* point;
    std::string feature;
  };
  std::vector<Row> rows;
  if (plan.alignment) {
    for (const DatumFeature& d : plan.alignment->datums)
      for (const PlannedPoint& p : d.points) rows.push_back({&p, "DATUM_" + d.label});
    for (const PlannedPoint& p : plan.alignment->manual) rows.push_back({&p, "MANUAL"});
  }
  const std::size_t alignment_rows = rows.size();
  std::vector<const PlannedPoint*> order;
  for (const PlannedPoint& p : plan.points) order.push_back(&p);
  std::stable_sort(order.begin(), order.end(), [](const PlannedPoint* a, const PlannedPoint* b) { return a->order < b->order; });
  for (const PlannedPoint* p : order) rows.push_back({p, "FREE_FORM"});

  std::ostringstream out;
  out << "# Furrow probe plan: part " << (plan.part.empty() ? "(unnamed)" : plan.part) << ", probe "
      << plan.probe.name << " diameter " << shortest(plan.probe.diameter) << " mm, " << plan.points.size()
      << " points";
  if (alignment_rows) out << " after " << alignment_rows << " alignment points";
  out << ", units mm\n";
  // The tip columns only in plans for an indexable head, the feature column
  // only in plans with an alignment: other plans keep their bytes.
  const bool tips = std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.point->tip.has_value(); });
  const bool features = alignment_rows > 0;
  out << "order,id,face,face_index,region,u,v,x,y,z,i,j,k,approach_x,approach_y,approach_z,retract_x,retract_y,"
         "retract_z"
      << (tips ? ",tip_a,tip_b" : "") << (features ? ",feature" : "") << "\n";
  for (const Row& row : rows) {
    const PlannedPoint* p = row.point;
    out << p->order << ',' << csv_field(p->id) << ',' << csv_field(p->face) << ',' << p->face_index << ',';
    if (p->region) out << *p->region;
    out << ',' << shortest(p->uv.x()) << ',' << shortest(p->uv.y());
    vector_fields(out, p->xyz);
    vector_fields(out, p->ijk);
    vector_fields(out, p->approach);
    vector_fields(out, p->retract);
    if (tips) {
      out << ',';
      if (p->tip) out << shortest(p->tip->a) << ',' << shortest(p->tip->b);
      else out << ',';
    }
    if (features) out << ',' << row.feature;
    out << '\n';
  }
  return out.str();
}

}  // namespace furrow

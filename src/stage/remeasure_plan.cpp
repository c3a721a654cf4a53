#include "stage/remeasure_plan.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/closest_point.hpp"

namespace furrow {

namespace {

// A point to probe: where, and why it is in the plan.
struct Candidate {
  std::string id;
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::optional<int> region;
};

// Two unit tangents at a point with normal n: the first is +x projected
// into the tangent plane (+y where the normal is nearly along x), so the
// ring starts in the same direction everywhere.
std::pair<Eigen::Vector3d, Eigen::Vector3d> tangents(const Eigen::Vector3d& n) {
  const Eigen::Vector3d e = std::abs(n.x()) > 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d t1 = (e - e.dot(n) * n).normalized();
  return {t1, n.cross(t1)};
}

class Builder {
 public:
  Builder(const Part& part, const RemeasureOptions& options)
      : part_(part), finder_(part), options_(options) {
    const PlannerOptions& o = options.planner;
    probe_ = {o.probe_diameter / 2, o.stylus_diameter / 2, o.stylus_length};
    access_ = o.access;
    access_.approach = o.approach;
    access_.retract = o.retract;
    access_.max_tilt = o.max_tilt_degrees * kPi / 180;
    clearance_z_ = clearance_plane(part, probe_.ball_radius, o.clearance);
    access_.clearance_z = clearance_z_;
  }

  // The foot of q on the part as a candidate; nullopt with `why` set when it
  // is on an edge.
  std::optional<Candidate> project(const std::string& id, const Eigen::Vector3d& q, std::string& why) const {
    const ClosestPoint f = finder_.project(q);
    if (f.location != FootLocation::interior) {
      why = id + ": its foot on the part is on a face's " + std::string(to_string(f.location)) + " (the probe would touch the edge)";
      return std::nullopt;
    }
    return Candidate{id, f.face, f.uv, f.point, f.normal, std::nullopt};
  }

  // Plans `c` when it is new and reachable; else records why not.
  void add(const Candidate& c, RemeasureTarget& target) {
    if (!ids_.insert(c.id).second) {
      target.points.push_back(c.id);  // already planned for another reason
      return;
    }
    const AccessResult a = check_access(finder_, c.xyz, c.normal, probe_, access_);
    if (!a.ok()) {
      target.dropped.push_back(c.id + ": not reachable with a vertical stylus (" + to_string(a.problem) + ")");
      ids_.erase(c.id);
      return;
    }
    target.points.push_back(c.id);
    planned_.push_back(c);
  }

  // Ring of `ring_points` around c at `radius`, projected onto the part.
  void ring(const Candidate& c, RemeasureTarget& target) {
    const auto [t1, t2] = tangents(c.normal);
    for (int k = 0; k < options_.ring_points; ++k) {
      const double a = 2 * kPi * k / options_.ring_points;
      const Eigen::Vector3d q = c.xyz + options_.radius * (std::cos(a) * t1 + std::sin(a) * t2);
      const std::string id = c.id + "_R" + std::to_string(k + 1);
      std::string why;
      if (const auto p = project(id, q, why)) {
        Candidate r = *p;
        r.region = c.region;  // informative; a partition assigns regions by foot
        add(r, target);
      } else {
        target.dropped.push_back(why);
      }
    }
  }

  // Points of a face at (u, v) as a candidate when the part holds it there
  // (not trimmed away: its own foot is itself).
  void at_uv(const std::string& id, std::size_t face, const Eigen::Vector2d& uv, RemeasureTarget& target) {
    const DifferentialGeometry g = part_.faces[face].geometry(uv.x(), uv.y());
    const ClosestPoint f = finder_.project(g.point);
    if (f.location != FootLocation::interior || (f.point - g.point).norm() > 1e-6) {
      target.dropped.push_back(id + ": (u, v) = (" + std::to_string(uv.x()) + ", " + std::to_string(uv.y()) +
                               ") is not on the part (trimmed away or on an edge)");
      return;
    }
    add(Candidate{id, face, uv, g.point, g.normal, std::nullopt}, target);
  }

  PlanResult finish(const std::string& part_name) const {
    const PlannerOptions& o = options_.planner;
    PlanResult r;
    r.approach = o.approach;
    r.retract = o.retract;
    r.search = search_distance(o);
    r.border = 0;
    r.probe = probe_;
    r.clearance_z = clearance_z_;
    r.plan.part = part_name;
    r.plan.probe = {o.probe_name, o.probe_diameter};
    std::vector<Eigen::Vector3d> retracts;
    for (std::size_t k = 0; k < planned_.size(); ++k) {
      const Candidate& c = planned_[k];
      PlannedPoint p;
      p.id = c.id;
      p.order = static_cast<int>(k) + 1;
      p.face_index = c.face;
      p.face = part_.faces[c.face].name();
      p.region = c.region;
      p.uv = c.uv;
      p.xyz = c.xyz;
      p.ijk = c.normal;
      p.approach = approach_point(c.xyz, c.normal, probe_, access_);
      p.retract = retract_point(c.xyz, c.normal, probe_, access_);
      retracts.push_back(p.retract);
      r.plan.points.push_back(p);
      r.point_sites.emplace_back();
    }
    if (r.plan.points.empty()) return r;
    MoveOptions move;
    move.clearance = o.clearance;
    move.clearance_z = clearance_z_;
    move.contact_tolerance = access_.contact_tolerance;
    move.min_step = access_.min_step;
    move.max_steps = access_.max_steps;
    const PlannedPoint& first = r.plan.points.front();
    r.start = {first.approach.x(), first.approach.y(), std::max(clearance_z_, first.approach.z())};
    r.moves.resize(r.plan.points.size());
    r.moves[0].straight = false;
    r.moves[0].waypoints = {first.approach};
    r.moves[0].length = (first.approach - r.start).norm();
    for (std::size_t k = 1; k < r.plan.points.size(); ++k)
      r.moves[k] = plan_move(finder_, r.plan.points[k - 1].retract, r.plan.points[k].approach, probe_.ball_radius, move);
    const Eigen::Vector3d& last = r.plan.points.back().retract;
    if (last.z() < clearance_z_) r.final_moves = {Eigen::Vector3d(last.x(), last.y(), clearance_z_)};
    r.cycle = estimate_cycle(r.start, r.moves, retracts, r.final_moves, o.approach, o.retract, o.motion);
    return r;
  }

 private:
  const Part& part_;
  ClosestPointFinder finder_;
  const RemeasureOptions& options_;
  ProbeGeometry probe_;
  AccessOptions access_;
  double clearance_z_ = 0;
  std::set<std::string> ids_;
  std::vector<Candidate> planned_;
};

}  // namespace

void validate(const RemeasureOptions& o) {
  if (!(o.radius > 0) || !std::isfinite(o.radius)) throw InputError("--radius must be a positive number of mm");
  if (o.ring_points < 0 || o.ring_points > 24) throw InputError("--ring must lie between 0 and 24 points");
  validate(o.planner);
}

void check_comparison_against_part(const ComparisonDocument& c, const Part& part, const std::string& name) {
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    const ComparisonDocument::Point& p = c.points[k];
    const std::string where = name + ": points[" + std::to_string(k) + "] (id " + p.id + ")";
    if (p.face_index < 0 || static_cast<std::size_t>(p.face_index) >= part.faces.size())
      throw InputError(where + ": face_index " + std::to_string(p.face_index) + " but the part has " +
                       std::to_string(part.faces.size()) + " faces");
    if (part.faces[static_cast<std::size_t>(p.face_index)].name() != p.face)
      throw InputError(where + ": face " + p.face + " is not face " + std::to_string(p.face_index) +
                       " of the part; the comparison was made on another part");
  }
}

RemeasurePlan plan_remeasure(const Part& part, const ComparisonDocument& c, const InspectionPlan* plan,
                             const RemeasureOptions& options) {
  validate(options);
  Builder builder(part, options);
  RemeasurePlan out;
  const auto plan_index = plan ? plan->index_by_id() : std::unordered_map<std::string, std::size_t>{};
  for (const InconclusiveReason& reason : c.summary.inconclusive) {
    RemeasureTarget target{reason.kind, reason.subject, {}, {}};
    if (reason.kind == "suspected_blunder" || reason.kind == "point_not_checked") {
      const auto k = c.points_by_id.find(reason.subject);
      if (k == c.points_by_id.end())
        throw InputError("the verdict names point " + reason.subject + ", which the comparison does not hold");
      Candidate centre;
      centre.id = reason.subject;
      if (const auto j = plan_index.find(reason.subject); j != plan_index.end()) {
        const PlannedPoint& p = plan->points[j->second];
        centre = {p.id, p.face_index, p.uv, p.xyz, p.ijk, p.region};
      } else {
        const ComparisonDocument::Point& p = c.points[k->second];
        const DifferentialGeometry g = part.faces[static_cast<std::size_t>(p.face_index)].geometry(p.uv.x(), p.uv.y());
        centre = {p.id, static_cast<std::size_t>(p.face_index), p.uv, g.point, g.normal, p.region};
      }
      // A point the fit could not check was measured well: its neighbours
      // are what it lacks.
      if (reason.kind == "suspected_blunder") builder.add(centre, target);
      builder.ring(centre, target);
    } else if (reason.kind == "gouge_not_measured") {
      const GougeSiteCheck* site = nullptr;
      if (c.gouges)
        for (const GougeSiteCheck& s : c.gouges->sites)
          if (s.id == reason.subject) site = &s;
      if (!site) throw InputError("the verdict names gouge site " + reason.subject + ", which the comparison does not hold");
      if (site->face_index < 0 || static_cast<std::size_t>(site->face_index) >= part.faces.size())
        throw InputError("gouge site " + site->id + ": face_index " + std::to_string(site->face_index) +
                         " is not a face of the part");
      const std::size_t face = static_cast<std::size_t>(site->face_index);
      const Eigen::Vector2d mid = site->uv_box.center();
      const Eigen::Vector2d half = (site->uv_box.max() - site->uv_box.min()) / 2;
      builder.at_uv(site->id + "_C", face, mid, target);
      for (int k = 0; k < options.ring_points; ++k) {
        const double a = 2 * kPi * k / options.ring_points;
        const Eigen::Vector2d uv = mid + 0.5 * Eigen::Vector2d(half.x() * std::cos(a), half.y() * std::sin(a));
        builder.at_uv(site->id + "_R" + std::to_string(k + 1), face, uv, target);
      }
    } else if (reason.kind == "point_not_measured") {
      // The CMM answered the point with an error (or not at all): take the
      // same point again, as planned.
      const auto j = plan_index.find(reason.subject);
      if (j == plan_index.end()) {
        out.not_covered.push_back(reason.text + (plan ? " (the plan holds no point " + reason.subject + ")"
                                                      : std::string(" (needs the original plan: --plan)")));
        continue;
      }
      const PlannedPoint& p = plan->points[j->second];
      builder.add({p.id, p.face_index, p.uv, p.xyz, p.ijk, p.region}, target);
    } else if (reason.kind == "region_below_minimum") {
      if (!plan) {
        out.not_covered.push_back(reason.text + " (needs the original plan: --plan)");
        continue;
      }
      for (const PlannedPoint& p : plan->points) {
        if (!p.region || "region " + std::to_string(*p.region) != reason.subject) continue;
        const auto k = c.points_by_id.find(p.id);
        if (k != c.points_by_id.end() && c.points[k->second].evaluated) continue;
        builder.add({p.id, p.face_index, p.uv, p.xyz, p.ijk, p.region}, target);
      }
      // A region the planner could not cover has no plan point left to take
      // again: say why instead of an empty target (docs/cmm.md "Coverage").
      if (target.points.empty() && target.dropped.empty()) {
        std::string why = reason.text + ": the plan holds no point left to measure there";
        for (const UncoveredRegion& u : plan->uncovered_regions)
          if ("region " + std::to_string(u.region) == reason.subject)
            why += " (the planner could not cover it: " + u.reason + "); plan it again with a smaller probe or a lower "
                   "--border, or measure it by other means";
        out.not_covered.push_back(why);
        continue;
      }
    } else {
      out.not_covered.push_back(reason.text);
      continue;
    }
    out.targets.push_back(std::move(target));
  }
  out.result = builder.finish(plan ? plan->part : c.sources.part);
  return out;
}

}  // namespace furrow

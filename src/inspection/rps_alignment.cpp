#include "inspection/rps_alignment.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <map>
#include <set>

#include "base/error.hpp"
#include "base/number_text.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace {

// One RPS point matched with its measurement.
struct Matched {
  const ReferencePoint* rps = nullptr;
  Eigen::Vector3d measured = Eigen::Vector3d::Zero();  // as read (centre or contact), CMM
  Eigen::Vector3d target = Eigen::Vector3d::Zero();    // where T must put it: nominal + r n, part
};

std::vector<Matched> match(const ReferencePointSystem& rps, const MeasurementSet& set) {
  if (!set.ids_from_file)
    throw InputError(set.source + ": the points carry no ids, and an RPS alignment matches its points by id");
  std::map<std::string, const MeasuredPoint*> by_id;
  for (const MeasuredPoint& p : set.points) by_id.emplace(p.id, &p);
  std::vector<Matched> out;
  for (const ReferencePoint& r : rps.points) {
    const auto it = by_id.find(r.id);
    if (it == by_id.end())
      throw InputError(set.source + ": RPS point " + quote_field(r.id) + " of " + rps.source + " was not measured");
    out.push_back({&r, it->second->xyz, r.nominal + set.probe_radius * r.normal});
  }
  return out;
}

Eigen::Vector3d axis(char a) { return Eigen::Vector3d::Unit(a - 'x'); }

// The motion a right singular vector of the scaled Jacobian stands for, in
// words ("a turn about (0, 0, 1)", "a slide along (1, 0, 0)").
std::string motion_words(const Eigen::Matrix<double, 6, 1>& v) {
  const Eigen::Vector3d turn = v.head<3>(), slide = v.tail<3>();
  const bool is_turn = turn.norm() > slide.norm();
  const Eigen::Vector3d d = (is_turn ? turn : slide).normalized();
  return std::string(is_turn ? "a turn about (" : "a slide along (") + fixed(d.x(), 2) + ", " + fixed(d.y(), 2) +
         ", " + fixed(d.z(), 2) + ")";
}

}  // namespace

DatumFrame fit_rps_alignment(const ReferencePointSystem& rps, const MeasurementSet& set,
                             const RpsFitOptions& options) {
  const std::vector<Matched> points = match(rps, set);
  const auto n = static_cast<Eigen::Index>(points.size());
  // Start: the point-to-point fit of every coordinate (needs three points
  // that span a plane).
  Eigen::Matrix3Xd from(3, n), to(3, n);
  for (Eigen::Index i = 0; i < n; ++i) from.col(i) = points[i].measured, to.col(i) = points[i].target;
  const Eigen::Vector3d g = to.rowwise().mean();
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> shape(to.colwise() - g, Eigen::ComputeThinU);
  if (n < 3 || !(shape.singularValues()(1) > 1e-6 * shape.singularValues()(0)))
    throw DatumFrameError(rps.source + ": the RPS points lie on a line (or are fewer than three): they cannot fix "
                          "the part's turn about it");
  const double extent = std::sqrt((to.colwise() - g).colwise().squaredNorm().mean());
  Eigen::Isometry3d T = Eigen::Isometry3d(Eigen::umeyama(from, to, false));

  std::size_t rows = 0;
  for (const Matched& m : points) rows += m.rps->directions.size();
  if (rows < 6)
    throw DatumFrameError(rps.source + ": the RPS points fix " + std::to_string(rows) +
                          " coordinates, fewer than the part's 6 degrees of freedom");
  bool converged = false;
  for (int iteration = 0; iteration < options.max_iterations && !converged; ++iteration) {
    // Rows: sqrt(w) e_a . (x - target), x = T m; columns: the turn about g
    // (scaled by the extent, so a unit turn moves points like a unit slide)
    // and the slide.
    Eigen::MatrixXd J(rows, 6);
    Eigen::VectorXd r(rows);
    Eigen::Index row = 0;
    for (const Matched& m : points) {
      const Eigen::Vector3d x = T * m.measured;
      const double s = std::sqrt(m.rps->weight);
      for (char a : m.rps->directions) {
        const Eigen::Vector3d e = axis(a);
        J.row(row).head<3>() = s * (x - g).cross(e).transpose() / extent;
        J.row(row).tail<3>() = s * e.transpose();
        r(row) = s * e.dot(x - m.target);
        ++row;
      }
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinU | Eigen::ComputeFullV);
    const Eigen::VectorXd sv = svd.singularValues();
    if (!(sv(5) > options.rank_ratio * sv(0)))
      throw DatumFrameError(rps.source + ": the RPS points do not fix the part: they leave " +
                            motion_words(svd.matrixV().col(5)) +
                            " free; declare more axes (a 3-2-1 RPS fixes z at three points, y at two, x at one)");
    const Eigen::Matrix<double, 6, 1> step = svd.solve(-r);
    const Eigen::Vector3d turn = step.head<3>() / extent, slide = step.tail<3>();
    const double angle = turn.norm();
    const Eigen::Matrix3d Q =
        angle > 0 ? Eigen::AngleAxisd(angle, turn / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
    Eigen::Isometry3d next = Eigen::Isometry3d::Identity();
    next.linear() = Q * T.linear();
    next.translation() = Q * (T.translation() - g) + g + slide;
    double moved = 0;
    for (const Matched& m : points) moved = std::max(moved, (next * m.measured - T * m.measured).norm());
    T = next;
    converged = moved <= options.step_tolerance;
  }
  if (!converged)
    throw DatumFrameError(rps.source + ": the RPS fit did not converge in " + std::to_string(options.max_iterations) +
                          " iterations");

  DatumFrame frame;
  frame.transform = T;
  frame.measured = T.inverse();
  frame.nominal = Eigen::Isometry3d::Identity();
  for (const Matched& m : points) {
    ReferencePointFit f;
    f.id = m.rps->id;
    f.directions = m.rps->directions;
    f.weight = m.rps->weight;
    f.normal = m.rps->normal;
    f.contact = m.measured - set.probe_radius * (T.linear().transpose() * m.rps->normal);
    const Eigen::Vector3d d = T * m.measured - m.target;
    for (char a : m.rps->directions) f.residual[a - 'x'] = d[a - 'x'];
    frame.reference_points.push_back(f);
  }
  return frame;
}

MeasurementSet without_reference_points(const MeasurementSet& set, const ReferencePointSystem& rps) {
  std::set<std::string> ids;
  for (const ReferencePoint& p : rps.points) ids.insert(p.id);
  return without_points(set, ids);
}

}  // namespace furrow

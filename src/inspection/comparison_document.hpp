#pragma once
// comparison.json as plain data: what read_comparison() (comparison_file.hpp)
// returns to the QA report and to anyone else who reads a comparison back,
// without nlohmann. Every number is the one written (the writer uses
// shortest round-trip text), so write -> read gives identical values.
//
// Units: mm, except rotations [rad] in the covariance and registration
// parameters and the placement's rotation_deg [deg]. Sign of deviations and
// errors (docs/architecture.md): + material left (undercut), - removed (overcut/gouge).
// Member names follow the file (docs/formats.md "Comparison").
#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison.hpp"
#include "inspection/gouge_confirmation.hpp"
#include "inspection/prediction_comparison.hpp"
#include "inspection/tolerance_zone.hpp"

namespace furrow {

struct ComparisonDocument {
  int version = 0;

  // Input files as given on the command line; empty when not given.
  struct Sources {
    std::string part, measurements, plan, regions, prediction;
    // Every measurement file in measuring order with the points read from
    // it (one entry for one file; empty in files written before merging).
    struct MeasurementFile {
      std::string path;
      std::size_t points = 0;
      std::string sha256;  // hex; empty when not recorded (furrow run records inputs in report.json)
    };
    std::vector<MeasurementFile> measurement_files;
    // Points a later file measured again (docs/verification.md "Re-measuring").
    struct Replacement {
      std::string id;
      std::size_t file = 0, by_file = 0;  // indices into measurement_files
      Eigen::Vector3d was = Eigen::Vector3d::Zero();  // replaced coordinates, CMM frame [mm]
    };
    std::vector<Replacement> replaced;
  } sources;

  // Every option the comparison ran with.
  struct Options {
    ToleranceZone tolerance;  // width and the part on the + side
    std::string disposition;  // bilateral, unilateral outside/inside, unequal
    std::string dof;          // "all", "translation", "rotation" or "rx,tz"...
    std::string loss;         // cauchy, huber, none (first fit)
    double loss_scale = 0;    // [mm]
    std::string points;       // "centre" or "contact": what the file holds
    double probe_diameter = 0;      // [mm] (0 for contact points)
    std::string units;              // of the measurement file's coordinates
    bool outlier_rejection = true;  // false: --no-outlier-rejection
    double outlier_sigma = 0;       // robust sigmas of a large deviation
    double outlier_floor = 0;       // [mm]
    double edge_tolerance = 0;      // [mm]
    int confirm_neighbours = 0;
    double neighbour_radius = 0;    // [mm]
    int max_outer_iterations = 0, max_solver_iterations = 0, max_outlier_passes = 0;
    double motion_tolerance = 0;    // [mm]
    // Verification rules (written always, used with a prediction only).
    PredictionComparisonOptions prediction;
    GougeConfirmationOptions gouges;
  } options;

  struct Registration {
    Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();  // CMM -> part
    // The part on the CMM: x_cmm = Rz Ry Rx x_part + t (simulate's --misalign).
    Eigen::Vector3d placement_rotation_deg = Eigen::Vector3d::Zero();
    Eigen::Vector3d placement_translation = Eigen::Vector3d::Zero();
    std::string coarse_method;  // "plan ids", "dmis nominals", "global search", "identity", "alignment frame"
    int coarse_matched_ids = 0, coarse_candidates = 0;
    double coarse_median_distance = 0;
    bool coarse_ambiguous = false;
    double rms_before = 0, rms_after = 0, sigma = 0;
    int outer_iterations = 0, solver_iterations = 0, outlier_passes = 0;
    bool converged = false;
    std::string status;                                     // "converged" or why not
    std::string outcome = "converged";  // "converged", "not_converged", "too_few_points"
    int fitted_dof = 6;                 // motions fitted: the free DOF less the held weak ones
    // Weakly constrained directions (observability.hpp): held at the start
    // and/or weak at the solution.
    struct WeakDirection {
      std::string text;                 // in words
      bool translation = false;
      Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // unit; translation direction or axis
      Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();  // rotation: a point of the axis [mm]
      double pitch = 0;                 // rotation: [mm per rad]
      double ratio = 0;                 // lambda / largest lambda
      std::optional<double> sigma;      // 1-sigma RMS displacement of the points [mm]; none: unconstrained
      bool held = false;                // weak at the start: not fitted
      bool from_points = false;         // the measured faces would fix it, the points do not
    };
    std::vector<WeakDirection> weak;
    std::optional<Eigen::Matrix<double, 6, 6>> covariance;  // rx ry rz [rad], tx ty tz [mm]
    std::string covariance_status;
    // Point ids whose outlier status the points cannot decide
    // (few_point_search.hpp); files written before have none.
    std::vector<std::string> ambiguous_outliers;
    // Outliers by reason: "blunder", "large_deviation", "beyond_edge",
    // "no_foot_point" (every reason present, zero when none).
    std::map<std::string, std::size_t> outliers;
  } registration;

  // How the points were put into the part frame (docs/registration.md
  // "Alignments"); files written before it have none: a best fit.
  struct Alignment {
    std::string method = "bestfit";  // "bestfit", "cmm", "datums"
    std::string note;                // cmm/datums: why there is no fit and no observability question
    struct Datum {
      std::string label, kind;       // "A"; "plane", "line", "point"; an RPS point: its id, "rps"
      std::vector<std::string> points;
      Eigen::Vector3d origin = Eigen::Vector3d::Zero();     // as measured (rps: the contact), CMM frame [mm]
      Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); // plane normal, line direction, point normal
      // plane flatness, line straightness, 0 for the point, an RPS point's
      // largest residual [mm]
      double form_error = 0;
      std::string directions;  // rps: the part axes the point fixes
      Eigen::Vector3d residual = Eigen::Vector3d::Zero();   // rps: along those axes, part frame [mm]
      double weight = 1;       // rps
    };
    std::vector<Datum> datums;       // datums and rps only
    // cmm/datums: the best fit of the same points, form alone [mm].
    std::optional<double> bestfit_profile;
    std::string bestfit_status;
  } alignment;

  struct Point {
    std::string id;
    std::size_t file = 0;  // index into sources.measurement_files it came from
    Eigen::Vector3d measured = Eigen::Vector3d::Zero();    // CMM frame, as read
    Eigen::Vector3d registered = Eigen::Vector3d::Zero();  // part frame (a centre for centre data)
    Eigen::Vector3d contact = Eigen::Vector3d::Zero();     // registered - r_probe normal
    int face_index = 0;
    std::string face;
    Eigen::Vector2d uv = Eigen::Vector2d::Zero();
    Eigen::Vector3d foot = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    std::string foot_location;          // interior, domain_edge, trim_edge
    double deviation = 0;               // [mm]
    std::optional<double> uncertainty;  // 1-sigma from the registration covariance [mm]
    std::optional<double> redundancy;   // share of a deviation that shows (RegisteredPoint), likewise
    bool evaluated = false;
    std::optional<bool> in_tolerance;   // unset for points not evaluated
    bool in_fit = false;
    std::string outlier;         // reason, empty for none
    std::string outlier_detail;  // the numbers behind it
    std::optional<int> region;
    // With a prediction: the predicted error at the foot, the deviation
    // after the prediction alignment (`measured`), residual, sigma_total.
    std::optional<PointPrediction> prediction;
  };
  std::vector<Point> points;
  std::map<std::string, std::size_t> points_by_id;  // id -> index into points

  // Counts, statistics, pass; its `regions` are the per-region deviation
  // statistics; confirmed_gouges and unexplained_overcuts are 0 without a
  // prediction.
  ComparisonSummary summary;

  // With a prediction (sources.prediction set), else unset. `prediction`'s
  // per-point vector repeats points[i].prediction; gouge sites and
  // unexplained clusters refer to points by index into `points`.
  std::optional<PredictionComparison> prediction;
  std::optional<GougeConfirmation> gouges;
};

}  // namespace furrow

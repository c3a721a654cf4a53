// CAD import of spheres, cylinders and tori written as IGES trimmed surfaces
// of revolution the way CATIA/NX-class systems write them (type 144 of a
// type 120, boundaries as type 142 with parameter-space and model-space
// curves; tests/io/cad/iges_revolved_patches.hpp), not through
// OpenCASCADE's own writer. Every imported face must keep the region its
// boundary encloses: its area is compared with the analytic area (a sphere
// lune/zone: R^2 (theta1 - theta0) (sin phi1 - sin phi0)), and its centroid
// with the patch's (analytic for spheres, by quadrature of the exact
// parametrisation for cylinders and tori), which also tells a half sphere
// from the other half.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/cad/cad_import.hpp"
#include "iges_revolved_patches.hpp"
#include "kept_region.hpp"
#include "support/run_cli.hpp"
#include "support/trimmed_area.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kSpacing = 80;  // sphere centres along x, one per case

// Centroid of a cylinder or torus patch by the midpoint rule on the exact
// parametrisation (area element |dP/ds x dP/dtheta| = generatrix speed times
// distance from the axis).
Eigen::Vector3d patch_centroid(const RevolvedPatch& p) {
  constexpr int n = 400;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weight = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double s = p.s0 + (p.s1 - p.s0) * (i + 0.5) / n;
      const double theta = p.theta0 + (p.theta1 - p.theta0) * (j + 0.5) / n;
      const double speed = p.kind == RevolvedPatch::Kind::cylinder ? p.height : p.radius;
      const double w = speed * p.generatrix(s).x();
      sum += w * p.point(s, theta);
      weight += w;
    }
  return sum / weight;
}

// The normal of the file's surface (Su x Sv of the type 120, which IGES
// trimmed surfaces keep: a type 144 has no sense of its own) at `p` on the
// patch, unit. The writer's surfaces turn the generatrix about +y from x
// toward -z, so with the generatrix running south to north (up, for
// cylinders; counterclockwise for the torus's tube) it points towards the
// axis side: into the sphere, the cylinder, the tube. A generatrix running
// north to south, or the axis -y, turns it round.
Eigen::Vector3d file_normal(const SpherePatch& patch, const Eigen::Vector3d& p) {
  const double sign = (patch.north_to_south ? -1 : 1) * (patch.axis_reversed ? -1 : 1);
  return -sign * (p - patch.centre).normalized();
}
Eigen::Vector3d file_normal(const RevolvedPatch& patch, const Eigen::Vector3d& p) {
  const Eigen::Vector3d r = p - patch.centre;
  const Eigen::Vector3d radial = Eigen::Vector3d(r.x(), 0, r.z()).normalized();
  if (patch.kind == RevolvedPatch::Kind::cylinder) return -radial;
  return -(r - patch.major * radial).normalized();
}

// Share of the face's kept points whose normal (Face::reversed() applied)
// is the file's surface normal there.
template <class Patch>
double normal_agreement(const Face& f, const Patch& patch) {
  return kept_share(f, [&](const DifferentialGeometry& g) { return g.normal.dot(file_normal(patch, g.point)) > 0.99; });
}

void write_patch(IgesBuilder& b, const SpherePatch& p) { write_sphere_patch(b, p); }
void write_patch(IgesBuilder& b, const RevolvedPatch& p) { write_revolved_patch(b, p); }

// Writes all cases into one file (each at its own place along x), imports
// it and checks every face's area against the analytic one, and its
// centroid against the patch's.
// With `normals`, every face's normal must also be the file's surface
// normal (file_normal()): faces that sew to nothing keep the file's sense.
// `expected`, when given, is the region each case must come in as (else the
// case itself).
template <class Patch>
void check_cases(std::vector<Patch> cases, const std::string& file_name, bool normals = false,
                 std::vector<Patch> expected = {}) {
  if (expected.empty()) expected = cases;
  IgesBuilder builder;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    cases[k].centre = Eigen::Vector3d(kSpacing * static_cast<double>(k), 0, 0);
    expected[k].centre = cases[k].centre;
    write_patch(builder, cases[k]);
  }
  const std::string dir = scratch_dir(file_name + "-" + std::to_string(getpid()));
  const std::string path = dir + "/" + file_name + ".igs";
  builder.file.write(path);
  const CadImportResult result = import_cad(path);
  CHECK(result.format == "IGES");
  REQUIRE(result.part.faces.size() == cases.size());
  std::map<long, const Face*> by_case;
  for (const Face& f : result.part.faces) {
    const ParameterDomain& d = f.domain();
    const Eigen::Vector3d p = f.surface().point(d.u0 + 0.5 * d.width_u(), d.v0 + 0.5 * d.width_v());
    by_case[std::lround(p.x() / kSpacing)] = &f;
  }
  REQUIRE(by_case.size() == cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    CAPTURE(cases[k].name());
    const Face& face = *by_case.at(static_cast<long>(k));
    CHECK(trimmed_area(face) == doctest::Approx(expected[k].area()).epsilon(1e-6));
    // The same area on the other side (a half sphere's rest) is still wrong.
    CHECK((kept_centroid(face) - patch_centroid(expected[k])).norm() < 5e-3 * cases[k].radius);
    if (normals) CHECK(normal_agreement(face, expected[k]) == 1.0);
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}

struct Range {
  double theta0, theta1, phi0, phi1;
};

// A sphere patch over `r`, everything else as SpherePatch's defaults.
SpherePatch patch_over(const Range& r) {
  SpherePatch p;
  p.theta0 = r.theta0;
  p.theta1 = r.theta1;
  p.phi0 = r.phi0;
  p.phi1 = r.phi1;
  return p;
}

}  // namespace

TEST_CASE("CAD import: the report's quarter sphere from IGES keeps its area in every way it can be written") {
  // A quarter of a 4.75 mm sphere (70.88 mm^2) between two meridians a
  // quarter turn apart, from pole to pole of the surface of revolution:
  // half a great circle and two quarter circles (split at the equator) that
  // meet at the surface's poles, as in the report.
  std::vector<SpherePatch> cases;
  for (const ArcParameter parameter : {ArcParameter::standard, ArcParameter::signed_angle, ArcParameter::normalised})
    for (const bool transformed : {false, true})
      for (const bool reversed : {false, true})
        for (const int pcurve_type : {126, 110, 106})
          for (const int pref : {0, 1, 2, 3})
            for (const bool along_pole : {true, false}) {
              // A normalised generatrix parameter is not the surface's
              // parameter (IGES 5.3 type 120: the generatrix's own, for a
              // type 100 arc its angle); only a reader that takes the
              // model-space curves can follow it.
              if (parameter == ArcParameter::normalised && pref != 2) continue;
              SpherePatch p;
              p.theta0 = 0;
              p.theta1 = M_PI / 2;
              p.phi0 = -M_PI / 2;
              p.phi1 = M_PI / 2;
              p.parameter = parameter;
              p.generatrix_transformed = transformed;
              p.reversed_loop = reversed;
              p.line_pcurves = pcurve_type == 110;
              p.polyline_pcurves = pcurve_type == 106;
              p.pref = pref;
              p.pcurve_along_pole = along_pole;
              p.split_at_equator = true;
              cases.push_back(p);
            }
  REQUIRE(cases.front().area() == doctest::Approx(70.88).epsilon(1e-4));
  check_cases(cases, "iges-quarter-sphere");
}

namespace {

// Rotation angle theta0..theta1 (as the file writes it: across the seam
// either below 0 or beyond 2 pi), latitude phi0..phi1.
const double pi = M_PI;
const Range kRanges[] = {
      {0, pi, 0, pi / 2},                // half the equator and two quarter meridians, one pole
      {-pi / 2, pi / 2, 0, pi / 2},      // the same across the seam, written below 0
      {1.5 * pi, 2.5 * pi, 0, pi / 2},   // ... and written beyond 2 pi
      {pi, 2 * pi, 0, pi / 2},           // ending on the seam
      {0, pi / 2, -pi / 2, pi / 2},      // lunes from pole to pole, on the seam,
      {1.0, 2.0, -pi / 2, pi / 2},       // inside,
      {-0.5, 0.5, -pi / 2, pi / 2},      // across it,
      {0, pi, -pi / 2, pi / 2},          // half,
      {0, 1.5 * pi, -pi / 2, pi / 2},    // three quarters,
      {0.2, 0.2 + 1.6 * pi, -pi / 2, pi / 2},
      {0.5 * pi, 2 * pi, -0.3, 1.0},     // zones without a pole
      {0.3, 2.0, -pi / 2, 0},            // the south pole
      {0.5, 1.8 * pi, -pi / 2, 0.4},
      {-pi / 2, pi / 2, -pi / 2, pi / 2},
      {0, 2 * pi, 0.3, pi / 2},          // a cap around the pole: the seam twice in the boundary,
      {0, 2 * pi, -0.5, 0.8},            // a band
};

}  // namespace

TEST_CASE("CAD import: IGES sphere patches touching and crossing the seam and the poles keep the enclosed region") {
  std::vector<SpherePatch> cases;
  int variant = 0;
  for (const Range& r : kRanges)
    for (const bool reversed : {false, true})
      for (const int pref : {0, 1, 2, 3}) {
        SpherePatch p = patch_over(r);
        p.reversed_loop = reversed;
        p.pref = pref;
        // The other choices cycle through the cases.
        p.parameter = variant % 2 ? ArcParameter::signed_angle : ArcParameter::standard;
        p.generatrix_transformed = (variant / 2) % 2;
        p.line_pcurves = (variant / 4) % 2;
        p.pcurve_along_pole = (variant / 8) % 2 == 0;
        ++variant;
        cases.push_back(p);
      }
  check_cases(cases, "iges-sphere-patches");
}

// Sphere patches whose type 120's start and terminate angles are the face's
// own range, loops both ways, generatrix with and without a type 124.
std::vector<SpherePatch> partial_revolution_cases(bool model_space_only) {
  const Range ranges[] = {{0, pi, 0, pi / 2}, {0, pi / 2, -pi / 2, pi / 2}, {1.0, 2.5, -pi / 2, pi / 2},
                          {-pi / 2, pi / 2, -pi / 2, pi / 2}, {0.3, 1.8 * pi, -pi / 2, pi / 2}};
  std::vector<SpherePatch> cases;
  for (const Range& r : ranges)
    for (const bool reversed : {false, true})
      for (const bool transformed : {false, true}) {
        SpherePatch p = patch_over(r);
        p.start_angle = r.theta0;
        p.end_angle = r.theta1;
        p.reversed_loop = reversed;
        p.generatrix_transformed = transformed;
        p.model_space_only = model_space_only;
        p.pref = model_space_only ? 2 : 0;
        cases.push_back(p);
      }
  return cases;
}

TEST_CASE("CAD import: IGES sphere patches of a surface of revolution turned only over the face keep their area") {
  check_cases(partial_revolution_cases(false), "iges-sphere-partial-revolution");
}

// The sphere patches of kRanges with the generatrix running north to south,
// or the axis -y, or both (all but the writer's default), loops both ways;
// `model_space_only` with PREF 2.
std::vector<SpherePatch> axis_generatrix_cases(bool model_space_only) {
  std::vector<SpherePatch> cases;
  for (const Range& r : kRanges)
    for (const bool north_to_south : {false, true})
      for (const bool axis_reversed : {false, true})
        for (const bool reversed : {false, true}) {
          if (!north_to_south && !axis_reversed) continue;  // the default: the tests above
          SpherePatch p = patch_over(r);
          p.north_to_south = north_to_south;
          p.axis_reversed = axis_reversed;
          p.reversed_loop = reversed;
          p.model_space_only = model_space_only;
          p.pref = model_space_only ? 2 : 0;
          cases.push_back(p);
        }
  return cases;
}

TEST_CASE("CAD import: IGES sphere patches keep their region whichever way the generatrix and the axis run") {
  // The surface's normal and the sense of the file's loops change with the
  // generatrix's direction (south to north or north to south) and the
  // axis line's; the face must not.
  check_cases(axis_generatrix_cases(false), "iges-sphere-axis-generatrix");
}

// Cylinder and torus patches touching and crossing the seam, loops both
// ways, PREF 0, 1 and 2 (and 3, and every CRTN, for model-space curves only).
std::vector<RevolvedPatch> revolved_cases(bool model_space_only) {
  using Kind = RevolvedPatch::Kind;
  struct Case {
    Kind kind;
    double theta0, theta1, s0, s1;
  };
  const Case shapes[] = {
      {Kind::cylinder, 0, pi, 0, 1},          {Kind::cylinder, -pi / 2, pi / 2, 0, 1},
      {Kind::cylinder, 1.5 * pi, 2.5 * pi, 0.2, 0.7}, {Kind::cylinder, pi, 2 * pi, 0, 1},
      {Kind::cylinder, 0, 1.5 * pi, 0, 1},    {Kind::cylinder, 0.2, 0.2 + 1.6 * pi, 0.1, 0.9},
      {Kind::cylinder, 0, 2 * pi, 0, 1},      // a full ring, the seam twice in the boundary
      {Kind::torus, 0, pi / 2, 0, pi / 2},    {Kind::torus, -pi / 2, pi / 2, pi / 2, 1.5 * pi},
      {Kind::torus, 0, 1.5 * pi, -pi / 2, pi / 2}, {Kind::torus, 0.3, 2.0, 1.5 * pi, 2.5 * pi},
      {Kind::torus, 0, pi, 0, 2 * pi},        // the whole tube over half a turn
      {Kind::torus, 0.2, 0.2 + 1.6 * pi, 0.5, 1.5 * pi},
  };
  std::vector<RevolvedPatch> cases;
  int variant = 0;
  for (const Case& c : shapes)
    for (const bool reversed : {false, true})
      for (const int pref : {0, 1, 2, 3}) {
        // PREF 3 (both representations alike) only without a parameter-space
        // curve; model-space boundaries also cycle through CRTN 0-3.
        if (pref == 3 && !model_space_only) continue;
        RevolvedPatch p;
        p.crtn = model_space_only ? variant++ % 4 : 0;
        p.kind = c.kind;
        p.theta0 = c.theta0;
        p.theta1 = c.theta1;
        p.s0 = c.s0;
        p.s1 = c.s1;
        p.reversed_loop = reversed;
        p.pref = pref;
        p.model_space_only = model_space_only;
        cases.push_back(p);
      }
  return cases;
}

TEST_CASE("CAD import: IGES cylinder and torus patches as surfaces of revolution keep the enclosed region") {
  check_cases(revolved_cases(false), "iges-cylinder-torus-patches");
}

TEST_CASE("CAD import: a whole IGES sphere bounded by its seam and poles in parameter space is the whole sphere") {
  // Not with PREF 2: its model-space boundary, the seam once up and once
  // down, encloses nothing, and OpenCASCADE, which then builds the face
  // from the model-space curves, gives a face along the seam only (the
  // import reports it as a face that cannot be converted).
  std::vector<SpherePatch> cases;
  for (const bool reversed : {false, true})
    for (const bool transformed : {false, true})
      for (const int pref : {0, 1, 3}) {
        SpherePatch p;
        p.theta0 = 0;
        p.theta1 = 2 * pi;
        p.phi0 = -pi / 2;
        p.phi1 = pi / 2;
        p.reversed_loop = reversed;
        p.generatrix_transformed = transformed;
        p.pref = pref;
        cases.push_back(p);
      }
  check_cases(cases, "iges-whole-sphere");
}

// Boundaries given as model-space curves only (type 142 with PPTR = 0, any
// PREF and CRTN), as CATIA writes every boundary: the importer builds the
// loop in the surface's parameters from the 3-D curves (docs/formats.md
// "CAD import", "IGES boundaries"). Every face keeps the region its loop
// encloses and the file's surface normal.
TEST_CASE("CAD import: IGES sphere patches bounded by model-space curves only keep the enclosed region") {
  std::vector<SpherePatch> cases;
  int variant = 0;
  for (const Range& r : kRanges)
    for (const bool reversed : {false, true})
      for (const int pref : {0, 1, 2, 3}) {
        SpherePatch p = patch_over(r);
        p.model_space_only = true;
        p.reversed_loop = reversed;
        p.pref = pref;
        p.crtn = (variant / 3) % 4;
        p.generatrix_transformed = variant % 2;
        p.split_at_equator = (variant / 2) % 2;
        p.arc_meridians = (variant / 4) % 2;
        ++variant;
        if (!p.seam_lune()) cases.push_back(p);  // the test after the next
      }
  check_cases(cases, "iges-sphere-model-space", true);
}

TEST_CASE("CAD import: IGES sphere patches bounded by model-space curves, any generatrix and axis direction") {
  std::vector<SpherePatch> cases;
  for (const SpherePatch& p : axis_generatrix_cases(true))
    if (!p.seam_lune()) cases.push_back(p);  // the next test
  check_cases(cases, "iges-sphere-model-space-axis", true);
}

TEST_CASE("CAD import: an IGES lune on or across the seam bounded by model-space curves goes by its rectangle, then its direction") {
  // Two meridians from pole to pole bound the lune and the rest of the
  // sphere alike. The file's rectangle (rotation angles from start to
  // terminate) holds only the rest when the lune crosses the seam; it holds
  // both when a meridian lies on the seam, and then the face is the one the
  // file's loop runs counterclockwise around in the file's (u,v)
  // (docs/formats.md "IGES boundaries"; the writer's loop as built runs
  // clockwise, the generatrix north to south and the axis -y each turn it).
  std::vector<SpherePatch> cases, expected;
  for (const Range& r : kRanges)
    for (const bool north_to_south : {false, true})
      for (const bool axis_reversed : {false, true})
        for (const bool reversed : {false, true}) {
          SpherePatch p = patch_over(r);
          p.model_space_only = true;
          p.north_to_south = north_to_south;
          p.axis_reversed = axis_reversed;
          p.reversed_loop = reversed;
          p.pref = 2;
          if (!p.seam_lune()) continue;
          const double a = std::min(p.file_v(p.theta0), p.file_v(p.theta1));
          const double b = std::max(p.file_v(p.theta0), p.file_v(p.theta1));
          const bool crosses = a < p.start_angle - 1e-12 || b > p.end_angle + 1e-12;
          const bool counterclockwise = (reversed != north_to_south) != axis_reversed;
          SpherePatch rest = p;  // the rest of the sphere
          rest.theta0 = p.theta1;
          rest.theta1 = p.theta0 + 2 * pi;
          cases.push_back(p);
          expected.push_back(!crosses && counterclockwise ? p : rest);
        }
  REQUIRE(cases.size() >= 20);
  check_cases(cases, "iges-sphere-model-space-seam-lunes", true, expected);
}

TEST_CASE("CAD import: IGES cylinder and torus patches bounded by model-space curves only") {
  check_cases(revolved_cases(true), "iges-cylinder-torus-model-space", true);
}

TEST_CASE("CAD import: IGES sphere patches bounded by model-space curves on a partial revolution") {
  // A lune from pole to pole then lies in the file's rectangle on one side
  // only, whichever way its loop runs.
  check_cases(partial_revolution_cases(true), "iges-sphere-partial-model-space", true);
}

TEST_CASE("CAD import: a ball of IGES octants bounded by model-space curves sews closed, every face outward") {
  // Eight one-pole octants of one sphere, each its own type 144 of its own
  // type 120 (whose normal points into the ball), loops in both directions:
  // they sew into a closed shell whose faces must all point out of the ball
  // (docs/formats.md "Orientation") and keep their area, a quarter of the
  // hemisphere each.
  IgesBuilder builder;
  std::vector<SpherePatch> octants;
  for (int k = 0; k < 4; ++k)
    for (const bool north : {true, false}) {
      SpherePatch p = patch_over({k * pi / 2, (k + 1) * pi / 2, north ? 0.0 : -pi / 2, north ? pi / 2 : 0.0});
      p.model_space_only = true;
      p.reversed_loop = (k + (north ? 1 : 0)) % 2 == 1;
      p.pref = 2;
      write_sphere_patch(builder, p);
      octants.push_back(p);
    }
  const std::string dir = scratch_dir("iges-octant-ball-" + std::to_string(getpid()));
  builder.file.write(dir + "/ball.igs");
  const CadImportResult result = import_cad(dir + "/ball.igs");
  REQUIRE(result.part.faces.size() == octants.size());
  CHECK(result.closed_shells == 1);
  const double expected = octants.front().area();
  REQUIRE(expected == doctest::Approx(4.75 * 4.75 * pi / 2).epsilon(1e-12));
  for (std::size_t f = 0; f < result.part.faces.size(); ++f) {
    const Face& face = result.part.faces[f];
    CAPTURE(f);
    CHECK(result.faces[f].orientation == CadFaceOrientation::closed_shell);
    CHECK(trimmed_area(face) == doctest::Approx(expected).epsilon(1e-6));
    // Every kept point's normal points away from the centre.
    CHECK(kept_share(face, [](const DifferentialGeometry& g) { return g.normal.dot(g.point.normalized()) > 0.99; }) ==
          1.0);
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}

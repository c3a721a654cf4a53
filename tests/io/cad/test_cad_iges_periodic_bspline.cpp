// CAD import of IGES trimmed surfaces on a closed periodic rational
// B-spline surface (type 128 with PROP1 closed and PROP4 periodic in u): a
// cylinder of radius 6 about +z written as the rational quadratic circle
// (9 poles, knots at quarter turns, where its parameter equals the angle)
// times a line of 10 mm, so that OpenCASCADE makes it a periodic B-spline
// (docs/formats.md "IGES boundaries"). Faces over angles across the seam,
// ending on it and the whole ring, bounded
// - by model-space curves only (type 142 PPTR 0), in every CRTN and PREF
//   and either loop direction, with and without a circular hole across
//   the seam, and
// - by the same loops with their parameter-space curves (straight lines in
//   (u, v)),
// are held to the analytic area (R (theta1 - theta0) (z1 - z0), less
// pi rho^2 for a circle drawn on the cylinder unrolled), to the file's
// surface normal (Su x Sv: out of the cylinder), and each model-space face
// to the same face written with parameter curves: the same integral of
// its unit normal over the kept region.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "iges_case_import.hpp"
#include "iges_occt_curves.hpp"
#include "iges_writer.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kSpacing = 80;  // case k lies around x = k * kSpacing
constexpr double kRadius = 6, kHeight = 10;
const double pi = M_PI;

// The cylinder c + (R cos u, R sin u, v), u in [0, 2 pi], v in [0, H], as a
// type 128 closed and periodic in u; returns its DE pointer.
int periodic_cylinder(IgesBuilder& b, const Eigen::Vector3d& c) {
  std::vector<std::vector<Eigen::Vector3d>> poles;
  std::vector<std::vector<double>> weights;
  const double corner = std::sqrt(0.5);  // cos(pi / 4)
  for (int i = 0; i <= 8; ++i) {
    const double a = i * pi / 4;
    const double scale = i % 2 ? kRadius / corner : kRadius;
    const Eigen::Vector3d p = c + Eigen::Vector3d(scale * std::cos(a), scale * std::sin(a), 0);
    poles.push_back({p, p + Eigen::Vector3d(0, 0, kHeight)});
    weights.push_back({i % 2 ? corner : 1.0, i % 2 ? corner : 1.0});
  }
  const std::vector<double> knots_u{0, 0, 0, pi / 2, pi / 2, pi, pi, 1.5 * pi, 1.5 * pi, 2 * pi, 2 * pi, 2 * pi};
  return b.bspline_surface(2, 1, knots_u, {0, 0, kHeight, kHeight}, poles, weights, true, true);
}

struct CylinderFace {
  double theta0, theta1, z0 = 2, z1 = 8;
  bool hole = false;  // a circle of radius 1.5 at angle 0, mid-height (across the seam)
};
constexpr double kHole = 1.5;

// Writes one face on its own cylinder at `centre`: model-space curves only
// (pcurves false) or with parameter curves too; `reversed` runs the loop
// the other way (the hole always the other way than the outer loop).
void write_face(IgesBuilder& b, const CylinderFace& f, const Eigen::Vector3d& centre, bool pcurves, bool reversed, int crtn,
                int pref) {
  const int surface = periodic_cylinder(b, centre);
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  auto at = [&](double theta, double z) {
    return Eigen::Vector3d(centre + Eigen::Vector3d(kRadius * std::cos(theta), kRadius * std::sin(theta), z));
  };
  struct Corner {
    double theta, z;
  };
  std::vector<Corner> corners{{f.theta0, f.z0}, {f.theta1, f.z0}, {f.theta1, f.z1}, {f.theta0, f.z1}};
  if (reversed) corners = {corners[0], corners[3], corners[2], corners[1]};
  std::vector<int> model, parameter;
  for (std::size_t k = 0; k < 4; ++k) {
    const Corner& a = corners[k];
    const Corner& e = corners[(k + 1) % 4];
    if (a.z == e.z)
      model.push_back(b.bspline_arc(centre + a.z * Z, X, Y, kRadius, a.theta, e.theta));
    else
      model.push_back(b.line(at(a.theta, a.z), at(e.theta, e.z)));
    // The surface's u is the angle at quarter turns (the corners' angles).
    if (pcurves)
      parameter.push_back(b.bspline_line({a.theta, a.z, 0}, {e.theta, e.z, 0}, 0, 1, true, IgesBuilder::kParametric));
  }
  const int outer = b.curve_on_surface(surface, pcurves ? b.composite(parameter, IgesBuilder::kParametric) : 0,
                                       b.composite(model), pref, crtn);
  std::vector<int> inner;
  if (f.hole) {
    const int circle = write_unrolled_circle(b, at, kRadius, 0, 0.5 * (f.z0 + f.z1), kHole, !reversed);
    inner.push_back(b.curve_on_surface(surface, 0, circle, pref, crtn));
  }
  b.trimmed_surface(surface, outer, inner);
}

double face_area(const CylinderFace& f) {
  return kRadius * (f.theta1 - f.theta0) * (f.z1 - f.z0) - (f.hole ? pi * kHole * kHole : 0.0);
}

std::function<Eigen::Vector3d(const Eigen::Vector3d&)> outward(const Eigen::Vector3d& centre) {
  return [centre](const Eigen::Vector3d& q) {
    const Eigen::Vector3d r = q - centre;
    return Eigen::Vector3d(Eigen::Vector3d(r.x(), r.y(), 0).normalized());
  };
}

std::string face_name(const CylinderFace& f, bool pcurves, bool reversed, int crtn, int pref) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "periodic B-spline cylinder theta %.4f..%.4f%s, %s, %s, CRTN %d, PREF %d", f.theta0,
                f.theta1, f.hole ? " with a hole across the seam" : "",
                pcurves ? "with parameter curves" : "model-space curves only", reversed ? "reversed" : "as built",
                crtn, pref);
  return buf;
}

// Angles as the file writes them: across the seam below 0, ending on it,
// a whole turn (the seam twice in the boundary).
const CylinderFace kFaces[] = {{-pi / 2, pi / 2}, {0, pi}, {pi, 2 * pi}, {-pi / 2, pi}, {0, 2 * pi}};

}  // namespace

TEST_CASE("CAD import: IGES faces on a periodic type 128 cylinder bounded by model-space curves only, every CRTN and PREF") {
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  std::vector<CylinderFace> faces(std::begin(kFaces), std::end(kFaces));
  faces.push_back({-pi / 2, pi / 2, 2, 8, true});
  faces.push_back({0, 2 * pi, 2, 8, true});
  // Every CRTN with every PREF, each pair on several faces and both loop
  // directions: face i takes PREF = (CRTN + i) mod 4, so faces 0..3 hold all
  // 16 pairs and every face all four of each (the whole cross product on
  // every face took three minutes for the same paths through the reader).
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (int crtn = 0; crtn <= 3; ++crtn)
      for (const bool reversed : {false, true}) {
        const CylinderFace& f = faces[i];
        const int pref = static_cast<int>((static_cast<std::size_t>(crtn) + i) % 4);
        const Eigen::Vector3d centre(kSpacing * static_cast<double>(cases.size()), 0, 0);
        write_face(builder, f, centre, false, reversed, crtn, pref);
        cases.push_back({face_name(f, false, reversed, crtn, pref), face_area(f), outward(centre)});
      }
  check_case_file(builder, cases, "iges-periodic-bspline-model-space", kSpacing);
}

TEST_CASE("CAD import: an IGES face on a periodic type 128 cylinder is the same from model-space curves as from parameter curves") {
  // Each face twice in one file, with and without parameter curves: both
  // against the analytic area and normal, and the model-space face's
  // normal integral against the parameter-curve face's, moved to its place.
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  // Two PREF values a face and direction, all four over the faces (each
  // pair with CRTN = PREF + 1 mod 4).
  for (std::size_t i = 0; i < std::size(kFaces); ++i)
    for (const bool reversed : {false, true})
      for (const std::size_t step : {0, 2})
        for (const bool pcurves : {false, true}) {
          const int pref = static_cast<int>((2 * i + (reversed ? 1 : 0) + step) % 4);
          const CylinderFace& f = kFaces[i];
          const int crtn = (pref + 1) % 4;
          const Eigen::Vector3d centre(kSpacing * static_cast<double>(cases.size()), 0, 0);
          write_face(builder, f, centre, pcurves, reversed, crtn, pref);
          cases.push_back({face_name(f, pcurves, reversed, crtn, pref), face_area(f), outward(centre)});
        }
  check_case_file(builder, cases, "iges-periodic-bspline-both", kSpacing);

  // The pairs: the same region with the same sense has the same normal
  // integral (a face turned round or the rest of the ring would not).
  const std::string dir = scratch_dir("iges-periodic-bspline-pairs-" + std::to_string(getpid()));
  builder.file.write(dir + "/pairs.igs");
  const CadImportResult result = import_cad(dir + "/pairs.igs");
  const std::map<long, const furrow::Face*> imported = faces_by_case(result, kSpacing);
  REQUIRE(imported.size() == cases.size());
  for (std::size_t k = 0; k + 1 < cases.size(); k += 2) {
    CAPTURE(cases[k].name);
    const Eigen::Vector3d model = normal_integral(*imported.at(static_cast<long>(k)));
    const Eigen::Vector3d parameter = normal_integral(*imported.at(static_cast<long>(k + 1)));
    CHECK((model - parameter).norm() < 1e-2 * cases[k].area);
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}

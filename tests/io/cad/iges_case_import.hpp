#pragma once
// The CAD import tests write many cases into one IGES file, case k placed
// around x = k * spacing, and find each imported face again by where it
// lies: whatever order the import keeps faces in, each case's face is the
// one whose middle lies nearest its place. check_case_file() then holds
// every face to its case's oracles.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "iges_writer.hpp"
#include "io/cad/cad_import.hpp"
#include "kept_region.hpp"
#include "support/run_cli.hpp"
#include "support/trimmed_area.hpp"

namespace furrow::test {

// Imported faces by the case they belong to (the point of the face's
// surface at the middle of its domain, rounded to the nearest place).
inline std::map<long, const Face*> faces_by_case(const CadImportResult& result, double spacing) {
  std::map<long, const Face*> faces;
  for (const Face& f : result.part.faces) {
    const ParameterDomain& d = f.domain();
    const Eigen::Vector3d p = f.surface().point(d.u0 + 0.5 * d.width_u(), d.v0 + 0.5 * d.width_v());
    faces[std::lround(p.x() / spacing)] = &f;
  }
  return faces;
}

// What one case's face must be.
struct ExpectedFace {
  std::string name;
  double area = 0;                                               // analytic [mm^2]
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> normal;  // the file's surface normal at a point
  // The kept region's centroid, where the area alone does not tell the
  // region from another (a half sphere from the other half); NaN: unchecked.
  Eigen::Vector3d centroid = Eigen::Vector3d::Constant(std::nan(""));
  double centroid_tolerance = 0;  // [mm]
};

// Writes `builder`'s file into a scratch folder named after `file_name`,
// imports it and checks every case's face: its area within 1e-6 of the
// analytic one (relative: the trim polygons' balanced sag leaves ~1e-11 of
// the area, curves interpolated through points ~1e-7), at every kept grid
// point the file's surface normal (a face that sews to nothing keeps it),
// and the centroid where given (kept_centroid() on a 160 x 160 grid).
inline void check_case_file(const IgesBuilder& builder, const std::vector<ExpectedFace>& cases,
                            const std::string& file_name, double spacing) {
  const std::string dir = scratch_dir(file_name + "-" + std::to_string(getpid()));
  const std::string path = dir + "/" + file_name + ".igs";
  builder.file.write(path);
  const CadImportResult result = import_cad(path);
  CHECK(result.format == "IGES");
  REQUIRE(result.part.faces.size() == cases.size());
  const std::map<long, const Face*> faces = faces_by_case(result, spacing);
  REQUIRE(faces.size() == cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const ExpectedFace& expected = cases[k];
    CAPTURE(expected.name);
    const Face& face = *faces.at(static_cast<long>(k));
    const double area = trimmed_area(face);
    CAPTURE(area);
    CAPTURE(expected.area);
    CHECK(std::abs(area - expected.area) < 1e-6 * expected.area);
    CHECK(kept_share(face, [&](const DifferentialGeometry& g) {
            return g.normal.dot(expected.normal(g.point)) > 0.99;
          }) == 1.0);
    if (expected.centroid.allFinite()) {
      const Eigen::Vector3d centroid = kept_centroid(face, 160);
      CAPTURE(centroid.transpose());
      CAPTURE(expected.centroid.transpose());
      CHECK((centroid - expected.centroid).norm() < expected.centroid_tolerance);
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}

}  // namespace furrow::test

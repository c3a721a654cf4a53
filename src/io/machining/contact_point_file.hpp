#pragma once
// Cutter-contact point files (CSV): the points a gouge check or a tool
// selection is run at (furrow gouge --points, furrow select-tool --points).
//
//   # comment
//   x,y,z,nx,ny,nz        <- optional header (any column order; "id" allowed)
//   12.5,40,21.37,0.01,-0.2,0.98
//
// One point per line: `x,y,z` or `x,y,z,nx,ny,nz` (the outward surface
// normal the CAM system used, checked against the part by the caller). A
// header names the columns: x, y, z required; nx, ny, nz all or none; an
// optional id column (kept as text). '#' starts a comment; blank lines are
// skipped. Coordinates are millimetres unless `units` says "inch".
// Errors name `file:line`: a wrong column count, a value that is not a finite
// number, a zero normal, duplicate or unknown header columns, an empty file.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace furrow {

struct ContactPointRecord {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [mm]
  bool has_normal = false;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // unit when has_normal
  std::string id;                                      // from an id column, else empty
  int line = 0;                                        // 1-based source line
};

std::vector<ContactPointRecord> parse_contact_points_csv(const std::string& text,
                                                         const std::string& name,
                                                         const std::string& units = "mm");
std::vector<ContactPointRecord> read_contact_points(const std::string& path,
                                                    const std::string& units = "mm");

}  // namespace furrow

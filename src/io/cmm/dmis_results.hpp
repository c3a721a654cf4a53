#pragma once
// DMIS results (docs/formats.md "Measurements", DMIS): the output file a CMM
// writes when it runs a DMIS program, Furrow's (dmis_writer.hpp) or one that
// also measures the datum features of the set-up.
//
//   FA(label)=FEAT/POINT,CART,x,y,z,i,j,k            a measured point
//   F(label)=FEAT/POINT,CART,x,y,z,i,j,k             its nominal (same label)
//   FA(label)=FEAT/PLANE,CART,x,y,z,i,j,k            a measured plane
//   FA(label)=FEAT/CIRCLE,INNER|OUTER,CART,x,y,z,i,j,k,diam
//   FA(label)=FEAT/CYLNDR,INNER|OUTER,CART,x,y,z,i,j,k,diam[,length]
//   D(label)=DATSET/...                              the datum set now in force
//   UNITS/MM|INCH[,...]                              for what follows
//
// "$" at the end of a line continues the statement on the next; "$$" starts
// a comment; keywords in any case, blanks anywhere. Other statements and
// feature types, and nominals of non-point features, are skipped. Points go
// to MeasurementSet::points, planes, circles and cylinders to `features`;
// each records the label of the DATSET in force (no transform is applied:
// the registration aligns the points to the part).
//
// Errors: InputError "FILE:LINE: ..." (line where the statement starts) for
// a malformed feature (not CART, a wrong count, a bad number, a zero
// direction, INNER/OUTER missing, a non-positive diameter), an unknown unit,
// a duplicate label.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/cmm/measurement_file.hpp"

namespace furrow {

// Fills set.points and set.features from `text` (no byte-order mark).
void parse_dmis_results(std::string_view text, const std::string& name, MeasurementSet& set);

// The DMIS output a CMM would write for `set`: a "$$" comment with the probe
// kind, DMISMN, UNITS/MM, then per point its nominal F(id) when the point has
// one and FA(id)=FEAT/POINT,CART,x,y,z,i,j,k (shortest exact numbers;
// direction the nominal's, else the point's, else +z), ENDFIL. Ids must be
// DMIS labels (InputError otherwise).
std::string dmis_results_text(const MeasurementSet& set);

// DMIS text as statements, shared with the reader of Furrow's own DMIS
// programs (dmis_program_reader.hpp): "$$" comments removed, a line ending
// in "$" joined with the next, blank lines dropped; `line` is where the
// statement starts (1-based).
struct DmisStatement {
  int line = 0;
  std::string text;
};
std::vector<DmisStatement> dmis_statements(const std::string& text);

// F(label)=FEAT/POINT,CART,x,y,z,i,j,k (a nominal) or FA(label)=... (an
// actual), coordinates times `scale`, ijk normalised; nullopt for any other
// statement (other feature types included); InputError "name:line: ..." for
// a malformed point (not CART, wrong count, bad number, zero direction).
struct DmisPointFeature {
  std::string label;  // as written
  bool actual = false;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d ijk = Eigen::Vector3d::UnitZ();
};
std::optional<DmisPointFeature> parse_dmis_point_feature(const DmisStatement& statement, const std::string& name,
                                                         double scale);

}  // namespace furrow

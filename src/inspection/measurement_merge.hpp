#pragma once
// Several measurement files of one part merged into one set
// (docs/verification.md "Re-measuring"): `furrow compare --measurements a.csv
// --measurements b.csv`. The files are taken in the order given, which is
// the order they were measured in: a later file's point replaces the earlier
// point with the same id in place (a re-measure of P0006 replaces P0006), a
// new id is appended. Every point remembers the file it came from and every
// replacement is listed, so comparison.json can say which file each
// deviation belongs to and what was measured again.
//
// Ids are what points are matched by, so with several files every file must
// carry its ids (CSV with an id column, DMIS): generated ids (XYZ, CSV
// without ids) are positions in their file, and "point 6" of a re-measure is
// not point 6 of the first run. Such a mix is refused (InputError naming the
// file), as are files whose probe data differ (centres and contact points,
// or different ball diameters): one set has one probe. One file is returned
// as it is.
#include <string>
#include <vector>

#include "io/cmm/measurement_file.hpp"

namespace furrow {

struct MeasurementReplacement {
  std::string id;
  std::size_t file = 0;      // index of the file whose point was replaced
  std::size_t by_file = 0;   // index of the later file that replaced it
  Eigen::Vector3d was = Eigen::Vector3d::Zero();  // the replaced coordinates [mm], the sets' frame (CMM; part frame for setups)
};

struct MergedMeasurements {
  MeasurementSet set;                 // source: the file names joined by " + "
  std::vector<std::string> files;     // as given
  std::vector<std::size_t> file_points;  // points read from each file
  // SHA-256 (hex) of each file, filled by the caller that read the bytes
  // (report/qa_report.hpp digest_file); empty when not known. comparison.json
  // records them when several files were merged.
  std::vector<std::string> sha256;
  std::vector<std::size_t> origin;    // per point of `set`: index into `files`
  std::vector<MeasurementReplacement> replaced;  // in the order they happened
};

// `sets` in measuring order, at least one; `sets[k].source` names file k.
MergedMeasurements merge_measurements(const std::vector<MeasurementSet>& sets);

}  // namespace furrow

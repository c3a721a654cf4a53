#include "planning/face_orientation_hint.hpp"

#include <cmath>
#include <map>

namespace furrow {

std::vector<FaceFacingDown> faces_facing_down(const std::vector<OrientationSample>& samples,
                                              const std::vector<Face>& faces) {
  struct Count {
    int candidates = 0, down = 0, kept = 0;
  };
  std::map<std::size_t, Count> per_face;
  for (const OrientationSample& s : samples) {
    Count& c = per_face[s.face];
    ++c.candidates;
    c.down += s.normal.z() < 0;
    c.kept += s.kept;
  }
  std::vector<FaceFacingDown> out;
  for (const auto& [face, c] : per_face) {
    if (face < faces.size() && faces[face].orientation_established()) continue;
    const double share = static_cast<double>(c.down) / c.candidates;
    if (c.candidates < kOrientationMinCandidates || share < kOrientationDownShare || c.kept > 0) continue;
    out.push_back({face, face < faces.size() ? faces[face].name() : std::string(), c.candidates, share});
  }
  return out;
}

std::string describe(const FaceFacingDown& f) {
  return "face " + std::to_string(f.face) + " \"" + f.name + "\" (" +
         std::to_string(static_cast<int>(std::floor(100 * f.down_share))) + " % of its " +
         std::to_string(f.candidates) + " candidate normals point down)";
}

const char* const kFacingDownHint =
    "normals into the material? normals must point out of it: re-import the CAD file with furrow import "
    "--outward (+z, -z or point:x,y,z), or set \"reversed\" on the face in the part file";

}  // namespace furrow

#pragma once
// Rapid moves checked against the part (docs/formats.md "prediction.json",
// `rapids`): a rapid is not cut, so a cutter that touches the design surface
// on one, or enters the stock box, crashes into material. Such a move is a
// *rapid gouge* site, reported with the rapid's source line, where its
// deepest point is and how deep it goes.
//
// Part: the cutter (its generic profile) swept along the straight tip
// segment of the rapid has the lower envelope of swept_envelope.hpp. At
// design-surface samples (a regular (u, v) grid per face, spacing about
// `sample_spacing` mm on the surface, as the error map samples) the envelope
// is compared with the surface; where it lies below, the overcut along the
// normal is the depth (normal_error.hpp, the same measure as the z-map's
// gouge sites). The deepest sample is then refined by a local search in
// (u, v). Samples the tool cannot reach from above (n_z < 0) and trimmed
// ones are skipped, as in the error map. Each face's samples are grouped in
// blocks with their bounding box (padded by a sample step), so a rapid only
// visits blocks in its shadow that rise above the lowest its envelope comes
// over them (SweptEnvelope::lower_bound; a plunge visits the blocks near
// where it lands): a rapid at a
// safe height costs one box test per block, and nothing at all when it is
// above the part's control nets (which contain every face); when no rapid
// comes that low, the surface is not sampled.
//
// Stock (only with a stock box): the cutter starts at its tip, so a rapid
// enters the stock when its tip is below the box's top while the cutter's
// disc (radius R) overlaps the box in xy. The depth is the box top minus the
// lowest such tip, located at that tip. The box is the raw stock: its top is
// not lowered by the cuts. A rapid that gouges the part is reported as a
// part gouge only (one site per rapid).
//
// Rapids whose ends are not both in the part frame (RapidMove::known false:
// G28, G53, a rapid from an unknown position) are counted as unchecked.
// Each rapid's result depends on that rapid only and findings are listed in
// path order, so the result does not depend on the thread count.
// Units: millimetres, part frame, tool axis +z.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/prediction/normal_error.hpp"

namespace furrow {

enum class RapidGougeKind { part, stock };
const char* to_string(RapidGougeKind kind);

struct RapidCheckOptions {
  double threshold = 0.02;       // [mm] deeper than this is a rapid gouge (the gouge threshold)
  double sample_spacing = 0.05;  // [mm] on the surface
  std::optional<Eigen::AlignedBox3d> stock;  // raw stock box, part frame
  std::size_t max_samples = 40'000'000;      // per face; InputError beyond
  int block = 16;                // samples per block side
  // Local search rounds (u then v each), stopping early once a round gains
  // less than 1e-12 mm: the depth's ridge may run diagonally in (u, v).
  int refine_rounds = 50;
  NormalErrorOptions normal;     // max_distance is raised to the part's size
};

struct RapidGouge {
  std::size_t rapid = 0;  // index in the tool path's rapids
  int line = 0;           // source line of the rapid
  RapidGougeKind kind = RapidGougeKind::part;
  double depth = 0;       // [mm] > threshold: overcut along the normal (part), below the stock top (stock)
  Eigen::Vector3d at = Eigen::Vector3d::Zero();  // deepest point: on the surface (part), the tip (stock)
  int face = -1;          // part: face and (u, v) of `at`; -1 for stock
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
};

struct RapidCheck {
  std::size_t rapids = 0;     // all rapid moves of the path
  std::size_t checked = 0;    // with both ends in the part frame
  std::size_t unchecked = 0;  // not in the part frame (RapidMove::known false)
  bool stock = false;         // a stock box was checked too
  std::vector<RapidGouge> gouges;  // in path order
};

// Throws InputError when a face would need more than max_samples samples or
// the options are out of range (non-positive spacing, negative threshold,
// an empty stock box).
RapidCheck check_rapids(const Part& part, const Cutter& cutter, const std::vector<RapidMove>& rapids,
                        const RapidCheckOptions& options = {});

}  // namespace furrow

#pragma once
// The I-MR control chart of one characteristic as a Drawing
// (render/drawing.hpp), for spc.html (docs/spc.md "spc.html").
//
// Two panels over the parts of the selection (x: part index, so a part
// that did not measure the characteristic leaves a gap): above, the
// individual values in µm with the centre line and the control limits;
// below, the moving ranges in µm with their mean and upper limit. Values
// that belong to a Nelson violation are drawn red. Only the latest
// kSpcChartParts parts are drawn (below).
//
// For readers and tests, each panel's plotting rectangle is an invisible
// rect of class "plot-area" whose data-x0/x1/y0/y1 give the data range it
// spans (x in part index, y in µm), each value is a circle of class
// "value" (or "mr") with data-part and data-value (shortest text, µm),
// and each horizontal line of class "centre" or "limit" has data-value.
#include <cstddef>

#include "render/drawing.hpp"
#include "results/spc_statistics.hpp"

namespace furrow {

// The parts a chart shows: the latest ones only. The figures are computed
// over the whole selection; a chart of every part of a long batch would be
// unreadable (thousands of dots in 600 px) and the page too large to open
// (1,000 parts x 300 points: ~70 MB).
constexpr std::size_t kSpcChartParts = 100;

// `part_count`: the number of parts in the selection. The x range is the
// last `window` parts of it (all when there are fewer): values and moving
// ranges of parts before it are left out; the centre line and limits are
// the whole selection's.
Drawing imr_chart(const CharacteristicSpc& c, std::size_t part_count, std::size_t window = kSpcChartParts);

}  // namespace furrow

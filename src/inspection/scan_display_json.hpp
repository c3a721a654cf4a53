#pragma once
// comparison.json members "display" and "histogram" of a scan
// (scan_display.hpp; docs/formats.md "comparison.json of a scan"), written
// and read back. Every number reads back as written: coordinates are
// rounded to 0.1 um before they are written, a deviation is written as the
// shortest text of its float.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <string>

#include "base/json_cursor.hpp"
#include "inspection/scan_display.hpp"

namespace furrow {

json_fields::json scan_display_json(const ScanDisplay& d);
json_fields::json scan_histogram_json(const ScanHistogram& h);

// InputError naming the member for anything missing, mistyped or
// inconsistent (counts that do not match the edges, edges not increasing,
// more points than the cap).
ScanDisplay read_scan_display(const JsonCursor& c);
ScanHistogram read_scan_histogram(const JsonCursor& c);

}  // namespace furrow

#pragma once
// The point table of report.html (docs/report.md "Point table"): the rows
// of point_table.hpp with the metrologist's columns - #, id, face, nominal
// X Y Z, nominal I J K, actual X Y Z (part frame), deviation, lower and
// upper limit, out-of-tolerance amount, status - out-of-tolerance rows red,
// points not evaluated grey.
//
// Readable without script: it is a plain <table>. A few lines of inline
// script (no library, no CDN) add a filter box, a status filter and
// sorting by a click on a column header; each numeric cell carries its
// exact value in data-v so sorting never parses rounded or signed text.
//
// Size: a report of 100 000 points must still open, so the HTML holds at
// most `max_rows` rows (default 2000): every point when there are no more,
// otherwise the out-of-tolerance points first (largest amount first, as
// many as fit) and then the others in measurement order up to the cap,
// shown in measurement order; a note says how many are shown and that
// points.csv holds them all.
#include <cstddef>
#include <string>

#include "inspection/comparison_document.hpp"

namespace furrow {

inline constexpr std::size_t kPointTableHtmlRows = 2000;

// The <section id="points"> with the table, the note and the script.
std::string point_table_html(const ComparisonDocument& doc, std::size_t max_rows = kPointTableHtmlRows);

// CSS of the table and of its controls (for the page's <style>).
const char* point_table_css();

}  // namespace furrow

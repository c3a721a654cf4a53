#include "report/point_table_html.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "report/html.hpp"
#include "report/point_table.hpp"

#include "base/number_text.hpp"

namespace furrow {

namespace {

using html::escape;

// The exact value (shortest round-trip text) for sorting, the rounded one shown.
std::string number_cell(double v, int decimals) {
  return "<td data-v=\"" + shortest(v) + "\">" + fixed(v, decimals) + "</td>";
}

// The rows the page shows (indices into the table, in measurement order).
std::vector<std::size_t> shown_rows(const std::vector<PointTableRow>& rows, std::size_t max_rows) {
  std::vector<std::size_t> shown;
  if (rows.size() <= max_rows) {
    for (std::size_t i = 0; i < rows.size(); ++i) shown.push_back(i);
    return shown;
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].status == "OUT") out.push_back(i);
  std::stable_sort(out.begin(), out.end(), [&](std::size_t a, std::size_t b) {
    return *rows[a].out_of_tolerance > *rows[b].out_of_tolerance;
  });
  if (out.size() > max_rows) out.resize(max_rows);
  std::vector<char> taken(rows.size(), 0);
  for (std::size_t i : out) taken[i] = 1;
  std::size_t count = out.size();
  for (std::size_t i = 0; i < rows.size() && count < max_rows; ++i)
    if (!taken[i]) {
      taken[i] = 1;
      ++count;
    }
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (taken[i]) shown.push_back(i);
  return shown;
}

// Filter box, status filter and click-to-sort; added by the script itself,
// so a page read without script shows no dead controls.
const char* kTableScript =
    "<script>(function(){var t=document.getElementById('point-table');if(!t||!t.tBodies.length)return;"
    "var b=t.tBodies[0],rows=Array.prototype.slice.call(b.rows);"
    "var bar=document.createElement('div');bar.className='table-controls';"
    "bar.innerHTML='Filter <input type=\"search\" id=\"point-filter\" placeholder=\"id, face, status\"> "
    "<select id=\"point-status\"><option value=\"\">all</option><option>IN</option><option>OUT</option>"
    "<option>NOT EVALUATED</option></select> <span id=\"point-count\"></span>';"
    "t.parentNode.insertBefore(bar,t);"
    "var q=bar.querySelector('input'),s=bar.querySelector('select'),c=bar.querySelector('span');"
    "function apply(){var f=q.value.toLowerCase(),st=s.value,n=0;rows.forEach(function(r){"
    "var ok=(!st||r.getAttribute('data-status')===st)&&(!f||r.textContent.toLowerCase().indexOf(f)>=0);"
    "r.style.display=ok?'':'none';if(ok)n++;});c.textContent=n+' of '+rows.length+' rows shown';}"
    "q.addEventListener('input',apply);s.addEventListener('change',apply);var dir={};"
    "Array.prototype.forEach.call(t.tHead.rows[0].cells,function(h,i){h.className+=' sortable';"
    "h.title='click to sort';h.addEventListener('click',function(){var d=dir[i]=dir[i]===1?-1:1;"
    "rows.sort(function(x,y){var u=x.cells[i].getAttribute('data-v'),v=y.cells[i].getAttribute('data-v');"
    "if(u!==null&&v!==null){u=parseFloat(u);v=parseFloat(v);}else{u=x.cells[i].textContent;"
    "v=y.cells[i].textContent;}return (u<v?-1:u>v?1:0)*d;});"
    "rows.forEach(function(r){b.appendChild(r);});});});apply();})();</script>\n";

}  // namespace

const char* point_table_css() {
  return "table.pointtable{font-size:0.78em}table.pointtable td{white-space:nowrap}"
         "table.pointtable th.sortable{cursor:pointer}table.pointtable th.sortable:hover{background:#e2e2e2}"
         ".table-controls{margin:0.4em 0;font-size:0.9em}.table-controls input{width:16em}"
         ".table-scroll{overflow-x:auto;max-width:100%}"
         "@media print{.table-controls{display:none}.table-scroll{overflow:visible}}\n";
}

std::string point_table_html(const ComparisonDocument& doc, std::size_t max_rows) {
  const std::vector<PointTableRow> rows = point_table(doc);
  const std::vector<std::size_t> shown = shown_rows(rows, max_rows);
  std::string out =
      "<section id=\"points\"><h2>Points</h2>\n<p>Nominal: the foot point on the CAD surface and its outward "
      "normal; actual: the probe-compensated measured point in the part frame after registration; deviation "
      "along the normal, + material left, &minus; removed; out of tolerance: how far beyond the nearer limit "
      "(0 inside). Lengths in mm.";
  if (shown.size() < rows.size())
    out += " <b>" + std::to_string(shown.size()) + " of " + std::to_string(rows.size()) +
           " points shown</b>: every out-of-tolerance point (the worst first when they are more), then the first "
           "in measurement order; <code>points.csv</code> holds them all.";
  else
    out += " Every measured point in measurement order (also in <code>points.csv</code>).";
  out += "</p>\n<div class=\"table-scroll\"><table class=\"pointtable\" id=\"point-table\" data-rows=\"" +
         std::to_string(shown.size()) + "\" data-points=\"" + std::to_string(rows.size()) + "\">\n<thead><tr>";
  for (const char* h : {"#", "Id", "Face", "Nominal X", "Nominal Y", "Nominal Z", "I", "J", "K", "Actual X",
                        "Actual Y", "Actual Z", "Deviation", "Lower tol.", "Upper tol.", "Out of tol.", "Status"})
    out += std::string("<th>") + h + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (std::size_t k : shown) {
    const PointTableRow& r = rows[k];
    const char* css = r.status == "OUT" ? " class=\"out\"" : r.status == "IN" ? "" : " class=\"outlier\"";
    out += "<tr" + std::string(css) + " data-status=\"" + r.status + "\"><td data-v=\"" + std::to_string(r.index + 1) +
           "\">" + std::to_string(r.index + 1) + "</td><td>" + escape(r.id) + "</td><td>" + escape(r.face) + "</td>";
    for (int i = 0; i < 3; ++i) out += number_cell(r.nominal[i], 4);
    for (int i = 0; i < 3; ++i) out += number_cell(r.normal[i], 6);
    for (int i = 0; i < 3; ++i) out += number_cell(r.actual[i], 4);
    out += number_cell(r.deviation, 4) + number_cell(r.lower, 4) + number_cell(r.upper, 4);
    // A point not evaluated has no amount; -1 sorts it below every judged point.
    out += r.out_of_tolerance ? number_cell(*r.out_of_tolerance, 4) : "<td data-v=\"-1\">&ndash;</td>";
    out += "<td>" + escape(r.status + (r.outlier.empty() ? "" : " (" + r.outlier + ")")) + "</td></tr>\n";
  }
  return out + "</tbody></table></div>\n" + kTableScript + "</section>\n";
}

}  // namespace furrow

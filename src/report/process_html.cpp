#include "report/process_html.hpp"

#include <algorithm>

#include "base/number_text.hpp"
#include "report/html.hpp"

namespace furrow {

namespace {

constexpr double kWidth = 180, kHeight = 36, kPad = 4;

// A sparkline: the recent values as a line, this part's value a larger red
// or blue dot, the zone's limits as faint lines when they fall in range.
// Each value is a circle with data-serial and data-value (mm, shortest
// text) for readers and tests; the y range is data-y0 .. data-y1 (mm).
std::string sparkline(const RegionProcess& r) {
  double lo = r.recent.front(), hi = r.recent.front();
  for (double v : r.recent) lo = std::min(lo, v), hi = std::max(hi, v);
  if (hi - lo < 1e-6) lo -= 0.001, hi += 0.001;  // one level only: a 2 um window
  const std::size_t n = r.recent.size();
  const auto x = [&](std::size_t i) { return n == 1 ? kWidth / 2 : kPad + (kWidth - 2 * kPad) * i / (n - 1.0); };
  const auto y = [&](double v) { return kPad + (kHeight - 2 * kPad) * (hi - v) / (hi - lo); };
  std::string svg = "<svg class=\"sparkline\" width=\"" + fixed(kWidth, 0) + "\" height=\"" + fixed(kHeight, 0) +
                    "\" viewBox=\"0 0 " + fixed(kWidth, 0) + " " + fixed(kHeight, 0) + "\" data-y0=\"" +
                    shortest(lo) + "\" data-y1=\"" + shortest(hi) + "\" role=\"img\" aria-label=\"region " +
                    html::escape(r.region) + ", last " + std::to_string(n) + " parts\">";
  for (double limit : {r.lower, r.upper})
    if (limit >= lo && limit <= hi)
      svg += "<line class=\"limit\" x1=\"0\" x2=\"" + fixed(kWidth, 0) + "\" y1=\"" + fixed(y(limit), 2) +
             "\" y2=\"" + fixed(y(limit), 2) + "\" stroke=\"#d08020\" stroke-width=\"0.8\"/>";
  if (n > 1) {
    svg += "<polyline fill=\"none\" stroke=\"#5080b0\" stroke-width=\"1\" points=\"";
    for (std::size_t i = 0; i < n; ++i) svg += (i ? " " : "") + fixed(x(i), 2) + "," + fixed(y(r.recent[i]), 2);
    svg += "\"/>";
  }
  for (std::size_t i = 0; i < n; ++i) {
    const bool part = r.has_part && i + 1 == n;
    const bool alarm = part && !r.rules_at_part.empty();
    svg += "<circle class=\"" + std::string(part ? "value part" : "value") + "\" cx=\"" + fixed(x(i), 2) +
           "\" cy=\"" + fixed(y(r.recent[i]), 2) + "\" r=\"" + (part ? "3" : "1.5") + "\" fill=\"" +
           (alarm ? "#c81e1e" : part ? "#1a4f8a" : "#5080b0") + "\" data-serial=\"" + html::escape(r.serials[i]) +
           "\" data-value=\"" + shortest(r.recent[i]) + "\"/>";
  }
  return svg + "</svg>";
}

std::string rules_text(const std::vector<int>& rules) {
  if (rules.empty()) return "none";
  std::string s;
  for (int rule : rules) s += (s.empty() ? "" : ", ") + std::to_string(rule);
  return s;
}

}  // namespace

std::string process_section_html(const std::optional<ProcessContext>& process) {
  if (!process) return "";
  const ProcessContext& p = *process;
  std::string out = "<section id=\"process\"><h2>Process</h2>\n<p>Part <code>" + html::escape(p.serial) + "</code> is part " +
                    std::to_string(p.position + 1) + " of " + std::to_string(p.parts) +
                    " in the results database <code>" + html::escape(p.source) + "</code>" +
                    (p.stored ? "" : " (not stored yet: shown after the stored parts)") +
                    ". Per region, its mean deviation over the last " + std::to_string(kProcessRecentParts) +
                    " parts (this part the large dot, red when a Nelson rule is violated at it), and the "
                    "region's Cpk over the whole process (docs/spc.md).</p>\n";
  std::vector<html::TableRow> rows;
  for (const RegionProcess& r : p.regions) {
    if (r.recent.empty()) continue;  // measured only after this part
    html::TableRow row;
    row.cells = {"R" + html::escape(r.region),
                 sparkline(r),
                 r.has_part ? signed_fixed(r.recent.back() * 1000, 1) : "&ndash;",
                 r.mean ? signed_fixed(*r.mean * 1000, 1) : "&ndash;",
                 std::to_string(r.n),
                 r.cpk ? fixed(*r.cpk, 2) : "&ndash;",
                 rules_text(r.rules_at_part)};
    row.css_class = r.rules_at_part.empty() ? "" : "out";
    rows.push_back(std::move(row));
  }
  out += html::table({"Region", "Last parts", "This part [um]", "Process mean [um]", "Parts", "Cpk",
                      "Rules violated here"},
                     rows, "process");
  return out + "</section>\n";
}

}  // namespace furrow

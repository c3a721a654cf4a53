#include "results/spc_html.hpp"

#include <optional>
#include <vector>

#include "base/number_text.hpp"
#include "base/text_fields.hpp"
#include "render/svg.hpp"
#include "results/spc_chart.hpp"

namespace furrow {
namespace {

std::string esc(const std::string& s) { return markup_escape(s); }

// A figure in a table cell, or an em dash for an absent one.
std::string cell(const std::optional<double>& v, int decimals, double scale = 1) {
  return v ? fixed(*v * scale, decimals) : std::string("&#8212;");
}

// docs/spc.md "Nelson rules", in a few words each.
const char* const kRuleText[8] = {"a value beyond 3 σ",
                                  "nine in a row on one side of the mean",
                                  "six in a row steadily rising or falling",
                                  "fourteen in a row alternating up and down",
                                  "two of three beyond 2 σ on one side",
                                  "four of five beyond 1 σ on one side",
                                  "fifteen in a row within 1 σ",
                                  "eight in a row beyond 1 σ on both sides"};

const char* kStyle =
    "body{font-family:'DejaVu Sans',Helvetica,Arial,sans-serif;margin:24px;color:#232323}"
    "table{border-collapse:collapse;margin:8px 0 20px}"
    "th,td{border:1px solid #ccc;padding:3px 8px;text-align:right;white-space:nowrap}"
    "th{background:#f0f0f0}td.id,td.text{text-align:left}"
    "tr.alarm td{background:#fbe3e3}tr.fail td.verdict{color:#b00;font-weight:bold}"
    "section.characteristic{margin:18px 0;page-break-inside:avoid}"
    "p.note{color:#666;margin:2px 0}";

std::string capability_table(const SpcResult& r, const std::vector<std::size_t>& order) {
  std::string s =
      "<table class=\"capability\">\n<tr><th>characteristic</th><th>kind</th><th>n</th><th>mean [µm]</th>"
      "<th>σ within [µm]</th><th>σ overall [µm]</th><th>Cp</th><th>Cpk</th><th>Pp</th><th>Ppk</th>"
      "<th>slope [µm/part]</th><th>95 % interval [µm/part]</th><th>violations</th></tr>\n";
  for (std::size_t i : order) {
    const CharacteristicSpc& c = r.characteristics[i];
    std::string interval = "&#8212;";
    if (c.slope && c.slope->low)
      interval = fixed(*c.slope->low * 1000, 3) + " … " + fixed(*c.slope->high * 1000, 3);
    s += std::string("<tr") + (c.violations.empty() ? "" : " class=\"alarm\"") + " data-id=\"" + esc(c.id) +
         "\"><td class=\"id\"><a href=\"#chart-" + std::to_string(i) + "\">" + esc(c.id) + "</a></td><td class=\"text\">" +
         esc(c.kind) + "</td><td>" + std::to_string(c.n) + "</td><td>" + cell(c.mean, 2, 1000) + "</td><td>" +
         cell(c.sigma_within, 2, 1000) + "</td><td>" + cell(c.sigma_overall, 2, 1000) + "</td><td>" + cell(c.cp, 2) +
         "</td><td>" + cell(c.cpk, 2) + "</td><td>" + cell(c.pp, 2) + "</td><td>" + cell(c.ppk, 2) + "</td><td>" +
         (c.slope ? fixed(c.slope->value * 1000, 3) : std::string("&#8212;")) + "</td><td>" + interval + "</td><td>" +
         std::to_string(c.violations.size()) + "</td></tr>\n";
  }
  return s + "</table>\n";
}

std::string chart_section(const SpcResult& r, std::size_t i) {
  const CharacteristicSpc& c = r.characteristics[i];
  std::string s = "<section class=\"characteristic\" data-id=\"" + esc(c.id) + "\">\n";
  s += to_svg(imr_chart(c, r.parts.size()), "I-MR chart of " + c.id, "chart-" + std::to_string(i));
  if (r.parts.size() > kSpcChartParts)
    s += "<p class=\"window\">the chart shows the last " + std::to_string(kSpcChartParts) + " of " +
         std::to_string(r.parts.size()) + " parts; the figures are over all of them</p>\n";
  s += "<p>zone " + fixed(c.lower * 1000, 1) + " … " + fixed(c.upper * 1000, 1) + " µm</p>\n";
  if (!c.violations.empty()) {
    // One line per rule: its meaning, then where each violation starts.
    s += "<ul class=\"violations\">\n";
    for (int rule = 1; rule <= 8; ++rule) {
      std::string starts;
      std::size_t count = 0;
      for (const SpcViolation& v : c.violations) {
        if (v.rule != rule) continue;
        starts += (count++ ? ", " : "") + esc(v.serial);
        if (v.last > v.index) starts += " (" + std::to_string(v.last - v.index + 1) + " values)";
      }
      if (count)
        s += "<li data-rule=\"" + std::to_string(rule) + "\" data-count=\"" + std::to_string(count) + "\">rule " +
             std::to_string(rule) + ", " + kRuleText[rule - 1] + ": from " + starts + "</li>\n";
    }
    s += "</ul>\n";
  }
  for (const std::string& note : c.notes) s += "<p class=\"note\">" + esc(note) + "</p>\n";
  return s + "</section>\n";
}

std::string parts_table(const SpcResult& r) {
  std::string s =
      "<table class=\"parts\">\n"
      "<tr><th>#</th><th>serial</th><th>date</th><th>verdict</th><th>operator</th><th>CMM</th></tr>\n";
  for (std::size_t i = 0; i < r.parts.size(); ++i) {
    const PartRecord& p = r.parts[i];
    s += std::string("<tr") + (p.verdict == "FAIL" ? " class=\"fail\"" : "") + "><td>" + std::to_string(i) +
         "</td><td class=\"text\">" + esc(p.serial) + "</td><td class=\"text\">" + esc(p.date) +
         "</td><td class=\"text verdict\">" + esc(p.verdict) + "</td><td class=\"text\">" + esc(p.operator_name) +
         "</td><td class=\"text\">" + esc(p.cmm) + "</td></tr>\n";
  }
  return s + "</table>\n";
}

}  // namespace

std::string spc_html(const SpcResult& r, const SpcSelection& selection) {
  const std::vector<std::size_t> order = worst_first(r);
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>SPC</title>\n<style>";
  s += kStyle;
  s += "</style>\n</head>\n<body>\n<h1>Statistical process control</h1>\n";
  s += "<p>Source: " + esc(selection.source) + "; " + std::to_string(r.parts.size()) + " parts";
  if (!r.parts.empty()) s += ", " + esc(r.parts.front().serial) + " to " + esc(r.parts.back().serial);
  s += ".</p>\n";
  if (!selection.criteria.empty()) {
    s += "<p>Selection:";
    for (const auto& [option, value] : selection.criteria) s += " " + esc(option) + " = " + esc(value) + ";";
    s += "</p>\n";
  }
  s += std::string("<p class=\"latest\">") +
       (violation_in_latest_part(r) ? "A Nelson rule is violated at the latest part."
                                    : "No Nelson rule is violated at the latest part.") +
       "</p>\n";
  s += "<h2>Capability</h2>\n" + capability_table(r, order);
  s += "<h2>Control charts, worst first</h2>\n";
  for (std::size_t i : order) s += chart_section(r, i);
  s += "<h2>Parts</h2>\n" + parts_table(r);
  return s + "</body>\n</html>\n";
}

}  // namespace furrow

#include "results/spc_summary.hpp"

#include <set>
#include <vector>

#include "base/number_text.hpp"

namespace furrow {

namespace {

// A region's id is its number: "region 3" reads, a bare "3" does not.
std::string label(const CharacteristicSpc& c) { return c.kind == "region" ? "region " + c.id : c.id; }

}  // namespace

std::string spc_summary(const SpcResult& r, std::size_t worst) {
  std::size_t violations = 0;
  for (const CharacteristicSpc& c : r.characteristics) violations += c.violations.size();
  std::string s = "spc: " + std::to_string(r.parts.size()) + " parts";
  if (!r.parts.empty()) s += " (" + r.parts.front().serial + " .. " + r.parts.back().serial + ")";
  s += ", " + std::to_string(r.characteristics.size()) + " characteristics, " + std::to_string(violations) +
       " violations\n";
  const std::vector<std::size_t> order = worst_first(r);
  for (std::size_t k = 0; k < order.size() && k < worst; ++k) {
    const CharacteristicSpc& c = r.characteristics[order[k]];
    s += "  " + label(c) + "  n " + std::to_string(c.n);
    s += c.cpk ? "  cpk " + fixed(*c.cpk, 2) + "  ppk " + fixed(*c.ppk, 2) : std::string("  no cpk");
    if (c.slope) s += "  slope " + signed_fixed(c.slope->value * 1000, 3) + " µm/part";
    s += "  violations " + std::to_string(c.violations.size()) + "\n";
  }
  if (r.parts.empty()) return s + "no parts selected\n";
  const auto latest = latest_part_violations(r);
  s += "latest part " + r.parts.back().serial + ": ";
  if (latest.empty()) return s + "no Nelson rule violated\n";
  // One entry per characteristic: its id and the rules, in rule order.
  for (std::size_t k = 0; k < latest.size();) {
    if (k > 0) s += "; ";
    const std::size_t at = latest[k].first;
    std::set<int> rules;
    for (; k < latest.size() && latest[k].first == at; ++k) rules.insert(r.characteristics[at].violations[latest[k].second].rule);
    s += label(r.characteristics[at]) + (rules.size() > 1 ? " rules " : " rule ");
    bool first = true;
    for (int rule : rules) {
      s += (first ? "" : ", ") + std::to_string(rule);
      first = false;
    }
  }
  return s + "\n";
}

}  // namespace furrow
